// Implicit dynamics (timeIntegrator.H) on spring-mass chains built from
// the test bar (testElements.H: linear axial law, point mass at node b):
//  - single-dof oscillator: period and amplitude of the trapezoidal rule
//    and the Bathe scheme against the analytic solution, second-order
//    convergence in the time step, energy of the trapezoidal rule;
//  - Bathe & Noh (2012) three-dof model problem (BENCHMARKS.md): the
//    trapezoidal rule shows the spurious response of the stiff spring,
//    the Bathe scheme does not, both follow the slow response;
//  - a time step 100 times the period stays bounded with the Bathe scheme;
//  - the initial acceleration, bad input.
#include "staticSolver.H"
#include "testElements.H"
#include "structuredQuadMesh.H"
#include "material.H"
#include <gtest/gtest.h>
#include <cmath>
#include <iostream>
#include <sstream>

using namespace form;
using namespace form::test;

namespace
{

const double pi = 3.14159265358979323846;

// Chain of collinear bars along x: node i at x = i L, bar i joins nodes i
// and i + 1 with axial stiffness k[i] (linear law, EA = k[i] L) and
// carries the point mass m[i] at node i + 1. All y dofs are fixed; node 0
// is fixed in x, or moves as u0(t) if given. L = 10 keeps the bars far
// from collapse (the model problems move nodes by several units).
struct chainModel
{
    std::unique_ptr<solidModel> model;
    std::map<std::string, double> density;
};

chainModel springChain
(
    const std::vector<double>& k,
    const std::vector<double>& m,
    std::function<double(double)> u0 = nullptr
)
{
    registerTestElements();
    const int nBars = int(k.size());
    matX X = matX::Zero(nBars + 1, 2);
    const double L = 10;
    for (int i = 0; i <= nBars; ++i) X(i, 0) = i*L;
    feMesh mesh;
    mesh.nDim = 2;
    mesh.X = X;
    std::map<std::string, std::shared_ptr<material>> materials;
    chainModel c;
    for (int i = 0; i < nBars; ++i)
    {
        elementBlock b;
        b.name = "bar" + std::to_string(i);
        b.elementType = testTruss::typeName;
        b.materialName = b.name;
        b.nodesPerElement = 2;
        b.connectivity = {i, i + 1};
        mesh.blocks.push_back(b);
        auto law = std::make_shared<trussMaterial>();
        law->svk = false;
        law->EA = k[i]*L;
        materials[b.name] = law;
        c.density[b.name] = m[i];
    }
    c.model.reset
    (
        new solidModel(mesh, analysisType::planeStrain, materials)
    );
    std::vector<int> all;
    for (int i = 0; i <= nBars; ++i) all.push_back(i);
    c.model->addConstraint(all, 1);
    c.model->addConstraint({0}, 0, u0);
    c.model->finalise();
    return c;
}

struct sample
{
    double t;
    vecX U, V, A;
};

// Run a chain from its current state with the initial velocity V0 over
// [0, tEnd] in fixed steps h; samples at t = 0 and after every step
std::vector<sample> integrate
(
    chainModel& c,
    const std::string& scheme,
    double h,
    double tEnd,
    const vecX& V0,
    bool lumped = false,
    std::ostream* logOut = nullptr,
    energyBalance* energyOut = nullptr,
    bool keepTangent = false,
    int* tangents = nullptr
)
{
    c.model->setInertia(c.density, lumped);
    timeIntegrator integrator(scheme);
    integrator.initialise(*c.model, 0, V0);
    auto solver = linearSolver::New("cholmod");
    newtonControls nc;
    nc.forceTolerance = 1e-10;
    nc.energyTolerance = 1e-24;
    nc.absoluteForceTolerance = 1e-10;
    nc.lineSearch = false;
    nc.keepTangent = keepTangent;
    stepControls sc;
    sc.startTime = 0;
    sc.endTime = tEnd;
    sc.deltaT = h;
    sc.maxDeltaT = h;
    sc.growthFactor = 1;
    std::ostringstream log;
    staticSolver s(*c.model, *solver, nc, sc, log);
    s.setIntegrator(&integrator);
    std::vector<sample> out;
    out.push_back
    (
        {0, c.model->U(), integrator.velocity(), integrator.acceleration()}
    );
    if (tangents) *tangents = 0;
    s.run([&](const stepReport& r)
    {
        if (tangents) *tangents += r.newTangents;
        out.push_back
        (
            {
                r.time, c.model->U(), integrator.velocity(),
                integrator.acceleration()
            }
        );
    });
    if (logOut) *logOut << log.str();
    if (energyOut) *energyOut = integrator.energy();
    return out;
}

// Oscillator: k = 4 pi^2, m = 1 (period 1), u(0) = 1, v(0) = 0
std::vector<sample> oscillator
(
    const std::string& scheme,
    double h,
    double tEnd,
    bool lumped = false
)
{
    chainModel c = springChain({4*pi*pi}, {1});
    vecX U = vecX::Zero(4);
    U(2) = 1;
    c.model->setDisplacement(U);
    c.model->commit();
    return integrate(c, scheme, h, tEnd, vecX(), lumped);
}

// Largest error of u against cos(2 pi t) over the samples
double maxError(const std::vector<sample>& s)
{
    double e = 0;
    for (const sample& p : s)
    {
        e = std::max(e, std::abs(p.U(2) - std::cos(2*pi*p.t)));
    }
    return e;
}

// Mean period from the upward zero crossings of u (linear interpolation)
double measuredPeriod(const std::vector<sample>& s)
{
    std::vector<double> crossings;
    for (std::size_t i = 1; i < s.size(); ++i)
    {
        const double a = s[i - 1].U(2), b = s[i].U(2);
        if (a < 0 && b >= 0)
        {
            crossings.push_back
            (
                s[i - 1].t + (s[i].t - s[i - 1].t)*(-a)/(b - a)
            );
        }
    }
    if (crossings.size() < 2) return NAN;
    return (crossings.back() - crossings.front())/(crossings.size() - 1);
}

} // namespace


