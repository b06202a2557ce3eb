// logStrain: E = 1/2 ln C against closed forms and Eigen's matrix logarithm
// (unsupported/MatrixFunctions, an independent Schur-Parlett algorithm),
// tr E = 1/2 ln det C, rotation equivariance; the divided differences of
// 1/2 ln against their integral representation; P = 2 dE/dC and
// T : L = T : 4 d2E/dCdC against fourth-order central differences for
// random SPD C and for the delicate spectra (C = I, diag(a,a,b), clusters
// 1e-10 apart, clusters around the series switch-over, eigenvalues spread
// over 1e-2..1e2); P : C = I; Voigt conversions, push-forward and
// contractions against explicit index loops.
#include "logStrain.H"
#include "formError.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace form;

namespace
{

//- A test matrix C with, where known, its spectral construction
//  C = R diag(lambda) R^T; U is (an approximation of) C^(1/2), used to build
//  relative perturbations U S U that probe all eigenvalues alike
struct spdCase
{
    std::string name;
    mat3 C;
    //- Tolerance factor: the eigenvalues of C are only known to
    //  ~eps lambda_max, i.e. to ~eps cond(C) relative for lambda_min
    double cond() const
    {
        const vec3 l = C.selfadjointView<Eigen::Lower>().eigenvalues();
        return l.maxCoeff()/l.minCoeff();
    }
    //- Round-off tolerance for quantities of order one
    double tol() const { return 1e-14 + 1e-15*cond(); }
    bool spectral;      //!< R and lambda are exact
    mat3 R;
    vec3 lambda;
    mat3 U;
};

spdCase spectralCase(const std::string& name, const mat3& R, const vec3& l)
{
    spdCase c;
    c.name = name;
    c.spectral = true;
    c.R = R;
    c.lambda = l;
    c.C = R*l.asDiagonal()*R.transpose();
    c.C = 0.5*(c.C + c.C.transpose());
    c.U = R*l.cwiseSqrt().asDiagonal()*R.transpose();
    return c;
}

mat3 randomRotation(std::mt19937& rng)
{
    std::uniform_real_distribution<double> uni(-1, 1);
    return test::rotation(vec3(uni(rng), uni(rng), uni(rng)), 3.1*uni(rng));
}

//- The delicate spectra plus nRandom random SPD matrices with eigenvalues
//  log-uniform in [0.05, 20]
std::vector<spdCase> testCases(int nRandom = 20)
{
    std::mt19937 rng(7);
    std::vector<spdCase> cases;
    const mat3 I = mat3::Identity();
    const mat3 R1 = test::rotation(vec3(1, 2, -0.5), 0.9);
    const mat3 R2 = test::rotation(vec3(-0.3, 1, 1.4), 2.3);

    cases.push_back(spectralCase("identity", I, vec3(1, 1, 1)));
    cases.push_back(spectralCase("diag(a,a,a)", I, vec3(2.5, 2.5, 2.5)));
    cases.push_back(spectralCase("diag(a,a,b)", I, vec3(1.7, 1.7, 0.4)));
    cases.push_back(spectralCase("diag(a,b,b)", I, vec3(0.3, 3.1, 3.1)));
    cases.push_back(spectralCase("R diag(a,a,b) R^T", R1, vec3(0.6, 0.6, 2.2)));
    cases.push_back
    (
        spectralCase("R diag(a,a,a(1+1e-10)) R^T", R2,
                     vec3(1.3, 1.3, 1.3*(1 + 1e-10)))
    );
    cases.push_back
    (
        spectralCase("R diag(a,a(1+1e-10),a(1+2e-10)) R^T", R1,
                     vec3(0.8, 0.8*(1 + 1e-10), 0.8*(1 + 2e-10)))
    );
    cases.push_back
    (
        spectralCase("R diag(a,a(1+1e-10),b) R^T", R2,
                     vec3(2.1, 2.1*(1 + 1e-10), 0.7))
    );
    cases.push_back
    (
        spectralCase("R diag(a,a(1+1e-6),b) R^T", R1,
                     vec3(0.45, 0.45*(1 + 1e-6), 5.0))
    );
    cases.push_back
    (
        spectralCase("R diag(a,a(1+1e-3),a(1-1e-3)) R^T", R2,
                     vec3(1.9, 1.9*(1 + 1e-3), 1.9*(1 - 1e-3)))
    );
    // Clusters whose relative width sits just below, at and above the
    // series/direct switch-over of the second divided difference
    for (double w : {0.015, 0.08, 0.1, 0.12, 0.4})
    {
        cases.push_back
        (
            spectralCase("cluster width " + std::to_string(w), R1,
                         vec3(1.2*(1 - w/2), 1.2*(1 + w/6), 1.2*(1 + w/2)))
        );
    }
    cases.push_back
    (
        spectralCase("R diag(1e-2,1,1e2) R^T", R2, vec3(1e-2, 1, 1e2))
    );
    cases.push_back
    (
        spectralCase("R diag(1e-2,1e-2(1+1e-9),1e2) R^T", R1,
                     vec3(1e-2, 1e-2*(1 + 1e-9), 1e2))
    );

    // a (I + 1e-10 S), S random symmetric: eigenvalues 1e-10 apart in an
    // arbitrary, unknown eigenbasis
    {
        spdCase c;
        c.name = "a(I + 1e-10 S)";
        c.spectral = false;
        const double a = 1.6;
        c.C = a*(I + 1e-10*test::randomSym(rng));
        c.U = std::sqrt(a)*I;
        cases.push_back(c);
    }

    std::uniform_real_distribution<double> uni(0, 1);
    for (int k = 0; k < nRandom; ++k)
    {
        vec3 l;
        for (int i = 0; i < 3; ++i)
        {
            l(i) = 0.05*std::pow(20/0.05, uni(rng));
        }
        cases.push_back
        (
            spectralCase("random " + std::to_string(k), randomRotation(rng), l)
        );
    }
    return cases;
}

double tensorEntry(const tensor4& A, int i, int j, int k, int l)
{
    return A(3*i + j, 3*k + l);
}

//- Fourth-order central difference of a matrix function G along D
template<class Fn>
mat3 centralDiff(const Fn& G, const mat3& C, const mat3& D, double h)
{
    return (-G(C + 2*h*D) + 8*G(C + h*D) - 8*G(C - h*D) + G(C - 2*h*D))
           /(12*h);
}

//- Unit symmetric direction (e_k e_l^T + e_l e_k^T)/2: contracting a
//  minor-symmetric tensor with it picks the entry A_ijkl
mat3 symUnit(int k, int l)
{
    mat3 D = mat3::Zero();
    D(k, l) += 0.5;
    D(l, k) += 0.5;
    return D;
}

mat3 E_of(const mat3& C)
{
    mat3 E;
    tensor4 P;
    logStrain(C, E, P);
    return E;
}

tensor4 P_of(const mat3& C)
{
    mat3 E;
    tensor4 P;
    logStrain(C, E, P);
    return P;
}

//- (T : P)_kl = sum_ij T_ij P_ijkl by explicit loops
mat3 TcolonP(const mat3& T, const tensor4& P)
{
    mat3 M = mat3::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    M(k, l) += T(i, j)*tensorEntry(P, i, j, k, l);
    return M;
}

//- max |A_ijkl - A_jikl|, |A_ijkl - A_ijlk|, |A_ijkl - A_klij| / max |A|
double symmetryDefect(const tensor4& A)
{
    double d = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                {
                    const double a = tensorEntry(A, i, j, k, l);
                    d = std::max(d, std::abs(a - tensorEntry(A, j, i, k, l)));
                    d = std::max(d, std::abs(a - tensorEntry(A, i, j, l, k)));
                    d = std::max(d, std::abs(a - tensorEntry(A, k, l, i, j)));
                }
    return d/A.cwiseAbs().maxCoeff();
}

//- Independent reference for the divided differences of f = 1/2 ln, from
//  ln x = int_0^inf (1/(1+t) - 1/(x+t)) dt:
//    f[a,b]   =  1/2 int_0^inf dt/((a+t)(b+t))
//    f[a,b,c] = -1/2 int_0^inf dt/((a+t)(b+t)(c+t))
//  Substituting t = m e^y turns both into integrals over the real line of
//  functions analytic in the strip |Im y| < pi that decay exponentially,
//  where the trapezoidal rule converges geometrically (discretisation
//  error far below 1e-16 for step 0.02, range +-60).
double refDD(const std::vector<double>& x)
{
    const double m = std::sqrt(*std::min_element(x.begin(), x.end())
                              *(*std::max_element(x.begin(), x.end())));
    // Extended precision keeps the summed rounding of 6000 nodes ~1e-17
    const long double dy = 0.02L;
    long double sum = 0;
    for (int n = -3000; n <= 3000; ++n)
    {
        const long double t = m*std::exp(n*dy);
        long double g = t;
        for (double xi : x) g /= (xi + t);
        sum += g;
    }
    const long double sign = x.size() == 2 ? 0.5L : -0.5L;
    return double(sign*sum*dy);
}

void report(const std::string& what, double err)
{
    std::cout << "    [max rel err] " << what << ": " << err << std::endl;
}

} // namespace


