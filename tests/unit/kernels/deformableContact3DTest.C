// Node-to-face contact with a deformable body in 3D
// (contactModelDeformable3D.C): a punch of hexahedra pressed onto a block
// of hexahedra, overhanging it so that some contactor nodes are closed,
// some open and some off target. The Newton matrix of the contact block
// (the contactor node, the target face nodes, the normal and two friction
// multipliers per node) against central differences, on 9-node and
// 4-node faces, without and with friction (both friction laws, the Bathe
// slip-rate law); action = reaction (forces and moments); the restart
// state round trip.
#include "contactModel.H"
#include "contactTestTools.H"
#include "hexBoxMesh.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerance (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints the margin)
namespace
{
constexpr double fdTolDeformable3D = 2e-8;
}

using namespace form;

namespace
{

//- A 2 x 2 x 1 block [0, 2]^2 x [0, 1] and, on it, a punch of 3 x 2 x 1
//  hexahedra [0.9, 2.5] x [0.3, 1.7] x [1, 1.5] that overhangs the
//  block's right side; pair "punch" (its bottom against the block's top)
struct twoBlocks
{
    feMesh mesh;
    int firstPunchNode = 0;

    explicit twoBlocks(int nodes)
    {
        const std::string type = nodes == 27 ? "Hex27P4" : "Hex8";
        mesh = test::hexBox(2, 2, 1, nodes, vec3::Zero(), vec3(2, 2, 1), type);
        firstPunchNode = mesh.nNodes();
        test::appendMesh
        (
            mesh,
            test::hexBox
            (
                3, 2, 1, nodes, vec3(0.9, 0.3, 1), vec3(2.5, 1.7, 1.5), type
            ),
            "punch_"
        );
    }

    contactModel model
    (
        double friction,
        const std::string& law = "regularised"
    ) const
    {
        contactControls c;
        c.epsilonN = 1e-6;
        c.epsilonT = 1e-6;
        c.maxStatusChanges = 1000;
        c.frictionLaw = law;
        contactPairSpec p;
        p.name = "punch";
        p.faceSet = "punch_bottom";
        p.friction = friction;
        p.targetFaceSet = "top";
        return contactModel(mesh, analysisType::solid3D, 2e5, {}, {p}, c);
    }
};


//- bathe: the slip-rate law of the Bathe scheme's second stage
void checkTangent
(
    int nodes,
    double friction,
    const std::string& law = "regularised",
    bool bathe = false
)
{
    const twoBlocks s(nodes);
    contactModel cm = s.model(friction, law);
    const int N = 3*s.mesh.nNodes();

    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(-1, 1);
    // Committed state: both bodies displaced a little (slip reference)
    const vecX Un = test::commitRandomState(cm, N, gen, bathe);
    // Current state: the punch pushed down and sideways onto the block
    // (some nodes penetrating, some open), the block's top curved
    vecX U = Un;
    for (int a = 0; a < s.mesh.nNodes(); ++a)
    {
        if (a >= s.firstPunchNode)
        {
            U(3*a) += 0.02 + 0.002*u(gen);
            U(3*a + 1) += -0.01 + 0.002*u(gen);
            U(3*a + 2) += -0.002 + 0.006*u(gen);
        }
        else
        {
            const double x = s.mesh.X(a, 0), y = s.mesh.X(a, 1);
            U(3*a + 2) += 0.01*s.mesh.X(a, 2)*std::sin(3*x)*std::cos(2*y)
                        + 0.002*u(gen);
            U(3*a) += 0.002*u(gen);
            U(3*a + 1) += 0.002*u(gen);
        }
    }
    test::setTestMultipliers(cm, friction > 0 ? 3 : 1, gen);

    vecX R0;
    matX K;
    const double t = 0.5;
    test::contactResidual(cm, t, U, R0, &K);

    // Action = reaction: the contact forces sum to zero, and so do their
    // moments about the origin up to the gap (the forces on a node and on
    // the target point under it are g n apart: a moment g n x f per node,
    // zero for the frictionless normal force)
    const vecX F = R0.head(N);
    vec3 sum = vec3::Zero(), moment = vec3::Zero();
    for (int a = 0; a < s.mesh.nNodes(); ++a)
    {
        const vec3 f = F.segment<3>(3*a);
        const vec3 xa = s.mesh.X.row(a).transpose() + U.segment<3>(3*a);
        sum += f;
        moment += xa.cross(f);
    }
    EXPECT_GT(F.norm(), 0);
    EXPECT_LT(sum.norm(), 1e-12*F.norm()) << sum.transpose();
    if (friction == 0)
    {
        EXPECT_LT(moment.norm(), 1e-12*F.norm()) << moment.transpose();
    }

    const double h = 1e-7;
    const matX Kfd = test::contactTangentFD(cm, t, U, h);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0);
    Eigen::Index i, j;
    const double err = (K - Kfd).cwiseAbs().maxCoeff(&i, &j);
    EXPECT_TRUE
    (
        test::fdError
        (
            "contactModel deformable target 3D, "
          + std::to_string(nodes == 27 ? 9 : 4) + "-node faces",
            err/scale, fdTolDeformable3D
        )
    )
        << "friction " << friction << " " << law << ": K(" << i << "," << j
        << ") = " << K(i, j) << ", FD " << Kfd(i, j);

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

} // anonymous namespace


TEST(deformableContact3D, tangentFrictionless9NodeFaces)
{
    checkTangent(27, 0);
}

TEST(deformableContact3D, tangentFrictionless4NodeFaces)
{
    checkTangent(8, 0);
}

TEST(deformableContact3D, tangentWithFriction)
{
    checkTangent(27, 0.3);
    checkTangent(8, 0.3);
}

TEST(deformableContact3D, tangentWithFrictionAlartCurnier)
{
    checkTangent(27, 0.3, "alartCurnier");
}

TEST(deformableContact3D, tangentWithFrictionBatheSlipRateLaw)
{
    checkTangent(27, 0.3, "regularised", true);
}


TEST(deformableContact3D, restartStateRoundTrip)
{
    const twoBlocks s(27);
    contactModel a = s.model(0.2);
    const int N = 3*s.mesh.nNodes();
    vecX U = vecX::Zero(N);
    for (int q = 3*s.firstPunchNode + 2; q < N; q += 3) U(q) = -0.01;
    a.beginIncrement(0, 1, U);
    vecX x = vecX::Constant(a.nUnknowns(), 1e-3);
    a.addToUnknowns(x);
    vecX fext = vecX::Zero(N), r;
    a.evaluate(1, U, fext, r, nullptr);
    a.commit(U);

    contactModel b = s.model(0.2);
    b.setState(a.state());
    b.beginIncrement(1, 2, U);
    a.beginIncrement(1, 2, U);
    vecX fa = vecX::Zero(N), fb = vecX::Zero(N), ra, rb;
    a.evaluate(2, U, fa, ra, nullptr);
    b.evaluate(2, U, fb, rb, nullptr);
    EXPECT_EQ((fa - fb).norm(), 0);
    EXPECT_EQ((ra - rb).norm(), 0);
    EXPECT_GT(fa.norm(), 0);
}