TEST(dynamics, OscillatorSecondOrderInTheTimeStep)
{
    for (const std::string scheme : {"trapezoidal", "bathe"})
    {
        const double e1 = maxError(oscillator(scheme, 1.0/20, 2));
        const double e2 = maxError(oscillator(scheme, 1.0/40, 2));
        const double e3 = maxError(oscillator(scheme, 1.0/80, 2));
        std::cout
            << "    " << scheme << ": max |u - cos 2 pi t| over two periods,"
            << " h = T/20, T/40, T/80: " << e1 << ' ' << e2 << ' ' << e3
            << " (order " << std::log2(e1/e2) << ", " << std::log2(e2/e3)
            << ")\n";
        EXPECT_NEAR(std::log2(e1/e2), 2, 0.15) << scheme;
        EXPECT_NEAR(std::log2(e2/e3), 2, 0.1) << scheme;
        EXPECT_LT(e1, 0.2) << scheme;
    }
}


TEST(dynamics, OscillatorPeriodAndAmplitude)
{
    // Trapezoidal rule: no amplitude decay (energy 1/2 v^2 + 1/2 k u^2
    // conserved), period elongation tan(Omega h/2) = omega h/2, i.e.
    // T_h/T = (omega h/2)/atan(omega h/2) = 1 + (omega h)^2/12 + ...
    const double h = 1.0/20, omega = 2*pi;
    const std::vector<sample> trap = oscillator("trapezoidal", h, 10);
    const double exactTrap = (omega*h/2)/std::atan(omega*h/2);
    const double Ttrap = measuredPeriod(trap);
    double energyError = 0;
    for (const sample& p : trap)
    {
        const double E =
            0.5*p.V(2)*p.V(2) + 0.5*omega*omega*p.U(2)*p.U(2);
        energyError = std::max(energyError, std::abs(E/(0.5*omega*omega) - 1));
    }
    // Bathe scheme: shorter period error, slight amplitude decay
    const std::vector<sample> bathe = oscillator("bathe", h, 10);
    const double Tbathe = measuredPeriod(bathe);
    double amplitudeLast = 0;
    for (const sample& p : bathe)
    {
        if (p.t > 9 - 1e-9) amplitudeLast = std::max(amplitudeLast, std::abs(p.U(2)));
    }
    std::cout
        << "    h = T/20: trapezoidal period " << Ttrap << " (theory "
        << exactTrap << "), energy drift " << energyError
        << "; bathe period " << Tbathe << ", amplitude after 9 periods "
        << amplitudeLast << '\n';
    // Period from interpolated zero crossings: accurate to O(h^2) of
    // the crossing times, which cancel over many periods
    EXPECT_NEAR(Ttrap, exactTrap, 2e-4);
    EXPECT_LT(energyError, 1e-9);
    EXPECT_GT(Ttrap - 1, 0.8*(omega*h)*(omega*h)/12);
    EXPECT_LT(std::abs(Tbathe - 1), Ttrap - 1);
    EXPECT_LT(amplitudeLast, 1.0);
    EXPECT_GT(amplitudeLast, 0.95);
}


