// Lagrange shape functions of the 4- and 9-node quads (VTK order) and the
// 2-/3-node edge functions: partition of unity, Kronecker property at the
// nodes, linear completeness, derivatives against central differences.
#include "quadShape.H"
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

using namespace form;

namespace
{
template<int NN>
void checkQuad()
{
    using S = quadShape<NN>;
    typename S::vecN N, Nh1, Nh2;
    typename S::matN2 dN, dNh;

    // Kronecker property N_a(x_b) = delta_ab
    for (int b = 0; b < NN; ++b)
    {
        S::eval(S::nodeR(b), S::nodeS(b), N, dN);
        for (int a = 0; a < NN; ++a)
        {
            EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15) << "a=" << a << " b=" << b;
        }
    }

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    const double h = 1e-6;
    for (int k = 0; k < 50; ++k)
    {
        const double r = uni(rng), s = uni(rng);
        S::eval(r, s, N, dN);

        // Partition of unity and linear completeness
        double sumN = 0, sumR = 0, sumS = 0;
        for (int a = 0; a < NN; ++a)
        {
            sumN += N(a);
            sumR += N(a)*S::nodeR(a);
            sumS += N(a)*S::nodeS(a);
        }
        EXPECT_NEAR(sumN, 1.0, 1e-14);
        EXPECT_NEAR(sumR, r, 1e-14);
        EXPECT_NEAR(sumS, s, 1e-14);
        EXPECT_NEAR(dN.col(0).sum(), 0.0, 1e-13);
        EXPECT_NEAR(dN.col(1).sum(), 0.0, 1e-13);

        // Central differences
        S::eval(r + h, s, Nh1, dNh);
        S::eval(r - h, s, Nh2, dNh);
        const typename S::vecN dr = (Nh1 - Nh2)/(2*h);
        S::eval(r, s + h, Nh1, dNh);
        S::eval(r, s - h, Nh2, dNh);
        const typename S::vecN ds = (Nh1 - Nh2)/(2*h);
        EXPECT_LT((dr - dN.col(0)).norm(), 1e-9);
        EXPECT_LT((ds - dN.col(1)).norm(), 1e-9);
    }
}
}

TEST(quadShape, Q4PartitionKroneckerDerivatives) { checkQuad<4>(); }
TEST(quadShape, Q9PartitionKroneckerDerivatives) { checkQuad<9>(); }

TEST(quadShape, Q9ReproducesBiquadraticField)
{
    // f = r^2 s^2 + r s - s^2 is in the Q9 space: interpolation is exact
    auto f = [](double r, double s) { return r*r*s*s + r*s - s*s; };
    quadShape<9>::vecN N;
    quadShape<9>::matN2 dN;
    quadShape<9>::eval(0.3, -0.7, N, dN);
    double fi = 0;
    for (int a = 0; a < 9; ++a)
    {
        fi += N(a)*f(quadShape<9>::nodeR(a), quadShape<9>::nodeS(a));
    }
    EXPECT_NEAR(fi, f(0.3, -0.7), 1e-14);
}

TEST(quadShape, lineFunctions)
{
    vecX N, dN, N1, N2;
    for (int n : {2, 3})
    {
        // Nodes: start -1, end +1, [middle 0]
        const double xiNode[3] = {-1, 1, 0};
        for (int b = 0; b < n; ++b)
        {
            lineShape(n, xiNode[b], N, dN);
            for (int a = 0; a < n; ++a)
            {
                EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15);
            }
        }
        const double xi = 0.37, h = 1e-6;
        lineShape(n, xi, N, dN);
        EXPECT_NEAR(N.sum(), 1.0, 1e-15);
        lineShape(n, xi + h, N1, dN);
        lineShape(n, xi - h, N2, dN);
        lineShape(n, xi, N, dN);
        EXPECT_LT(((N1 - N2)/(2*h) - dN).norm(), 1e-9);
    }
    EXPECT_THROW(lineShape(4, 0.0, N, dN), std::invalid_argument);
}


// The run-time entry (point locator, output) gives the values of eval
// exactly; other node counts are an error
TEST(quadShape, valuesByNodeCountAreEval)
{
    quadShape<4>::vecN N4;
    quadShape<4>::matN2 dN4;
    quadShape<9>::vecN N9;
    quadShape<9>::matN2 dN9;
    for (const double r : {-1.0, -0.3, 0.0, 0.77})
    {
        for (const double s : {-0.9, 0.1, 1.0})
        {
            quadShape<4>::eval(r, s, N4, dN4);
            quadShape<9>::eval(r, s, N9, dN9);
            EXPECT_EQ((quadShapeValues(4, r, s) - N4).norm(), 0);
            EXPECT_EQ((quadShapeValues(9, r, s) - N9).norm(), 0);
        }
    }
    EXPECT_THROW(quadShapeValues(8, 0, 0), std::invalid_argument);
}


// Edge k: corner k, corner k+1, mid-side 4+k; the line functions of its
// nodes are the quad's functions restricted to the edge
TEST(quadShape, edgeNodeTableMatchesTheLineFunctions)
{
    EXPECT_EQ(quadEdgeNodes(4, 3), (std::vector<int>{3, 0}));
    EXPECT_EQ(quadEdgeNodes(9, 1), (std::vector<int>{1, 2, 5}));
    EXPECT_THROW(quadEdgeNodes(9, 4), std::invalid_argument);
    EXPECT_THROW(quadEdgeNodes(6, 0), std::invalid_argument);
    // Edge parameter xi runs from the edge's start to its end corner
    const double xi = 0.37;
    for (int edge = 0; edge < 4; ++edge)
    {
        const std::vector<int> en = quadEdgeNodes(9, edge);
        const double r0 = quadShape<9>::nodeR(en[0]);
        const double s0 = quadShape<9>::nodeS(en[0]);
        const double r1 = quadShape<9>::nodeR(en[1]);
        const double s1 = quadShape<9>::nodeS(en[1]);
        const double r = 0.5*(1 - xi)*r0 + 0.5*(1 + xi)*r1;
        const double s = 0.5*(1 - xi)*s0 + 0.5*(1 + xi)*s1;
        const vecX N = quadShapeValues(9, r, s);
        vecX L, dL;
        lineShape(3, xi, L, dL);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(N(en[a]), L(a), 1e-14);
        EXPECT_NEAR(N.sum(), 1, 1e-14);
    }
}
