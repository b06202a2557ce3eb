// Face loads of 3D elements: the follower pressure on a 4- or 9-node face
// (direction and total on a flat face, zero resultant and a symmetric
// load stiffness on the closed, deformed surface of a hexahedron: the
// pressure load of a closed volume is conservative, W = -p V) and its
// load stiffness K = -df/du against central differences; the same for
// 3-node triangles (MITC3+ mid-surfaces) on a flat triangle and the
// closed surface of a deformed tetrahedron.
#include "solidElement.H"
#include "hexShape.H"
#include "formError.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include "../fdCheck.H"

// Finite-difference tolerance (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints the margin)
namespace
{
constexpr double fdTolFaceLoad = 2e-9;
}

using namespace form;

namespace
{

matX gather3(const matX& X, const std::vector<int>& n)
{
    matX Y(n.size(), 3);
    for (std::size_t a = 0; a < n.size(); ++a) Y.row(a) = X.row(n[a]);
    return Y;
}

// A distorted 27-node hexahedron: the reference cube [0,1]^3 with its
// nodes moved smoothly (curved faces)
matX distortedHex27(std::mt19937& rng, double amount)
{
    std::uniform_real_distribution<double> uni(-1, 1);
    matX X(27, 3);
    const double a = amount*uni(rng), b = amount*uni(rng), c = amount*uni(rng);
    for (int k = 0; k < 27; ++k)
    {
        const Eigen::Vector3d xi = hexShape<27>::node(k);
        Eigen::Vector3d p = 0.5*(xi.array() + 1).matrix();
        p(0) += a*std::sin(2*p(1)) + 0.1*p(2);
        p(1) += b*p(0)*p(2);
        p(2) += c*std::cos(p(0) + p(1));
        X.row(k) = p.transpose();
    }
    return X;
}

} // anonymous namespace


TEST(faceLoad, followerPressureDirectionAndTotal)
{
    // Flat 3 x 2 face in the plane z = 1, corners counter-clockwise seen
    // from +z: outward normal +z, total force -p A e_z for both orders
    for (const int n : {4, 9})
    {
        matX X(n, 3);
        X.row(0) << 0, 0, 1;
        X.row(1) << 3, 0, 1;
        X.row(2) << 3, 2, 1;
        X.row(3) << 0, 2, 1;
        if (n == 9)
        {
            for (int k = 0; k < 4; ++k)
            {
                X.row(4 + k) = 0.5*(X.row(k) + X.row((k + 1) % 4));
            }
            X.row(8) = X.topRows(4).colwise().mean();
        }
        vecX f;
        faceLoad::followerPressure(X, matX::Zero(n, 3), 2.0, f, nullptr);
        Eigen::Vector3d F = Eigen::Vector3d::Zero();
        for (int a = 0; a < n; ++a) F += f.segment<3>(3*a);
        EXPECT_LT((F - Eigen::Vector3d(0, 0, -12)).norm(), 1e-13) << n;
        // Dead and follower loads agree on the undeformed face
        const vecX fd = faceLoad::deadTraction(X, Eigen::Vector3d(0, 0, -2));
        EXPECT_LT((f - fd).norm(), 1e-13) << n;
    }
}

TEST(faceLoad, followerPressureOnClosedSurfaceIsSelfEquilibratedAndSymmetric)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> uni(-1, 1);
    for (const int nn : {8, 27})
    {
        const matX X27 = distortedHex27(rng, 0.2);
        matX X = nn == 27 ? X27 : matX(X27.topRows(8));
        const matX u = 0.15*matX::NullaryExpr(nn, 3, [&]() { return uni(rng); });
        vecX F = vecX::Zero(3*nn);
        matX KK = matX::Zero(3*nn, 3*nn);
        for (int face = 0; face < 6; ++face)
        {
            const std::vector<int> n = hexFaceNodes(nn, face);
            vecX f;
            matX K;
            faceLoad::followerPressure(gather3(X, n), gather3(u, n), 2.5, f, &K);
            for (std::size_t a = 0; a < n.size(); ++a)
            {
                F.segment<3>(3*n[a]) += f.segment<3>(3*a);
                for (std::size_t b = 0; b < n.size(); ++b)
                {
                    KK.block<3, 3>(3*n[a], 3*n[b]) += K.block<3, 3>(3*a, 3*b);
                }
            }
        }
        for (int i = 0; i < 3; ++i)
        {
            EXPECT_NEAR(F(Eigen::seq(i, 3*nn - 1, 3)).sum(), 0, 1e-12) << nn;
        }
        EXPECT_LT((KK - KK.transpose()).norm(), 1e-12*KK.norm()) << nn;
    }
}

