// Constraint-function contact: the constraint functions (values on their
// branches, derivatives against central differences, no cancellation far
// from the corner), and the contact model's residual against finite
// differences of its tangent, with friction, curved tool pieces and a
// force-controlled tool; the tool approach, a tool that can never touch,
// and chattering detection.
#include "contactModel.H"
#include "contactTestTools.H"
#include "constraintFunctions.H"
#include "structuredQuadMesh.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolContactModel = 1e-7;
}

using namespace form;

namespace
{

TEST(constraintFunctions, normalBranchesAndDerivatives)
{
    const double eps = 1e-6;
    // On the solution set: g lambda = eps
    for (double g : {1e-6, 1e-3, 0.1, 10.0})
    {
        const double l = eps/g;
        EXPECT_NEAR(normalConstraintFunction(g, l, eps).w, 0, 1e-15*(g + l));
    }
    // Far from the corner w = min(g, lambda) - O(eps)
    EXPECT_NEAR(normalConstraintFunction(5, 0, eps).w, -eps/5, 1e-13);
    EXPECT_NEAR(normalConstraintFunction(-2, 3, eps).w, -2, 1e-6);
    EXPECT_NEAR(normalConstraintFunction(1e8, 1e-3, 1e-12).w, 1e-3, 1e-15);

    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-3e-3, 3e-3);
    for (int k = 0; k < 200; ++k)
    {
        const double g = u(gen), l = u(gen);
        const normalConstraint c = normalConstraintFunction(g, l, eps);
        const double h = 1e-8;
        const double dg =
            (normalConstraintFunction(g + h, l, eps).w
           - normalConstraintFunction(g - h, l, eps).w)/(2*h);
        const double dl =
            (normalConstraintFunction(g, l + h, eps).w
           - normalConstraintFunction(g, l - h, eps).w)/(2*h);
        EXPECT_NEAR(c.dwdg, dg, 1e-6);
        EXPECT_NEAR(c.dwdl, dl, 1e-6);
        EXPECT_GE(c.dwdg, 0);
        EXPECT_GE(c.dwdl, 0);
    }
}


TEST(constraintFunctions, frictionLimitsAndDerivatives)
{
    const double epsT = 1e-8, mu = 0.2, lambda = 3;
    // Sliding: tau = -mu lambda sign(s)
    EXPECT_NEAR(frictionConstraintFunction(0.1, 0, lambda, mu, epsT).v,
                mu*lambda, 1e-6);
    const double tauSlide = -mu*lambda*0.1/std::sqrt(0.01 + epsT);
    EXPECT_NEAR(frictionConstraintFunction(0.1, tauSlide, lambda, mu, epsT).v,
                0, 1e-15);
    // No contact: tau = 0
    EXPECT_EQ(frictionConstraintFunction(0.1, 0, 0, mu, epsT).v, 0);

    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-3e-4, 3e-4);
    for (int k = 0; k < 100; ++k)
    {
        const double s = u(gen), tau = 1e3*u(gen), l = 1e4*std::abs(u(gen));
        const frictionConstraint c =
            frictionConstraintFunction(s, tau, l, mu, epsT);
        const double h = 1e-9;
        const auto v = [&](double ss, double tt, double ll)
        {
            return frictionConstraintFunction(ss, tt, ll, mu, epsT).v;
        };
        EXPECT_NEAR(c.dvds, (v(s + h, tau, l) - v(s - h, tau, l))/(2*h),
                    1e-5*std::max(1.0, std::abs(c.dvds)));
        EXPECT_NEAR(c.dvdl, (v(s, tau, l + h) - v(s, tau, l - h))/(2*h), 1e-6);
        EXPECT_NEAR(c.dvdtau, 1, 0);
    }
}


