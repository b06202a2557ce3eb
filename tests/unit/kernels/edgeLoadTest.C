// Edge loads: dead traction totals and nodal split (plane strain and the
// 2 pi r weighting of axisymmetric loads), follower pressure direction and
// totals, closed-contour equilibrium and symmetry, and the load stiffness
// K = -df/du against central differences.
#include "solidElement.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolEdgeLoad = 2e-9;
}

using namespace form;

namespace
{
matX edge(std::initializer_list<std::initializer_list<double>> rows)
{
    matX X(rows.size(), 2);
    int i = 0;
    for (const auto& r : rows)
    {
        X(i, 0) = *r.begin();
        X(i, 1) = *(r.begin() + 1);
        ++i;
    }
    return X;
}
}

TEST(edgeLoad, deadTractionPlaneStrain)
{
    // Edge of length 5; consistent split L/2, L/2 (2 nodes) and
    // L/6, L/6, 2L/3 (3 nodes: start, end, middle)
    const Eigen::Vector2d t(2, -1);
    const vecX f2 = edgeLoad::deadTraction(edge({{0, 0}, {3, 4}}), t,
                                           analysisType::planeStrain);
    EXPECT_LT((f2.segment<2>(0) - 2.5*t).norm(), 1e-14);
    EXPECT_LT((f2.segment<2>(2) - 2.5*t).norm(), 1e-14);
    const vecX f3 = edgeLoad::deadTraction
    (
        edge({{0, 0}, {3, 4}, {1.5, 2}}), t, analysisType::planeStrain
    );
    EXPECT_LT((f3.segment<2>(0) - 5.0/6*t).norm(), 1e-14);
    EXPECT_LT((f3.segment<2>(2) - 5.0/6*t).norm(), 1e-14);
    EXPECT_LT((f3.segment<2>(4) - 10.0/3*t).norm(), 1e-14);
}

TEST(edgeLoad, deadTractionAxisymmetricRingWeight)
{
    // Radial edge r = 1..3 at z = 0: total = t 2 pi int r dr = 8 pi t;
    // nodal shares 2 pi int N_a r dr = 2 pi (5/3, 7/3)
    const Eigen::Vector2d t(0.5, 3);
    const vecX f2 = edgeLoad::deadTraction(edge({{1, 0}, {3, 0}}), t,
                                           analysisType::axisymmetric);
    EXPECT_LT((f2.segment<2>(0) - 2*M_PI*5.0/3*t).norm(), 1e-13);
    EXPECT_LT((f2.segment<2>(2) - 2*M_PI*7.0/3*t).norm(), 1e-13);
    const vecX f3 = edgeLoad::deadTraction
    (
        edge({{1, 0}, {3, 0}, {2, 0}}), t, analysisType::axisymmetric
    );
    const Eigen::Vector2d total =
        f3.segment<2>(0) + f3.segment<2>(2) + f3.segment<2>(4);
    EXPECT_LT((total - 8*M_PI*t).norm(), 1e-13);
    // Axial edge at r = 2, z = 0..1: total = t 2 pi 2 * 1
    const vecX fz = edgeLoad::deadTraction(edge({{2, 0}, {2, 1}}), t,
                                           analysisType::axisymmetric);
    EXPECT_LT((fz.segment<2>(0) + fz.segment<2>(2) - 4*M_PI*t).norm(), 1e-13);
}

TEST(edgeLoad, followerPressureDirectionAndTotal)
{
    // Top edge of the body [0,2]x[0,1] run counter-clockwise (2,1)->(0,1):
    // outward normal +y, pressure p pushes down, total -p * 2 (plane)
    const double p = 3;
    vecX f;
    matX K;
    const matX X = edge({{2, 1}, {0, 1}, {1, 1}});
    edgeLoad::followerPressure(X, matX::Zero(3, 2), p,
                               analysisType::planeStrain, f, &K);
    EXPECT_NEAR(f(0) + f(2) + f(4), 0, 1e-14);
    EXPECT_NEAR(f(1) + f(3) + f(5), -2*p, 1e-14);

    // Follows the current edge: after a 90 degree rotation about the origin
    // the force turns with it; magnitude unchanged
    matX u(3, 2);
    for (int a = 0; a < 3; ++a) u.row(a) << -X(a, 1) - X(a, 0), X(a, 0) - X(a, 1);
    edgeLoad::followerPressure(X, u, p, analysisType::planeStrain, f, nullptr);
    EXPECT_NEAR(f(0) + f(2) + f(4), 2*p, 1e-13);
    EXPECT_NEAR(f(1) + f(3) + f(5), 0, 1e-13);

    // Axisymmetric: radial top edge r = 0..2 at z = 1 (run towards the
    // axis): total -p 2 pi int r dr = -4 pi p in z; r taken current
    edgeLoad::followerPressure(X, matX::Zero(3, 2), p,
                               analysisType::axisymmetric, f, nullptr);
    EXPECT_NEAR(f(1) + f(3) + f(5), -4*M_PI*p, 1e-13);
    matX ur = matX::Zero(3, 2);
    ur.col(0).setConstant(1);   // r = 1..3 now: -p 2 pi (9 - 1)/2
    edgeLoad::followerPressure(X, ur, p, analysisType::axisymmetric, f,
                               nullptr);
    EXPECT_NEAR(f(1) + f(3) + f(5), -8*M_PI*p, 1e-12);
}