TEST(logStrain, matchesDirectComputation)
{
    double maxErr = 0, maxErrLog = 0;
    for (const spdCase& c : testCases())
    {
        const mat3 E = E_of(c.C);
        // Eigen's matrix logarithm (Schur-Parlett with inverse scaling and
        // squaring; no eigen-decomposition of C by our code)
        const mat3 Elog = 0.5*c.C.log();
        const double scale = std::max(Elog.norm(), 1.0);
        const double eLog = (E - Elog).norm()/scale;
        const double tol = c.tol();
        EXPECT_LT(eLog, tol) << c.name;
        maxErrLog = std::max(maxErrLog, eLog);
        if (c.spectral)
        {
            const vec3 f = 0.5*c.lambda.array().log().matrix();
            const mat3 Eref = c.R*f.asDiagonal()*c.R.transpose();
            const double e = (E - Eref).norm()/std::max(Eref.norm(), 1.0);
            EXPECT_LT(e, tol) << c.name;
            maxErr = std::max(maxErr, e);
        }
        EXPECT_LT((E - E.transpose()).norm(), 1e-15*scale) << c.name;
    }
    EXPECT_EQ(E_of(mat3::Identity()).norm(), 0.0);
    report("E vs R diag(ln(lambda)/2) R^T", maxErr);
    report("E vs Eigen MatrixFunctions log", maxErrLog);
}

