// The vector (3D) smoothed Alart-Curnier friction function
// (constraintFunctions.H): Coulomb's law in the tangent plane. Its zero
// set is stick (s = 0) inside the disc |tau| < mu lambda and slip
// (tau = -mu lambda s/|s|) outside; along any fixed direction it is the
// scalar law; its derivatives match central differences at stick, slip,
// both sides of the cone's edge, around x = 0, at the knee lambda -> 0
// and at the negative multipliers of opening iterates, and out of contact
// v = tau.
#include "constraintFunctions.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include "../fdCheck.H"

using namespace form;

namespace
{
using vec2 = Eigen::Vector2d;
constexpr double mu = 0.2, lambda = 3, m = mu*lambda, epsT = 1e-8, r = 0.5;

vec2 v(const vec2& s, const vec2& tau, double l, double eT = epsT)
{
    return alartCurnierFrictionVector(s, tau, l, mu, eT, r).v;
}
}


TEST(frictionVector, zeroSetIsCoulombsLaw)
{
    // Stick: inside the disc v = r s (to the rounding)
    const vec2 tauIn(0.2*m, -0.1*m);
    EXPECT_LT(v(vec2::Zero(), tauIn, lambda).norm(), 1e-9);
    EXPECT_LT((v(vec2(1e-3, -2e-3), tauIn, lambda) - r*vec2(1e-3, -2e-3)).norm(), 1e-8);
    // Slip in an oblique direction: tau = -m s/|s|, whatever the trial
    const vec2 s(0.3, -0.4);
    EXPECT_LT(v(s, -m*s.normalized(), lambda).norm(), 1e-6*m);
    EXPECT_LT((v(4*s, vec2::Zero(), lambda) - m*s.normalized()).norm(), 1e-6*m);
    // A sharp rounding keeps the zero set exact to round-off
    EXPECT_LT(v(s, -m*s.normalized(), lambda, 1e-24).norm(), 1e-15);
    // Out of contact: v = tau, v_tau = I
    const frictionVector out = alartCurnierFrictionVector(s, tauIn, 0, mu, epsT, r);
    EXPECT_EQ((out.v - tauIn).norm(), 0);
    EXPECT_LT((out.dvdtau - Eigen::Matrix2d::Identity()).norm(), 1e-15);
}

TEST(frictionVector, alongADirectionItIsTheScalarLaw)
{
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 50; ++k)
    {
        const vec2 e = vec2(u(gen), u(gen)).normalized();
        const double s = 3*m/r*u(gen), tau = 2*m*u(gen), l = lambda*(1 + 0.5*u(gen));
        const frictionVector c = alartCurnierFrictionVector(s*e, tau*e, l, mu, epsT, r);
        const frictionConstraint c1 = alartCurnierFrictionFunction(s, tau, l, mu, epsT, r);
        EXPECT_LT((c.v - c1.v*e).norm(), 1e-13) << s << " " << tau;
        // derivatives along e
        EXPECT_NEAR(e.dot(c.dvds*e), c1.dvds, 1e-10);
        EXPECT_NEAR(e.dot(c.dvdtau*e), c1.dvdtau, 1e-10);
        EXPECT_NEAR(e.dot(c.dvdl), c1.dvdl, 1e-10);
    }
}

TEST(frictionVector, derivativesMatchFiniteDifferences)
{
    std::mt19937 gen(13);
    std::uniform_real_distribution<double> u(-1, 1);
    const double w = r*std::sqrt(epsT);
    struct sample { vec2 s, tau; double l; };
    std::vector<sample> samples;
    for (int k = 0; k < 60; ++k)
    {
        const double l = lambda*(1 + 0.5*u(gen));
        const double mk = mu*l;
        const vec2 tau = mk*vec2(u(gen), u(gen))/std::sqrt(2.0);
        const vec2 e = vec2(u(gen), u(gen)).normalized();
        // x = tau - r s: well inside, far outside, both sides of the edge,
        // near zero, and the knee (lambda of the rounding's size)
        const auto sFor = [&](const vec2& x) { return vec2((tau - x)/r); };
        samples.push_back({sFor(0.3*mk*e), tau, l});
        samples.push_back({sFor((2 + u(gen))*mk*e), tau, l});
        samples.push_back({sFor((mk + 3*w*u(gen))*e), tau, l});
        samples.push_back({sFor(3*w*vec2(u(gen), u(gen))), tau, l});
        samples.push_back({3*w*vec2(u(gen), u(gen))/r, 3*w*vec2(u(gen), u(gen)),
                           w*std::abs(u(gen))/mu});
        // A negative multiplier: the iterate of a node that is opening
        // (Newton overshoots lambda below 0; the solution never has it);
        // m = mu lambda < 0 and x on either side of |m| (the derivatives
        // were taken for m >= 0 only before 2026-11-27, found by formFoam
        // -checkTangent on the square cup)
        samples.push_back({sFor(0.3*mk*e), tau, -l});
        samples.push_back({sFor((2 + u(gen))*mk*e), tau, -l});
        samples.push_back({sFor((mk + 3*w*u(gen))*e), tau, -l});
        samples.push_back({sFor(3*w*vec2(u(gen), u(gen))), tau, -w*std::abs(u(gen))/mu});
    }
    for (const sample& p : samples)
    {
        const frictionVector c = alartCurnierFrictionVector(p.s, p.tau, p.l, mu, epsT, r);
        const double hs = 1e-4*w/r, ht = 1e-4*w, hl = 1e-4*w/mu;
        Eigen::Matrix2d ds, dt;
        for (int j = 0; j < 2; ++j)
        {
            vec2 e = vec2::Zero();
            e(j) = 1;
            ds.col(j) = (v(p.s + hs*e, p.tau, p.l) - v(p.s - hs*e, p.tau, p.l))/(2*hs);
            dt.col(j) = (v(p.s, p.tau + ht*e, p.l) - v(p.s, p.tau - ht*e, p.l))/(2*ht);
        }
        const vec2 dl = (v(p.s, p.tau, p.l + hl) - v(p.s, p.tau, p.l - hl))/(2*hl);
        EXPECT_TRUE(test::fdError("frictionVector v_s", (c.dvds - ds).norm()/r, 1e-6))
            << "s " << p.s.transpose() << " tau " << p.tau.transpose() << " l " << p.l;
        EXPECT_TRUE(test::fdError("frictionVector v_tau", (c.dvdtau - dt).norm(), 1e-6))
            << "s " << p.s.transpose() << " tau " << p.tau.transpose() << " l " << p.l;
        EXPECT_TRUE(test::fdError("frictionVector v_lambda", (c.dvdl - dl).norm()/mu, 1e-6))
            << "s " << p.s.transpose() << " tau " << p.tau.transpose() << " l " << p.l;
    }
}
