/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Tests of form::oscillation (oscillation.H): mean, amplitude and
    frequency of a sampled periodic signal over a time window, as Turek &
    Hron (2006) define them, against the signal's own values.
\*---------------------------------------------------------------------------*/
#include "oscillation.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace form;

namespace
{

// m + a sin(2 pi f t + phi) sampled every dt over [0, T]
oscillation sampledSine
(
    double m, double a, double f, double phi, double dt, double T,
    double t0, double t1
)
{
    oscillation o(t0, t1);
    const int n = int(std::lround(T/dt));
    for (int i = 0; i <= n; ++i)
    {
        const double t = i*dt;
        o.add(t, m + a*std::sin(2*M_PI*f*t + phi));
    }
    return o;
}

} // namespace


// A sine of mean 1.48, amplitude 34.38 and frequency 5.3 (FSI3's tip):
// the measures agree with the signal's to the sampling's resolution
TEST(oscillation, SineMeanAmplitudeFrequency)
{
    const double m = 1.48, a = 34.38, f = 5.3, dt = 1e-4;
    const oscillation o = sampledSine(m, a, f, 0.3, dt, 3, 1, 3);
    // max and min of the samples: within a (2 pi f dt)^2/2 of the peaks
    const double peak = a*std::pow(2*M_PI*f*dt, 2)/2;
    EXPECT_NEAR(o.mean(), m, peak);
    EXPECT_NEAR(o.amplitude(), a, peak);
    ASSERT_TRUE(o.hasFrequency());
    EXPECT_NEAR(o.frequency(), f, 1e-6*f);
    // the window holds 10.6 periods and 10 upward crossings (at
    // 5.3 t + 0.3/(2 pi) = 6, ..., 15): 9 whole periods between them
    EXPECT_EQ(o.periods(), 9);
    EXPECT_EQ(o.samples(), 20001);
}


// Only the samples inside the window count: a transient before it (a
// larger, slower swing) changes nothing
TEST(oscillation, OnlyTheWindowCounts)
{
    const double f = 2.0, dt = 1e-3;
    oscillation o(4, 8);
    oscillation ref(4, 8);
    for (int i = 0; i <= 8000; ++i)
    {
        const double t = i*dt;
        const double steady = 0.5 + 2*std::cos(2*M_PI*f*t);
        o.add(t, t < 3.9 ? 50*std::sin(t) : steady);
        ref.add(t, steady);
    }
    EXPECT_EQ(o.samples(), 4001);
    EXPECT_DOUBLE_EQ(o.mean(), ref.mean());
    EXPECT_DOUBLE_EQ(o.amplitude(), ref.amplitude());
    EXPECT_DOUBLE_EQ(o.frequency(), ref.frequency());
    EXPECT_NEAR(o.frequency(), f, 1e-6);
    EXPECT_NEAR(o.mean(), 0.5, 1e-4);
    EXPECT_NEAR(o.amplitude(), 2, 1e-4);
}


// A window holding less than one period has no frequency; an empty one
// no mean either
TEST(oscillation, TooShortAWindow)
{
    const oscillation o = sampledSine(0, 1, 1, 0, 1e-3, 2, 0.2, 0.9);
    EXPECT_FALSE(o.hasFrequency());
    EXPECT_EQ(o.periods(), 0);
    EXPECT_TRUE(o.hasSamples());
    const oscillation none(5, 6);
    EXPECT_FALSE(none.hasSamples());
    EXPECT_FALSE(none.hasFrequency());
}


// A triangle wave (the bar's tip in tests/cases/dynamics.sh: 0 to 2 u_s
// and back in a period of 40): mean u_s, amplitude u_s, frequency 1/40,
// exactly with samples on its corners
TEST(oscillation, TriangleWave)
{
    oscillation o(40, 120);
    for (int i = 0; i <= 480; ++i)
    {
        const double t = 0.25*i;
        const double s = std::fmod(t, 40.0);
        o.add(t, 0.01*(s <= 20 ? s/10 : (40 - s)/10));
    }
    EXPECT_NEAR(o.mean(), 0.01, 1e-15);
    EXPECT_NEAR(o.amplitude(), 0.01, 1e-15);
    EXPECT_NEAR(o.frequency(), 1.0/40, 1e-12);
    EXPECT_EQ(o.periods(), 1);
}


// ************************************************************************* //