TEST(logStrain, traceIsHalfLogDet)
{
    double maxErr = 0;
    for (const spdCase& c : testCases())
    {
        // ln det C from the construction where known: det() of an
        // ill-conditioned C itself loses up to ~eps cond(C) relative
        const double ref = c.spectral
            ? 0.5*c.lambda.array().log().sum()
            : 0.5*std::log(c.C.determinant());
        const double err = std::abs(E_of(c.C).trace() - ref)
                          /std::max(std::abs(ref), 1.0);
        EXPECT_LT(err, c.tol()) << c.name;
        maxErr = std::max(maxErr, err);
    }
    report("tr E vs ln(det C)/2", maxErr);
}

TEST(logStrain, rotationEquivariance)
{
    std::mt19937 rng(99);
    double maxE = 0, maxP = 0, maxL = 0;
    for (const spdCase& c : testCases(10))
    {
        const mat3 R = randomRotation(rng);
        const mat3 CR = R*c.C*R.transpose();
        const mat3 T = test::randomSym(rng);
        mat3 E, ER;
        tensor4 P, PR;
        logStrain(c.C, E, P);
        logStrain(CR, ER, PR);
        const double eE =
            (ER - R*E*R.transpose()).norm()/std::max(E.norm(), 1.0);
        const double eP = test::relErr(PR, pushForward(P, R));
        const double eL = test::relErr
        (
            logStrainSecond(CR, R*T*R.transpose()),
            pushForward(logStrainSecond(c.C, T), R)
        );
        const double tol = c.tol();
        EXPECT_LT(eE, tol) << c.name;
        EXPECT_LT(eP, 10*tol) << c.name;
        EXPECT_LT(eL, 100*tol) << c.name;
        maxE = std::max(maxE, eE);
        maxP = std::max(maxP, eP);
        maxL = std::max(maxL, eL);
    }
    report("E(R C R^T) vs R E R^T", maxE);
    report("P(R C R^T) vs push-forward of P by R", maxP);
    report("L(R C R^T) vs push-forward of L by R", maxL);
}

