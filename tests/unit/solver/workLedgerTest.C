// The work ledger (workLedger.H) and the plastic dissipation of a model
// (solidModel::plasticDissipation), the energies the effect report
// compares, on a Hex27P4 unit cube [0,1]^3 on its three symmetry planes
// pulled by a dead traction P(t) on x = 1 (uniaxial stress, homogeneous):
// - linear elastic (forces linear in U, so the trapezoidal increments are
//   exact): W_int = W_ext = P^2/(2E) (strain energy of the unit cube), no
//   dissipation, no dissipative material;
// - elasto-plastic, linear hardening sigma_y = s0 + H eps_p, loaded to P
//   and unloaded to zero. In log space the uniaxial state has T = tau =
//   P lambda (Kirchhoff stress, lambda = exp(eps)), eps = tau/E + eps_p,
//   tau = s0 + H eps_p at the peak (a fixed point in tau). The dissipation
//   is the work of the yield surface, s0 eps_p + H eps_p^2/2 (closed
//   form), and the energy balance holds: W_int = D + tau^2/(2E) at the
//   peak, W_int = D once unloaded (no stress, no stored energy), to the
//   trapezoidal rule's error over the 40 + 40 steps.
#include "staticSolver.H"
#include "workLedger.H"
#include "unitCube.H"
#include "shellTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace form;

namespace
{

//- One Hex27P4 element on the unit cube, held on x = 0, y = 0, z = 0 in
//  their normal directions, dead traction (P(t), 0, 0) on x = 1
solidModel pulledCube
(
    const std::shared_ptr<material>& mat,
    const std::function<double(double)>& P
)
{
    const feMesh mesh = test::unitCube("steel");
    solidModel model(mesh, analysisType::solid3D, {{"steel", mat}});
    model.addConstraint(mesh.nodeSets.at("x0"), 0);
    model.addConstraint(mesh.nodeSets.at("y0"), 1);
    model.addConstraint(mesh.nodeSets.at("z0"), 2);
    model.addTraction("right", [P](double t) { return vec3(P(t), 0, 0); });
    model.finalise();
    return model;
}

//- Run t = 0 -> endTime in steps of dt; at each converged step the
//  ledger takes the step's work and onStep sees the state
void run
(
    solidModel& model,
    double endTime,
    double dt,
    workLedger& ledger,
    const std::function<void(double)>& onStep
)
{
    auto solver = linearSolver::New("cholmod");
    stepControls steps;
    steps.endTime = endTime;
    steps.deltaT = dt;
    steps.maxDeltaT = dt;
    newtonControls newton;
    newton.forceTolerance = 1e-11;
    ledger.start(model);
    std::ostringstream log;
    staticSolver(model, *solver, newton, steps, log).run
    (
        [&](const stepReport& r)
        {
            ledger.add(model);
            onStep(r.time);
        }
    );
}

} // anonymous namespace


TEST(workLedger, elasticWorkIsTheStrainEnergy)
{
    const double E = 200e3, nu = 0.3, P = 300;
    solidModel model = pulledCube
    (
        material::New("linearElastic", {{"E", E}, {"nu", nu}}),
        [P](double t) { return P*t; }
    );
    workLedger ledger;
    run(model, 1, 0.25, ledger, [](double) {});
    const double W = P*P/(2*E);
    EXPECT_NEAR(ledger.internalWork, W, 1e-12*W);
    EXPECT_NEAR(ledger.externalWork, W, 1e-12*W);
    EXPECT_EQ(ledger.contactWork, 0);
    EXPECT_EQ(ledger.frictionWork, 0);
    EXPECT_FALSE(model.dissipative());
    EXPECT_EQ(model.plasticDissipation(), 0);

    // The state as a vector and back (restarts)
    workLedger copy;
    copy.setState(ledger.state(), model.nDofs());
    EXPECT_EQ(copy.internalWork, ledger.internalWork);
    EXPECT_EQ(copy.state(), ledger.state());
    EXPECT_THROW(copy.setState(ledger.state(), model.nDofs() + 1), numericalError);
}