// The smoothed Alart-Curnier function (constraintFunctions.H): its zero
// set is Coulomb's law (stick s = 0 inside the cone, tau = -mu lambda
// sign(s) outside), and its derivatives match central differences at
// stick, slip, the two transitions (trial force at the cone's edge), the
// knee of the normal law (lambda -> 0) and out of contact
TEST(constraintFunctions, alartCurnierBranchesAndDerivatives)
{
    const double mu = 0.2, lambda = 3, m = mu*lambda, epsT = 1e-8, r = 0.5;
    const auto v = [&](double s, double tau, double l, double eT = 1e-8)
    {
        return alartCurnierFrictionFunction(s, tau, l, mu, eT, r).v;
    };
    // Stick: inside the cone v = r s to the rounding, e/4 (1/(m + x) -
    // 1/(m - x)) with e = r^2 epsT (7e-10 here)
    EXPECT_NEAR(v(0, 0.3*m, lambda), 0, 1e-9);
    EXPECT_NEAR(v(1e-3, 0.3*m, lambda), r*1e-3, 1e-8);
    // Slip: tau = -mu lambda sign(s) whatever tau's trial
    EXPECT_NEAR(v(0.1, -m, lambda), 0, 1e-6*m);
    EXPECT_NEAR(v(-0.1, m, lambda), 0, 1e-6*m);
    EXPECT_NEAR(v(2, 0, lambda), m, 1e-6*m);
    EXPECT_NEAR(v(0.1, 0, lambda), r*0.1, 1e-8);   // trial in the cone
    // Out of contact: v = tau, v_tau = 1
    EXPECT_EQ(v(0.1, 0.25, 0), 0.25);
    EXPECT_EQ(alartCurnierFrictionFunction(0.1, 0.25, 0, mu, epsT, r).dvdtau, 1);
    // A sliding iterate whose slip reverses is classified as stick (the
    // reason for the law): v_s = r there, not ~0 as in the regularised law
    const frictionConstraint reversed =
        alartCurnierFrictionFunction(-0.2*m/r, -m, lambda, mu, epsT, r);
    EXPECT_NEAR(reversed.dvds, r, 1e-6*r);
    EXPECT_LT(frictionConstraintFunction(0.1, -m, lambda, mu, epsT).dvds, 1e-5);
    // A sharp rounding keeps the zero set exact to round-off
    EXPECT_NEAR(v(0.1, -m, lambda, 1e-24), 0, 1e-15);

    // Derivatives: random points near each branch and transition
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    const double w = r*std::sqrt(epsT);   // rounding width in trial force
    struct sample { double s, tau, l; };
    std::vector<sample> samples;
    for (int k = 0; k < 60; ++k)
    {
        const double l = lambda*(1 + 0.5*u(gen));
        const double mk = mu*l;
        const double tau = mk*u(gen);
        // stick (x well inside), slip (x far outside), both edges
        samples.push_back({0.3*mk*u(gen)/r, tau, l});
        samples.push_back({(tau + mk*(2 + u(gen)))/r, tau, l});
        samples.push_back({(tau - mk + 3*w*u(gen))/r, tau, l});
        samples.push_back({(tau + mk + 3*w*u(gen))/r, tau, l});
        // the knee: lambda of the rounding's size
        samples.push_back({3*w*u(gen)/r, 3*w*u(gen), w*std::abs(u(gen))/mu});
    }
    for (const sample& p : samples)
    {
        const frictionConstraint c =
            alartCurnierFrictionFunction(p.s, p.tau, p.l, mu, epsT, r);
        const double hs = 1e-4*w/r, ht = 1e-4*w, hl = 1e-4*w/mu;
        const double ds = (v(p.s + hs, p.tau, p.l) - v(p.s - hs, p.tau, p.l))/(2*hs);
        const double dt = (v(p.s, p.tau + ht, p.l) - v(p.s, p.tau - ht, p.l))/(2*ht);
        const double dl = (v(p.s, p.tau, p.l + hl) - v(p.s, p.tau, p.l - hl))/(2*hl);
        EXPECT_TRUE(test::fdError("alartCurnier v_s", std::abs(c.dvds - ds)/r, 1e-6))
            << "s " << p.s << " tau " << p.tau << " lambda " << p.l;
        EXPECT_TRUE(test::fdError("alartCurnier v_tau", std::abs(c.dvdtau - dt), 1e-6))
            << "s " << p.s << " tau " << p.tau << " lambda " << p.l;
        EXPECT_TRUE(test::fdError("alartCurnier v_lambda", std::abs(c.dvdl - dl)/mu, 1e-6))
            << "s " << p.s << " tau " << p.tau << " lambda " << p.l;
        EXPECT_GE(c.dvdtau, 0);
        EXPECT_GE(c.dvds, 0);
    }
}


