// Numerical inf-sup test (Chapelle & Bathe 1993; Bathe FEP sec. 4.5.5;
// shared/reference/BENCHMARKS.md) for the mixed quads, plane strain, on the
// unit square with all boundary displacements zero, N = 2, 4, 8, 16
// elements per side:
//     G phi = lambda S phi,  G = K_pu T^-1 K_pu^T,  beta_h = sqrt(lambda_min)
// with lambda_min the smallest non-zero eigenvalue, T the H1-norm matrix of
// the free displacements and S the pressure L2 mass matrix. Zero eigenvalues
// are pressure modes the displacements cannot see: the constant pressure
// (always, since u = 0 on the whole boundary) and spurious modes.
//
// Mesh families: uniform; "random" (interior vertices moved randomly by up
// to 0.2 h); "mapped" (the uniform mesh mapped piecewise bilinearly from a
// 2x2 coarse mesh whose centre vertex moved by 0.6*(0.4, -0.3): the
// distortion pattern is kept under refinement, elements tend to
// parallelograms).
//
// Values obtained (beta_h for N = 2, 4, 8, 16; zero eigenvalues in []):
//   Q9P3 uniform  0.513 0.503 0.483 0.470  [1 1 1 1]
//   Q9P3 random   0.505 0.503 0.482 0.470  [1 1 1 1]
//   Q9P3 mapped   0.458 0.498 0.482 0.470  [1 1 1 1]
//        -> levels off near 0.47 with no spurious mode: passes (Bathe's 9/3).
//   Q4P1 uniform  0.600 0.366 0.216 0.115  [2 2 2 2]
//        -> the checkerboard spurious mode at every level and beta_h = O(h)
//           for the remaining modes: fails.
//   Q4P1 mapped   0.538 0.098 0.091 0.063  [2 1 1 1]
//        -> distortion turns the checkerboard into a near-zero mode whose
//           beta_h decays with refinement: fails.
//   Q4P1 random   0.594 0.058 0.092 0.109  [2 1 1 1]
//        -> random distortion of fixed relative size damps the checkerboard
//           differently at every level: not monotone, and far below 9/3;
//           recorded, asserted only to stay well below Q9P3.
#include "solidElement.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cstdio>

using namespace form;

namespace
{
struct infSupValue
{
    double beta;
    int nZero;
};

infSupValue infSupOnUnitSquare(const std::string& type, int N,
                               test::distortionType dt, double distortion)
{
    const auto el = solidElement::New(type, analysisType::planeStrain);
    const test::quadMesh mesh =
        test::structuredMesh(el->nNodes(), N, 0, 0, 1, distortion, 3, dt);
    const int nn = mesh.nNodes(), np = el->nPressure();
    const int nP = np*int(mesh.elements.size());

    matX T = matX::Zero(2*nn, 2*nn), Kpu = matX::Zero(nP, 2*nn);
    matX S = matX::Zero(nP, nP);
    for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    {
        const std::vector<int>& nodes = mesh.elements[e];
        const infSupMatrices m = el->infSup(test::gather(mesh.X, nodes));
        for (std::size_t a = 0; a < nodes.size(); ++a)
        {
            for (std::size_t b = 0; b < nodes.size(); ++b)
            {
                T.block<2, 2>(2*nodes[a], 2*nodes[b]) +=
                    m.T.block<2, 2>(2*a, 2*b);
            }
            Kpu.block(np*e, 2*nodes[a], np, 2) += m.Kpu.block(0, 2*a, np, 2);
        }
        S.block(np*e, np*e, np, np) = m.Mp;
    }

    std::vector<bool> onBoundary(nn, false);
    for (int b : mesh.boundaryNodes) onBoundary[b] = true;
    std::vector<int> freeDofs;
    for (int i = 0; i < nn; ++i)
    {
        if (!onBoundary[i]) { freeDofs.push_back(2*i); freeDofs.push_back(2*i + 1); }
    }
    const matX Kf = Kpu(Eigen::all, freeDofs);
    matX G = Kf*T(freeDofs, freeDofs).llt().solve(Kf.transpose());
    G = 0.5*(G + G.transpose());
    Eigen::GeneralizedSelfAdjointEigenSolver<matX> eig(G, S,
                                                       Eigen::EigenvaluesOnly);
    const vecX& lambda = eig.eigenvalues();
    infSupValue v{0, 0};
    const double zero = 1e-10*lambda.maxCoeff();
    while (v.nZero < lambda.size() && lambda(v.nZero) < zero) ++v.nZero;
    v.beta = std::sqrt(lambda(v.nZero));
    return v;
}

std::vector<infSupValue> sequence(const std::string& type,
                                  test::distortionType dt, double distortion)
{
    std::vector<infSupValue> values;
    for (int N : {2, 4, 8, 16})
    {
        values.push_back(infSupOnUnitSquare(type, N, dt, distortion));
        std::printf("    inf-sup %-4s N = %2d: beta_h = %.4f, zero modes %d\n",
                    type.c_str(), N, values.back().beta, values.back().nZero);
    }
    return values;
}
}

TEST(upQuadInfSup, Q9P3PassesUniformAndDistorted)
{
    const std::pair<test::distortionType, double> meshes[] =
    {
        {test::distortionType::random, 0.0},
        {test::distortionType::random, 0.2},
        {test::distortionType::mapped, 0.6}
    };
    for (const auto& [dt, d] : meshes)
    {
        const auto v = sequence("Q9P3", dt, d);
        for (const auto& x : v)
        {
            EXPECT_EQ(x.nZero, 1) << "spurious pressure mode";   // constant
            EXPECT_GT(x.beta, 0.4);
        }
        EXPECT_GT(v[3].beta/v[2].beta, 0.8) << "does not level off";
    }
}

TEST(upQuadInfSup, Q4P1FailsUniformAndDistorted)
{
    // Uniform: constant + checkerboard zero modes, beta_h about halves with h
    const auto u = sequence("Q4P1", test::distortionType::random, 0.0);
    for (std::size_t k = 0; k < u.size(); ++k)
    {
        EXPECT_EQ(u[k].nZero, 2) << "checkerboard mode expected";
        if (k > 0) EXPECT_LT(u[k].beta, 0.7*u[k - 1].beta);
    }
    EXPECT_LT(u.back().beta, 0.6*u.front().beta);

    // Shape-preserving distortion: one near-spurious mode, beta_h decays
    const auto m = sequence("Q4P1", test::distortionType::mapped, 0.6);
    for (std::size_t k = 1; k < m.size(); ++k)
    {
        EXPECT_LT(m[k].beta, m[k - 1].beta);
    }
    EXPECT_LT(m.back().beta, 0.6*m.front().beta);

    // Random distortion: recorded (see above), well below Q9P3's 0.47
    const auto r = sequence("Q4P1", test::distortionType::random, 0.2);
    for (std::size_t k = 1; k < r.size(); ++k) EXPECT_LT(r[k].beta, 0.25);
}
