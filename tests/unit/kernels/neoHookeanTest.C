// neoHookean: stress against closed forms, objectivity, small-strain limit,
// and the spatial (Kirchhoff) tangent against central differences of
// tau((I + h D) F) at random large-deformation F (det F in [0.7, 1.4],
// rotations included): (tau(F+) - tau(F-))/(2h) - (D tau + tau D) = c : D.
#include "neoHookean.H"
#include "linearElastic.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolNhDev = 5e-10;
constexpr double fdTolNhTotal = 5e-10;
}

using namespace form;


TEST(neoHookean, stressClosedForms)
{
    const neoHookean m({{"E", 3}, {"nu", 0.25}});
    const double G = m.shearModulus();
    EXPECT_DOUBLE_EQ(G, 1.2);
    EXPECT_DOUBLE_EQ(m.bulkModulus(), 2);
    EXPECT_FALSE(m.geometricallyLinear());
    materialState s0 = m.initialState(), s1;
    mat3 tau;
    mat6 c;

    // Simple shear F = I + g e1 x e2 (J = 1): tau_xy = G g,
    // tau_xx = 2/3 G g^2, tau_yy = tau_zz = -1/3 G g^2
    const double g = 0.7;
    mat3 F = mat3::Identity();
    F(0, 1) = g;
    ASSERT_TRUE(m.deviatoric(F, s0, s1, tau, c));
    EXPECT_NEAR(tau(0, 1), G*g, 1e-14);
    EXPECT_NEAR(tau(0, 0), 2.0/3*G*g*g, 1e-14);
    EXPECT_NEAR(tau(1, 1), -1.0/3*G*g*g, 1e-14);
    EXPECT_NEAR(tau(2, 2), -1.0/3*G*g*g, 1e-14);

    // Pure dilatation: bbar = I, no deviatoric stress
    ASSERT_TRUE(m.deviatoric(1.3*mat3::Identity(), s0, s1, tau, c));
    EXPECT_LT(tau.norm(), 1e-14);
}

TEST(neoHookean, objectivity)
{
    const neoHookean m({{"E", 5}, {"nu", 0.3}});
    std::mt19937 rng(11);
    const mat3 F = test::randomF(rng);
    const mat3 Q = test::rotation(vec3(0.3, -1, 2), 2.1);
    materialState s0 = m.initialState(), s1;
    mat3 tau, tauQ;
    mat6 c, cQ;
    m.deviatoric(F, s0, s1, tau, c);
    m.deviatoric(Q*F, s0, s1, tauQ, cQ);
    EXPECT_LT((tauQ - Q*tau*Q.transpose()).norm(), 1e-13*tau.norm());
}

TEST(neoHookean, smallStrainLimitIsLinearElastic)
{
    const parameterMap p{{"E", 70}, {"nu", 0.33}};
    const neoHookean nh(p);
    const linearElastic le(p);
    materialState s0, s1;
    mat3 t1, t2;
    mat6 c1, c2;
    nh.deviatoric(mat3::Identity(), s0, s1, t1, c1);
    le.deviatoric(mat3::Identity(), s0, s1, t2, c2);
    EXPECT_LT((c1 - c2).norm(), 1e-13*c2.norm());
}

TEST(neoHookean, spatialTangentMatchesFiniteDifferences)
{
    const neoHookean m({{"E", 10}, {"nu", 0.35}});
    materialState s0 = m.initialState();
    auto tauOf = [&](const mat3& F)
    {
        materialState s1;
        mat3 tau;
        mat6 c;
        m.deviatoric(F, s0, s1, tau, c);
        return tau;
    };
    std::mt19937 rng(2024);
    for (int k = 0; k < 20; ++k)
    {
        const mat3 F = test::randomF(rng);
        ASSERT_GT(F.determinant(), 0.7 - 1e-12);
        ASSERT_LT(F.determinant(), 1.4 + 1e-12);
        materialState s1;
        mat3 tau;
        mat6 c;
        ASSERT_TRUE(m.deviatoric(F, s0, s1, tau, c));
        const mat6 cFD = test::fdSpatialTangent(tauOf, F, 1e-5);
        EXPECT_TRUE(test::fdError("neoHookean deviatoric tangent", test::relErr(c, cFD), fdTolNhDev)) << "sample " << k;

        // Random symmetric direction, engineering Voigt
        const mat3 D = test::randomSym(rng);
        const double h = 1e-5;
        const mat3 dtau = (tauOf((mat3::Identity() + h*D)*F)
                         - tauOf((mat3::Identity() - h*D)*F))/(2*h);
        const vec6 lie = toVoigtStress(dtau - D*tau - tau*D);
        EXPECT_LT((c*test::toVoigtStrain(D) - lie).norm(), 1e-6*lie.norm());
    }
}

TEST(neoHookean, volumetricTangentConventionOfDisplacementElements)
{
    // Displacement elements use tau = tau_dev + kappa ln J I with
    // c = c_dev + kappa 1 (x) 1 - 2 p I_sym (material.H, upQuad.H):
    // check this total spatial tangent by finite differences too
    const neoHookean m({{"E", 4}, {"nu", 0.45}});
    const double kappa = m.bulkModulus();
    materialState s0 = m.initialState();
    auto tauOf = [&](const mat3& F)
    {
        materialState s1;
        mat3 tau;
        mat6 c;
        m.deviatoric(F, s0, s1, tau, c);
        return mat3(tau + kappa*std::log(F.determinant())*mat3::Identity());
    };
    std::mt19937 rng(5);
    vec6 m1, iSym;
    m1 << 1, 1, 1, 0, 0, 0;
    iSym << 1, 1, 1, 0.5, 0.5, 0.5;
    for (int k = 0; k < 10; ++k)
    {
        const mat3 F = test::randomF(rng);
        materialState s1;
        mat3 tau;
        mat6 c;
        m.deviatoric(F, s0, s1, tau, c);
        const double p = kappa*std::log(F.determinant());
        c += kappa*m1*m1.transpose();
        c.diagonal() -= 2*p*iSym;
        EXPECT_TRUE(test::fdError("neoHookean total tangent", test::relErr(c, test::fdSpatialTangent(tauOf, F, 1e-5)), fdTolNhTotal));
    }
}