// An oscillator started by an initial velocity (u(0) = 0, v(0) = 2 pi,
// T_0 = 2 pi^2): its kinetic energy is part of the balance, so the
// trapezoidal rule dissipates nothing (T_0 + W_ext = T + W_int to
// round-off), and the Bathe scheme a little (0.1 % per period at h = T/20)
TEST(dynamics, EnergyBalanceCountsTheInitialKineticEnergy)
{
    for (const std::string scheme : {"trapezoidal", "bathe"})
    {
        chainModel c = springChain({4*pi*pi}, {1});
        vecX V0 = vecX::Zero(4);
        V0(2) = 2*pi;
        energyBalance e;
        integrate(c, scheme, 1.0/20, 5, V0, false, nullptr, &e);
        EXPECT_NEAR(e.initialKinetic, 2*pi*pi, 1e-12) << scheme;
        const double T0 = e.initialKinetic;
        if (scheme == "trapezoidal")
        {
            EXPECT_LT(std::abs(e.dissipated()), 1e-12*T0);
            EXPECT_NEAR(e.kinetic + e.internalWork, T0, 1e-12*T0);
        }
        else
        {
            EXPECT_GT(e.dissipated(), 1e-4*T0);
            EXPECT_LT(e.dissipated(), 2e-2*T0);
        }
    }
}


TEST(dynamics, BatheNohThreeDofModelProblem)
{
    // Bathe & Noh (2012): k1 = 1e7, k2 = 1, masses (0, 1, 1), node 1
    // driven with u1 = sin 1.2 t, h = 0.2618; exact
    //   u2 = 2.7273e-7 sin t + sin 1.2t,  u3 = 2.7273 sin t - 2.2727 sin 1.2t
    // (node numbers of the paper; nodes 0, 1, 2 here)
    const double tEnd = 0.2618*40;
    auto exactU3 = [](double t)
    {
        return 2.7273*std::sin(t) - 2.2727*std::sin(1.2*t);
    };
    auto exactV2 = [](double t)
    {
        return 2.7273e-7*std::cos(t) + 1.2*std::cos(1.2*t);
    };
    auto exactA2 = [](double t)
    {
        return -2.7273e-7*std::sin(t) - 1.44*std::sin(1.2*t);
    };
    // errors[scheme][h index] = {u3, v2, a2}
    std::map<std::string, std::vector<std::vector<double>>> errors;
    for (const std::string scheme : {"trapezoidal", "bathe"})
    {
        for (const double h : {0.2618, 0.1309})
        {
            chainModel c = springChain
            (
                {1e7, 1}, {1, 1}, [](double t) { return std::sin(1.2*t); }
            );
            // Initial velocities of the exact solution: v1 = v2 = 1.2,
            // v3 = 2.7273 - 2.2727*1.2 (~ 0)
            vecX V0 = vecX::Zero(6);
            V0(0) = 1.2;
            V0(2) = 1.2 + 2.7273e-7;
            V0(4) = 2.7273 - 2.2727*1.2;
            const std::vector<sample> s = integrate(c, scheme, h, tEnd, V0);
            // u3 over the run; v2, a2 over the second half (what
            // persists)
            double eU3 = 0, eV2 = 0, eA2 = 0;
            for (const sample& p : s)
            {
                eU3 = std::max(eU3, std::abs(p.U(4) - exactU3(p.t)));
                if (p.t < 0.5*tEnd) continue;
                eV2 = std::max(eV2, std::abs(p.V(2) - exactV2(p.t)));
                eA2 = std::max(eA2, std::abs(p.A(2) - exactA2(p.t)));
            }
            errors[scheme].push_back({eU3, eV2, eA2});
            std::cout
                << "    " << scheme << ", h = " << h << " to t = " << tEnd
                << ": max error u3 " << eU3 << " (amplitude 5); over the"
                << " second half: v2 " << eV2 << " (amplitude 1.2), a2 "
                << eA2 << " (amplitude 1.44)\n";
        }
    }
    const auto& trap = errors["trapezoidal"];
    const auto& bathe = errors["bathe"];
    for (int i = 0; i < 2; ++i)
    {
        // Both follow the slow response (u3: amplitude up to 5)
        EXPECT_LT(trap[i][0], 0.25);
        EXPECT_LT(bathe[i][0], 0.15);
        EXPECT_LT(trap[i][1], 0.05);
        EXPECT_LT(bathe[i][1], 0.02);
        // The stiff spring rings in the trapezoidal rule: a spurious
        // acceleration of node 2 larger than the physical one, which a
        // smaller step does not remove
        EXPECT_GT(trap[i][2], 2.0);
        EXPECT_LT(bathe[i][2], 0.25);
    }
    // ... while the Bathe scheme's acceleration error is a discretisation
    // error that shrinks with the step (measured: halves with h here; the
    // acceleration of node 2 is carried by the stiff spring, whose
    // quasi-static response the scheme reaches through its damped stiff
    // mode)
    EXPECT_GT(bathe[0][2]/bathe[1][2], 1.7);
    EXPECT_GT(trap[1][2], 2.0);
    // u3 converges at second order in both
    EXPECT_GT(trap[0][0]/trap[1][0], 3.0);
    EXPECT_GT(bathe[0][0]/bathe[1][0], 3.0);
}


