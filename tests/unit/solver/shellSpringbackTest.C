// Springback of MITC4 shells (issue 22): a plate strip bent in plane
// strain to a radius R and released (BENCHMARKS.md, "Pure bending of a
// plate, plane strain"). The strip L = 1, b = 0.2, t = 0.02 (16
// elements), E = 2e5, nu = 0.3, u_y = 0 and the rotation about x held at
// every node (plane strain); clamped at x = 0. Bending: every node's
// rotation about y prescribed to -x/R (uniform curvature, also where the
// section's moment-curvature law is flat); release: those constraints
// removed gradually (their reactions decay to zero), the strip springs
// back elastically to a uniform curvature 1/R_f = tip rotation / L.
//   - Elastic-perfectly plastic, sigma_y = 250, R S/(E' t) = 0.15 (E' =
//     E/(1 - nu^2), S = 2 sigma_y/sqrt(3)): the closed form
//         R/R_f = 4 (R S/(E' t))^3 - 3 R S/(E' t) + 1
//     within 1 % with 10 Gauss points through the thickness (observed
//     -0.77 %: the rule's error on the kinked stress profile; 5 points:
//     -2.2 %, asserted 3 %);
//   - Swift hardening sigma = 500 (0.01 + eps_p)^0.2, R S0/(E' t) = 0.05:
//     1/R_f = 1/R - M/(E' t^3/12) with M the bending moment per width of
//     the section integrated finely (400 fibres, each through the lamina
//     law along its strain path E11 = z/R + (z/R)^2/2, E22 = 0), within
//     1 % with 10 Gauss points (observed +0.19 %).
#include "staticSolver.H"
#include "shellTestTools.H"
#include "planeStressMaterial.H"
#include "materialInput.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace form;

namespace
{

const double E = 2e5, nu = 0.3, L = 1, b = 0.2, t = 0.02;
const double Ep = E/(1 - nu*nu);

std::shared_ptr<material> elastoPlastic(const materialInput& hardening)
{
    return test::elastoPlastic(E, nu, hardening);
}

//- Bend the strip to radius R in 10 steps, release in 5: the final
//  radius (from the tip's rotation)
double springbackRadius(const std::shared_ptr<material>& mat, double R, int points)
{
    feMesh mesh = test::strip(16, L, b, t, points);
    solidModel model(mesh, analysisType::solid3D, {{"sheet", mat}});
    for (int c = 0; c < 5; ++c) model.addConstraint(mesh.nodeSets.at("clamp"), c);
    std::vector<int> all(mesh.nNodes()), free;
    for (int n = 0; n < mesh.nNodes(); ++n)
    {
        all[n] = n;
        if (mesh.X(n, 0) > 0) free.push_back(n);
    }
    model.addConstraint(all, 1);
    model.addConstraint(all, 3);
    // beta = -dw/dx: -x/R bends the strip up
    model.addNodalConstraint
    (
        free, 4,
        [&mesh, R](int n, double time)
        {
            return -mesh.X(n, 0)/R*std::min(time, 1.0);
        }
    );
    model.finalise();
    auto solver = linearSolver::New("cholmod");
    const newtonControls newton = test::tight();
    std::ostringstream log;
    stepControls steps;
    steps.deltaT = 0.1;
    steps.maxDeltaT = 0.1;
    staticSolver(model, *solver, newton, steps, log).run(nullptr);
    model.releaseConstraint(free, 4, 1, 2);
    stepControls release;
    release.startTime = 1;
    release.endTime = 2;
    release.deltaT = 0.2;
    release.maxDeltaT = 0.2;
    staticSolver(model, *solver, newton, release, log).run(nullptr);
    const int tip = mesh.nodeSets.at("tip")[0];
    const double theta = -model.U()(model.dofs().dof(tip, 4));
    return L/theta;
}

} // anonymous namespace


TEST(shellSpringback, perfectPlasticityClosedForm)
{
    const double sy = 250, S = 2*sy/std::sqrt(3.0);
    materialInput h;
    h.words["type"] = "perfect";
    h.scalars = {{"sigmaY0", sy}};
    const auto mat = elastoPlastic(h);
    const double rho = 0.15, R = rho*Ep*t/S;
    const double Rf = R/(4*rho*rho*rho - 3*rho + 1);
    for (int points : {5, 10})
    {
        const double r = springbackRadius(mat, R, points);
        std::printf
        (
            "    springback, perfect plasticity, %d Gauss points: R %.5f ->"
            " R_f %.5f (closed form %.5f, %+.2f %%)\n",
            points, R, r, Rf, 100*(r/Rf - 1)
        );
        if (points == 10) EXPECT_NEAR(r/Rf, 1, 0.01);
        else EXPECT_NEAR(r/Rf, 1, 0.03);
    }
}


TEST(shellSpringback, swiftHardeningAgainstTheSectionIntegral)
{
    materialInput h;
    h.words["type"] = "swift";
    h.scalars = {{"K", 500}, {"eps0", 0.01}, {"n", 0.2}};
    const auto mat = elastoPlastic(h);
    const double S0 = 2/std::sqrt(3.0)*500*std::pow(0.01, 0.2);
    const double R = 0.05*Ep*t/S0;
    // The section's moment per width at 1/R: 400 fibres, each loaded
    // along its strain path in 100 steps through the lamina law
    const planeStressMaterial law(mat);
    const int nf = 400, ns = 100;
    double M = 0;
    for (int i = 0; i < nf; ++i)
    {
        const double z = t*((i + 0.5)/nf - 0.5);
        materialState state = law.initialState(), trial = state;
        vec5 eps = vec5::Zero(), s;
        mat5 D;
        for (int k = 1; k <= ns; ++k)
        {
            const double kz = z/R*k/ns;
            eps(0) = kz + 0.5*kz*kz;
            ASSERT_TRUE(law.stress(mat3::Identity(), eps, state, trial, s, D));
            state = trial;
        }
        M += s(0)*(1 + z/R)*z*t/nf;
    }
    const double Rf = 1/(1/R - M/(Ep*t*t*t/12));
    const double r = springbackRadius(mat, R, 10);
    std::printf
    (
        "    springback, Swift, 10 Gauss points: R %.5f -> R_f %.5f"
        " (section integral %.5f, %+.2f %%)\n", R, r, Rf, 100*(r/Rf - 1)
    );
    EXPECT_NEAR(r/Rf, 1, 0.01);
}
