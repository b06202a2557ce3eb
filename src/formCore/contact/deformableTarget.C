/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Closest-point projection onto the edges of a deformable body
    (deformableTarget.H).
\*---------------------------------------------------------------------------*/
#include "deformableTarget.H"
#include "quadShape.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace form
{



deformableTarget::edgePoint deformableTarget::at
(
    int e,
    double zeta,
    const Eigen::VectorXd& U
) const
{
    const std::vector<int>& nodes = edges_[e];
    const int n = int(nodes.size());
    const Eigen::VectorXd d2 = lineShapeSecond(n);
    edgePoint E;
    lineShape(n, zeta, E.N, E.dN);
    E.x.setZero();
    E.x1.setZero();
    E.x2.setZero();
    for (int b = 0; b < n; ++b)
    {
        const Eigen::Vector2d xb = position(nodes[b], U);
        E.x += E.N(b)*xb;
        E.x1 += E.dN(b)*xb;
        E.x2 += d2(b)*xb;
    }
    return E;
}


deformableTarget::deformableTarget
(
    const feMesh& mesh,
    const std::vector<feFace>& faces
)
:
    mesh_(&mesh),
    dofs_(dofMap::of(mesh))
{
    std::map<int, int> endCount;
    for (const feFace& f : faces)
    {
        const int n = int(f.nodes.size());
        if (n != 2 && n != 3)
        {
            throw numericalError
            (
                "deformableTarget: edges of 2 or 3 nodes expected, got "
              + std::to_string(n)
            );
        }
        edges_.push_back(f.nodes);
        ++endCount[f.nodes[0]];
        ++endCount[f.nodes[1]];

        // Orientation: the normal (t_y, -t_x) of the chord, flipped if it
        // points into the edge's element
        const Eigen::Vector2d xs = mesh.X.row(f.nodes[0]).transpose();
        const Eigen::Vector2d xe = mesh.X.row(f.nodes[1]).transpose();
        const Eigen::Vector2d chord = xe - xs;
        const Eigen::Vector2d n0(chord(1), -chord(0));
        const elementBlock& b = mesh.blocks[f.block];
        const int* en = b.nodes(f.element);
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        for (int a = 0; a < b.nodesPerElement; ++a)
        {
            c += mesh.X.row(en[a]).transpose();
        }
        c /= b.nodesPerElement;
        sigma_.push_back(n0.dot(0.5*(xs + xe) - c) >= 0 ? 1.0 : -1.0);
    }
    for (const auto& e : edges_)
    {
        sharedEnd_.push_back({endCount[e[0]] > 1, endCount[e[1]] > 1});
    }
}


bool deformableTarget::closestZeta
(
    int e,
    const Eigen::Vector2d& y,
    const Eigen::VectorXd& U,
    double& zeta
) const
{
    const std::vector<int>& nodes = edges_[e];
    const int n = int(nodes.size());
    const Eigen::Vector2d xs = position(nodes[0], U);
    const Eigen::Vector2d xe = position(nodes[1], U);
    const double chord2 = (xe - xs).squaredNorm();
    if (!(chord2 > 0)) return false;
    zeta = std::clamp(2*(y - xs).dot(xe - xs)/chord2 - 1, -3.0, 3.0);
    if (n == 2) return true;

    for (int it = 0; it < 30; ++it)
    {
        const edgePoint E = at(e, zeta, U);
        const Eigen::Vector2d& x1 = E.x1;
        const Eigen::Vector2d& x2 = E.x2;
        const Eigen::Vector2d s = y - E.x;
        const double phi = s.dot(x1);
        double A = -x1.squaredNorm() + s.dot(x2);
        // Far from a strongly curved edge A may lose its sign: fall back
        // to a Gauss-Newton step (-|x'|^2), which still descends |s|^2
        if (!(A < 0)) A = -x1.squaredNorm();
        const double step = -phi/A;
        zeta = std::clamp(zeta + step, -3.0, 3.0);
        if (std::abs(step) < 1e-14) return true;
    }
    return std::isfinite(zeta);
}


void deformableTarget::evaluateAt
(
    int e,
    double zeta,
    const Eigen::Vector2d& y,
    const Eigen::VectorXd& U,
    segmentProjection& P
) const
{
    const std::vector<int>& nodes = edges_[e];
    const int n = int(nodes.size());
    const edgePoint E = at(e, zeta, U);
    const Eigen::VectorXd& N = E.N;
    const Eigen::VectorXd& dN = E.dN;
    const Eigen::Vector2d& x = E.x;
    const Eigen::Vector2d& x1 = E.x1;
    const Eigen::Vector2d& x2 = E.x2;
    const double L = x1.norm();
    const Eigen::Vector2d t = x1/L;
    const Eigen::Vector2d nrm = sigma_[e]*Eigen::Vector2d(t(1), -t(0));
    const Eigen::Vector2d s = y - x;
    const double A = -L*L + s.dot(x2);

    P.onTarget = true;
    P.edge = e;
    P.zeta = zeta;
    P.gap = s.dot(nrm);
    P.normal = nrm;
    P.tangent = t;
    P.nodes = nodes;
    P.N = N;
    P.dN = dN;
    P.length = L;

    const int nq = 2 + 2*n;
    P.dGap.setZero(nq);
    P.dZeta.setZero(nq);
    P.h.setZero(nq);
    P.dGap.head<2>() = nrm;
    P.dZeta.head<2>() = -x1/A;
    for (int b = 0; b < n; ++b)
    {
        P.dGap.segment<2>(2 + 2*b) = -N(b)*nrm;
        P.dZeta.segment<2>(2 + 2*b) = -(dN(b)*s - N(b)*x1)/A;
        P.h.segment<2>(2 + 2*b) = dN(b)*nrm;
    }
    P.h += nrm.dot(x2)*P.dZeta;
}


segmentProjection deformableTarget::project
(
    const Eigen::Vector2d& y,
    int node,
    const Eigen::VectorXd& U,
    int preferredEdge
) const
{
    // Hysteresis (deformableTarget.H): keep the edge of the last iteration
    if (preferredEdge >= 0 && preferredEdge < nEdges())
    {
        const std::vector<int>& nodes = edges_[preferredEdge];
        double zeta = 0;
        if
        (
            std::find(nodes.begin(), nodes.end(), node) == nodes.end()
         && closestZeta(preferredEdge, y, U, zeta)
         && std::abs(zeta) <= 1.01
        )
        {
            segmentProjection P;
            evaluateAt(preferredEdge, zeta, y, U, P);
            if (std::abs(P.gap) <= 0.1*P.length) return P;
        }
    }

    const double inf = std::numeric_limits<double>::infinity();
    double bestInside = inf;
    int edgeInside = -1;
    double zetaInside = 0;
    double bestOutside = inf;
    int edgeOutside = -1;
    double zetaOutside = 0;

    for (int e = 0; e < nEdges(); ++e)
    {
        const std::vector<int>& nodes = edges_[e];
        if (std::find(nodes.begin(), nodes.end(), node) != nodes.end())
        {
            continue;
        }
        // Bounding box of the edge's Bezier control points (the curve
        // lies in their hull): skip edges farther than the best so far
        const Eigen::Vector2d xs = position(nodes[0], U);
        const Eigen::Vector2d xe = position(nodes[1], U);
        Eigen::Vector2d lo = xs.cwiseMin(xe);
        Eigen::Vector2d hi = xs.cwiseMax(xe);
        if (nodes.size() == 3)
        {
            const Eigen::Vector2d c = 2*position(nodes[2], U) - 0.5*(xs + xe);
            lo = lo.cwiseMin(c);
            hi = hi.cwiseMax(c);
        }
        const Eigen::Vector2d out =
            (lo - y).cwiseMax(y - hi).cwiseMax(Eigen::Vector2d::Zero());
        if (out.norm() > std::min(bestInside, bestOutside)) continue;

        double zeta = 0;
        if (!closestZeta(e, y, U, zeta)) continue;
        if (std::abs(zeta) <= 1 + 1e-12)
        {
            const double d = (y - at(e, zeta, U).x).norm();
            if (d < bestInside)
            {
                bestInside = d;
                edgeInside = e;
                zetaInside = zeta;
            }
        }
        else
        {
            // Distance to the end it overshoots
            const Eigen::Vector2d xEnd = zeta > 0 ? xe : xs;
            const double d = (y - xEnd).norm();
            if (d < bestOutside)
            {
                bestOutside = d;
                edgeOutside = e;
                zetaOutside = zeta;
            }
        }
    }

    segmentProjection P;
    if (edgeInside >= 0 && bestInside <= bestOutside)
    {
        evaluateAt(edgeInside, zetaInside, y, U, P);
        return P;
    }
    if (edgeOutside >= 0)
    {
        const int end = zetaOutside > 0 ? 1 : 0;
        // In the wedge of a kink between two target edges: the edge
        // extrapolated a little; beyond a free end: off target, except
        // within 1 % of the edge (a node level with the end, as at the
        // ends of two bodies of equal width, stays in contact whatever
        // the round-off)
        const double reach = sharedEnd_[edgeOutside][end] ? 0.5 : 0.02;
        if (std::abs(zetaOutside) < 1 + reach)
        {
            evaluateAt(edgeOutside, zetaOutside, y, U, P);
            return P;
        }
        P.edge = edgeOutside;
        P.zeta = zetaOutside;
    }
    P.onTarget = false;
    return P;
}

} // namespace form
