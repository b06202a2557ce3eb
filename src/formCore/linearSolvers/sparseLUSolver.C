/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of sparseLUSolver.H: Eigen's SparseLU with COLAMD
    ordering.
\*---------------------------------------------------------------------------*/
#include "sparseLUSolver.H"
#include "formError.H"
#include <Eigen/SparseLU>

namespace form
{

struct sparseLUSolver::impl
{
    Eigen::SparseLU<sparseMatrix, Eigen::COLAMDOrdering<int>> lu;
    bool analysed = false;
    bool factorised = false;
};

} // namespace form


form::sparseLUSolver::sparseLUSolver()
:
    impl_(std::make_unique<impl>())
{}


form::sparseLUSolver::~sparseLUSolver() = default;


void form::sparseLUSolver::analyzePattern(const sparseMatrix& K)
{
    if (K.rows() != K.cols())
    {
        throw numericalError("sparseLU: matrix is not square");
    }
    impl_->lu.analyzePattern(K);
    impl_->analysed = true;
    impl_->factorised = false;
}


void form::sparseLUSolver::factorize(const sparseMatrix& K)
{
    if (!impl_->analysed)
    {
        analyzePattern(K);
    }
    impl_->factorised = false;
    impl_->lu.factorize(K);
    if (impl_->lu.info() != Eigen::Success)
    {
        throw numericalError
        (
            "sparseLU: numeric factorisation failed: "
          + impl_->lu.lastErrorMessage()
        );
    }
    impl_->factorised = true;
}


form::vecX form::sparseLUSolver::solve(const vecX& r)
{
    if (!impl_->factorised)
    {
        throw numericalError("sparseLU: solve() called without factorisation");
    }
    vecX x = impl_->lu.solve(r);
    if (impl_->lu.info() != Eigen::Success || !x.allFinite())
    {
        throw numericalError("sparseLU: solve failed");
    }
    return x;
}
