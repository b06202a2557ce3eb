// Node-to-face projection onto the faces of a deformable body in 3D
// (deformableSurface.H): the closest point on curved 9-node faces against
// a brute-force search, the outward normal, the off-target and convex-edge
// rules, the preferred face (hysteresis), and the derivatives of the gap,
// the face coordinates and the normal over the node and the face nodes
// (9-node and 4-node faces) against central differences. The second
// derivatives of the quad functions behind them are checked too.
#include "deformableSurface.H"
#include "quadShape.H"
#include "formError.H"
#include "hexBoxMesh.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerance (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints the margin)
namespace
{
constexpr double fdTolFace = 5e-9;
}

using namespace form;

namespace
{

//- The top of a 2 x 2 x 1 box [0, 2]^2 x [0, 1] bent: z of the top nodes
//  raised by a smooth bump, all top nodes moved a little in-plane (so
//  the faces are curved and distorted)
vecX bentTop(const feMesh& m, int seed, double amplitude = 0.06)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    vecX U = vecX::Zero(3*m.nNodes());
    for (int a = 0; a < m.nNodes(); ++a)
    {
        if (m.X(a, 2) < 1 - 1e-12) continue;
        const double x = m.X(a, 0), y = m.X(a, 1);
        U(3*a + 2) = amplitude*std::sin(1.3*x + 0.4)*std::cos(0.9*y - 0.2)
                   + 0.01*u(gen);
        U(3*a) = 0.03*u(gen);
        U(3*a + 1) = 0.03*u(gen);
    }
    return U;
}

//- Current position on face f of the target at xi
vec3 facePoint
(
    const feMesh& m,
    const std::vector<int>& nodes,
    const vecX& U,
    double r,
    double s
)
{
    const vecX N = quadShapeValues(int(nodes.size()), r, s);
    vec3 x = vec3::Zero();
    for (std::size_t b = 0; b < nodes.size(); ++b)
    {
        x += N(b)*(m.X.row(nodes[b]).transpose() + U.segment<3>(3*nodes[b]));
    }
    return x;
}

} // anonymous namespace


TEST(quadShape, secondDerivativesMatchCentralDifferences)
{
    for (int n : {4, 9})
    {
        const double r = 0.31, s = -0.57, h = 1e-5;
        const matX d2 = quadShapeSecond(n, r, s);
        vecX N, dNp, dNm;
        matX Dp, Dm;
        quadShapeEval(n, r + h, s, N, Dp);
        quadShapeEval(n, r - h, s, N, Dm);
        const matX dr = (Dp - Dm)/(2*h);
        quadShapeEval(n, r, s + h, N, Dp);
        quadShapeEval(n, r, s - h, N, Dm);
        const matX ds = (Dp - Dm)/(2*h);
        for (int a = 0; a < n; ++a)
        {
            EXPECT_NEAR(d2(a, 0), dr(a, 0), 1e-8) << n << " " << a;
            EXPECT_NEAR(d2(a, 1), ds(a, 1), 1e-8) << n << " " << a;
            EXPECT_NEAR(d2(a, 2), dr(a, 1), 1e-8) << n << " " << a;
            EXPECT_NEAR(d2(a, 2), ds(a, 0), 1e-8) << n << " " << a;
        }
    }
}


TEST(deformableSurface, projectionOnCurvedFacesMatchesBruteForce)
{
    const feMesh m = test::hexBox(2, 2, 1, 27, vec3::Zero(), vec3(2, 2, 1));
    const deformableSurface target(m, m.faceSets.at("top"));
    ASSERT_EQ(target.nFaces(), 4);
    const vecX U = bentTop(m, 5);

    std::mt19937 gen(3);
    std::uniform_real_distribution<double> ux(0.1, 1.9), uz(0.75, 1.4);
    int nInside = 0;
    for (int k = 0; k < 60; ++k)
    {
        const vec3 y(ux(gen), ux(gen), uz(gen));
        const faceProjection P = target.project(y, -1, U);
        ASSERT_TRUE(P.onTarget) << y.transpose();
        // Brute force: a 101 x 101 grid on every face, then finer grids
        // around the best point (last step 1.25e-7 in xi)
        double best = 1e30;
        int bf = -1;
        double br = 0, bs = 0;
        for (int f = 0; f < 4; ++f)
        {
            for (int i = 0; i <= 100; ++i)
            for (int j = 0; j <= 100; ++j)
            {
                const double r = -1 + 0.02*i, s = -1 + 0.02*j;
                const double d =
                    (y - facePoint(m, target.faceNodes(f), U, r, s)).norm();
                if (d < best) { best = d; bf = f; br = r; bs = s; }
            }
        }
        for (double w : {0.02, 1e-3, 5e-5, 2.5e-6})
        {
            const double r0 = br, s0 = bs;
            for (int i = -20; i <= 20; ++i)
            for (int j = -20; j <= 20; ++j)
            {
                const double r = std::clamp(r0 + w*i/20, -1.0, 1.0);
                const double s = std::clamp(s0 + w*j/20, -1.0, 1.0);
                const double d =
                    (y - facePoint(m, target.faceNodes(bf), U, r, s)).norm();
                if (d < best) { best = d; br = r; bs = s; }
            }
        }
        const vec3 xBest = facePoint(m, target.faceNodes(bf), U, br, bs);
        if (P.xi.cwiseAbs().maxCoeff() < 1)
        {
            ++nInside;
            EXPECT_NEAR(std::abs(P.gap), best, 1e-9) << y.transpose();
            // Outward: the gap's sign is the side of the top surface
            EXPECT_GT(P.gap*(y(2) - xBest(2)), 0) << y.transpose();
            EXPECT_GT(P.normal(2), 0.9);
        }
        else
        {
            // Extrapolated over a convex edge: no larger than the distance
            EXPECT_LE(std::abs(P.gap), best + 1e-7) << y.transpose();
        }
    }
    EXPECT_GT(nInside, 50);

    // Beyond the free border: off target; within 1 % of it: on
    EXPECT_FALSE(target.project(vec3(2.3, 1, 1.1), -1, U).onTarget);
    EXPECT_FALSE(target.project(vec3(1, -0.3, 1.1), -1, U).onTarget);
    const vecX U0 = vecX::Zero(3*m.nNodes());
    const faceProjection Pb = target.project(vec3(2.005, 0.5, 1.1), -1, U0);
    EXPECT_TRUE(Pb.onTarget);
    EXPECT_NEAR(Pb.gap, 0.1, 1e-12);
    // A node's own faces are skipped: the top's corner node projects onto
    // a face it does not belong to, or is off target
    const int corner = 0 + 5*(0 + 5*2);
    const faceProjection Pc =
        target.project(m.X.row(corner).transpose(), corner, U0);
    for (int node : Pc.nodes) EXPECT_NE(node, corner);
}


