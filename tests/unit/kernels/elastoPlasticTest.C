// elastoPlastic (finite strain, Hencky elasticity, exponential map):
// - consistent spatial tangent against central differences of
//   tau((I + h D) F) at plastically deformed states, for von Mises / Hill,
//   isotropic / kinematic / mixed hardening, and one-step increments of 0.5;
// - homogeneous (single-element) uniaxial tension: true stress against log
//   plastic strain reproduces the Swift curve up to eps = 1;
// - symmetric tangent except with Armstrong-Frederick hardening;
// - Hill'48 tensile tests at 0/45/90 degrees recover r0, r45, r90;
// - Armstrong-Frederick tension-compression: back stress against the
//   closed form, Bauschinger effect;
// - objectivity: rotating a plastically deformed point by 90 degrees in
//   large steps keeps the invariants and rotates the stress;
// - small strains: agrees with the small-strain kernel;
// - secondPiola (S and dS/dE formed in log space, the shells' path):
//   the pulled-back response of the default path, and central
//   differences of S.
// The homogeneous driver solves the lateral stretches for zero lateral
// Kirchhoff stress (tau = tau_dev + kappa ln J I) by Newton with a
// finite-difference Jacobian.
#include "elastoPlastic.H"
#include "logStrain.H"
#include "kernelTestTools.H"
#include "materialTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolElastoPlastic = 2e-6;
}

using namespace form;
using namespace form::test;

namespace
{

//- Full Kirchhoff stress of the model at F (deviatoric + kappa ln J)
mat3 tauFull(const material& m, const mat3& F, const materialState& s0,
             materialState& s1)
{
    mat3 tau;
    mat6 c;
    EXPECT_TRUE(m.deviatoric(F, s0, s1, tau, c));
    return tau + m.bulkModulus()*std::log(F.determinant())*mat3::Identity();
}

//- Homogeneous uniaxial Kirchhoff-stress state along the unit vector d:
//  F = R diag-free symmetric stretch; the 5 components of U other than
//  d.U.d are solved so that tau has only its d-d component. Updates the
//  state; returns F.
struct uniaxialDriver
{
    const material& m;
    vec3 d;
    materialState state;
    mat3 U = mat3::Identity();

    uniaxialDriver(const material& mat, const vec3& dir)
    : m(mat), d(dir.normalized()), state(mat.initialState()) {}

    //- Basis with e0 = d
    mat3 basis() const
    {
        vec3 a = std::abs(d(2)) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0);
        vec3 e1 = a.cross(d).normalized();
        vec3 e2 = d.cross(e1);
        mat3 Q;
        Q.col(0) = d; Q.col(1) = e1; Q.col(2) = e2;
        return Q;
    }

    //- Stretch along d to lambda (one step), solving the lateral state
    bool step(double lambda, mat3& tauOut, int maxIt = 50)
    {
        const mat3 Q = basis();
        // Unknowns: local stretch components (11, 22, 12, 02, 01) except 00
        mat3 Ul = Q.transpose()*U*Q;
        Ul(0, 0) = lambda;
        auto residual = [&](const mat3& ul, materialState& s1)
        {
            const mat3 tau = Q.transpose()*tauFull(m, Q*ul*Q.transpose(),
                                                   state, s1)*Q;
            Eigen::Matrix<double, 5, 1> r;
            r << tau(1, 1), tau(2, 2), tau(1, 2), tau(0, 2), tau(0, 1);
            return r;
        };
        auto setX = [](mat3& ul, const Eigen::Matrix<double, 5, 1>& x)
        {
            ul(1, 1) = x(0); ul(2, 2) = x(1);
            ul(1, 2) = ul(2, 1) = x(2);
            ul(0, 2) = ul(2, 0) = x(3);
            ul(0, 1) = ul(1, 0) = x(4);
        };
        Eigen::Matrix<double, 5, 1> x;
        x << Ul(1, 1), Ul(2, 2), Ul(1, 2), Ul(0, 2), Ul(0, 1);
        // Incompressible guess for the lateral stretches
        if (x(0) == 1 && x(1) == 1)
        {
            x(0) = x(1) = 1/std::sqrt(lambda);
        }
        materialState s1;
        for (int it = 0; it < maxIt; ++it)
        {
            setX(Ul, x);
            const auto r = residual(Ul, s1);
            if (r.norm() < 1e-9*(1 + m.shearModulus()*1e-6))
            {
                U = Q*Ul*Q.transpose();
                tauOut = tauFull(m, U, state, s1);
                state = s1;
                return true;
            }
            Eigen::Matrix<double, 5, 5> J;
            for (int k = 0; k < 5; ++k)
            {
                const double h = 1e-7;
                Eigen::Matrix<double, 5, 1> xp = x, xm = x;
                xp(k) += h; xm(k) -= h;
                mat3 up = Ul, um = Ul;
                setX(up, xp); setX(um, xm);
                materialState sp, sm;
                J.col(k) = (residual(up, sp) - residual(um, sm))/(2*h);
            }
            x -= J.partialPivLu().solve(r);
        }
        return false;
    }
};