TEST(logStrain, dividedDifferencesMatchIntegralRepresentation)
{
    const std::vector<std::vector<double>> pairs =
    {
        {1, 1}, {2.5, 2.5}, {1, 1 + 1e-12}, {0.3, 0.3*(1 + 1e-10)},
        {1, 1 + 1e-4}, {1, 1 + 2e-3}, {1, 1.01}, {1, 1.1}, {1, 3},
        {1, 2.99}, {1, 3.01}, {1e-2, 1e2}, {7, 0.05}, {1e-3, 1e3}
    };
    double max1 = 0;
    for (const auto& p : pairs)
    {
        const double ref = refDD(p);
        const double e = std::abs(logDividedDifference(p[0], p[1]) - ref)
                        /std::abs(ref);
        EXPECT_LT(e, 2e-15) << p[0] << " " << p[1];
        max1 = std::max(max1, e);
        // Symmetric in its arguments
        EXPECT_EQ(logDividedDifference(p[0], p[1]),
                  logDividedDifference(p[1], p[0]));
    }

    std::vector<std::vector<double>> triples =
    {
        {1, 1, 1}, {0.2, 0.2, 0.2}, {1, 1, 2}, {3, 0.5, 0.5},
        {1, 1, 1 + 1e-10}, {1, 1 + 1e-10, 1 + 2e-10}, {1, 1 + 1e-10, 4},
        {1, 1 + 1e-6, 1 - 1e-6}, {1, 1.001, 0.999}, {1e-2, 1, 1e2},
        {1e-2, 1e-2, 1e2}, {1e-2, 1e2, 1e2}, {0.05, 20, 3},
        {1, 1.1, 1.3}, {1, 1.2, 1.2}, {0.8, 1, 1.25}, {1, 1, 1.5}
    };
    // Widths just below / at / above the switch-over, several shapes
    for (double w : {0.02, 0.0999, 0.1, 0.1001, 0.15, 0.3})
    {
        triples.push_back({1, 1, 1 + w});
        triples.push_back({1, 1 + w/2, 1 + w});
        triples.push_back({1, 1 + w, 1 + w});
        triples.push_back({1 - w/2, 1 + w/5, 1 + w/2});
    }
    double max2 = 0;
    for (const auto& t : triples)
    {
        const double ref = refDD(t);
        const double d = logDividedDifference(t[0], t[1], t[2]);
        const double e = std::abs(d - ref)/std::abs(ref);
        EXPECT_LT(e, 5e-14) << t[0] << " " << t[1] << " " << t[2];
        max2 = std::max(max2, e);
        // Symmetric in its arguments (up to rounding)
        EXPECT_NEAR(logDividedDifference(t[2], t[0], t[1]), d,
                    1e-14*std::abs(d));
        EXPECT_NEAR(logDividedDifference(t[1], t[2], t[0]), d,
                    1e-14*std::abs(d));
    }
    // Analytic limits f[a,a] = f'(a) = 1/(2a), f[a,a,a] = f''(a)/2
    EXPECT_NEAR(logDividedDifference(0.7, 0.7), 1/1.4, 1e-16);
    EXPECT_NEAR(logDividedDifference(0.7, 0.7, 0.7), -1/(4*0.49), 1e-15);
    report("f[a,b] vs integral", max1);
    report("f[a,b,c] vs integral", max2);
}

TEST(logStrain, tangentMatchesFiniteDifferences)
{
    std::mt19937 rng(2024);
    double maxFull = 0, maxDir = 0, maxSym = 0;
    for (const spdCase& c : testCases())
    {
        mat3 E;
        tensor4 P;
        logStrain(c.C, E, P);
        const double lmin = c.C.selfadjointView<Eigen::Lower>().eigenvalues()
                           .minCoeff();

        // Full tensor from the six symmetric unit directions:
        // P_ijkl = 2 dE_ij/dC along (e_k e_l + e_l e_k)/2
        const double h = 1e-3*lmin;
        tensor4 Pfd;
        for (int k = 0; k < 3; ++k)
        {
            for (int l = 0; l < 3; ++l)
            {
                const mat3 dE = 2*centralDiff(E_of, c.C, symUnit(k, l), h);
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        Pfd(3*i + j, 3*k + l) = dE(i, j);
            }
        }
        const double eFull = test::relErr(P, Pfd);
        EXPECT_LT(eFull, 1e-7) << c.name;
        maxFull = std::max(maxFull, eFull);

        // Random relative directions dC = U S U, P : dC = 2 dE[dC]
        for (int r = 0; r < 3; ++r)
        {
            const mat3 D = c.U*test::randomSym(rng)*c.U;
            const mat3 ref = 2*centralDiff(E_of, c.C, D, 1e-3);
            const double e = (contract(P, D) - ref).norm()/ref.norm();
            EXPECT_LT(e, 1e-7) << c.name;
            maxDir = std::max(maxDir, e);
        }

        // Exact by construction (the kernel symmetrises)
        const double s = symmetryDefect(P);
        EXPECT_EQ(s, 0.0) << c.name;
        maxSym = std::max(maxSym, s);
    }
    // C = I: E = 1/2 ln C has P = I_sym
    tensor4 Isym = tensor4::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
            Isym(3*i + j, 3*i + j) += 0.5;
            Isym(3*i + j, 3*j + i) += 0.5;
        }
    EXPECT_LT((P_of(mat3::Identity()) - Isym).norm(), 1e-15);

    report("P vs FD (full tensor)", maxFull);
    report("P:dC vs FD (relative directions)", maxDir);
    report("P symmetry defect", maxSym);
}