//- A 9-node 3 x 1 strip under a filleted punch; pair "top"
struct contactSetup
{
    feMesh mesh;
    std::vector<rigidToolSpec> tools;

    explicit contactSetup(bool forceControlled)
    {
        mesh = structuredQuadMesh
        (
            {{{0, 0}, {3, 0}, {3, 1}, {0, 1}}}, 3, 1, 9, "Q9P3", "steel"
        );
        // Punch above the strip: bottom face from x = -0.5 to 2.2 at y = 1
        // (tool on the left when walking, i.e. above), a fillet of radius
        // 0.4 at x = 2.2, and the side wall rising from it
        rigidToolSpec punch;
        punch.name = "punch";
        punch.profile = std::make_shared<rigidProfile>
        (
            std::vector<Eigen::Vector2d>
            {
                {-0.5, 1.0}, {2.2, 1.0}, {2.2, 3}
            },
            std::vector<double>{0.4}
        );
        if (forceControlled)
        {
            punch.forceControlled = true;
            punch.direction = vec3(0, -1, 0);
            punch.force = [](double t) { return 1e3*t; };
        }
        else
        {
            punch.translation = [](double t)
            {
                return vec3(0.3*t, -0.01*t, 0);
            };
        }
        tools.push_back(punch);
    }

    contactModel model
    (
        double friction,
        double epsN,
        double epsT,
        const std::string& law = contactControls().frictionLaw
    ) const
    {
        contactControls c;
        c.epsilonN = epsN;
        c.epsilonT = epsT;
        c.frictionLaw = law;
        c.maxStatusChanges = 1000;
        return contactModel
        (
            mesh, analysisType::planeStrain, 2e5, tools,
            {{"top", "top", "punch", friction}}, c
        );
    }
};


//- bathe: the slip-rate law of the Bathe scheme's second stage
//  (contactModel::setSlipRateLaw), after a committed first stage that
//  slid the nodes
//  law: the friction law (contactModel.H; default: the default law)
void checkTangent
(
    double friction,
    bool forceControlled,
    bool bathe = false,
    const std::string& law = contactControls().frictionLaw
)
{
    const contactSetup s(forceControlled);
    // eps large enough for central differences to resolve the corner
    contactModel cm = s.model(friction, 1e-6, 1e-6, law);
    const int N = s.mesh.nNodes()*2;
    const int nC = cm.nUnknowns();

    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    vecX U = vecX::Zero(N);
    // Strip pushed up against the punch face and sheared: some nodes in
    // contact, some near the fillet, some away from it
    for (int a = 0; a < s.mesh.nNodes(); ++a)
    {
        U(2*a) = 0.05*s.mesh.X(a, 1) + 0.002*u(gen);
        U(2*a + 1) = 0.004*u(gen) + 0.001;
    }
    test::commitStart(cm, U, bathe);
    vecX x(nC);
    for (int j = 0; j < nC; ++j) x(j) = 2e-3*u(gen);
    cm.addToUnknowns(x - cm.unknowns());

    vecX R0;
    matX K;
    const double t = 0.5;
    test::contactResidual(cm, t, U, R0, &K);

    // Central differences over every nodal dof and unknown
    const double h = 1e-7;
    const matX Kfd = test::contactTangentFD(cm, t, U, h);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0);
    EXPECT_TRUE(test::fdError("contactModel rigid tool", (K - Kfd).cwiseAbs().maxCoeff()/scale, fdTolContactModel))
        << "friction " << friction << " forceControlled " << forceControlled
        << " law " << law;
}


TEST(contactModel, tangentFrictionless)
{
    checkTangent(0, false);
}

TEST(contactModel, tangentWithFriction)
{
    checkTangent(0.3, false);
}

TEST(contactModel, tangentForceControlledTool)
{
    checkTangent(0.2, true);
}

TEST(contactModel, tangentWithFrictionBatheSlipRateLaw)
{
    checkTangent(0.3, false, true);
    checkTangent(0.2, true, true);
}