//- Plastic log strain E_p from the history
mat3 plasticLogStrain(const materialState& s)
{
    const vec6 v = s.history.segment<6>(0);
    mat3 e;
    e << v(0), v(3)/2, v(5)/2,
         v(3)/2, v(1), v(4)/2,
         v(5)/2, v(4)/2, v(2);
    return e;
}

} // anonymous namespace


TEST(elastoPlastic, registeredWithCheckedInput)
{
    EXPECT_NE(material::validTypes().find("elastoPlastic"), std::string::npos);
    materialInput in = input(200e3, 0.3, swift(500, 0.01, 0.2));
    EXPECT_EQ(material::New("elastoPlastic", in)->type(), "elastoPlastic");
    EXPECT_TRUE(material::New("elastoPlastic", in)->symmetricTangent());
    materialInput kaf = kinematic("armstrongFrederick", 1000, 10);
    EXPECT_FALSE(material::New("elastoPlastic",
        input(200e3, 0.3, swift(500, 0.01, 0.2), nullptr, &kaf))->symmetricTangent());

    materialInput bad = in;
    bad.scalars["nuu"] = 0.3;
    try { material::New("elastoPlastic", bad); FAIL(); }
    catch (const inputError& e) { EXPECT_EQ(e.entry(), "nuu"); }

    bad = in;
    bad.dicts["hardening"].scalars["n"] = -1;
    try { material::New("elastoPlastic", bad); FAIL(); }
    catch (const inputError& e) { EXPECT_EQ(e.entry(), "hardening/n"); }

    bad = in;
    bad.dicts.erase("hardening");
    try { material::New("elastoPlastic", bad); FAIL(); }
    catch (const inputError& e) { EXPECT_EQ(e.entry(), "hardening"); }

    bad = in;
    bad.scalars["nu"] = 0.5;
    EXPECT_THROW(material::New("elastoPlastic", bad), inputError);

    materialInput y = hill(1.8, 1.2, -2);
    bad = input(200e3, 0.3, swift(500, 0.01, 0.2), &y);
    try { material::New("elastoPlastic", bad); FAIL(); }
    catch (const inputError& e) { EXPECT_EQ(e.entry(), "yield/r90"); }
}


TEST(elastoPlastic, virginStateAndDeviatoricStress)
{
    const auto m = material::New("elastoPlastic", input(200e3, 0.3, perfect(250)));
    const materialState s0 = m->initialState();
    ASSERT_EQ(s0.history.size(), 13);
    EXPECT_EQ(s0.history.norm(), 0);
    std::mt19937 rng(3);
    materialState s1;
    mat3 tau;
    mat6 c;
    for (int k = 0; k < 20; ++k)
    {
        const mat3 F = test::randomF(rng);
        ASSERT_TRUE(m->deviatoric(F, s0, s1, tau, c));
        EXPECT_NEAR(tau.trace(), 0, 1e-10*tau.norm());
        EXPECT_LT((tau - tau.transpose()).norm(), 1e-10*tau.norm());
    }
}