TEST(logStrain, tangentContractsCToIdentity)
{
    double maxErr = 0;
    for (const spdCase& c : testCases())
    {
        const tensor4 P = P_of(c.C);
        // P : C = I (E((1+s)C) = E + 1/2 ln(1+s) I) and, by major
        // symmetry, C : P = I
        const double e1 = (contract(P, c.C) - mat3::Identity()).norm();
        const double e2 = (TcolonP(c.C, P) - mat3::Identity()).norm();
        EXPECT_LT(e1, c.tol()) << c.name;
        EXPECT_LT(e2, c.tol()) << c.name;
        maxErr = std::max({maxErr, e1, e2});
    }
    report("P:C - I", maxErr);
}

TEST(logStrain, secondDerivativeMatchesFiniteDifferences)
{
    std::mt19937 rng(31);
    double maxFull = 0, maxDir = 0, maxSym = 0;
    for (const spdCase& c : testCases())
    {
        const mat3 T = test::randomSym(rng);
        const tensor4 TL = logStrainSecond(c.C, T);
        const double lmin = c.C.selfadjointView<Eigen::Lower>().eigenvalues()
                           .minCoeff();

        // M(C) = T : P(C); since P = 2 dE/dC and L = 4 d2E/dCdC,
        // (T : L) : dC = 2 dM[dC]
        auto M = [&T](const mat3& C) { return TcolonP(T, P_of(C)); };

        const double h = 1e-3*lmin;
        tensor4 TLfd;
        for (int m = 0; m < 3; ++m)
        {
            for (int n = 0; n < 3; ++n)
            {
                const mat3 dM = 2*centralDiff(M, c.C, symUnit(m, n), h);
                for (int k = 0; k < 3; ++k)
                    for (int l = 0; l < 3; ++l)
                        TLfd(3*k + l, 3*m + n) = dM(k, l);
            }
        }
        const double eFull = test::relErr(TL, TLfd);
        EXPECT_LT(eFull, 1e-7) << c.name;
        maxFull = std::max(maxFull, eFull);

        for (int r = 0; r < 3; ++r)
        {
            const mat3 D = c.U*test::randomSym(rng)*c.U;
            const mat3 ref = 2*centralDiff(M, c.C, D, 1e-3);
            const double e = (contract(TL, D) - ref).norm()/ref.norm();
            EXPECT_LT(e, 1e-7) << c.name;
            maxDir = std::max(maxDir, e);
        }

        const double s = symmetryDefect(TL);
        EXPECT_EQ(s, 0.0) << c.name;
        maxSym = std::max(maxSym, s);
    }
    // C = I: E = 1/2 ln C, d2E[H,K] = -1/4 (HK + KH), so
    // (T:L):H = -(TH + HT) (symmetric T, H)
    const mat3 T = test::randomSym(rng), H = test::randomSym(rng);
    const mat3 ref = -(T*H + H*T);
    EXPECT_LT((contract(logStrainSecond(mat3::Identity(), T), H) - ref).norm(),
              1e-14*ref.norm());

    report("T:L vs FD (full tensor)", maxFull);
    report("(T:L):dC vs FD (relative directions)", maxDir);
    report("T:L symmetry defect", maxSym);
}

