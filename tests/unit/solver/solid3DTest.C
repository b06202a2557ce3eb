// The solid model in 3D (issue 21): a Hex27P4 cube [0,1]^3 held on its
// three symmetry planes x = 0, y = 0, z = 0 (each in its normal direction)
// and pulled by a dead traction sigma on x = 1, linear elastic: the
// uniaxial solution u = sigma/E (x, -nu y, -nu z) lies in the element's
// space, so one static step reproduces it to round-off. It exercises the
// 3D path of the model: the dof map with 3 dofs per node, face sets of
// hexahedra (hexFaceNodes), the face traction (faceLoad), the constraints
// and the static solver. And faceLoad's consistent nodal forces on a
// flat face: 1/36, 4/36, 16/36 of t A for the 9-node face, 1/4 for the
// 4-node one.
#include "staticSolver.H"
#include "hexShape.H"
#include "quadShape.H"
#include "formError.H"
#include "unitCube.H"
#include <gtest/gtest.h>
#include <sstream>

using namespace form;

TEST(faceLoad, consistentForcesOnAFlatFace)
{
    // A 2 x 3 rectangle in the plane through (0.1, 0.2, 0.3) spanned by two
    // orthonormal vectors, traction t
    const vec3 o(0.1, 0.2, 0.3);
    const vec3 e1 = vec3(1, 2, 2).normalized();
    const vec3 e2 = vec3(2, 1, -2).normalized();
    const vec3 t(0.4, -1.1, 2.5);
    const double A = 6;
    for (const int n : {4, 9})
    {
        matX X(n, 3);
        for (int a = 0; a < n; ++a)
        {
            const double r = quadShape<9>::nodeR(a), s = quadShape<9>::nodeS(a);
            X.row(a) = (o + (1 + r)*e1 + 1.5*(1 + s)*e2).transpose();
        }
        const vecX f = faceLoad::deadTraction(X, t);
        for (int a = 0; a < n; ++a)
        {
            const double share =
                n == 4 ? 0.25 : (a < 4 ? 1.0/36 : a < 8 ? 4.0/36 : 16.0/36);
            EXPECT_LT((f.segment<3>(3*a) - share*A*t).norm(), 1e-13) << n << " " << a;
        }
    }
    EXPECT_THROW(faceLoad::deadTraction(matX::Zero(5, 3), t), numericalError);
}


using test::unitCube;


TEST(solid3D, uniaxialTractionOnAHex27P4Cube)
{
    feMesh mesh = unitCube("steel");

    const double E = 200, nu = 0.3, sigma = 10;
    std::map<std::string, std::shared_ptr<material>> mats;
    mats["steel"] = material::New("linearElastic", {{"E", E}, {"nu", nu}});
    solidModel model(mesh, analysisType::solid3D, mats);
    model.addConstraint(mesh.nodeSets["x0"], 0);
    model.addConstraint(mesh.nodeSets["y0"], 1);
    model.addConstraint(mesh.nodeSets["z0"], 2);
    model.addTraction("right", [sigma](double t) { return vec3(sigma*t, 0, 0); });
    model.finalise();
    EXPECT_EQ(model.nDofs(), 81);

    auto solver = linearSolver::New("cholmod");
    stepControls steps;
    steps.deltaT = 1;
    std::ostringstream log;
    staticSolver(model, *solver, newtonControls(), steps, log).run(nullptr);

    const matX u = model.displacement();
    double err = 0;
    for (int a = 0; a < 27; ++a)
    {
        const vec3 X = mesh.X.row(a).transpose();
        const vec3 exact = sigma/E*vec3(X(0), -nu*X(1), -nu*X(2));
        err = std::max(err, (u.row(a).transpose() - exact).norm());
    }
    EXPECT_LT(err, 1e-12) << log.str();
    // The reaction on x = 0 balances the applied force sigma * 1
    EXPECT_NEAR(model.reaction(mesh.nodeSets["x0"])(0), -sigma, 1e-10);
}


// A neo-Hookean Hex27P4 cube on its three symmetry planes, a follower
// pressure p on the other three faces (x = 1, y = 1, z = 1): the exact
// state is a uniform compression u = (lambda - 1) X with the Cauchy stress
// -p I, whatever lambda the material gives. A dead load of p per
// reference area would give -p/lambda^2 I instead (here 8 % less), so the
// stress tells the follower load from a dead one; Newton converges to
// machine precision with the consistent load stiffness of faceLoad.
TEST(solid3D, followerPressureCompressesANeoHookeanCube)
{
    feMesh mesh = unitCube("rubber");
    for (const int face : {1, 3, 5})
    {
        mesh.faceSets["loaded"].push_back({0, 0, face, hexFaceNodes(27, face)});
    }

    const double E = 10, nu = 0.3, p = 1.5;
    std::map<std::string, std::shared_ptr<material>> mats;
    mats["rubber"] = material::New("neoHookean", {{"E", E}, {"nu", nu}});
    solidModel model(mesh, analysisType::solid3D, mats);
    model.addConstraint(mesh.nodeSets["x0"], 0);
    model.addConstraint(mesh.nodeSets["y0"], 1);
    model.addConstraint(mesh.nodeSets["z0"], 2);
    model.addPressure("loaded", [p](double t) { return p*t; });
    model.finalise();

    auto solver = linearSolver::New("umfpack");
    stepControls steps;
    steps.deltaT = 0.5;
    std::ostringstream log;
    staticSolver(model, *solver, newtonControls(), steps, log).run(nullptr);

    const matX u = model.displacement();
    const double stretch = 1 + u(6, 0);     // node 6: (1, 1, 1)
    EXPECT_LT(stretch, 0.97) << log.str();  // compressed by a few %
    double err = 0;
    for (int a = 0; a < 27; ++a)
    {
        const vec3 X = mesh.X.row(a).transpose();
        err = std::max(err, (u.row(a).transpose() - (stretch - 1)*X).norm());
    }
    EXPECT_LT(err, 1e-12) << log.str();
    const mat3 sigma = model.elementResults()[0].cauchy;
    EXPECT_LT((sigma + p*mat3::Identity()).norm(), 1e-10*p) << sigma;
}
