/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Closest-point projection onto the faces of a deformable body in 3D
    (deformableSurface.H).
\*---------------------------------------------------------------------------*/
#include "deformableSurface.H"
#include "quadShape.H"
#include "rigidSurface.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace form
{

deformableSurface::facePoint deformableSurface::at
(
    int f,
    const Eigen::Vector2d& xi,
    const vecX& U
) const
{
    const std::vector<int>& nodes = faces_[f];
    const int n = int(nodes.size());
    facePoint F;
    quadShapeEval(n, xi(0), xi(1), F.N, F.dN);
    const matX d2 = quadShapeSecond(n, xi(0), xi(1));
    F.x.setZero();
    F.x1.setZero();
    F.x2.setZero();
    F.x11.setZero();
    F.x22.setZero();
    F.x12.setZero();
    for (int b = 0; b < n; ++b)
    {
        const vec3 xb = position(nodes[b], U);
        F.x += F.N(b)*xb;
        F.x1 += F.dN(b, 0)*xb;
        F.x2 += F.dN(b, 1)*xb;
        F.x11 += d2(b, 0)*xb;
        F.x22 += d2(b, 1)*xb;
        F.x12 += d2(b, 2)*xb;
    }
    return F;
}


deformableSurface::deformableSurface
(
    const feMesh& mesh,
    const std::vector<feFace>& faces
)
:
    mesh_(&mesh),
    dofs_(dofMap::of(mesh))
{
    if (mesh.nDim != 3)
    {
        throw numericalError("deformableSurface: a 3D mesh is required");
    }
    // Edges by their (sorted) corner nodes, to find the shared ones
    std::map<std::pair<int, int>, int> edgeCount;
    const auto edgeKey = [](const std::vector<int>& n, int k)
    {
        const int a = n[k], b = n[(k + 1) % 4];
        return std::make_pair(std::min(a, b), std::max(a, b));
    };
    for (const feFace& f : faces)
    {
        const int n = int(f.nodes.size());
        if (n != 4 && n != 9)
        {
            throw numericalError
            (
                "deformableSurface: faces of 4 or 9 nodes expected, got "
              + std::to_string(n)
            );
        }
        faces_.push_back(f.nodes);
        for (int k = 0; k < 4; ++k) ++edgeCount[edgeKey(f.nodes, k)];
    }
    for (const auto& f : faces_)
    {
        std::array<bool, 4> shared;
        for (int k = 0; k < 4; ++k) shared[k] = edgeCount[edgeKey(f, k)] > 1;
        sharedEdge_.push_back(shared);
    }
}


bool deformableSurface::closestXi
(
    int f,
    const vec3& y,
    const vecX& U,
    Eigen::Vector2d& xi
) const
{
    xi.setZero();
    for (int it = 0; it < 30; ++it)
    {
        const facePoint F = at(f, xi, U);
        const vec3 s = y - F.x;
        const Eigen::Vector2d phi(s.dot(F.x1), s.dot(F.x2));
        Eigen::Matrix2d G;
        G << F.x1.dot(F.x1), F.x1.dot(F.x2), F.x1.dot(F.x2), F.x2.dot(F.x2);
        Eigen::Matrix2d A = G;
        A(0, 0) -= s.dot(F.x11);
        A(1, 1) -= s.dot(F.x22);
        A(0, 1) -= s.dot(F.x12);
        A(1, 0) -= s.dot(F.x12);
        // Far from a strongly curved face A may lose its definiteness:
        // fall back to Gauss-Newton (G), which still descends |s|^2
        if (!(A.determinant() > 0 && A.trace() > 0)) A = G;
        if (!(G.determinant() > 0)) return false;
        const Eigen::Vector2d step = A.ldlt().solve(phi);
        xi = (xi + step).cwiseMax(-3.0).cwiseMin(3.0);
        if (!xi.allFinite()) return false;
        if (step.cwiseAbs().maxCoeff() < 1e-14) return true;
    }
    return xi.allFinite();
}


void deformableSurface::evaluateAt
(
    int f,
    const Eigen::Vector2d& xi,
    const vec3& y,
    const vecX& U,
    faceProjection& P
) const
{
    const std::vector<int>& nodes = faces_[f];
    const int m = int(nodes.size());
    const int nq = 3 + 3*m;
    const facePoint F = at(f, xi, U);
    const vec3 a = F.x1.cross(F.x2);
    const double la = a.norm();
    const vec3 n = a/la;
    const vec3 s = y - F.x;

    P.onTarget = true;
    P.face = f;
    P.xi = xi;
    P.gap = s.dot(n);
    P.normal = n;
    P.nodes = nodes;
    P.N = F.N;
    P.dN = F.dN;
    P.size = 0;
    for (int i = 0; i < 4; ++i)
    {
        for (int j = i + 1; j < 4; ++j)
        {
            P.size = std::max
            (
                P.size,
                (position(nodes[i], U) - position(nodes[j], U)).norm()
            );
        }
    }

    Eigen::Matrix2d A;
    A << F.x1.dot(F.x1) - s.dot(F.x11), F.x1.dot(F.x2) - s.dot(F.x12),
         F.x1.dot(F.x2) - s.dot(F.x12), F.x2.dot(F.x2) - s.dot(F.x22);
    // Right-hand side of A dxi = B dq
    matX B = matX::Zero(2, nq);
    B.block<1, 3>(0, 0) = F.x1.transpose();
    B.block<1, 3>(1, 0) = F.x2.transpose();
    P.dGap.setZero(nq);
    P.dGap.head<3>() = n;
    for (int b = 0; b < m; ++b)
    {
        B.block<1, 3>(0, 3 + 3*b) = (F.dN(b, 0)*s - F.N(b)*F.x1).transpose();
        B.block<1, 3>(1, 3 + 3*b) = (F.dN(b, 1)*s - F.N(b)*F.x2).transpose();
        P.dGap.segment<3>(3 + 3*b) = -F.N(b)*n;
    }
    P.dXi = A.inverse()*B;

    // dx_a/dq = [0, N_b,a I] + x_ab dxi_b
    matX D1 = matX::Zero(3, nq), D2 = matX::Zero(3, nq);
    for (int b = 0; b < m; ++b)
    {
        D1.block<3, 3>(0, 3 + 3*b) = F.dN(b, 0)*mat3::Identity();
        D2.block<3, 3>(0, 3 + 3*b) = F.dN(b, 1)*mat3::Identity();
    }
    D1 += F.x11*P.dXi.row(0) + F.x12*P.dXi.row(1);
    D2 += F.x12*P.dXi.row(0) + F.x22*P.dXi.row(1);
    // da = dx_1 x x_2 + x_1 x dx_2 = -[x_2]x dx_1 + [x_1]x dx_2
    const matX da = -skew(F.x2)*D1 + skew(F.x1)*D2;
    P.dNormal = (mat3::Identity() - n*n.transpose())*da/la;
}


faceProjection deformableSurface::project
(
    const vec3& y,
    int node,
    const vecX& U,
    int preferredFace
) const
{
    const auto own = [node](const std::vector<int>& nodes)
    {
        return std::find(nodes.begin(), nodes.end(), node) != nodes.end();
    };

    // Hysteresis (deformableSurface.H): keep the face of the last iteration
    if (preferredFace >= 0 && preferredFace < nFaces())
    {
        Eigen::Vector2d xi;
        if
        (
            !own(faces_[preferredFace])
         && closestXi(preferredFace, y, U, xi)
         && xi.cwiseAbs().maxCoeff() <= 1.01
        )
        {
            faceProjection P;
            evaluateAt(preferredFace, xi, y, U, P);
            if (std::abs(P.gap) <= 0.1*P.size) return P;
        }
    }

    const double inf = std::numeric_limits<double>::infinity();
    double bestInside = inf;
    int faceInside = -1;
    Eigen::Vector2d xiInside = Eigen::Vector2d::Zero();
    double bestOutside = inf;
    int faceOutside = -1;
    Eigen::Vector2d xiOutside = Eigen::Vector2d::Zero();

    for (int f = 0; f < nFaces(); ++f)
    {
        const std::vector<int>& nodes = faces_[f];
        if (own(nodes)) continue;
        // Bounding box of the face's nodes, widened by a quarter of its
        // extent (a curved 9-node face bulges beyond its nodes by at most
        // that for the shapes a mesh accepts): skip faces farther than
        // the best so far
        vec3 lo = position(nodes[0], U), hi = lo;
        for (int node : nodes)
        {
            const vec3 x = position(node, U);
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
        const vec3 pad = vec3::Constant(0.25*(hi - lo).maxCoeff());
        const vec3 out =
            (lo - pad - y).cwiseMax(y - hi - pad).cwiseMax(vec3::Zero());
        if (out.norm() > std::min(bestInside, bestOutside)) continue;

        Eigen::Vector2d xi;
        if (!closestXi(f, y, U, xi)) continue;
        if (xi.cwiseAbs().maxCoeff() <= 1 + 1e-12)
        {
            const double d = (y - at(f, xi, U).x).norm();
            if (d < bestInside)
            {
                bestInside = d;
                faceInside = f;
                xiInside = xi;
            }
        }
        else
        {
            // Distance to the nearest point of the face (clamped xi)
            const Eigen::Vector2d xc = xi.cwiseMax(-1.0).cwiseMin(1.0);
            const double d = (y - at(f, xc, U).x).norm();
            if (d < bestOutside)
            {
                bestOutside = d;
                faceOutside = f;
                xiOutside = xi;
            }
        }
    }

    faceProjection P;
    if (faceInside >= 0 && bestInside <= bestOutside)
    {
        evaluateAt(faceInside, xiInside, y, U, P);
        return P;
    }
    if (faceOutside >= 0)
    {
        // The face's edges the node overshoots: edge 0 (xi_2 = -1),
        // 1 (xi_1 = +1), 2 (xi_2 = +1), 3 (xi_1 = -1). Within half a face
        // beyond shared edges (the wedge of a convex edge), 1 % beyond
        // free ones; otherwise off target
        const std::array<bool, 4>& shared = sharedEdge_[faceOutside];
        const Eigen::Vector2d& xi = xiOutside;
        bool inReach = true;
        const auto check = [&](double over, int edge)
        {
            if (over <= 1) return;
            const double reach = shared[edge] ? 0.5 : 0.02;
            if (over >= 1 + reach) inReach = false;
        };
        check(-xi(1), 0);
        check(xi(0), 1);
        check(xi(1), 2);
        check(-xi(0), 3);
        if (inReach)
        {
            evaluateAt(faceOutside, xiOutside, y, U, P);
            return P;
        }
        P.face = faceOutside;
        P.xi = xiOutside;
    }
    P.onTarget = false;
    return P;
}

} // namespace form