TEST(logStrain, voigtConversions)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uni(-1, 1);

    // Voigt -> tensor4 -> Voigt is the identity for any 6x6 matrix
    mat6 M;
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b) M(a, b) = uni(rng);
    EXPECT_EQ(toVoigt(fromVoigt(M)), M);

    // fromVoigt fills every minor-symmetric entry
    const tensor4 A = fromVoigt(M);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                {
                    EXPECT_EQ(tensorEntry(A, i, j, k, l),
                              tensorEntry(A, j, i, l, k));
                    EXPECT_EQ(tensorEntry(A, i, j, k, l),
                              tensorEntry(A, i, j, l, k));
                }
    EXPECT_EQ(tensorEntry(A, 2, 1, 0, 2), M(4, 5));
    EXPECT_EQ(tensorEntry(A, 1, 0, 1, 1), M(3, 1));

    // tensor4 (minor-symmetric) -> Voigt -> tensor4 round trip
    const tensor4 P = P_of(spectralCase("r", randomRotation(rng),
                                        vec3(0.3, 1.2, 4)).C);
    EXPECT_EQ(fromVoigt(toVoigt(P)), P);

    // Symmetric identity: stress-like out, engineering strain in
    tensor4 Isym = tensor4::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    Isym(3*i + j, 3*k + l) =
                        0.5*((i == k)*(j == l) + (i == l)*(j == k));
    vec6 d;
    d << 1, 1, 1, 0.5, 0.5, 0.5;
    EXPECT_EQ(toVoigt(Isym), mat6(d.asDiagonal()));

    // Consistency with formTypes: sigma = A : eps  <=>
    // toVoigtStress(sigma) = toVoigt(A) * engineering(eps)
    const mat3 eps = test::randomSym(rng);
    EXPECT_LT((toVoigtStress(contract(P, eps))
              - toVoigt(P)*test::toVoigtStrain(eps)).norm(),
              1e-14*P.norm());
}

TEST(logStrain, pushForwardMatchesExplicitLoops)
{
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> uni(-1, 1);
    tensor4 A;
    for (int a = 0; a < 9; ++a)
        for (int b = 0; b < 9; ++b) A(a, b) = uni(rng);   // no symmetry
    const mat3 F = test::randomF(rng);

    tensor4 B = tensor4::Zero();
    for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
    for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J)
    for (int K = 0; K < 3; ++K)
    for (int L = 0; L < 3; ++L)
    {
        B(3*i + j, 3*k + l) +=
            F(i, I)*F(j, J)*F(k, K)*F(l, L)*tensorEntry(A, I, J, K, L);
    }
    const double e = test::relErr(pushForward(A, F), B);
    EXPECT_LT(e, 1e-14);
    report("pushForward vs loops", e);
}

TEST(logStrain, contractionsMatchExplicitLoops)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> uni(-1, 1);
    tensor4 A;
    for (int a = 0; a < 9; ++a)
        for (int b = 0; b < 9; ++b) A(a, b) = uni(rng);
    mat3 T;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) T(i, j) = uni(rng);   // non-symmetric

    mat3 AT = mat3::Zero(), TA = mat3::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                {
                    AT(i, j) += tensorEntry(A, i, j, k, l)*T(k, l);
                    TA(k, l) += T(i, j)*tensorEntry(A, i, j, k, l);
                }
    EXPECT_LT((contract(A, T) - AT).norm(), 1e-14*AT.norm());
    EXPECT_LT((contractLeft(T, A) - TA).norm(), 1e-14*TA.norm());
}

TEST(logStrain, rejectsInvalidInput)
{
    mat3 E;
    tensor4 P;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    mat3 C = mat3::Identity();
    C(2, 2) = -0.1;                                   // indefinite
    EXPECT_THROW(logStrain(C, E, P), numericalError);
    EXPECT_THROW(logStrainSecond(C, mat3::Identity()), numericalError);

    EXPECT_THROW(logStrain(-mat3::Identity(), E, P), numericalError);
    EXPECT_THROW(logStrain(mat3::Zero(), E, P), numericalError);

    C = mat3::Identity();
    C(1, 1) = 0;                                      // singular
    EXPECT_THROW(logStrain(C, E, P), numericalError);

    C = mat3::Identity();
    C(0, 1) = C(1, 0) = nan;
    EXPECT_THROW(logStrain(C, E, P), numericalError);
    EXPECT_THROW(logStrainSecond(C, mat3::Identity()), numericalError);

    C = mat3::Identity();
    C(2, 2) = inf;
    EXPECT_THROW(logStrain(C, E, P), numericalError);

    // Finite T required too
    mat3 T = mat3::Identity();
    T(0, 0) = nan;
    EXPECT_THROW(logStrainSecond(mat3::Identity(), T), numericalError);

    // Rank-deficient F^T F (plane collapsed)
    mat3 F = mat3::Identity();
    F(2, 2) = 0;
    EXPECT_THROW(logStrain(F.transpose()*F, E, P), numericalError);
}
