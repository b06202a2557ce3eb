/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of pointLocator.H: finds the element of a 2D quad mesh
    (4- or 9-node, VTK ordering) that contains a reference point, its natural
    coordinates (r, s) by Newton inversion of the bilinear corner map, and
    interpolates nodal fields there with the element's Lagrange shape
    functions.
\*---------------------------------------------------------------------------*/
#include "pointLocator.H"
#include <cmath>

form::pointLocation form::locatePoint
(
    const feMesh& mesh,
    const Eigen::Vector2d& x,
    double tol
)
{
    pointLocation best;
    double bestErr = 1e30;
    for (int b = 0; b < int(mesh.blocks.size()); ++b)
    {
        const auto& blk = mesh.blocks[b];
        for (int e = 0; e < blk.nElements(); ++e)
        {
            Eigen::Matrix<double, 4, 2> C;
            for (int k = 0; k < 4; ++k)
            {
                C.row(k) = mesh.X.row(blk.nodes(e)[k]).head<2>();
            }
            // bounding-box rejection
            const Eigen::Vector2d lo = C.colwise().minCoeff();
            const Eigen::Vector2d hi = C.colwise().maxCoeff();
            const double h = (hi - lo).norm();
            if ((x.array() < lo.array() - 1e-6*h).any()
             || (x.array() > hi.array() + 1e-6*h).any())
            {
                continue;
            }
            // Newton inversion of the bilinear map
            double r = 0, s = 0;
            for (int it = 0; it < 30; ++it)
            {
                const vecX N = quadShapeValues(4, r, s);
                Eigen::Vector2d xr = C.transpose()*N;
                Eigen::Matrix<double, 4, 2> dN;
                dN << -(1 - s), -(1 - r),  (1 - s), -(1 + r),
                       (1 + s),  (1 + r), -(1 + s),  (1 - r);
                dN *= 0.25;
                const Eigen::Matrix2d J = C.transpose()*dN;
                const Eigen::Vector2d d = J.inverse()*(x - xr);
                r += d(0);
                s += d(1);
                if (d.norm() < 1e-14) break;
            }
            const double err = std::max(std::abs(r), std::abs(s)) - 1.0;
            if (err < bestErr)
            {
                bestErr = err;
                best = {b, e, r, s};
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
    const vecX N = quadShapeValues(blk.nodesPerElement, loc.r, loc.s);
    vecX v = vecX::Zero(f.cols());
    for (int a = 0; a < blk.nodesPerElement; ++a)
    {
        v += N(a)*f.row(blk.nodes(loc.element)[a]).transpose();
    }
    return v;
}
