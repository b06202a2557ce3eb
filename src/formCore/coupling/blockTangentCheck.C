/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Finite-difference check of a coupled block's tangent
    (blockTangentCheck.H).
\*---------------------------------------------------------------------------*/
#include "blockTangentCheck.H"
#include <algorithm>
#include <cmath>
#include <map>

namespace form
{

blockTangentError checkBlockTangent
(
    coupledBlock& block,
    double t,
    const vecX& U,
    double step,
    bool couplingOnly
)
{
    const int n = block.nUnknowns();
    const int N = int(U.size());
    vecX fext = vecX::Zero(N), r;
    std::vector<coupledBlock::triplet> trips;
    block.evaluate(t, U, fext, r, &trips);

    // The block's rows and columns: its own unknowns, and the nodal dofs
    // its triplets reach (its coupling with the solid)
    std::vector<int> nodal;
    for (const auto& tr : trips)
    {
        if (tr.row() < N) nodal.push_back(tr.row());
        if (tr.col() < N) nodal.push_back(tr.col());
    }
    std::sort(nodal.begin(), nodal.end());
    nodal.erase(std::unique(nodal.begin(), nodal.end()), nodal.end());
    const int m = int(nodal.size());
    std::map<int, int> local;
    for (int k = 0; k < m; ++k) local[nodal[k]] = k;
    const auto index = [&](int g) { return g < N ? local.at(g) : m + g - N; };
    const int nCols = couplingOnly ? m : m + n;
    matX K = matX::Zero(m + n, nCols);
    for (const auto& tr : trips)
    {
        const int j = index(tr.col());
        if (j < nCols) K(index(tr.row()), j) += tr.value();
    }
    blockTangentError e;
    // max |K| over the checked columns
    e.maxEntry = K.cwiseAbs().maxCoeff();
    e.nodalDofs = m;
    e.couplingOnly = couplingOnly;
    double worst = 0;
    vecX rp, rm, fp(N), fm(N), dx = vecX::Zero(n), Up(U), Um(U);
    // G = [f_ext (the block's, on the nodal dofs); r]: K = -dG/dq
    for (int j = 0; j < nCols; ++j)
    {
        fp.setZero();
        fm.setZero();
        double h;
        if (j < m)
        {
            const int g = nodal[j];
            h = step*(1 + std::abs(U(g)));
            Up(g) = U(g) + h;
            Um(g) = U(g) - h;
            block.evaluate(t, Up, fp, rp, nullptr);
            block.evaluate(t, Um, fm, rm, nullptr);
            Up(g) = U(g);
            Um(g) = U(g);
        }
        else
        {
            h = step*(1 + std::abs(block.unknowns()(j - m)));
            dx.setZero();
            dx(j - m) = h;
            block.addToUnknowns(dx);
            block.evaluate(t, U, fp, rp, nullptr);
            dx(j - m) = -2*h;
            block.addToUnknowns(dx);
            block.evaluate(t, U, fm, rm, nullptr);
            dx(j - m) = h;
            block.addToUnknowns(dx);
        }
        for (int i = 0; i < m + n; ++i)
        {
            const double fd = i < m
                ? -(fp(nodal[i]) - fm(nodal[i]))/(2*h)
                : -(rp(i - m) - rm(i - m))/(2*h);
            const double d = std::abs(fd - K(i, j));
            if (d > worst)
            {
                worst = d;
                e.row = i < m ? -1 - nodal[i] : i - m;
                e.col = j < m ? -1 - nodal[j] : j - m;
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
