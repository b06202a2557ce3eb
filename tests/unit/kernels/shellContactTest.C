// Contact of shells with rigid tools (issue 22): a contactor node of a
// sheet of MITC4 shells touches with the point x + h V of the face its
// patch covers (h = +-t/2, V its current director), so the contact
// forces act on its rotation dofs too (contactModel::setShells,
// contactModelAssembly.C).
//   - the Newton matrix of the contact block over every nodal dof (the
//     rotations included) and contact unknown against central
//     differences, with the directors turned by random rotations: a
//     sphere on the top face (frictionless, with friction, both friction
//     laws and the Bathe rate), a force-controlled plane on the bottom
//     face (largest error 1.2e-9; without the term of the directors'
//     second derivatives it fails at 1.5e-4);
//   - the contact point is the face's: a sheet whose top face just
//     touches a plane has zero gap there, the mid-surface a gap of t/2;
//     thinned (setShellThickness), the face moves with the thickness;
//   - pairs on a shell's edge, on patches covering both faces, and shells
//     against deformable targets are input errors naming the pair.
#include "contactModel.H"
#include "shellSet.H"
#include "rigidSurface.H"
#include "contactTestTools.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <random>
#include "../fdCheck.H"

namespace
{
// about 10 x the largest error observed (fdCheck.H)
constexpr double fdTolShellContact = 1.5e-8;
}

using namespace form;

namespace
{

//- An n x n sheet of MITC4 shells on [0, 2] x [0, 2] at z = 1, thickness
//  0.1: face sets "top" (mid-surface quads ordered with the normal +z),
//  "bottom" (ordered with -z), "both" (both), "edge" (the shell edge at
//  x = 0, 2-node faces)
feMesh sheet(int n)
{
    feMesh m;
    m.nDim = 3;
    m.X.resize((n + 1)*(n + 1), 3);
    const auto id = [n](int i, int j) { return j*(n + 1) + i; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.X.row(id(i, j)) << 2.0*i/n, 2.0*j/n, 1;
    elementBlock b;
    b.name = "sheet";
    b.elementType = "MITC4";
    b.materialName = "sheet";
    b.nodesPerElement = 4;
    b.shell.thickness = 0.1;
    b.shell.points = 2;
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            const int e = j*n + i;
            const std::vector<int> q =
                {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            b.connectivity.insert(b.connectivity.end(), q.begin(), q.end());
            m.faceSets["top"].push_back({0, e, -1, q});
            const std::vector<int> r = {q[0], q[3], q[2], q[1]};
            m.faceSets["bottom"].push_back({0, e, -1, r});
            m.faceSets["both"].push_back({0, e, -1, j % 2 ? q : r});
            if (i == 0) m.faceSets["edge"].push_back({0, e, 3, {q[3], q[0]}});
        }
    }
    m.blocks.push_back(b);
    shellSet::assignNodeDofs(m);
    return m;
}

shellSet shellsOf(const feMesh& m)
{
    return shellSet(m, {std::make_shared<shellElastic>(2e5, 0.3)});
}

rigidToolSpec sphereAbove()
{
    rigidToolSpec tool;
    tool.name = "punch";
    // touching the top face (z = 1.05) at (1, 1), sliding obliquely
    tool.surface = rigidSurface::New
    ("sphere", {{"centre", vec3(1, 1, 4.05)}}, {{"radius", 3.0}});
    tool.translation = [](double t) { return vec3(0.3*t, 0.2*t, -0.01*t); };
    return tool;
}

rigidToolSpec planeBelow()
{
    rigidToolSpec tool;
    tool.name = "die";
    // just under the bottom face (z = 0.95), slightly tilted, pushed up
    // by a force
    tool.surface = rigidSurface::New
    ("plane", {{"point", vec3(0, 0, 0.95)}, {"normal", vec3(0.1, 0, 1)}}, {});
    tool.forceControlled = true;
    tool.direction = vec3(0, 0, 1);
    tool.force = [](double t) { return 50*t; };
    return tool;
}

contactControls testControls(const std::string& law)
{
    contactControls c;
    c.epsilonN = 1e-6;
    c.epsilonT = 1e-6;
    c.frictionLaw = law;
    c.maxStatusChanges = 1000;
    return c;
}

void checkTangent
(
    bool plane,
    double friction,
    bool bathe = false,
    const std::string& law = contactControls().frictionLaw
)
{
    const feMesh mesh = sheet(2);
    const shellSet shells = shellsOf(mesh);
    contactModel cm
    (
        mesh, analysisType::solid3D, 2e5,
        {plane ? planeBelow() : sphereAbove()},
        {{"pair", plane ? "bottom" : "top", plane ? "die" : "punch", friction}},
        testControls(law)
    );
    cm.setShells(&shells);
    const dofMap dofs = dofMap::of(mesh);
    const int N = dofs.nDofs();
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    // pushed against the tool, sheared, directors turned by up to 0.3
    vecX U = vecX::Zero(N);
    for (int a = 0; a < mesh.nNodes(); ++a)
    {
        U(dofs.dof(a, 0)) = 0.002*u(gen);
        U(dofs.dof(a, 1)) = 0.002*u(gen);
        U(dofs.dof(a, 2)) = 0.004*u(gen) + (plane ? -0.001 : 0.001);
        U(dofs.dof(a, 3)) = 0.3*u(gen);
        U(dofs.dof(a, 4)) = 0.3*u(gen);
    }
    test::commitStart(cm, U, bathe);
    test::setTestMultipliers(cm, friction > 0 ? 3 : 1, gen);

    vecX R0;
    matX K;
    const double t = 0.5;
    test::contactResidual(cm, t, U, R0, &K);
    // forces on the rotation dofs: the contact points are off the nodes
    double rotation = 0;
    for (int a = 0; a < mesh.nNodes(); ++a)
    {
        rotation += std::abs(R0(dofs.dof(a, 3))) + std::abs(R0(dofs.dof(a, 4)));
    }
    EXPECT_GT(rotation, 0);
    const matX Kfd = test::contactTangentFD(cm, t, U, 1e-7);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0);
    EXPECT_TRUE
    (
        test::fdError
        (
            "shell contact, rigid tool",
            (K - Kfd).cwiseAbs().maxCoeff()/scale, fdTolShellContact
        )
    ) << "plane " << plane << " friction " << friction << " law " << law
      << " bathe " << bathe;
}

} // anonymous namespace