TEST(elastoPlastic, spatialTangentMatchesFiniteDifferences)
{
    materialInput yh = hill(2.1, 1.6, 2.7);
    materialInput kp = kinematic("prager", 2000, 0);
    materialInput ka = kinematic("armstrongFrederick", 20000, 50);
    struct caseDef { std::string name; materialInput in; };
    const std::vector<caseDef> cases
    {
        {"vonMises swift", input(200e3, 0.3, swift(565, 0.007, 0.26))},
        {"vonMises voce", input(200e3, 0.3, voce(450, 715, 16.93, 129))},
        {"hill48 swift", input(200e3, 0.3, swift(565, 0.007, 0.26), &yh)},
        {"prager", input(200e3, 0.3, perfect(300), nullptr, &kp)},
        {"mixed AF swift", input(200e3, 0.3, swift(565, 0.007, 0.26), nullptr, &ka)},
        {"hill AF", input(200e3, 0.3, voce(300, 500, 10, 100), &yh, &ka)}
    };
    std::mt19937 rng(11);
    for (const auto& cd : cases)
    {
        const auto m = material::New("elastoPlastic", cd.in);
        for (int trial = 0; trial < 4; ++trial)
        {
            // Plastic history: a committed state after a random large
            // deformation, then a further increment from it
            materialState s0 = m->initialState(), s1;
            const mat3 F1 = test::randomF(rng);
            mat3 tau;
            mat6 c;
            ASSERT_TRUE(m->deviatoric(F1, s0, s1, tau, c)) << cd.name;
            ASSERT_GT(s1.history(6), 0) << cd.name << ": no plastic flow";
            const materialState committed = s1;
            const mat3 F2 = (mat3::Identity() + 0.05*test::randomSym(rng))*F1
                           *test::rotation(vec3(1, 2, 3), 0.3);
            materialState s2;
            ASSERT_TRUE(m->deviatoric(F2, committed, s2, tau, c)) << cd.name;
            const auto tauOf = [&](const mat3& F)
            {
                materialState s;
                mat3 t;
                mat6 cc;
                EXPECT_TRUE(m->deviatoric(F, committed, s, t, cc));
                return t;
            };
            const mat6 cFD = test::fdSpatialTangent(tauOf, F2, 1e-6);
            EXPECT_TRUE(test::fdError("elastoPlastic spatial tangent", test::relErr(c, cFD), fdTolElastoPlastic)) << cd.name << "\n" << c
                << "\nFD\n" << cFD;
        }
    }
}


TEST(elastoPlastic, secondPiolaInLogSpaceIsThePulledBackResponse)
{
    // elastoPlastic::secondPiola forms S and dS/dE in log space (the
    // volumetric part through the map); material::secondPiola, the
    // default, pulls tau_dev + kappa ln J I and c back with F^-1: the two
    // agree to round-off, the history too, and dS/dE matches central
    // differences of S in the Green-Lagrange strain
    materialInput yh = hill(2.1, 1.6, 2.7);
    materialInput ka = kinematic("armstrongFrederick", 20000, 50);
    const std::vector<materialInput> inputs
    {
        input(200e3, 0.3, swift(565, 0.007, 0.26)),
        input(200e3, 0.3, swift(565, 0.007, 0.26), &yh),
        input(200e3, 0.3, voce(300, 500, 10, 100), &yh, &ka)
    };
    std::mt19937 rng(23);
    for (const materialInput& in : inputs)
    {
        const auto m = material::New("elastoPlastic", in);
        for (int k = 0; k < 3; ++k)
        {
            materialState s0 = m->initialState(), committed;
            mat3 tau;
            mat6 c;
            const mat3 F1 = test::randomF(rng);
            ASSERT_TRUE(m->deviatoric(F1, s0, committed, tau, c));
            const mat3 F2 = (mat3::Identity() + 0.05*test::randomSym(rng))*F1;
            const mat3 C = F2.transpose()*F2;
            materialState t1, t2;
            mat3 S1, S2;
            mat6 CC1, CC2;
            ASSERT_TRUE(m->secondPiola(C, committed, t1, S1, CC1));
            ASSERT_TRUE(m->material::secondPiola(C, committed, t2, S2, CC2));
            EXPECT_LT((S1 - S2).norm(), 1e-12*S2.norm());
            EXPECT_LT((CC1 - CC2).norm(), 1e-12*CC2.norm());
            // (the default path sees C through its Cholesky factor:
            // round-off in C, 1e-15 relative in the history)
            EXPECT_LT((t1.history - t2.history).norm(), 1e-13*(1 + t2.history.norm()));
            // dS/dE: column b from S(C + 2 h dE_b), dE_b the unit
            // engineering strain b
            const double h = 1e-6;
            mat6 fd;
            for (int b = 0; b < 6; ++b)
            {
                mat3 dE = mat3::Zero();
                const int i = voigtI[b], j = voigtJ[b];
                dE(i, j) = dE(j, i) = i == j ? 1 : 0.5;
                materialState tp, tm;
                mat3 Sp, Sm;
                mat6 unused;
                ASSERT_TRUE(m->secondPiola(C + 2*h*dE, committed, tp, Sp, unused));
                ASSERT_TRUE(m->secondPiola(C - 2*h*dE, committed, tm, Sm, unused));
                for (int a = 0; a < 6; ++a)
                {
                    fd(a, b) = (Sp(voigtI[a], voigtJ[a]) - Sm(voigtI[a], voigtJ[a]))/(2*h);
                }
            }
            EXPECT_TRUE(test::fdError("elastoPlastic material tangent dS/dE", test::relErr(CC1, fd), fdTolElastoPlastic));
        }
    }
}