TEST(deformableSurface, convexEdgeAndPreferredFace)
{
    // The top of a flat 2 x 2 target folded down about x = 1 (a convex
    // ridge): z = 1 - 0.3 |x - 1|
    const feMesh m = test::hexBox(2, 2, 1, 27, vec3::Zero(), vec3(2, 2, 1));
    const deformableSurface target(m, m.faceSets.at("top"));
    vecX U = vecX::Zero(3*m.nNodes());
    for (int a = 0; a < m.nNodes(); ++a)
    {
        if (m.X(a, 2) > 0.5) U(3*a + 2) = -0.3*std::abs(m.X(a, 0) - 1);
    }
    // Above the ridge, in the wedge where no face's closest point lies
    // inside: extrapolated from a face, gap = distance to the ridge or
    // less
    const vec3 y(1.0, 0.7, 1.2);
    const faceProjection P = target.project(y, -1, U);
    ASSERT_TRUE(P.onTarget);
    EXPECT_LE(P.gap, 0.2 + 1e-12);
    EXPECT_GT(P.gap, 0.15);
    // Just beside the ridge the preferred face is kept within 1 % beyond
    // its border; far beyond, the search takes over
    const vec3 y1(1.004, 0.7, 1.0 + 1e-4);
    const faceProjection Pl = target.project(vec3(0.99, 0.7, 1.0), -1, U);
    ASSERT_TRUE(Pl.onTarget);
    const faceProjection Pk = target.project(y1, -1, U, Pl.face);
    EXPECT_EQ(Pk.face, Pl.face);
    const faceProjection Pf = target.project(vec3(1.5, 0.7, 0.9), -1, U, Pl.face);
    EXPECT_NE(Pf.face, Pl.face);
}


namespace
{

//- Derivatives of the projection over q = (y, x_b) against central
//  differences, at random points near random (curved, distorted) faces
void checkDerivatives(int nodes)
{
    const feMesh m =
        test::hexBox(2, 2, 1, nodes, vec3::Zero(), vec3(2, 2, 1),
            nodes == 27 ? "Hex27P4" : "Hex8");
    const deformableSurface target(m, m.faceSets.at("top"));
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> ux(0.05, 1.95), uz(0.85, 1.15);
    const std::string site =
        "deformableSurface projection, " + std::to_string(nodes == 27 ? 9 : 4)
      + "-node faces";
    int n = 0;
    for (int k = 0; k < 40 && n < 12; ++k)
    {
        const vecX U = bentTop(m, 100 + k, nodes == 27 ? 0.06 : 0.0);
        const vec3 y(ux(gen), ux(gen), uz(gen));
        const faceProjection P = target.project(y, -1, U);
        if (!P.onTarget || P.xi.cwiseAbs().maxCoeff() > 0.95) continue;
        ++n;
        const int nq = 3 + 3*int(P.nodes.size());
        const double h = 1e-6;
        matX fd(1 + 2 + 3, nq);
        for (int q = 0; q < nq; ++q)
        {
            vec3 yp = y, ym = y;
            vecX Up = U, Um = U;
            if (q < 3)
            {
                yp(q) += h;
                ym(q) -= h;
            }
            else
            {
                const int dof = 3*P.nodes[(q - 3)/3] + (q - 3) % 3;
                Up(dof) += h;
                Um(dof) -= h;
            }
            const faceProjection Pp = target.project(yp, -1, Up, P.face);
            const faceProjection Pm = target.project(ym, -1, Um, P.face);
            ASSERT_EQ(Pp.face, P.face);
            ASSERT_EQ(Pm.face, P.face);
            fd(0, q) = (Pp.gap - Pm.gap)/(2*h);
            fd.block<2, 1>(1, q) = (Pp.xi - Pm.xi)/(2*h);
            fd.block<3, 1>(3, q) = (Pp.normal - Pm.normal)/(2*h);
        }
        matX an(6, nq);
        an.row(0) = P.dGap.transpose();
        an.middleRows(1, 2) = P.dXi;
        an.bottomRows(3) = P.dNormal;
        const double err = (an - fd).norm()/fd.norm();
        EXPECT_TRUE(test::fdError(site, err, fdTolFace))
            << "y " << y.transpose() << " xi " << P.xi.transpose();
    }
    EXPECT_GE(n, 10);
}

} // anonymous namespace


TEST(deformableSurface, derivativesMatchCentralDifferences9Node)
{
    checkDerivatives(27);
}


TEST(deformableSurface, derivativesMatchCentralDifferences4Node)
{
    checkDerivatives(8);
}