TEST(shellContact, tangentFrictionlessSphere)
{
    checkTangent(false, 0);
}

TEST(shellContact, tangentWithFrictionBothLawsAndBatheRate)
{
    for (const std::string law : {"alartCurnier", "regularised"})
    {
        checkTangent(false, 0.3, false, law);
        checkTangent(false, 0.3, true, law);
    }
}

TEST(shellContact, tangentForceControlledPlaneOnTheBottomFace)
{
    checkTangent(true, 0);
    checkTangent(true, 0.25);
}

TEST(shellContact, theContactPointIsOnTheFace)
{
    // A plane at z = 1.05 (the top face of the flat sheet): gap zero at
    // every node of the top face; the same plane against the bottom face
    // (from below: its normal down) would see the face at 0.95
    const feMesh mesh = sheet(2);
    const shellSet shells = shellsOf(mesh);
    rigidToolSpec tool;
    tool.name = "plane";
    tool.surface = rigidSurface::New
    ("plane", {{"point", vec3(0, 0, 1.05)}, {"normal", vec3(0, 0, -1)}}, {});
    contactModel cm
    (
        mesh, analysisType::solid3D, 2e5, {tool},
        {{"pair", "top", "plane", 0}}, testControls("alartCurnier")
    );
    cm.setShells(&shells);
    const vecX U = vecX::Zero(dofMap::of(mesh).nDofs());
    cm.beginIncrement(0, 1, U);
    vecX fext = vecX::Zero(U.size()), r;
    cm.evaluate(1, U, fext, r, nullptr);
    for (const contactNodeResult& n : cm.pairResults("pair", U, 1))
    {
        EXPECT_NEAR(n.gap, 0, 1e-14) << n.node;
        EXPECT_NEAR(n.x(2), 1.05, 1e-14) << n.node;
    }
    // The sheet thinned to 0.08 (setShellThickness, as solidModel does at
    // a commit): the top face at 1.04, a gap of 0.01 to the plane
    cm.setShellThickness(std::vector<double>(mesh.nNodes(), 0.08));
    cm.evaluate(1, U, fext, r, nullptr);
    for (const contactNodeResult& n : cm.pairResults("pair", U, 1))
    {
        EXPECT_NEAR(n.gap, 0.01, 1e-14) << n.node;
        EXPECT_NEAR(n.x(2), 1.04, 1e-14) << n.node;
    }
    // Without the shells given, a shell pair is refused at evaluation
    contactModel bare
    (
        mesh, analysisType::solid3D, 2e5, {tool},
        {{"pair", "top", "plane", 0}}, testControls("alartCurnier")
    );
    bare.beginIncrement(0, 1, U);
    EXPECT_THROW(bare.evaluate(1, U, fext, r, nullptr), numericalError);
}

TEST(shellContact, inputErrorsNameThePair)
{
    const feMesh mesh = sheet(2);
    const shellSet shells = shellsOf(mesh);
    for (const std::string patch : {"edge", "both"})
    {
        contactModel cm
        (
            mesh, analysisType::solid3D, 2e5, {sphereAbove()},
            {{"pair", patch, "punch", 0}}, testControls("alartCurnier")
        );
        try
        {
            cm.setShells(&shells);
            ADD_FAILURE() << "no error for patch " << patch;
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), "pair/patch") << e.what();
        }
    }
    contactPairSpec onTarget;
    onTarget.name = "pair";
    onTarget.faceSet = "top";
    onTarget.targetFaceSet = "bottom";
    contactModel cm
    (
        mesh, analysisType::solid3D, 2e5, {}, {onTarget},
        testControls("alartCurnier")
    );
    EXPECT_THROW(cm.setShells(&shells), inputError);
}
