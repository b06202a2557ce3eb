// Node-to-segment contact with a deformable target (deformableTarget.H,
// contactModel.H "Deformable targets"): the closest-point projection on
// curved 3-node edges against a brute-force search, the off-target and
// kink rules, action = reaction, and the contact residual's tangent
// (contactor node, target edge nodes, multipliers; with and without
// friction) against central differences.
#include "contactModel.H"
#include "contactTestTools.H"
#include "hexBoxMesh.H"
#include "deformableTarget.H"
#include "structuredQuadMesh.H"
#include "quadShape.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolDeformable = 2e-8;
}

using namespace form;

namespace
{

//- A 2 x 1 Q9 block [0, 2] x [0, 1] and, on it, a 3 x 1 Q9 punch
//  [x0, x0 + 1.4] x [1, 1.5]; pair "punch" (its bottom against the
//  block's top)
struct twoBodies
{
    feMesh mesh;

    explicit twoBodies(double x0)
    {
        mesh = structuredQuadMesh
        (
            {{{0, 0}, {2, 0}, {2, 1}, {0, 1}}}, 2, 1, 9, "Q9P3", "steel"
        );
        test::appendMesh
        (
            mesh,
            structuredQuadMesh
            (
                {{{x0, 1}, {x0 + 1.4, 1}, {x0 + 1.4, 1.5}, {x0, 1.5}}},
                3, 1, 9, "Q9P3", "steel"
            ),
            "punch_"
        );
    }

