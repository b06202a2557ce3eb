/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of cholmodSolver.H: Supernodal sparse Cholesky
    factorisation K = L L^T (SuiteSparse CHOLMOD through
    Eigen::CholmodSupernodalLLT) with the METIS nested-dissection ordering
    forced (one ordering method, no AMD fall-back), so that the fill is
    predictable for the large 2D/3D meshes of forming problems.
\*---------------------------------------------------------------------------*/
#include "cholmodSolver.H"
#include "formError.H"
#include <Eigen/CholmodSupport>

namespace form
{

// Access to the CHOLMOD factor held by Eigen's wrapper (protected member)
struct cholmodSolver::impl
:
    public Eigen::CholmodSupernodalLLT<sparseMatrix, Eigen::Lower>
{
    const cholmod_factor* factor() const { return m_cholmodFactor; }
    bool analysed = false;
    bool factorised = false;
};

} // namespace form


form::cholmodSolver::cholmodSolver()
:
    impl_(std::make_unique<impl>())
{
    cholmod_common& c = impl_->cholmod();
    // METIS nested dissection only (CHOLMOD user guide, sec. "nmethods")
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_METIS;
    c.postorder = 1;
    // Failures are reported by our exceptions, not by CHOLMOD's printer
    c.print = 0;
}


form::cholmodSolver::~cholmodSolver() = default;


void form::cholmodSolver::analyzePattern(const sparseMatrix& K)
{
    if (K.rows() != K.cols())
    {
        throw numericalError("cholmod: matrix is not square");
    }
    impl_->analyzePattern(K);
    const cholmod_common& c = impl_->cholmod();
    if (!impl_->factor() || c.status < CHOLMOD_OK)
    {
        throw numericalError
        (
            "cholmod: symbolic analysis (METIS ordering) failed, status "
          + std::to_string(c.status)
        );
    }
    impl_->analysed = true;
    impl_->factorised = false;
}


void form::cholmodSolver::factorize(const sparseMatrix& K)
{
    if (!impl_->analysed)
    {
        analyzePattern(K);
    }
    impl_->factorised = false;
    impl_->factorize(K);
    const cholmod_factor* L = impl_->factor();
    if (impl_->info() != Eigen::Success)
    {
        throw numericalError
        (
            "cholmod: matrix is not positive definite (factorisation failed"
            " at column " + std::to_string(L->minor) + " of "
          + std::to_string(L->n) + "); use umfpack for indefinite or"
            " unsymmetric systems, or check the constraints"
        );
    }
    if (impl_->cholmod().status < CHOLMOD_OK)
    {
        throw numericalError
        (
            "cholmod: numeric factorisation failed, status "
          + std::to_string(impl_->cholmod().status)
        );
    }
    impl_->factorised = true;
}


form::vecX form::cholmodSolver::solve(const vecX& r)
{
    if (!impl_->factorised)
    {
        throw numericalError("cholmod: solve() called without factorisation");
    }
    vecX x = impl_->solve(r);
    if (impl_->info() != Eigen::Success)
    {
        throw numericalError("cholmod: triangular solves failed");
    }
    return x;
}


double form::cholmodSolver::factorMemory() const
{
    const cholmod_factor* L = impl_->factor();
    if (!L || !impl_->factorised) return 0;
    if (L->is_super)
    {
        return double(L->xsize)*sizeof(double) + double(L->ssize)*sizeof(int);
    }
    return double(L->nzmax)*(sizeof(double) + sizeof(int));
}


form::linearSolver::factorStats form::cholmodSolver::stats() const
{
    // From the symbolic analysis: nonzeros of L and the flop count of
    // the numeric factorisation (CHOLMOD user guide, cholmod_common: lnz,
    // fl)
    const cholmod_common& c = impl_->cholmod();
    if (!impl_->factorised) return {};
    return {c.lnz, c.fl};
}


bool form::cholmodSolver::usedMetis() const
{
    const cholmod_factor* L = impl_->factor();
    return L && L->ordering == CHOLMOD_METIS;
}