TEST(elastoPlastic, largeIncrementInOneStep)
{
    // Strain increment 0.5 in one step from the virgin state and from a
    // plastically deformed one
    materialInput yh = hill(0.5, 2.0, 3.0);
    materialInput ka = kinematic("armstrongFrederick", 20000, 50);
    const auto m = material::New
    (
        "elastoPlastic", input(200e3, 0.3, swift(565, 0.007, 0.26), &yh, &ka)
    );
    materialState s0 = m->initialState(), s1, s2;
    mat3 tau;
    mat6 c;
    const double e = 0.5;
    mat3 F = mat3::Identity();
    F(0, 0) = std::exp(e);
    F(1, 1) = F(2, 2) = std::exp(-e/2);
    ASSERT_TRUE(m->deviatoric(F, s0, s1, tau, c));
    EXPECT_GT(s1.history(6), 0.49);
    F(0, 1) = 0.5;   // and a shear of 0.5 on top
    ASSERT_TRUE(m->deviatoric(F, s1, s2, tau, c));
    EXPECT_GT(s2.history(6), s1.history(6));
}


TEST(elastoPlastic, uniaxialTensionReproducesSwiftCurve)
{
    // Homogeneous single element in uniaxial tension to a true strain of 1
    // (100 steps). The yield condition is stated on the Kirchhoff stress,
    // so tau_xx = K (eps0 + eps_p)^n to the return mapping's tolerance;
    // the Cauchy (true) stress tau_xx/J lies below by the elastic volume
    // change, J - 1 = (1 - 2 nu) sigma/E (0.11 % at sigma = 565 MPa)
    const double E = 206e3, nu = 0.3;
    const double K = 565.32, eps0 = 0.007117, n = 0.2589;
    const auto m = material::New("elastoPlastic", input(E, nu, swift(K, eps0, n)));
    uniaxialDriver drv(*m, vec3(1, 0, 0));
    double maxErr = 0, maxErrJ = 0;
    for (int k = 1; k <= 100; ++k)
    {
        const double eps = 0.01*k;
        mat3 tau;
        ASSERT_TRUE(drv.step(std::exp(eps), tau)) << "step " << k;
        const double J = drv.U.determinant();
        const double ep = drv.state.history(6);
        const mat3 Ep = plasticLogStrain(drv.state);
        // the log plastic strain along the bar equals the accumulated one
        EXPECT_NEAR(Ep(0, 0), ep, 1e-6*(1 + ep));
        if (ep > 1e-3)
        {
            const double ref = K*std::pow(eps0 + ep, n);
            maxErr = std::max(maxErr, std::abs(tau(0, 0)/ref - 1));
            // the Cauchy stress against the Swift value reduced by J
            const double Je = 1 + (1 - 2*nu)*ref/E;
            maxErrJ = std::max(maxErrJ, std::abs(tau(0, 0)/J/(ref/Je) - 1));
        }
        if (k == 100) EXPECT_GT(ep, 0.99);
    }
    EXPECT_LT(maxErr, 1e-10);       // observed 8e-12
    EXPECT_LT(maxErrJ, 3e-6);       // observed 6e-7 (J = 1 + tr(eps_e) to first order)
    RecordProperty("maxRelativeError", std::to_string(maxErr));
    std::cout << "    Swift curve to eps = 1: Kirchhoff stress, max relative"
              << " error " << maxErr << "; Cauchy stress with J, " << maxErrJ
              << std::endl;
}


