// stVenantKirchhoff: stress against closed forms (uniaxial stretch, simple
// shear), objectivity, the small-strain limit, and the spatial (Kirchhoff)
// tangent against central differences of tau((I + h D) F), both of the
// deviatoric part the element receives and of the total stress with the
// element's volumetric convention tau = tau_dev + kappa ln J I.
#include "stVenantKirchhoff.H"
#include "linearElastic.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolSvkDev = 5e-9;
constexpr double fdTolSvkTotal = 2e-9;
}

using namespace form;

namespace
{

//- The total Kirchhoff stress of the model (deviatoric + kappa ln J I)
mat3 totalTau(const material& m, const mat3& F)
{
    materialState s0 = m.initialState(), s1;
    mat3 tau;
    mat6 c;
    m.deviatoric(F, s0, s1, tau, c);
    return tau + m.bulkModulus()*std::log(F.determinant())*mat3::Identity();
}

} // namespace


TEST(stVenantKirchhoff, stressClosedForms)
{
    const double E = 1.4e6, nu = 0.4;
    const stVenantKirchhoff m({{"E", E}, {"nu", nu}});
    const double mu = E/(2*(1 + nu)), lambda = E*nu/((1 + nu)*(1 - 2*nu));
    EXPECT_DOUBLE_EQ(m.shearModulus(), mu);
    EXPECT_DOUBLE_EQ(m.bulkModulus(), lambda + 2*mu/3);

    // Uniaxial stretch F = diag(l, 1, 1): E11 = (l^2 - 1)/2,
    // S11 = (lambda + 2 mu) E11, S22 = S33 = lambda E11, tau = F S F^T
    const double l = 1.3;
    mat3 F = mat3::Identity();
    F(0, 0) = l;
    const double E11 = (l*l - 1)/2;
    const mat3 tau = totalTau(m, F);
    EXPECT_NEAR(tau(0, 0), l*l*(lambda + 2*mu)*E11, 1e-9*E);
    EXPECT_NEAR(tau(1, 1), lambda*E11, 1e-9*E);
    EXPECT_NEAR(tau(2, 2), lambda*E11, 1e-9*E);
    EXPECT_NEAR(tau(0, 1), 0, 1e-9*E);

    // Simple shear F = I + g e1 x e2: C = [1 g; g 1 + g^2],
    // E12 = g/2, E22 = g^2/2, tr E = g^2/2
    const double g = 0.4;
    F = mat3::Identity();
    F(0, 1) = g;
    mat3 Eg = mat3::Zero();
    Eg(0, 1) = Eg(1, 0) = g/2;
    Eg(1, 1) = g*g/2;
    const mat3 S = lambda*Eg.trace()*mat3::Identity() + 2*mu*Eg;
    EXPECT_LT((totalTau(m, F) - F*S*F.transpose()).norm(), 1e-9*E);
}

TEST(stVenantKirchhoff, objectivity)
{
    const stVenantKirchhoff m({{"E", 5}, {"nu", 0.3}});
    std::mt19937 rng(17);
    const mat3 F = test::randomF(rng);
    const mat3 Q = test::rotation(vec3(0.3, -1, 2), 2.1);
    const mat3 tau = totalTau(m, F), tauQ = totalTau(m, Q*F);
    EXPECT_LT((tauQ - Q*tau*Q.transpose()).norm(), 1e-13*tau.norm());
}

TEST(stVenantKirchhoff, smallStrainLimitIsLinearElastic)
{
    const parameterMap p{{"E", 70}, {"nu", 0.33}};
    const stVenantKirchhoff svk(p);
    const linearElastic le(p);
    materialState s0, s1;
    mat3 t1, t2;
    mat6 c1, c2;
    svk.deviatoric(mat3::Identity(), s0, s1, t1, c1);
    le.deviatoric(mat3::Identity(), s0, s1, t2, c2);
    EXPECT_LT((c1 - c2).norm(), 1e-13*c2.norm());
    EXPECT_LT(t1.norm(), 1e-14);
}

TEST(stVenantKirchhoff, spatialTangentMatchesFiniteDifferences)
{
    const stVenantKirchhoff m({{"E", 10}, {"nu", 0.35}});
    const double kappa = m.bulkModulus();
    materialState s0 = m.initialState();
    auto tauDevOf = [&](const mat3& F)
    {
        materialState s1;
        mat3 tau;
        mat6 c;
        m.deviatoric(F, s0, s1, tau, c);
        return tau;
    };
    auto tauOf = [&](const mat3& F) { return totalTau(m, F); };
    vec6 m1, iSym;
    m1 << 1, 1, 1, 0, 0, 0;
    iSym << 1, 1, 1, 0.5, 0.5, 0.5;
    std::mt19937 rng(2027);
    for (int k = 0; k < 20; ++k)
    {
        const mat3 F = test::randomF(rng);
        materialState s1;
        mat3 tau;
        mat6 c;
        ASSERT_TRUE(m.deviatoric(F, s0, s1, tau, c));
        EXPECT_TRUE(test::fdError("stVenantKirchhoff deviatoric tangent", test::relErr(c, test::fdSpatialTangent(tauDevOf, F, 1e-5)), fdTolSvkDev))
            << "deviatoric, sample " << k;
        // The element's total tangent c_dev + kappa 1 (x) 1 - 2 p I_sym
        const double p = kappa*std::log(F.determinant());
        mat6 cTotal = c + kappa*m1*m1.transpose();
        cTotal.diagonal() -= 2*p*iSym;
        EXPECT_TRUE(test::fdError("stVenantKirchhoff total tangent", test::relErr(cTotal, test::fdSpatialTangent(tauOf, F, 1e-5)), fdTolSvkTotal))
            << "total, sample " << k;
        // and it is the push-forward of lambda I (x) I + 2 mu I_sym:
        // c = lambda b (x) b + mu (b_ik b_jl + b_il b_jk), symmetric
        EXPECT_LT((cTotal - cTotal.transpose()).norm(), 1e-12*cTotal.norm());
    }
}
