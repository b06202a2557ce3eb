// Contact in 3D with rigid tools (contactModel3D.C): the Newton matrix of
// the contact block (nodal dofs, normal and two friction multipliers per
// node, a force-controlled tool's position) against central differences,
// for a sphere, a cylinder-filleted extruded die and a force-controlled
// plane, without and with friction (both friction laws, the Bathe
// slip-rate law); the contact force balance of a frictionless plane; the
// tangent frame carried over at a commit; restart state round trip; 3D
// input errors.
#include "contactModel.H"
#include "hexShape.H"
#include "formError.H"
#include "contactTestTools.H"
#include <gtest/gtest.h>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerance (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints the margin)
namespace
{
constexpr double fdTolContact3D = 1.5e-8;
}

using namespace form;

namespace
{

//- nx x ny x 1 27-node hexahedra on [0, nx] x [0, ny] x [0, 1]; face set
//  "top" (z = 1)
feMesh hexBox(int nx, int ny)
{
    feMesh m;
    m.nDim = 3;
    const int NI = 2*nx + 1, NJ = 2*ny + 1, NK = 3;
    m.X.resize(NI*NJ*NK, 3);
    const auto id = [&](int i, int j, int k) { return i + NI*(j + NJ*k); };
    for (int k = 0; k < NK; ++k)
        for (int j = 0; j < NJ; ++j)
            for (int i = 0; i < NI; ++i)
                m.X.row(id(i, j, k)) << 0.5*i, 0.5*j, 0.5*k;
    elementBlock b;
    b.name = "box";
    b.elementType = "Hex27P4";
    b.materialName = "steel";
    b.nodesPerElement = 27;
    for (int ey = 0; ey < ny; ++ey)
    {
        for (int ex = 0; ex < nx; ++ex)
        {
            for (int a = 0; a < 27; ++a)
            {
                const Eigen::Vector3d xi = hexShape<27>::node(a);
                b.connectivity.push_back
                (
                    id(2*ex + 1 + int(xi(0)), 2*ey + 1 + int(xi(1)), 1 + int(xi(2)))
                );
            }
            feFace f;
            f.element = ey*nx + ex;
            f.localFace = 5;
            for (const int a : hexFaceNodes(27, 5))
            {
                f.nodes.push_back(b.connectivity[27*f.element + a]);
            }
            m.faceSets["top"].push_back(f);
        }
    }
    m.blocks.push_back(b);
    return m;
}

enum class toolKind { sphere, extrudedDie, forcePlane };

rigidToolSpec makeTool(toolKind kind)
{
    rigidToolSpec tool;
    tool.name = "tool";
    if (kind == toolKind::sphere)
    {
        // touching the top face at (1, 1, 1), sliding obliquely
        tool.surface = rigidSurface::New
        ("sphere", {{"centre", vec3(1, 1, 4)}}, {{"radius", 3.0}});
        tool.translation = [](double t) { return vec3(0.3*t, 0.2*t, -0.01*t); };
    }
    else if (kind == toolKind::extrudedDie)
    {
        // a die edge along y: flat at z = 1 for x < 1, fillet 0.5, wall
        // rising at x = 1.5, in the (x, z) plane; tool above the sheet
        tool.surface = rigidSurface::New
        (
            "extrudedProfile",
            {{"origin", vec3(0, 0, 0)}, {"xAxis", vec3(1, 0, 0)}, {"yAxis", vec3(0, 0, 1)}},
            {},
            std::make_shared<rigidProfile>
            (
                std::vector<Eigen::Vector2d>{{-1, 1}, {1.5, 1}, {1.5, 3}},
                std::vector<double>{0.5}
            )
        );
        tool.translation = [](double t) { return vec3(0.1*t, 0.3*t, 0); };
    }
    else
    {
        tool.surface = rigidSurface::New
        ("plane", {{"point", vec3(0, 0, 1)}, {"normal", vec3(0.1, 0, -1)}}, {});
        tool.forceControlled = true;
        tool.direction = vec3(0, 0, -1);
        tool.force = [](double t) { return 50*t; };
    }
    return tool;
}

contactModel makeModel
(
    const feMesh& mesh,
    toolKind kind,
    double friction,
    const std::string& law = contactControls().frictionLaw
)
{
    contactControls c;
    c.epsilonN = 1e-6;
    c.epsilonT = 1e-6;
    c.frictionLaw = law;
    c.maxStatusChanges = 1000;
    return contactModel
    (
        mesh, analysisType::solid3D, 2e5, {makeTool(kind)},
        {{"top", "top", "tool", friction}}, c
    );
}

void checkTangent
(
    toolKind kind,
    double friction,
    bool bathe = false,
    const std::string& law = contactControls().frictionLaw
)
{
    const feMesh mesh = hexBox(2, 2);
    contactModel cm = makeModel(mesh, kind, friction, law);
    const int N = 3*mesh.nNodes();
    const int nC = cm.nUnknowns();
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    vecX U = vecX::Zero(N);
    // pushed up against the tool and sheared: some nodes in contact
    for (int a = 0; a < mesh.nNodes(); ++a)
    {
        U(3*a) = 0.05*mesh.X(a, 2) + 0.002*u(gen);
        U(3*a + 1) = -0.03*mesh.X(a, 2) + 0.002*u(gen);
        U(3*a + 2) = 0.004*u(gen) + 0.001;
    }
    test::commitStart(cm, U, bathe);
    vecX x(nC);
    for (int j = 0; j < nC; ++j) x(j) = 2e-3*u(gen);
    cm.addToUnknowns(x - cm.unknowns());

    vecX R0;
    matX K;
    const double t = 0.5;
    test::contactResidual(cm, t, U, R0, &K);
    const matX Kfd = test::contactTangentFD(cm, t, U, 1e-7);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0);
    EXPECT_TRUE(test::fdError("contact3D rigid tool", (K - Kfd).cwiseAbs().maxCoeff()/scale, fdTolContact3D))
        << "tool " << int(kind) << " friction " << friction << " law " << law
        << " bathe " << bathe;
}

} // anonymous namespace


