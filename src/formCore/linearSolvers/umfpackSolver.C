/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of umfpackSolver.H: Sparse LU factorisation P R K Q = L U
    (SuiteSparse UMFPACK through Eigen::UmfPackLU) with the METIS or the
    AMD column ordering (umfpackSolver.H says which).
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
    //- The factorisation, and the other ordering's analysis while the
    //  first factorisation compares them (else null)
    std::unique_ptr<umfpackLU> lu = std::make_unique<umfpackLU>();
    std::unique_ptr<umfpackLU> other;
    // UMFPACK's solve reads the matrix again (iterative refinement), so the
    // factorised matrix is kept here rather than referenced
    sparseMatrix K;
    bool analysed = false;
    bool factorised = false;
    //- The ordering a first factorisation chose (-1: none yet), and the
    //  nonzeros of its matrix
    int chosen = -1;
    double chosenNonZeros = 0;

    //- Symbolic analysis of K with an ordering into a new object
    std::unique_ptr<umfpackLU> analyse(int ordering) const
    {
        auto lu = std::make_unique<umfpackLU>();
        lu->umfpackControl()(UMFPACK_ORDERING) = ordering;
        lu->analyzePattern(K);
        if (lu->info() != Eigen::Success)
        {
            throw numericalError
            (
                "umfpack: symbolic analysis failed, status "
              + std::to_string(int(lu->infoValue(UMFPACK_STATUS)))
            );
        }
        return lu;
    }

    bool metis(const umfpackLU& lu) const
    {
        return int(lu.infoValue(UMFPACK_ORDERING_USED)) == UMFPACK_ORDERING_METIS;
    }
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


form::umfpackSolver::umfpackSolver(ordering o)
:
    impl_(std::make_unique<impl>()),
    ordering_(o)
{
}


form::umfpackSolver::~umfpackSolver() = default;


void form::umfpackSolver::analyzePattern(const sparseMatrix& K)
{
    if (K.rows() != K.cols())
    {
        throw numericalError("umfpack: matrix is not square");
    }
    impl& m = *impl_;
    m.K = K;
    m.K.makeCompressed();
    m.analysed = false;
    m.factorised = false;
    m.other.reset();
    if (hasDenseRowOrColumn(m.K) && ordering_ == ordering::automatic)
    {
        m.lu = m.analyse(UMFPACK_ORDERING_AMD);
    }
    else if
    (
        ordering_ != ordering::automatic
     || (
            m.chosen >= 0
         && std::abs(m.K.nonZeros() - m.chosenNonZeros) <= 0.25*m.chosenNonZeros
        )
    )
    {
        const int o =
            ordering_ == ordering::metis ? UMFPACK_ORDERING_METIS
          : ordering_ == ordering::amd ? UMFPACK_ORDERING_AMD
          : m.chosen;
        m.lu = m.analyse(o);
    }
    else
    {
        // The first pattern, or one of another size: both orderings. The
        // symbolic flop estimates decide if they differ by more than a
        // factor 4 (the FSI matrix at rest: 32), else the first numeric
        // factorisation
        auto metis = m.analyse(UMFPACK_ORDERING_METIS);
        auto amd = m.analyse(UMFPACK_ORDERING_AMD);
        const double fm = metis->infoValue(UMFPACK_FLOPS_ESTIMATE);
        const double fa = amd->infoValue(UMFPACK_FLOPS_ESTIMATE);
        const bool amdFirst = fa < fm;
        m.lu = std::move(amdFirst ? amd : metis);
        if (std::max(fm, fa) <= 4*std::min(fm, fa))
        {
            m.other = std::move(amdFirst ? metis : amd);
        }
        else
        {
            m.chosen = amdFirst ? UMFPACK_ORDERING_AMD : UMFPACK_ORDERING_METIS;
            m.chosenNonZeros = m.K.nonZeros();
        }
    }
    m.analysed = true;
}


void form::umfpackSolver::factorize(const sparseMatrix& K)
{
    impl& m = *impl_;
    if (!m.analysed)
    {
        analyzePattern(K);
    }
    m.factorised = false;
    m.K = K;
    m.K.makeCompressed();
    const auto factor = [&](umfpackLU& lu)
    {
        lu.factorize(m.K);
        if (lu.info() != Eigen::Success)
        {
            const int status = lu.umfpackFactorizeReturncode();
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
    };
    factor(*m.lu);
    if (m.other)
    {
        // The first factorisation with the other ordering too: the one
        // with fewer flops stays, for the later patterns as well
        factor(*m.other);
        if (m.other->infoValue(UMFPACK_FLOPS) < m.lu->infoValue(UMFPACK_FLOPS))
        {
            std::swap(m.lu, m.other);
        }
        m.other.reset();
        m.chosen = m.metis(*m.lu) ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
        m.chosenNonZeros = m.K.nonZeros();
    }
    m.factorised = true;
}


form::vecX form::umfpackSolver::solve(const vecX& r)
{
    if (!impl_->factorised)
    {
        throw numericalError("umfpack: solve() called without factorisation");
    }
    vecX x = impl_->lu->solve(r);
    if (impl_->lu->info() != Eigen::Success || !x.allFinite())
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
        impl_->lu->infoValue(UMFPACK_LNZ) + impl_->lu->infoValue(UMFPACK_UNZ),
        impl_->lu->infoValue(UMFPACK_FLOPS)
    };
}


double form::umfpackSolver::factorMemory() const
{
    if (!impl_->factorised || !impl_->lu->numeric()) return 0;
    int lnz = 0, unz = 0, nRow = 0, nCol = 0, nzUdiag = 0;
    umfpack_di_get_lunz
    (
        &lnz, &unz, &nRow, &nCol, &nzUdiag, impl_->lu->numeric()
    );
    return (double(lnz) + double(unz))*(sizeof(double) + sizeof(int));
}


bool form::umfpackSolver::usedMetis() const
{
    return impl_->analysed && impl_->metis(*impl_->lu);
}
