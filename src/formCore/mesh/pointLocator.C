/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of pointLocator.H: finds the element of a quad or hex
    mesh that contains a reference point by Newton inversion of the
    isoparametric map, and interpolates nodal fields there.
\*---------------------------------------------------------------------------*/
#include "pointLocator.H"
#include "formError.H"
#include "hexShape.H"
#include "quadShape.H"
#include <cmath>

namespace
{

template<class Shape, int NN, int D>
void evalInto(const form::vecX& xi, form::vecX& N, form::matX& dN)
{
    typename Shape::vecN n;
    Eigen::Matrix<double, NN, D> d;
    if constexpr (D == 2) Shape::eval(xi(0), xi(1), n, d);
    else Shape::eval(xi(0), xi(1), xi(2), n, d);
    N = n;
    dN = d;
}

} // anonymous namespace


void form::elementShape
(
    int nDim,
    int nNodes,
    const vecX& xi,
    vecX& N,
    matX& dN
)
{
    if (nDim == 2 && nNodes == 4) evalInto<quadShape<4>, 4, 2>(xi, N, dN);
    else if (nDim == 2 && nNodes == 9) evalInto<quadShape<9>, 9, 2>(xi, N, dN);
    else if (nDim == 3 && nNodes == 8) evalInto<hexShape<8>, 8, 3>(xi, N, dN);
    else if (nDim == 3 && nNodes == 27) evalInto<hexShape<27>, 27, 3>(xi, N, dN);
    else
    {
        throw numericalError
        (
            "elementShape: no " + std::to_string(nNodes) + "-node element in "
          + std::to_string(nDim) + "D"
        );
    }
}


form::pointLocation form::locatePoint
(
    const feMesh& mesh,
    const vecX& x,
    double tol
)
{
    const int D = mesh.nDim;
    pointLocation best;
    double bestErr = 1e30;
    vecX N, xi;
    matX dN, C;
    for (int b = 0; b < int(mesh.blocks.size()); ++b)
    {
        const auto& blk = mesh.blocks[b];
        const int nn = blk.nodesPerElement;
        C.resize(nn, D);
        for (int e = 0; e < blk.nElements(); ++e)
        {
            for (int a = 0; a < nn; ++a) C.row(a) = mesh.X.row(blk.nodes(e)[a]);
            // bounding-box rejection (the nodes of a curved element bound
            // it closely enough at this tolerance)
            const vecX lo = C.colwise().minCoeff();
            const vecX hi = C.colwise().maxCoeff();
            const double h = (hi - lo).norm();
            if
            (
                (x.array() < lo.array() - 1e-2*h).any()
             || (x.array() > hi.array() + 1e-2*h).any()
            )
            {
                continue;
            }
            // Newton inversion of x(xi) = C^T N(xi), damped to stay in a
            // box around the element
            xi = vecX::Zero(D);
            for (int it = 0; it < 50; ++it)
            {
                elementShape(D, nn, xi, N, dN);
                const matX J = C.transpose()*dN;
                const vecX d = J.lu().solve(x - C.transpose()*N);
                if (!d.allFinite()) break;
                xi += d;
                xi = xi.cwiseMax(-2.0).cwiseMin(2.0);
                if (d.norm() < 1e-14) break;
            }
            const double err = xi.cwiseAbs().maxCoeff() - 1.0;
            if (err < bestErr)
            {
                bestErr = err;
                best.block = b;
                best.element = e;
                best.r = xi(0);
                best.s = xi(1);
                best.t = D == 3 ? xi(2) : 0.0;
            }
        }
    }
    if (bestErr > tol)
    {
        return pointLocation();
    }
    return best;
}


form::vecX form::interpolate
(
    const feMesh& mesh,
    const pointLocation& loc,
    const matX& f
)
{
    const auto& blk = mesh.blocks[loc.block];
    vecX xi(mesh.nDim);
    xi(0) = loc.r;
    xi(1) = loc.s;
    if (mesh.nDim == 3) xi(2) = loc.t;
    vecX N;
    matX dN;
    elementShape(mesh.nDim, blk.nodesPerElement, xi, N, dN);
    vecX v = vecX::Zero(f.cols());
    for (int a = 0; a < blk.nodesPerElement; ++a)
    {
        v += N(a)*f.row(blk.nodes(loc.element)[a]).transpose();
    }
    return v;
}