TEST(workLedger, plasticDissipationAndTheEnergyBalance)
{
    const double E = 200e3, nu = 0.3, s0 = 250, H = 1000, P = 300;
    materialInput h;
    h.words["type"] = "linear";
    h.scalars = {{"sigmaY0", s0}, {"H", H}};
    solidModel model = pulledCube
    (
        test::elastoPlastic(E, nu, h),
        [P](double t) { return P*(1 - std::abs(t - 1)); }
    );
    ASSERT_TRUE(model.dissipative());

    // The peak: tau = P exp(tau/E + (tau - s0)/H)
    double tau = P;
    for (int i = 0; i < 200; ++i) tau = P*std::exp(tau/E + (tau - s0)/H);
    const double epsP = (tau - s0)/H;
    const double D = s0*epsP + 0.5*H*epsP*epsP;

    workLedger ledger;
    bool atPeak = false;
    double peakWork = 0, peakD = 0;
    run
    (
        model, 2, 0.025, ledger,
        [&](double t)
        {
            if (std::abs(t - 1) < 1e-9)
            {
                atPeak = true;
                peakWork = ledger.internalWork;
                peakD = model.plasticDissipation();
            }
        }
    );
    ASSERT_TRUE(atPeak);
    EXPECT_NEAR(peakD, D, 1e-8*D);
    EXPECT_NEAR(model.plasticDissipation(), D, 1e-8*D);
    // The balance, to the trapezoidal rule's error
    const double stored = tau*tau/(2*E);
    std::printf
    (
        "plastic cube: D %.9g (closed form %.9g), W_int at the peak %.9g"
        " (D + stored %.9g), unloaded %.9g, W_ext %.9g\n",
        model.plasticDissipation(), D, peakWork, D + stored,
        ledger.internalWork, ledger.externalWork
    );
    EXPECT_NEAR(peakWork, D + stored, 2e-3*(D + stored))
        << "D " << D << " stored " << stored;
    EXPECT_NEAR(ledger.internalWork, D, 2e-3*D);
    EXPECT_NEAR(ledger.externalWork, ledger.internalWork, 1e-6*D);
}


// The same balance on a strip of MITC4 shells pulled in its plane by a
// line load P h per unit width on its tip and unloaded (uniaxial plane
// stress, homogeneous): the shells' dissipation (shellSet::
// plasticDissipation, the lamina law's density over the integration
// points' volumes) is the closed form times the strip's volume L b h.
TEST(workLedger, plasticDissipationOfShells)
{
    const double E = 200e3, nu = 0.3, s0 = 250, H = 1000, P = 300;
    const double L = 1, b = 0.2, h = 0.01;
    feMesh mesh = test::strip(2, L, b, h, 3);
    solidModel model
    (
        mesh, analysisType::solid3D,
        test::linearHardeningSheet(E, nu, s0, H)
    );
    std::vector<int> all(mesh.nNodes());
    for (int n = 0; n < mesh.nNodes(); ++n) all[n] = n;
    model.addConstraint(mesh.nodeSets.at("clamp"), 0);
    model.addConstraint({0}, 1);
    for (int c : {2, 3, 4}) model.addConstraint(all, c);
    model.addLineLoad
    (
        "tip",
        [=](double t) { return vec3(P*h*(1 - std::abs(t - 1)), 0, 0); }
    );
    model.finalise();
    ASSERT_TRUE(model.dissipative());

    double tau = P;
    for (int i = 0; i < 200; ++i) tau = P*std::exp(tau/E + (tau - s0)/H);
    const double epsP = (tau - s0)/H;
    const double D = (s0*epsP + 0.5*H*epsP*epsP)*L*b*h;

    workLedger ledger;
    run(model, 2, 0.025, ledger, [](double) {});
    std::printf
    (
        "plastic shell strip: D %.9g (closed form %.9g), W_int unloaded"
        " %.9g\n", model.plasticDissipation(), D, ledger.internalWork
    );
    EXPECT_NEAR(model.plasticDissipation(), D, 1e-7*D);
    EXPECT_NEAR(ledger.internalWork, D, 2e-3*D);
}
