/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of umfpackSolver.H: Sparse LU factorisation P R K Q = L U
    (SuiteSparse UMFPACK through Eigen::UmfPackLU) with the METIS column
    ordering, or AMD (UMFPACK's default) if a row or column of K has more
    than 10 sqrt(n) entries.
\*---------------------------------------------------------------------------*/
#include "umfpackSolver.H"
#include "formError.H"
#include <Eigen/UmfPackSupport>
#include <cmath>
#include <vector>

namespace form
{

// Access to UMFPACK's Numeric object and Info array held by Eigen's wrapper
struct umfpackLU
:
    public Eigen::UmfPackLU<sparseMatrix>
{
    void* numeric() const { return m_numeric; }
    using Eigen::UmfPackLU<sparseMatrix>::info;
    double infoValue(int i) const { return m_umfpackInfo(i); }
};

struct umfpackSolver::impl
{
    umfpackLU lu;
    // UMFPACK's solve reads the matrix again (iterative refinement), so the
    // factorised matrix is kept here rather than referenced
    sparseMatrix K;
    bool analysed = false;
    bool factorised = false;
    bool metis = false;
};

namespace
{

// True if a row or column of K has more than 10 sqrt(n) entries: the
// threshold above which AMD (and so UMFPACK's AMD/COLAMD ordering) treats
// it as dense and orders it last (Amestoy, Davis & Duff, ACM TOMS 30,
// 2004). METIS on the pattern of K + K^T has no such treatment: a dense
// border widens every front to its width.
bool hasDenseRowOrColumn(const form::sparseMatrix& K)
{
    const double dense = 10*std::sqrt(double(K.rows()));
    std::vector<int> rowCount(K.rows(), 0);
    for (int k = 0; k < K.outerSize(); ++k)
    {
        const int n = K.outerIndexPtr()[k + 1] - K.outerIndexPtr()[k];
        if (n > dense) return true;
        for (int i = K.outerIndexPtr()[k]; i < K.outerIndexPtr()[k + 1]; ++i)
        {
            if (++rowCount[K.innerIndexPtr()[i]] > dense) return true;
        }
    }
    return false;
}

} // namespace

} // namespace form


form::umfpackSolver::umfpackSolver()
:
    impl_(std::make_unique<impl>())
{
}


form::umfpackSolver::~umfpackSolver() = default;


void form::umfpackSolver::analyzePattern(const sparseMatrix& K)
{
    if (K.rows() != K.cols())
    {
        throw numericalError("umfpack: matrix is not square");
    }
    impl_->K = K;
    impl_->K.makeCompressed();
    impl_->lu.umfpackControl()(UMFPACK_ORDERING) =
        hasDenseRowOrColumn(impl_->K)
      ? UMFPACK_ORDERING_AMD
      : UMFPACK_ORDERING_METIS;
    impl_->lu.analyzePattern(impl_->K);
    if (impl_->lu.info() != Eigen::Success)
    {
        throw numericalError
        (
            "umfpack: symbolic analysis failed, status "
          + std::to_string(int(impl_->lu.infoValue(UMFPACK_STATUS)))
        );
    }
    impl_->metis =
        int(impl_->lu.infoValue(UMFPACK_ORDERING_USED)) == UMFPACK_ORDERING_METIS;
    impl_->analysed = true;
    impl_->factorised = false;
}


void form::umfpackSolver::factorize(const sparseMatrix& K)
{
    if (!impl_->analysed)
    {
        analyzePattern(K);
    }
    impl_->factorised = false;
    impl_->K = K;
    impl_->K.makeCompressed();
    impl_->lu.factorize(impl_->K);
    if (impl_->lu.info() != Eigen::Success)
    {
        const int status = impl_->lu.umfpackFactorizeReturncode();
        throw numericalError
        (
            std::string("umfpack: numeric factorisation failed (")
          + (
                status == UMFPACK_WARNING_singular_matrix
              ? "singular matrix"
              : "status " + std::to_string(status)
            )
          + ")"
        );
    }
    impl_->factorised = true;
}


form::vecX form::umfpackSolver::solve(const vecX& r)
{
    if (!impl_->factorised)
    {
        throw numericalError("umfpack: solve() called without factorisation");
    }
    vecX x = impl_->lu.solve(r);
    if (impl_->lu.info() != Eigen::Success || !x.allFinite())
    {
        throw numericalError("umfpack: solve failed");
    }
    return x;
}


form::linearSolver::factorStats form::umfpackSolver::stats() const
{
    // UMFPACK user guide, Info array of umfpack_numeric: nonzeros of L
    // and U, flop count
    if (!impl_->factorised) return {};
    return
    {
        impl_->lu.infoValue(UMFPACK_LNZ) + impl_->lu.infoValue(UMFPACK_UNZ),
        impl_->lu.infoValue(UMFPACK_FLOPS)
    };
}


double form::umfpackSolver::factorMemory() const
{
    if (!impl_->factorised || !impl_->lu.numeric()) return 0;
    int lnz = 0, unz = 0, nRow = 0, nCol = 0, nzUdiag = 0;
    umfpack_di_get_lunz
    (
        &lnz, &unz, &nRow, &nCol, &nzUdiag, impl_->lu.numeric()
    );
    return (double(lnz) + double(unz))*(sizeof(double) + sizeof(int));
}


bool form::umfpackSolver::usedMetis() const
{
    return impl_->metis;
}