TEST(contact3D, tangentFrictionlessSphere)
{
    checkTangent(toolKind::sphere, 0);
}

TEST(contact3D, tangentWithFrictionSphereAndDie)
{
    checkTangent(toolKind::sphere, 0.3);
    checkTangent(toolKind::extrudedDie, 0.2);
}

TEST(contact3D, tangentForceControlledPlane)
{
    checkTangent(toolKind::forcePlane, 0);
    checkTangent(toolKind::forcePlane, 0.25);
}

TEST(contact3D, tangentEachFrictionLawAndBatheRate)
{
    for (const std::string law : {"alartCurnier", "regularised"})
    {
        checkTangent(toolKind::sphere, 0.3, true, law);
        checkTangent(toolKind::forcePlane, 0.2, true, law);
    }
}

TEST(contact3D, restartStateRoundTrip)
{
    const feMesh mesh = hexBox(2, 2);
    contactModel a = makeModel(mesh, toolKind::sphere, 0.3);
    const int N = 3*mesh.nNodes();
    vecX U = vecX::Constant(N, 1e-3);
    a.beginIncrement(0, 0.5, vecX::Zero(N));
    vecX fext = vecX::Zero(N), r;
    a.evaluate(0.5, U, fext, r, nullptr);
    a.commit(U);
    contactModel b = makeModel(mesh, toolKind::sphere, 0.3);
    b.setState(a.state());
    EXPECT_EQ(a.state(), b.state());
    vecX fa = vecX::Zero(N), fb = vecX::Zero(N), ra, rb;
    a.beginIncrement(0.5, 1, U);
    b.beginIncrement(0.5, 1, U);
    a.evaluate(1, 1.1*U, fa, ra, nullptr);
    b.evaluate(1, 1.1*U, fb, rb, nullptr);
    EXPECT_EQ((fa - fb).norm(), 0);
    EXPECT_EQ((ra - rb).norm(), 0);
}

TEST(contact3D, inputErrors)
{
    const feMesh mesh = hexBox(1, 1);
    // a 2D tool (profile only) in a 3D model
    rigidToolSpec flat;
    flat.name = "flat";
    flat.profile = std::make_shared<rigidProfile>
    (
        std::vector<Eigen::Vector2d>{{-1, 1}, {3, 1}}
    );
    EXPECT_THROW
    (
        contactModel(mesh, analysisType::solid3D, 2e5, {flat}, {{"top", "top", "flat", 0}}),
        inputError
    );
    // an unknown deformable target in 3D
    EXPECT_THROW
    (
        contactModel
        (
            mesh, analysisType::solid3D, 2e5, {makeTool(toolKind::sphere)},
            {{"self", "top", "", 0, "topp"}}
        ),
        inputError
    );
    // a 3D mesh in a 2D analysis
    EXPECT_THROW
    (
        contactModel
        (
            mesh, analysisType::planeStrain, 2e5, {makeTool(toolKind::sphere)},
            {{"top", "top", "tool", 0}}
        ),
        inputError
    );
}