// Both friction laws, whatever the default
TEST(contactModel, tangentWithEachFrictionLaw)
{
    for (const std::string law : {"alartCurnier", "regularised"})
    {
        checkTangent(0.3, false, false, law);
        checkTangent(0.2, true, true, law);
    }
}

TEST(contactModel, unknownFrictionLawIsAnInputError)
{
    const contactSetup s(false);
    EXPECT_THROW(s.model(0.3, 1e-6, 1e-6, "coulomb"), inputError);
}


// The slip rate of the friction law is the integrator's velocity
// (contactModel.H): a node sliding on the fixed flat ground along
// x(t) = 0.3 t + 2 t^2 (a quadratic, which both formulas below
// differentiate exactly) is stepped with h = 0.1 from t = 0.2 as the
// integrators do: the trapezoidal rule's rate is the mean velocity over
// the step, x'(t + h/2); the Bathe scheme's is, in the first stage (a
// trapezoidal sub-step over gamma h) x'(t + gamma h/2), and in the second
// (three-point Euler backward) the end velocity x'(t + h). The arc
// length xi runs along the outline from x = 10 to x = -10, so the rate is
// -x'
TEST(contactModel, slipRateIsTheIntegratorsVelocity)
{
    const feMesh mesh = structuredQuadMesh
    (
        {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, 1, 1, 4, "Q4", "steel"
    );
    rigidToolSpec ground;
    ground.name = "ground";
    ground.profile = std::make_shared<rigidProfile>
    (
        std::vector<Eigen::Vector2d>{{10, 0}, {-10, 0}},
        std::vector<double>{}
    );
    const auto x = [](double t) { return 0.3*t + 2*t*t; };
    const auto v = [](double t) { return 0.3 + 4*t; };
    const auto U = [&](double t)
    {
        // The bottom nodes slide by x(t), touching the ground
        vecX u = vecX::Zero(2*mesh.nNodes());
        for (int a = 0; a < mesh.nNodes(); ++a) u(2*a) = x(t);
        return u;
    };
    const auto rateAt = [&](contactModel& cm, double t0, double t1)
    {
        vecX fext = vecX::Zero(2*mesh.nNodes()), r;
        cm.evaluate(t1, U(t1), fext, r, nullptr);
        const double rate = cm.pairResults("bottom", U(t1), t1)[0].slipRate;
        cm.commit(U(t1));
        (void)t0;
        return rate;
    };
    const double t0 = 0.2, h = 0.1;
    for (const double gamma : {0.5, 2 - std::sqrt(2.0)})
    {
        contactControls c;
        c.epsilonT = 1e-6;
        contactModel cm
        (
            mesh, analysisType::planeStrain, 2e5, {ground},
            {{"bottom", "bottom", "ground", 0.3}}, c
        );
        cm.beginIncrement(0, t0, U(0));
        rateAt(cm, 0, t0);

        // Trapezoidal step
        cm.setSlipRateLaw(1, 0);
        cm.beginIncrement(t0, t0 + h, U(t0));
        EXPECT_NEAR(rateAt(cm, t0, t0 + h), -v(t0 + h/2), 1e-12);

        // Bathe step: stage 1 to t + gamma h, stage 2 to t + h
        const double t = t0 + h, tm = t + gamma*h;
        cm.setSlipRateLaw(1, 0);
        cm.beginIncrement(t, tm, U(t));
        EXPECT_NEAR(rateAt(cm, t, tm), -v(t + gamma*h/2), 1e-12);
        cm.setSlipRateLaw(2 - gamma, -(1 - gamma)*(1 - gamma)/gamma);
        cm.beginIncrement(tm, t + h, U(tm));
        EXPECT_NEAR(rateAt(cm, tm, t + h), -v(t + h), 1e-12)
            << "gamma " << gamma;
    }

    contactModel cm
    (
        mesh, analysisType::planeStrain, 2e5, {ground},
        {{"bottom", "bottom", "ground", 0.3}}
    );
    EXPECT_THROW(cm.setSlipRateLaw(0, 0), numericalError);
}


TEST(contactModel, forceControlledToolApproachesTheBody)
{
    const contactSetup s(true);
    contactModel cm = s.model(0, 0, 0);
    const int N = s.mesh.nNodes()*2;
    // Lift the tool 2 units above the strip, then begin a step
    vecX lift = vecX::Zero(cm.nUnknowns());
    lift(cm.nUnknowns() - 1) = -2;
    cm.addToUnknowns(lift);
    cm.commit(vecX::Zero(N));
    cm.beginIncrement(0, 0.1, vecX::Zero(N));
    double minGap = 1e30;
    for (const auto& r : cm.pairResults("top", vecX::Zero(N), 0.1))
    {
        minGap = std::min(minGap, r.gap);
    }
    EXPECT_NEAR(minGap, 0, 1e-12);
    EXPECT_NEAR(cm.toolTranslation("punch", 0.1)(1), 0, 1e-12);
}


// The predictor's rule (contactModel::keepCommitted): a multiplier against
// a rigid tool is extrapolated only where its last two increments have the
// same sign; one that alternates, or has no history, keeps its committed
// value; a force-controlled tool's position is always extrapolated
TEST(contactModel, predictorKeepsAlternatingForces)
{
    const contactSetup s(true);
    contactModel cm = s.model(0.2, 0, 0);
    const int nC = cm.nUnknowns();
    ASSERT_GT(nC, 4);
    const int z = nC - 1;
    ASSERT_EQ(cm.unknownName(z), "punch position");
    vecX dx(nC), previous(nC);
    for (int j = 0; j < nC; ++j)
    {
        dx(j) = 0.1*(j + 1);
        // even: same sign as the step before; odd: the sign alternated
        previous(j) = j % 2 == 0 ? 0.05 : -0.05;
    }
    vecX d = dx;
    cm.keepCommitted(d, previous);
    for (int j = 0; j < z; ++j)
    {
        EXPECT_EQ(d(j), j % 2 == 0 ? dx(j) : 0.0) << cm.unknownName(j);
    }
    EXPECT_EQ(d(z), dx(z));
    // No history: every multiplier starts from its committed value
    d = dx;
    cm.keepCommitted(d, vecX());
    EXPECT_EQ(d.head(z).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(d(z), dx(z));
}


// active(): true while a pair acts; false once its tool is released (the
// scene then chooses the energy line search: formScene.C)
TEST(contactModel, releasingEveryToolLeavesNoActivePair)
{
    const contactSetup s(false);
    contactModel cm = s.model(0.2, 0, 0);
    const int N = s.mesh.nNodes()*2;
    EXPECT_TRUE(cm.active());
    EXPECT_FALSE(cm.released("punch"));
    cm.releaseTool("punch", vecX::Zero(N));
    EXPECT_TRUE(cm.released("punch"));
    EXPECT_FALSE(cm.active());
}


TEST(contactModel, toolThatCannotTouchIsAnInputError)
{
    contactSetup s(true);
    s.tools[0].direction = vec3(0, 1, 0);   // moving away
    contactModel cm = s.model(0, 0, 0);
    const int N = s.mesh.nNodes()*2;
    try
    {
        cm.beginIncrement(0, 0.1, vecX::Zero(N));
        FAIL() << "no error";
    }
    catch (const inputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("punch"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("never touch"), std::string::npos);
    }
}


TEST(contactModel, chatteringIsReported)
{
    const contactSetup s(false);
    contactControls c;
    c.maxStatusChanges = 4;
    contactModel cm
    (
        s.mesh, analysisType::planeStrain, 2e5, s.tools,
        {{"top", "top", "punch", 0}}, c
    );
    const int N = s.mesh.nNodes()*2;
    const vecX U = vecX::Zero(N);
    cm.beginIncrement(0, 1, U);
    vecX fext(N), r;
    std::vector<contactModel::triplet> tr;
    bool thrown = false;
    for (int k = 0; k < 10 && !thrown; ++k)
    {
        // Alternate every multiplier between "pressed" and "open"
        const vecX x = vecX::Constant(cm.nUnknowns(), k % 2 ? 1.0 : 0.0);
        cm.addToUnknowns(x - cm.unknowns());
        fext.setZero();
        try
        {
            cm.evaluate(1, U, fext, r, &tr);
        }
        catch (const numericalError& e)
        {
            thrown = true;
            EXPECT_NE(std::string(e.what()).find("chattering"),
                      std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(thrown);
}

} // namespace
