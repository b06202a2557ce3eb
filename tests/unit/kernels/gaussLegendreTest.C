// Gauss-Legendre rules: exact for polynomials of degree <= 2n - 1 on [-1, 1]
// (and its tensor products), and not exact for degree 2n; Gauss-Lobatto
// rules: the end points among theirs, exact to degree 2n - 3, not 2n - 2.
#include "gaussLegendre.H"
#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>

using namespace form;

namespace
{
// int_-1^1 x^k dx
double exactMonomial(int k)
{
    return k % 2 ? 0.0 : 2.0/(k + 1);
}
}

TEST(gaussLegendre, exactUpToDegree2nMinus1)
{
    for (int n = 1; n <= 10; ++n)
    {
        std::vector<double> x, w;
        gaussLegendre1D(n, x, w);
        ASSERT_EQ(int(x.size()), n);
        ASSERT_EQ(int(w.size()), n);
        for (int k = 0; k <= 2*n - 1; ++k)
        {
            double sum = 0;
            for (int q = 0; q < n; ++q) sum += w[q]*std::pow(x[q], k);
            EXPECT_NEAR(sum, exactMonomial(k), 2e-15) << "n=" << n << " k=" << k;
        }
        // Degree 2n is not integrated exactly (it is a Gauss rule, no more)
        double sum = 0;
        for (int q = 0; q < n; ++q) sum += w[q]*std::pow(x[q], 2*n);
        EXPECT_GT(std::abs(sum - exactMonomial(2*n)), 1e-8) << "n=" << n;
    }
}

TEST(gaussLegendre, tensorProductExactForBiDegree2nMinus1)
{
    for (int n = 1; n <= 5; ++n)
    {
        const auto pts = gaussLegendreQuad(n);
        ASSERT_EQ(int(pts.size()), n*n);
        for (int i = 0; i <= 2*n - 1; ++i)
        {
            for (int j = 0; j <= 2*n - 1; ++j)
            {
                double sum = 0;
                for (const auto& p : pts)
                {
                    sum += p.w*std::pow(p.r, i)*std::pow(p.s, j);
                }
                EXPECT_NEAR(sum, exactMonomial(i)*exactMonomial(j), 1e-14)
                    << "n=" << n << " i=" << i << " j=" << j;
            }
        }
    }
}

TEST(gaussLegendre, knownTwoAndThreePointRules)
{
    // Bathe FEP table 5.6
    std::vector<double> x, w;
    gaussLegendre1D(2, x, w);
    EXPECT_NEAR(x[1], 0.577350269189626, 1e-15);
    gaussLegendre1D(3, x, w);
    EXPECT_NEAR(x[2], 0.774596669241483, 1e-15);
    EXPECT_NEAR(w[1], 0.888888888888889, 1e-15);
}

TEST(gaussLegendre, rejectsUnavailableOrder)
{
    std::vector<double> x, w;
    EXPECT_THROW(gaussLegendre1D(0, x, w), std::invalid_argument);
    EXPECT_THROW(gaussLegendre1D(11, x, w), std::invalid_argument);
    EXPECT_THROW(gaussLobatto1D(1, x, w), std::invalid_argument);
    EXPECT_THROW(gaussLobatto1D(11, x, w), std::invalid_argument);
}

TEST(gaussLobatto, endPointsAndExactUpToDegree2nMinus3)
{
    for (int n = 2; n <= 10; ++n)
    {
        std::vector<double> x, w;
        gaussLobatto1D(n, x, w);
        ASSERT_EQ(int(x.size()), n);
        EXPECT_EQ(x.front(), -1);
        EXPECT_EQ(x.back(), 1);
        for (int q = 1; q < n; ++q) EXPECT_GT(x[q], x[q - 1]) << n;
        for (int k = 0; k <= 2*n - 3; ++k)
        {
            double sum = 0;
            for (int q = 0; q < n; ++q) sum += w[q]*std::pow(x[q], k);
            EXPECT_NEAR(sum, exactMonomial(k), 2e-15) << "n=" << n << " k=" << k;
        }
        double sum = 0;
        for (int q = 0; q < n; ++q) sum += w[q]*std::pow(x[q], 2*n - 2);
        EXPECT_GT(std::abs(sum - exactMonomial(2*n - 2)), 1e-8) << "n=" << n;
    }
    // Abramowitz & Stegun table 25.6: n = 5, the interior point
    // 0.654653670707977 with weight 0.544444444444444
    std::vector<double> x, w;
    gaussLobatto1D(5, x, w);
    EXPECT_NEAR(x[3], 0.654653670707977, 1e-15);
    EXPECT_NEAR(w[3], 0.544444444444444, 1e-15);
    EXPECT_NEAR(x[2], 0, 1e-16);
}
