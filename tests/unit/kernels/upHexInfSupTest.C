// Numerical inf-sup test in 3D (Chapelle & Bathe 1993; Bathe FEP sec.
// 4.5.5) for the mixed hexahedra on the unit cube with all boundary
// displacements zero, N = 2, 3, 4, 5 elements per side:
//     G phi = lambda S phi,  G = K_pu T^-1 K_pu^T,  beta_h = sqrt(lambda_min)
// with lambda_min the smallest non-zero eigenvalue (T: H1-norm matrix of
// the free displacements, S: pressure L2 mass). Zero eigenvalues are
// pressure modes the displacements cannot see: the constant pressure
// (always, u = 0 on the boundary) and spurious modes.
// Meshes: uniform, and "random" (interior vertices moved randomly by up
// to 0.15 h; mid-edge, mid-face and centre nodes at the means of their
// vertices, so the cells stay trilinear).
// The values are printed in the Alltest log. Obtained (2026-11-26; beta_h
// for N = 2, 3, 4, 5, zero modes in []):
//   Hex27P4 uniform    0.393 0.391 0.383 0.378  [1 1 1 1]
//   Hex27P4 random     0.390 0.391 0.383 0.377  [1 1 1 1]
//        -> levels off near 0.38 with the constant mode only: passes (27/4,
//           like the 9/3 in 2D, tests/unit/kernels/upQuadInfSupTest.C)
//   Hex8P1  uniform    0.427 0.253 0.177 0.127  [5 8 11 14]
//        -> spurious (checkerboard-type) modes, more with every level, and
//           beta_h falling like h: fails
//   Hex8P1  random     0.425 0.006 0.012 0.011  [5 3 1 1]
//        -> distortion turns the spurious modes into near-zero ones: fails
#include "solidElement.H"
#include "hexShape.H"
#include <gtest/gtest.h>
#include <cstdio>
#include <map>
#include <random>

using namespace form;

namespace
{
struct infSupValue
{
    double beta;
    int nZero;
};

infSupValue infSupOnUnitCube(const std::string& type, int N, double distortion)
{
    const auto el = solidElement::New(type, analysisType::solid3D);
    const int order = el->nNodes() == 27 ? 2 : 1;
    const int M = order*N + 1;                 // grid points per side
    const auto id = [M](int i, int j, int k) { return i + M*(j + M*k); };
    const int nn = M*M*M;

    // Vertices (grid points with indices multiple of order), distorted
    matX V(nn, 3);
    std::mt19937 rng(2024 + N);
    std::uniform_real_distribution<double> uni(-1, 1);
    const double h = 1.0/N;
    for (int k = 0; k < M; ++k)
    for (int j = 0; j < M; ++j)
    for (int i = 0; i < M; ++i)
    {
        V.row(id(i, j, k)) << double(i)/(M - 1), double(j)/(M - 1),
            double(k)/(M - 1);
        const bool vertex = i % order == 0 && j % order == 0 && k % order == 0;
        const bool interior =
            i > 0 && j > 0 && k > 0 && i < M - 1 && j < M - 1 && k < M - 1;
        if (vertex && interior)
        {
            for (int c = 0; c < 3; ++c) V(id(i, j, k), c) += distortion*h*uni(rng);
        }
    }
    // Higher-order nodes at the means of their cell's vertices along the
    // odd index directions
    matX X = V;
    if (order == 2)
    {
        for (int k = 0; k < M; ++k)
        for (int j = 0; j < M; ++j)
        for (int i = 0; i < M; ++i)
        {
            const int oi = i % 2, oj = j % 2, ok = k % 2;
            if (!oi && !oj && !ok) continue;
            Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
            int n = 0;
            for (int di : {-oi, oi}) for (int dj : {-oj, oj}) for (int dk : {-ok, ok})
            {
                x += V.row(id(i + di, j + dj, k + dk));
                ++n;
            }
            X.row(id(i, j, k)) = x/n;
        }
    }

    const int np = el->nPressure();
    const int nE = N*N*N;
    const int nP = np*nE;
    matX T = matX::Zero(3*nn, 3*nn), Kpu = matX::Zero(nP, 3*nn);
    matX S = matX::Zero(nP, nP);
    int e = 0;
    for (int ek = 0; ek < N; ++ek)
    for (int ej = 0; ej < N; ++ej)
    for (int ei = 0; ei < N; ++ei, ++e)
    {
        std::vector<int> nodes(el->nNodes());
        matX Xe(el->nNodes(), 3);
        for (int a = 0; a < el->nNodes(); ++a)
        {
            const Eigen::Vector3d xi = hexShape<27>::node(a);
            const int gi = order*ei + int(std::lround(0.5*order*(1 + xi(0))));
            const int gj = order*ej + int(std::lround(0.5*order*(1 + xi(1))));
            const int gk = order*ek + int(std::lround(0.5*order*(1 + xi(2))));
            nodes[a] = id(gi, gj, gk);
            Xe.row(a) = X.row(nodes[a]);
        }
        const infSupMatrices m = el->infSup(Xe);
        for (std::size_t a = 0; a < nodes.size(); ++a)
        {
            for (std::size_t b = 0; b < nodes.size(); ++b)
            {
                T.block<3, 3>(3*nodes[a], 3*nodes[b]) +=
                    m.T.block<3, 3>(3*a, 3*b);
            }
            Kpu.block(np*e, 3*nodes[a], np, 3) += m.Kpu.block(0, 3*a, np, 3);
        }
        S.block(np*e, np*e, np, np) = m.Mp;
    }

    std::vector<int> freeDofs;
    for (int k = 1; k < M - 1; ++k)
    for (int j = 1; j < M - 1; ++j)
    for (int i = 1; i < M - 1; ++i)
    {
        for (int c = 0; c < 3; ++c) freeDofs.push_back(3*id(i, j, k) + c);
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

std::vector<infSupValue> sequence(const std::string& type, double distortion)
{
    std::vector<infSupValue> values;
    for (int N : {2, 3, 4, 5})
    {
        values.push_back(infSupOnUnitCube(type, N, distortion));
        std::printf
        (
            "    inf-sup %-7s distortion %.2f N = %d: beta_h = %.4f,"
            " zero modes %d\n", type.c_str(), distortion, N,
            values.back().beta, values.back().nZero
        );
    }
    return values;
}
}

TEST(upHexInfSup, Hex27P4PassesUniformAndDistorted)
{
    for (const double d : {0.0, 0.15})
    {
        const auto v = sequence("Hex27P4", d);
        for (const auto& x : v)
        {
            EXPECT_EQ(x.nZero, 1) << "spurious pressure mode";   // constant
            EXPECT_GT(x.beta, 0.3);
        }
        EXPECT_GT(v[2].beta/v[1].beta, 0.9) << "does not level off";
    }
}

TEST(upHexInfSup, Hex8P1Fails)
{
    // Uniform: spurious modes at every level, more with refinement, and
    // beta_h of the rest falling
    const auto u = sequence("Hex8P1", 0.0);
    for (std::size_t k = 0; k < u.size(); ++k)
    {
        EXPECT_GT(u[k].nZero, 1) << "spurious modes expected";
        if (k > 0)
        {
            EXPECT_GT(u[k].nZero, u[k - 1].nZero);
            EXPECT_LT(u[k].beta, 0.8*u[k - 1].beta);
        }
    }
    // Distorted: the spurious modes become near-zero ones
    const auto r = sequence("Hex8P1", 0.15);
    for (std::size_t k = 1; k < r.size(); ++k) EXPECT_LT(r[k].beta, 0.05);
}