    contactModel model(double friction, double epsN, double epsT) const
    {
        contactControls c;
        c.epsilonN = epsN;
        c.epsilonT = epsT;
        c.maxStatusChanges = 1000;
        contactPairSpec p;
        p.name = "punch";
        p.faceSet = "punch_bottom";
        p.friction = friction;
        p.targetFaceSet = "top";
        return contactModel
        (
            mesh, analysisType::planeStrain, 2e5, {}, {p}, c
        );
    }
};


TEST(deformableTarget, projectionOnCurvedEdgesMatchesBruteForce)
{
    const twoBodies s(0.3);
    const deformableTarget target(s.mesh, s.mesh.faceSets.at("top"));
    ASSERT_EQ(target.nEdges(), 2);
    // Bend the top edges: mid-side nodes up, the shared node down
    vecX U = vecX::Zero(2*s.mesh.nNodes());
    for (int e = 0; e < 2; ++e)
    {
        const std::vector<int>& n = target.edgeNodes(e);
        U(2*n[2] + 1) = 0.08;
    }
    const int shared = nearestNode(s.mesh, Eigen::Vector2d(1, 1));
    U(2*shared + 1) = -0.03;

    std::mt19937 gen(3);
    std::uniform_real_distribution<double> ux(0.1, 1.9), uy(0.9, 1.4);
    vecX N, dN;
    for (int k = 0; k < 200; ++k)
    {
        const Eigen::Vector2d y(ux(gen), uy(gen));
        const segmentProjection P = target.project(y, -1, U);
        // Brute force: the closest of 20001 points on each edge
        double best = 1e30;
        Eigen::Vector2d xBest;
        for (int e = 0; e < 2; ++e)
        {
            const std::vector<int>& n = target.edgeNodes(e);
            for (int i = 0; i <= 20000; ++i)
            {
                const double z = -1 + i*1e-4;
                lineShape(3, z, N, dN);
                Eigen::Vector2d x = Eigen::Vector2d::Zero();
                for (int b = 0; b < 3; ++b)
                {
                    x += N(b)*(s.mesh.X.row(n[b]).transpose()
                             + U.segment<2>(2*n[b]));
                }
                if ((y - x).norm() < best)
                {
                    best = (y - x).norm();
                    xBest = x;
                }
            }
        }
        if (!P.onTarget)
        {
            ADD_FAILURE() << "point (" << y.transpose() << ") off target";
            continue;
        }
        // Inside an edge |gap| is the distance; in the wedge of the kink
        // (the shared node is a convex corner here) the extrapolated edge
        // gives a gap no larger than the distance to the corner
        if (std::abs(P.zeta) < 1)
        {
            // (brute force: points 5e-5 apart in zeta, i.e. a distance
            // error up to about (2.5e-5)^2/(2 |gap|) ~ 2e-7 at |gap| 1e-3)
            EXPECT_NEAR(std::abs(P.gap), best, 1e-6) << y.transpose();
            EXPECT_GT(P.gap*(y(1) - xBest(1)), 0) << "normal points out";
        }
        else
        {
            EXPECT_LE(std::abs(P.gap), best + 1e-7) << y.transpose();
        }
    }
    // Beyond the free ends: off target
    EXPECT_FALSE(target.project(Eigen::Vector2d(2.3, 1.2), -1, U).onTarget);
    EXPECT_FALSE(target.project(Eigen::Vector2d(-0.2, 1.1), -1, U).onTarget);
}


//- bathe: the slip-rate law of the Bathe scheme's second stage
void checkTangent(double friction, bool bathe = false)
{
    // The punch overhangs the block's right end: two of its bottom nodes
    // are beyond the target (off target)
    const twoBodies s(0.9);
    contactModel cm = s.model(friction, 1e-6, 1e-6);
    const int N = s.mesh.nNodes()*2;

    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(-1, 1);
    // Committed state: both bodies displaced a little (slip reference)
    const vecX Un = test::commitRandomState(cm, N, gen, bathe);
    // Current state: the punch pushed down and sideways onto the block
    // (some nodes penetrating, some open), the block's top curved
    vecX U = Un;
    const int firstPunch = s.mesh.nNodes() - 7*3;
    for (int a = 0; a < s.mesh.nNodes(); ++a)
    {
        if (a >= firstPunch)
        {
            U(2*a) += 0.02 + 0.002*u(gen);
            U(2*a + 1) += -0.002 + 0.006*u(gen);
        }
        else
        {
            U(2*a + 1) += 0.01*s.mesh.X(a, 1)*std::sin(3*s.mesh.X(a, 0))
                        + 0.002*u(gen);
        }
    }
    test::setTestMultipliers(cm, friction > 0 ? 2 : 1, gen);

    vecX R0;
    matX K;
    const double t = 0.5;
    test::contactResidual(cm, t, U, R0, &K);

    // Action = reaction: the contact forces on all nodes sum to zero
    EXPECT_LT(std::abs(R0.head(N)(Eigen::seq(0, N - 1, 2)).sum()), 1e-9*R0.head(N).norm());
    EXPECT_LT(std::abs(R0.head(N)(Eigen::seq(1, N - 1, 2)).sum()), 1e-9*R0.head(N).norm());
    EXPECT_GT(R0.head(N).norm(), 0);

    const double h = 1e-7;
    const matX Kfd = test::contactTangentFD(cm, t, U, h);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0);
    Eigen::Index i, j;
    const double err = (K - Kfd).cwiseAbs().maxCoeff(&i, &j);
    EXPECT_TRUE(test::fdError("contactModel deformable target", err/scale, fdTolDeformable))
        << "friction " << friction << ": K(" << i << "," << j << ") = "
        << K(i, j) << ", FD " << Kfd(i, j);

    // Some nodes closed, some open, some off target
    int closed = 0, open = 0, off = 0;
    for (const auto& r : cm.pairResults("punch", U, t))
    {

        if (std::isinf(r.gap)) ++off;
        else if (r.closed) ++closed;
        else ++open;
    }
    EXPECT_GT(closed, 0);
    EXPECT_GT(open, 0);
    EXPECT_GT(off, 0);
}


TEST(deformableContact, tangentFrictionless)
{
    checkTangent(0);
}

TEST(deformableContact, tangentWithFriction)
{
    checkTangent(0.3);
}

TEST(deformableContact, tangentWithFrictionBatheSlipRateLaw)
{
    checkTangent(0.3, true);
}


TEST(deformableContact, pairNeedsExactlyOneTarget)
{
    const twoBodies s(0.3);
    contactPairSpec p;
    p.name = "punch";
    p.faceSet = "punch_bottom";
    try
    {
        contactModel cm(s.mesh, analysisType::planeStrain, 2e5, {}, {p});
        FAIL() << "no error";
    }
    catch (const inputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("tool or a target"),
                  std::string::npos) << e.what();
    }
    p.targetFaceSet = "nowhere";
    try
    {
        contactModel cm(s.mesh, analysisType::planeStrain, 2e5, {}, {p});
        FAIL() << "no error";
    }
    catch (const inputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("nowhere"), std::string::npos);
    }
}

} // namespace
