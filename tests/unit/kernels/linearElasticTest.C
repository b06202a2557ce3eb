// linearElastic: Hooke's law, moduli, and the deviatoric tangent (exact,
// constant) in engineering Voigt form.
#include "linearElastic.H"
#include "formError.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>

using namespace form;

TEST(linearElastic, moduliAndFlags)
{
    const linearElastic m({{"E", 200}, {"nu", 0.25}});
    EXPECT_EQ(m.type(), "linearElastic");
    EXPECT_TRUE(m.geometricallyLinear());
    EXPECT_DOUBLE_EQ(m.shearModulus(), 80);                 // E/(2(1+nu))
    EXPECT_NEAR(m.bulkModulus(), 200/(3*0.5), 1e-12);       // E/(3(1-2nu))
}

TEST(linearElastic, hookeWithElementPressure)
{
    // sigma = tau_dev + kappa tr(eps) I must equal lambda tr(eps) I + 2G eps
    const double E = 210, nu = 0.3;
    const linearElastic m({{"E", E}, {"nu", nu}});
    const double G = E/(2*(1 + nu)), lambda = E*nu/((1 + nu)*(1 - 2*nu));
    std::mt19937 rng(3);
    mat3 H = 0.01*test::randomSym(rng);
    H(0, 1) += 0.004;   // unsymmetric gradient: only sym(H) may count
    const mat3 F = mat3::Identity() + H;
    materialState s0 = m.initialState(), s1;
    mat3 tauDev;
    mat6 c;
    ASSERT_TRUE(m.deviatoric(F, s0, s1, tauDev, c));
    const mat3 eps = 0.5*(H + H.transpose());
    const mat3 sigma = tauDev + m.bulkModulus()*eps.trace()*mat3::Identity();
    const mat3 hooke = lambda*eps.trace()*mat3::Identity() + 2*G*eps;
    EXPECT_LT((sigma - hooke).norm(), 1e-12*hooke.norm());
    EXPECT_NEAR(tauDev.trace(), 0, 1e-14);

    // c maps engineering strains to stress: c eps_v = tau_dev
    EXPECT_LT((c*test::toVoigtStrain(eps) - toVoigtStress(tauDev)).norm(),
              1e-12*tauDev.norm());
    // shear entry is G (not 2G): tau_xy = G gamma_xy
    EXPECT_NEAR(c(3, 3), G, 1e-12);
    EXPECT_NEAR(c(0, 0), 4*G/3, 1e-12);
    EXPECT_NEAR(c(0, 1), -2*G/3, 1e-12);
    EXPECT_LT((c - c.transpose()).norm(), 1e-14);
}
