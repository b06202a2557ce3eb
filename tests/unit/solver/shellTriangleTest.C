// MITC3+ triangles in the solid model (issue 22; mitc3.H, shellSet.H):
// the strips of shellModelTest.C with every quadrilateral cut into two
// triangles (alternating diagonals, test::triangulated), through
// solidModel and staticSolver:
//   - Sze's cantilever under end shear (Sze, Liu & Lo 2004, SHELLS.md):
//     the tip displacements at half and full load (JLLB15 Fig. 4: MITC3+
//     on such a strip follows the reference curve);
//   - the strip rolled up into a full circle by an end moment (exact:
//     pure bending, inextensible) with the bubbles committed at every
//     step and folded into their frames;
//   - mass: the strip's translational mass rho t A and rotary inertia
//     rho t^3/12 A (consistent and lumped); under its own weight the
//     cantilever deflects q L^4/(8 EI);
//   - a save / restore of a converged state restores the bubbles (the
//     element states) with the frames: the next step is the same.
#include "staticSolver.H"
#include "shellTestTools.H"
#include "shellSet.H"
#include "materialInput.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace form;

namespace
{

std::map<std::string, std::shared_ptr<material>> elastic(double E, double nu)
{
    return {{"sheet", material::New("stVenantKirchhoff", {{"E", E}, {"nu", nu}})}};
}

void clamp(solidModel& model)
{
    for (int c = 0; c < 5; ++c) model.addConstraint(model.mesh().nodeSets.at("clamp"), c);
}

feMesh triangleStrip(int n, double L, double b, double h, int points = 2)
{
    return test::triangulated(test::strip(n, L, b, h, points));
}

} // anonymous namespace