TEST(elastoPlastic, hillTensileTestsRecoverRValues)
{
    // Sheet: rolling direction x, normal z. Tensile tests in the sheet plane
    // at 0, 45, 90 degrees to 20 % strain: r = eps_p(width)/eps_p(thickness)
    const double r[3] = {1.8, 1.3, 2.4};
    materialInput yh = hill(r[0], r[1], r[2]);
    const auto m = material::New
    (
        "elastoPlastic", input(206e3, 0.3, swift(565.32, 0.007117, 0.2589), &yh)
    );
    const double angles[3] = {0, M_PI/4, M_PI/2};
    for (int a = 0; a < 3; ++a)
    {
        const vec3 d(std::cos(angles[a]), std::sin(angles[a]), 0);
        const vec3 w(-std::sin(angles[a]), std::cos(angles[a]), 0);
        uniaxialDriver drv(*m, d);
        mat3 tau;
        for (int k = 1; k <= 20; ++k)
        {
            ASSERT_TRUE(drv.step(std::exp(0.01*k), tau));
        }
        const mat3 Ep = plasticLogStrain(drv.state);
        const double rNum = w.dot(Ep*w)/Ep(2, 2);
        EXPECT_NEAR(rNum/r[a], 1, 0.01) << "angle " << angles[a];
        std::cout << "    r at " << angles[a]*180/M_PI << " deg: " << rNum
                  << " (input " << r[a] << ")" << std::endl;
    }
}


TEST(elastoPlastic, armstrongFrederickCycle)
{
    // Uniaxial tension to eps_p ~ 0.05, then compression; perfect
    // isotropic part: the axial back stress follows
    //   beta_xx = 2/3 C/gamma (1 - exp(-gamma eps_p))   (monotonic, 3/2 beta_xx = alpha)
    // i.e. the uniaxial back stress alpha = 3/2 beta_xx = C/gamma (1 - e^...)
    // and the flow stress is sigma_y0 + alpha. Reverse yielding starts at
    // sigma = alpha - sigma_y0 (Bauschinger effect).
    const double s0 = 250, C = 20000, gamma = 100;
    materialInput ka = kinematic("armstrongFrederick", C, gamma);
    const auto m = material::New
    (
        "elastoPlastic", input(206e3, 0.3, perfect(s0), nullptr, &ka)
    );
    uniaxialDriver drv(*m, vec3(1, 0, 0));
    mat3 tau;
    double maxErr = 0;
    double eps = 0;
    // Steps small against 1/gamma: backward Euler of the back stress
    // lags the exponential by about gamma d(eps_p)/2 relative
    for (int k = 1; k <= 600; ++k)
    {
        eps += 0.0001;
        ASSERT_TRUE(drv.step(std::exp(eps), tau));
        const double ep = drv.state.history(6);
        if (ep > 0.002)
        {
            const double alpha = C/gamma*(1 - std::exp(-gamma*ep));
            const double sigma = tau(0, 0)/drv.U.determinant();
            maxErr = std::max(maxErr, std::abs(sigma/(s0 + alpha) - 1));
            const double betaXX = drv.state.history(7);
            maxErr = std::max(maxErr, std::abs(1.5*betaXX/alpha - 1));
        }
    }
    EXPECT_LT(maxErr, 0.01);
    const double alphaMax = C/gamma*(1 - std::exp(-gamma*drv.state.history(6)));
    // Reverse: find the stress at which plastic flow restarts
    const double epAtReversal = drv.state.history(6);
    double reverseYield = 0;
    for (int k = 1; k <= 2000; ++k)
    {
        eps -= 0.00001;
        ASSERT_TRUE(drv.step(std::exp(eps), tau));
        if (drv.state.history(6) > epAtReversal + 1e-9)
        {
            reverseYield = tau(0, 0)/drv.U.determinant();
            break;
        }
    }
    // Plastic flow restarts in compression at |sigma| ~ s0 - alpha, far
    // below the forward flow stress s0 + alpha
    EXPECT_LT(reverseYield, 0);
    EXPECT_NEAR(reverseYield, alphaMax - s0, 0.02*s0);
    EXPECT_LT(std::abs(reverseYield), 0.6*(s0 + alphaMax));
    std::cout << "    AF: forward flow stress " << s0 + alphaMax
              << ", reverse yield " << reverseYield << ", max error "
              << maxErr << std::endl;
}