TEST(edgeLoad, followerPressureOnClosedContourIsSelfEquilibratedAndSymmetric)
{
    // Plane strain: uniform pressure on a closed, deformed Q9 boundary has
    // zero resultant, and its assembled load stiffness is symmetric
    // (pressure loading of a closed volume is conservative: W = -p V)
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> uni(-1, 1);
    const matX X = test::randomQuad<9>(rng, 0, 0, 1);
    const matX u = 0.2*matX::NullaryExpr(9, 2, [&]() { return uni(rng); });
    const auto el = solidElement::New("Q9", analysisType::planeStrain);
    vecX F = vecX::Zero(18);
    matX KK = matX::Zero(18, 18);
    for (int e = 0; e < 4; ++e)
    {
        const std::vector<int> n = el->edgeNodes(e);
        vecX f;
        matX K;
        edgeLoad::followerPressure(test::gather(X, n), test::gather(u, n),
                                   2.5, analysisType::planeStrain, f, &K);
        for (int a = 0; a < 3; ++a)
        {
            F.segment<2>(2*n[a]) += f.segment<2>(2*a);
            for (int b = 0; b < 3; ++b)
            {
                KK.block<2, 2>(2*n[a], 2*n[b]) += K.block<2, 2>(2*a, 2*b);
            }
        }
    }
    EXPECT_NEAR(F(Eigen::seq(0, 17, 2)).sum(), 0, 1e-13);
    EXPECT_NEAR(F(Eigen::seq(1, 17, 2)).sum(), 0, 1e-13);
    EXPECT_LT((KK - KK.transpose()).norm(), 1e-13*KK.norm());
}

TEST(edgeLoad, followerPressureStiffnessMatchesFiniteDifferences)
{
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> uni(-1, 1);
    for (const analysisType a :
         {analysisType::planeStrain, analysisType::axisymmetric})
    {
        for (int n : {2, 3})
        {
            for (int sample = 0; sample < 3; ++sample)
            {
                matX X(n, 2);
                X.row(0) << 1 + 0.3*uni(rng), 0.3*uni(rng);
                X.row(1) << 2 + 0.3*uni(rng), 1 + 0.3*uni(rng);
                if (n == 3)
                {
                    X.row(2) = 0.5*(X.row(0) + X.row(1));
                    X(2, 0) += 0.1*uni(rng);
                    X(2, 1) += 0.1*uni(rng);
                }
                const matX u = 0.3*matX::NullaryExpr(n, 2,
                                   [&]() { return uni(rng); });
                vecX f, fp, fm;
                matX K;
                edgeLoad::followerPressure(X, u, 1.7, a, f, &K);
                matX Kfd(2*n, 2*n);
                const double h = 1e-6;
                for (int j = 0; j < 2*n; ++j)
                {
                    matX up = u, um = u;
                    up(j/2, j % 2) += h;
                    um(j/2, j % 2) -= h;
                    edgeLoad::followerPressure(X, up, 1.7, a, fp, nullptr);
                    edgeLoad::followerPressure(X, um, 1.7, a, fm, nullptr);
                    Kfd.col(j) = -(fp - fm)/(2*h);
                }
                EXPECT_TRUE(test::fdError("edgeLoad follower pressure", test::relErr(K, Kfd), fdTolEdgeLoad))
                    << analysisTypeName(a) << " n=" << n;
            }
        }
    }
}