TEST(shellTriangles, szeCantileverUnderEndShear)
{
    // L = 10, b = 1, h = 0.1, E = 1.2e6, nu = 0, end shear up to
    // P_max = 4: tip -u 1.604, w 4.933 at P_max/2 and -u 3.286, w 6.698
    // at P_max (Sze, Liu & Lo 2004)
    solidModel model(triangleStrip(16, 10, 1, 0.1), analysisType::solid3D, elastic(1.2e6, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addNodalLoad(tip, 2, [](double t) { return 0.5*4*t; });
    model.finalise();
    EXPECT_EQ(model.nDofs(), 5*34);
    auto solver = linearSolver::New("cholmod");
    stepControls steps;
    steps.deltaT = 0.05;
    steps.maxDeltaT = 0.05;
    std::ostringstream log;
    double uHalf = 0, wHalf = 0;
    int maxIterations = 0;
    staticSolver(model, *solver, test::tight(), steps, log).run
    (
        [&](const stepReport& r)
        {
            maxIterations = std::max(maxIterations, r.iterations);
            if (std::abs(r.time - 0.5) < 1e-9)
            {
                uHalf = -0.5*(model.displacement()(tip[0], 0) + model.displacement()(tip[1], 0));
                wHalf = 0.5*(model.displacement()(tip[0], 2) + model.displacement()(tip[1], 2));
            }
        }
    );
    const double u = -0.5*(model.displacement()(tip[0], 0) + model.displacement()(tip[1], 0));
    const double w = 0.5*(model.displacement()(tip[0], 2) + model.displacement()(tip[1], 2));
    std::printf
    (
        "    MITC3+ 16 x 1 x 2: end shear P_max/2 -u %.4f w %.4f (Sze 1.604,"
        " 4.933); P_max -u %.4f w %.4f (Sze 3.286, 6.698); at most %d"
        " iterations\n", uHalf, wHalf, u, w, maxIterations
    );
    // observed within 0.3 %
    EXPECT_NEAR(uHalf/1.604, 1, 0.01) << log.str();
    EXPECT_NEAR(wHalf/4.933, 1, 0.01);
    EXPECT_NEAR(u/3.286, 1, 0.01);
    EXPECT_NEAR(w/6.698, 1, 0.01);
}


TEST(shellTriangles, stripRolledUpIntoACircle)
{
    // L = 12, b = 1, h = 0.1, E = 1.2e6, nu = 0, end moment 2 pi EI/L
    // (a line moment on the tip edge, here two nodal moments of half of
    // it): a full circle, the tip back at the clamp
    const double L = 12, E = 1.2e6, h = 0.1;
    const double EI = E*h*h*h/12, Mmax = 2*M_PI*EI/L;
    solidModel model(triangleStrip(32, L, 1, h), analysisType::solid3D, elastic(E, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    for (const int n : tip)
    {
        model.addMoment({n}, [=](double t) { return vec3(0, -0.5*Mmax*t, 0); });
    }
    model.finalise();
    auto solver = linearSolver::New("umfpack");
    stepControls steps;
    steps.deltaT = 0.05;
    steps.maxDeltaT = 0.05;
    std::ostringstream log;
    double worst = 0;
    int maxIterations = 0;
    staticSolver(model, *solver, test::tight(), steps, log).run
    (
        [&](const stepReport& r)
        {
            maxIterations = std::max(maxIterations, r.iterations);
            const double phi = 2*M_PI*r.time;
            const double ue = L*(std::sin(phi)/phi - 1);
            const double we = L*(1 - std::cos(phi))/phi;
            const matX u = model.displacement();
            worst = std::max
            (
                worst, std::hypot(u(tip[0], 0) - ue, u(tip[0], 2) - we)/L
            );
        }
    );
    const vec3 tipPoint =
        model.mesh().X.row(tip[0]).transpose()
      + model.displacement().row(tip[0]).transpose();
    std::printf
    (
        "    MITC3+ 32 x 1 x 2: roll-up tip at (%.4f, %.4f, %.4f); largest"
        " tip error over the loading %.4f L; at most %d iterations\n",
        tipPoint(0), tipPoint(1), tipPoint(2), worst, maxIterations
    );
    EXPECT_LT(worst, 0.01) << log.str();
    EXPECT_LT(std::hypot(tipPoint(0), tipPoint(2)), 0.01*L);
    const vec3 d = model.shells()->director(tip[0], model.dofs(), model.U());
    EXPECT_GT(d(2), 0.99);
}


TEST(shellTriangles, massAndGravity)
{
    const double L = 10, b = 1, t = 0.1, E = 1.2e6, rho = 1;
    const double EI = E*b*t*t*t/12, rhoA = rho*b*t;
    for (const bool lumped : {false, true})
    {
        solidModel model(triangleStrip(16, L, b, t), analysisType::solid3D, elastic(E, 0));
        model.finalise();
        model.setInertia({{"sheet", rho}}, lumped);
        const sparseMatrix& M = model.massMatrix();
        const dofMap& d = model.dofs();
        vecX ez = vecX::Zero(model.nDofs()), rot = vecX::Zero(model.nDofs());
        for (int n = 0; n < model.mesh().nNodes(); ++n)
        {
            ez(d.dof(n, 2)) = 1;
            rot(d.dof(n, 3)) = 1;
        }
        EXPECT_NEAR(ez.dot(M*ez), rho*t*L*b, 1e-12) << lumped;
        EXPECT_NEAR(rot.dot(M*rot), rho*t*t*t/12*L*b, 1e-14) << lumped;
    }
    // Under its own weight g = -0.01 (a linear response): q L^4/(8 EI)
    solidModel model(triangleStrip(16, L, b, t), analysisType::solid3D, elastic(E, 0));
    clamp(model);
    model.finalise();
    model.setBodyForce(rho, [](double) { return vec3(0, 0, -0.01); });
    auto solver = linearSolver::New("cholmod");
    std::ostringstream log;
    stepControls steps;
    steps.deltaT = 1;
    staticSolver(model, *solver, test::tight(), steps, log).run(nullptr);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    const double w =
        0.5*(model.displacement()(tip[0], 2) + model.displacement()(tip[1], 2));
    const double exact = -0.01*rhoA*std::pow(L, 4)/(8*EI);
    std::printf("    MITC3+ gravity: tip %.6g (q L^4/8EI %.6g)\n", w, exact);
    EXPECT_NEAR(w/exact, 1, 2e-3) << log.str();      // observed +0.07 %
}


TEST(shellTriangles, saveRestoreKeepsTheBubbles)
{
    // The cantilever to half its load, saved; one more step; restored and
    // the same step again: the same displacements (the bubbles' frames
    // are element states, saved and restored with the rest)
    solidModel model(triangleStrip(8, 10, 1, 0.1), analysisType::solid3D, elastic(1.2e6, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addNodalLoad(tip, 2, [](double t) { return 2*t; });
    model.finalise();
    auto solver = linearSolver::New("cholmod");
    std::ostringstream log;
    stepControls steps;
    steps.deltaT = 0.25;
    steps.maxDeltaT = 0.25;
    steps.endTime = 0.5;
    staticSolver(model, *solver, test::tight(), steps, log).run(nullptr);
    const solidModel::savedState saved = model.save();
    steps.startTime = 0.5;
    steps.endTime = 0.75;
    staticSolver(model, *solver, test::tight(), steps, log).run(nullptr);
    const matX first = model.displacement();
    model.restore(saved);
    staticSolver(model, *solver, test::tight(), steps, log).run(nullptr);
    EXPECT_LT((model.displacement() - first).norm(), 1e-12*first.norm()) << log.str();
}