TEST(elastoPlastic, objectiveUnderLargeRotations)
{
    materialInput yh = hill(1.8, 1.3, 2.4);
    materialInput ka = kinematic("armstrongFrederick", 20000, 50);
    const auto m = material::New
    (
        "elastoPlastic", input(206e3, 0.3, swift(565, 0.007, 0.26), &yh, &ka)
    );
    // Plastic deformation, committed
    mat3 F = mat3::Identity();
    F(0, 0) = 1.2; F(1, 1) = 0.9; F(0, 1) = 0.15;
    materialState s0 = m->initialState(), s1;
    mat3 tau0;
    mat6 c;
    ASSERT_TRUE(m->deviatoric(F, s0, s1, tau0, c));
    ASSERT_GT(s1.history(6), 0.05);
    // Rotate by 90 degrees in 3 large steps, committing each
    materialState s = s1;
    const vec3 axis(0.3, -0.5, 1);
    mat3 tau;
    for (int k = 1; k <= 3; ++k)
    {
        materialState sNew;
        const mat3 R = test::rotation(axis, k*M_PI/6);
        ASSERT_TRUE(m->deviatoric(R*F, s, sNew, tau, c));
        s = sNew;
    }
    const mat3 R = test::rotation(axis, M_PI/2);
    EXPECT_LT((tau - R*tau0*R.transpose()).norm(), 1e-8*tau0.norm());
    EXPECT_NEAR(tau.squaredNorm(), tau0.squaredNorm(), 1e-8*tau0.squaredNorm());
    EXPECT_NEAR(tau.determinant(), tau0.determinant(),
                1e-8*std::pow(tau0.norm(), 3));
    EXPECT_NEAR(s.history(6), s1.history(6), 1e-12);
    // A frozen history re-evaluated at the same C gives the same stress
    materialState s3;
    mat3 tau3;
    ASSERT_TRUE(m->deviatoric(F, s1, s3, tau3, c));
    EXPECT_LT((tau3 - tau0).norm(), 1e-10*tau0.norm());
}


TEST(elastoPlastic, smallStrainLimitIsTheSmallStrainKernel)
{
    const auto m = material::New("elastoPlastic", input(200e3, 0.3, swift(565, 0.007, 0.26)));
    const auto* ep = dynamic_cast<const elastoPlastic*>(m.get());
    ASSERT_TRUE(ep);
    std::mt19937 rng(5);
    for (int k = 0; k < 5; ++k)
    {
        const mat3 eps = 1e-6*test::randomSym(rng) * 3000;   // ~3e-3, plastic
        const mat3 F = mat3::Identity() + eps;
        materialState s0 = m->initialState(), s1;
        mat3 tau;
        mat6 c;
        ASSERT_TRUE(m->deviatoric(F, s0, s1, tau, c));
        plasticState p0, p1;
        vec6 sDev, dEp;
        mat6 A;
        ASSERT_TRUE(ep->plasticityModel().update(test::toVoigtStrain(eps), p0, p1, sDev, A, dEp));
        // Agreement to first order in the strain (~3e-3 relative)
        EXPECT_LT((tau - fromVoigtStress(sDev)).norm(), 1e-2*tau.norm());
        EXPECT_NEAR(s1.history(6), p1.epsP, 1e-2*p1.epsP + 1e-12);
    }
}
