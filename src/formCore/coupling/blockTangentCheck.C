/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Finite-difference check of a coupled block's tangent
    (blockTangentCheck.H).
\*---------------------------------------------------------------------------*/
#include "blockTangentCheck.H"
#include <cmath>

namespace form
{

blockTangentError checkBlockTangent
(
    coupledBlock& block,
    double t,
    const vecX& U,
    double step
)
{
    const int n = block.nUnknowns();
    const int N = int(U.size());
    vecX fext = vecX::Zero(N), r;
    std::vector<coupledBlock::triplet> trips;
    block.evaluate(t, U, fext, r, &trips);
    matX K = matX::Zero(n, n);
    for (const auto& tr : trips)
    {
        if (tr.row() >= N && tr.col() >= N)
        {
            K(tr.row() - N, tr.col() - N) += tr.value();
        }
    }
    blockTangentError e;
    e.maxEntry = K.cwiseAbs().maxCoeff();
    double worst = 0;
    vecX rp, rm, dx = vecX::Zero(n);
    for (int j = 0; j < n; ++j)
    {
        const double h = step*(1 + std::abs(block.unknowns()(j)));
        dx.setZero();
        dx(j) = h;
        block.addToUnknowns(dx);
        fext.setZero();
        block.evaluate(t, U, fext, rp, nullptr);
        dx(j) = -2*h;
        block.addToUnknowns(dx);
        fext.setZero();
        block.evaluate(t, U, fext, rm, nullptr);
        dx(j) = h;
        block.addToUnknowns(dx);
        for (int i = 0; i < n; ++i)
        {
            const double fd = -(rp(i) - rm(i))/(2*h);
            const double d = std::abs(fd - K(i, j));
            if (d > worst)
            {
                worst = d;
                e.row = i;
                e.col = j;
                e.analytic = K(i, j);
                e.finiteDifference = fd;
            }
        }
    }
    // Leave the block evaluated at its state
    fext.setZero();
    block.evaluate(t, U, fext, r, nullptr);
    e.relative = e.maxEntry > 0 ? worst/e.maxEntry : worst;
    return e;
}

} // namespace form