TEST(dynamics, BatheBoundedAtTimeStepsFarBeyondThePeriod)
{
    // h = 100 T: the Bathe scheme annihilates the unresolved oscillation
    // (spectral radius -> 0), the trapezoidal rule keeps it (radius 1)
    const std::vector<sample> bathe = oscillator("bathe", 100, 2000);
    const std::vector<sample> trap = oscillator("trapezoidal", 100, 2000);
    double maxBathe = 0, maxTrap = 0;
    for (std::size_t i = 1; i < bathe.size(); ++i)
    {
        maxBathe = std::max(maxBathe, std::abs(bathe[i].U(2)));
        maxTrap = std::max(maxTrap, std::abs(trap[i].U(2)));
    }
    std::cout
        << "    h = 100 T, 20 steps: max |u| bathe " << maxBathe
        << ", trapezoidal " << maxTrap << " (u0 = 1)\n";
    EXPECT_LT(maxBathe, 1e-3);
    EXPECT_GT(maxTrap, 0.99);
    EXPECT_LE(maxTrap, 1 + 1e-9);
}


TEST(dynamics, LumpedMassOfTheQ9IsTheRowSum)
{
    // One Q9P3 element, 2 x 3, density 7 (mass 42 per direction). The
    // consistent mass int rho N_a N_b dA couples the nodes; the lumped one
    // is its row sum on the diagonal: for the biquadratic Lagrange element
    // the products of the 1D row sums (1/6, 2/3, 1/6), i.e. rho A/36 at
    // the corners, rho A/9 at mid-sides and 4 rho A/9 at the centre.
    const double rho = 7, A = 6;
    for (const bool lumped : {false, true})
    {
        feMesh mesh = structuredQuadMesh
        (
            {{{0, 0}, {2, 0}, {2, 3}, {0, 3}}}, 1, 1, 9, "Q9P3", "solid"
        );
        std::shared_ptr<material> mat =
            material::New("linearElastic", {{"E", 1}, {"nu", 0.3}});
        solidModel model
        (
            std::move(mesh), analysisType::planeStrain,
            std::map<std::string, std::shared_ptr<material>>{{"solid", mat}}
        );
        model.finalise();
        model.setInertia({{"solid", rho}}, lumped);
        const matX M = matX(model.massMatrix());
        const matX& X = model.mesh().X;
        ASSERT_EQ(M.rows(), 18);
        EXPECT_NEAR(M.sum(), 2*rho*A, 1e-12);
        const double offDiagonal =
            (M - matX(M.diagonal().asDiagonal())).cwiseAbs().maxCoeff();
        if (!lumped)
        {
            EXPECT_GT(offDiagonal, 0.01*rho*A);
            continue;
        }
        EXPECT_EQ(offDiagonal, 0);
        for (int a = 0; a < 9; ++a)
        {
            const int mid = (X(a, 0) == 1) + (X(a, 1) == 1.5);
            const double expected = rho*A*(mid == 0 ? 1.0/36 : mid == 1 ? 1.0/9 : 4.0/9);
            EXPECT_NEAR(M(2*a, 2*a), expected, 1e-12) << "node " << a;
            EXPECT_NEAR(M(2*a + 1, 2*a + 1), expected, 1e-12) << "node " << a;
        }
    }
}