TEST(faceLoad, followerPressureStiffnessMatchesFiniteDifferences)
{
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> uni(-1, 1);
    for (const int nn : {8, 27})
    {
        for (int sample = 0; sample < 3; ++sample)
        {
            const matX X27 = distortedHex27(rng, 0.3);
            const matX Xh = nn == 27 ? X27 : matX(X27.topRows(8));
            const std::vector<int> nodes = hexFaceNodes(nn, sample % 6);
            const matX X = gather3(Xh, nodes);
            const int n = int(nodes.size());
            const matX u = 0.3*matX::NullaryExpr(n, 3, [&]() { return uni(rng); });
            vecX f, fp, fm;
            matX K;
            faceLoad::followerPressure(X, u, 1.7, f, &K);
            matX Kfd(3*n, 3*n);
            const double h = 1e-6;
            for (int j = 0; j < 3*n; ++j)
            {
                matX up = u, um = u;
                up(j/3, j % 3) += h;
                um(j/3, j % 3) -= h;
                faceLoad::followerPressure(X, up, 1.7, fp, nullptr);
                faceLoad::followerPressure(X, um, 1.7, fm, nullptr);
                Kfd.col(j) = -(fp - fm)/(2*h);
            }
            EXPECT_TRUE(test::fdError("faceLoad follower pressure", test::relErr(K, Kfd), fdTolFaceLoad))
                << "face of " << nn << " nodes, sample " << sample;
        }
    }
}

TEST(faceLoad, followerPressureRejectsWrongShapes)
{
    vecX f;
    EXPECT_THROW
    (
        faceLoad::followerPressure(matX::Zero(5, 3), matX::Zero(5, 3), 1, f, nullptr),
        numericalError
    );
    EXPECT_THROW
    (
        faceLoad::followerPressure(matX::Zero(4, 3), matX::Zero(4, 2), 1, f, nullptr),
        numericalError
    );
}

TEST(faceLoad, followerPressureOnTriangles)
{
    // A flat triangle in z = 1, counter-clockwise from +z: area 3, the
    // total -p A e_z, a third at each corner, dead = follower undeformed
    matX X(3, 3);
    X << 0, 0, 1, 3, 0, 1, 1, 2, 1;
    vecX f;
    faceLoad::followerPressure(X, matX::Zero(3, 3), 2.0, f, nullptr);
    for (int a = 0; a < 3; ++a)
    {
        EXPECT_LT((f.segment<3>(3*a) - Eigen::Vector3d(0, 0, -2.0)).norm(), 1e-13);
    }
    EXPECT_LT((f - faceLoad::deadTraction(X, Eigen::Vector3d(0, 0, -2))).norm(), 1e-13);

    // The closed surface of a deformed tetrahedron (faces outward):
    // self-equilibrated, symmetric load stiffness; each face's stiffness
    // against central differences
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    matX T(4, 3);
    T << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    const matX u = 0.2*matX::NullaryExpr(4, 3, [&]() { return uni(rng); });
    const std::vector<std::vector<int>> faces =
        {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    vecX F = vecX::Zero(12);
    matX KK = matX::Zero(12, 12);
    for (const std::vector<int>& n : faces)
    {
        vecX fe;
        matX K;
        const matX Xf = gather3(T, n), uf = gather3(u, n);
        faceLoad::followerPressure(Xf, uf, 1.3, fe, &K);
        matX Kfd(9, 9);
        const double h = 1e-6;
        for (int j = 0; j < 9; ++j)
        {
            matX up = uf, um = uf;
            vecX fp, fm;
            up(j/3, j % 3) += h;
            um(j/3, j % 3) -= h;
            faceLoad::followerPressure(Xf, up, 1.3, fp, nullptr);
            faceLoad::followerPressure(Xf, um, 1.3, fm, nullptr);
            Kfd.col(j) = -(fp - fm)/(2*h);
        }
        EXPECT_TRUE(test::fdError("faceLoad follower pressure, triangle", test::relErr(K, Kfd), fdTolFaceLoad));
        for (int a = 0; a < 3; ++a)
        {
            F.segment<3>(3*n[a]) += fe.segment<3>(3*a);
            for (int b = 0; b < 3; ++b)
            {
                KK.block<3, 3>(3*n[a], 3*n[b]) += K.block<3, 3>(3*a, 3*b);
            }
        }
    }
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(F(Eigen::seq(i, 11, 3)).sum(), 0, 1e-13);
    }
    EXPECT_LT((KK - KK.transpose()).norm(), 1e-12*KK.norm());
}