TEST(dynamics, InitialAccelerationFromTheLoadedState)
{
    // Oscillator released from u = 1 at rest: a(0) = -k u/m = -4 pi^2
    chainModel c = springChain({4*pi*pi}, {1});
    vecX U = vecX::Zero(4);
    U(2) = 1;
    c.model->setDisplacement(U);
    c.model->commit();
    c.model->setInertia(c.density, false);
    timeIntegrator integrator("trapezoidal");
    integrator.initialise(*c.model, 0, vecX());
    EXPECT_NEAR(integrator.acceleration()(2), -4*pi*pi, 1e-10);
    EXPECT_EQ(integrator.acceleration()(0), 0);
}


TEST(dynamics, BadInput)
{
    EXPECT_THROW(timeIntegrator("newmark"), inputError);
    EXPECT_THROW(timeIntegrator("bathe", 1.0), inputError);
    chainModel c = springChain({1}, {1});
    EXPECT_THROW(c.model->setInertia({}, false), inputError);
    EXPECT_THROW(c.model->setInertia({{"bar0", -1.0}}, false), inputError);
    timeIntegrator integrator("trapezoidal");
    // No inertia built: a static model cannot be integrated in time
    EXPECT_THROW(integrator.initialise(*c.model, 0, vecX()), numericalError);
}


TEST(dynamics, KeptTangentFactorisesOncePerStageOfALinearChain)
{
    // The Bathe & Noh chain (linear): with kept tangents each stage of the
    // scheme keeps its own factors (the stages' tangents differ by their
    // acceleration coefficients), so the whole run factorises once per
    // stage and solves every later step with them, to full Newton's states
    for (const std::string scheme : {"trapezoidal", "bathe"})
    {
        std::vector<sample> s[2];
        int tangents[2];
        for (const bool keep : {false, true})
        {
            chainModel c = springChain
            (
                {1e7, 1}, {1, 1}, [](double t) { return std::sin(1.2*t); }
            );
            vecX V0 = vecX::Zero(6);
            V0(0) = V0(2) = 1.2;
            std::ostringstream log;
            s[keep] = integrate
            (
                c, scheme, 0.2618, 0.2618*20, V0, false, &log, nullptr,
                keep, &tangents[keep]
            );
            if (keep)
            {
                EXPECT_NE(log.str().find("  kept"), std::string::npos);
            }
        }
        const int stages = scheme == "bathe" ? 2 : 1;
        ASSERT_EQ(s[0].size(), s[1].size());
        EXPECT_EQ(tangents[0], 20*stages);
        EXPECT_EQ(tangents[1], stages) << scheme;
        double err = 0, size = 0;
        for (std::size_t k = 0; k < s[0].size(); ++k)
        {
            err = std::max(err, (s[1][k].U - s[0][k].U).norm());
            size = std::max(size, s[0][k].U.norm());
        }
        EXPECT_LE(err, 1e-9*size) << scheme;
        std::cout << "    " << scheme << ": " << tangents[0] << " -> "
            << tangents[1] << " factorisations, largest difference of U "
            << err << " (|U| up to " << size << ")\n";
    }
}
