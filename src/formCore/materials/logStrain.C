/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of logStrain.H: the geometric pre- and post-processor of
    finite-strain plasticity in logarithmic strain space (Miehe, Apel &
    Lambrecht, CMAME 191 (2002) 5383-5425).
\*---------------------------------------------------------------------------*/
#include "logStrain.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace form
{

namespace
{

constexpr double machineEps = std::numeric_limits<double>::epsilon();

//- Below this |d| = |a - b|/(a + b), phi(d) = atanh(d)/d by its series
constexpr double phiSeriesLimit = 1e-3;

//- Below this |d|, f[a,b] = phi(d)/(a + b); above (a/b outside (1/3, 3))
//  f[a,b] = ln(a/b)/(2(a - b))
constexpr double atanhFormLimit = 0.5;

//- Below this relative width (c - a)/mean, the second divided difference
//  is summed from its Taylor series about the mean (see logStrain.H)
constexpr double secondSeriesWidth = 0.1;

//- Highest power n of the series of f[a,b,c] (terms n = 2..nSeries)
constexpr int nSeries = 20;

//- The series' coefficients (-1)^(n-1)/n, n = 0..nSeries (entries 0 and 1
//  unused), rounded as the division itself
struct seriesCoefficients
{
    double c[nSeries + 1];
    constexpr seriesCoefficients() : c()
    {
        for (int n = 2; n <= nSeries; ++n) c[n] = (n % 2 ? 1.0 : -1.0)/n;
    }
};
constexpr seriesCoefficients series;

//- Voigt position of the index pair (i, j): xx yy zz xy yz xz
constexpr int voigtIndex[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};


//- phi(d) = atanh(d)/d, even, phi(0) = 1, for |d| < 1
double phi(double d)
{
    if (std::abs(d) < phiSeriesLimit)
    {
        // 1 + d^2/3 + d^4/5 + d^6/7; the next term d^8/9 is < 1.2e-25
        const double d2 = d*d;
        return 1 + d2*(1.0/3 + d2*(1.0/5 + d2*(1.0/7)));
    }
    return std::atanh(d)/d;
}


//- f[a,b,c] for a <= b <= c, given fab = f[a,b] and fbc = f[b,c]
double secondDividedDifferenceSorted
(
    double a, double b, double c,
    double fab, double fbc
)
{
    const double m = (a + b + c)/3;
    const double width = (c - a)/m;

    if (width >= secondSeriesWidth)
    {
        // Divide by the widest gap: the numerator is at least ~width/2 of
        // either term, so the rounding of the (accurate) first differences
        // is amplified by at most ~4/width
        return (fbc - fab)/(c - a);
    }

    // f[a,b,c] = 1/(2 m^2) sum_(n>=2) (-1)^(n-1)/n h_(n-2)(u), with h_k the
    // complete homogeneous symmetric polynomial of degree k in
    // u = (x - m)/m, built by the recurrences
    //   h_k(u0)         = u0^k
    //   h_k(u0, u1)     = h_k(u0) + u1 h_(k-1)(u0, u1)
    //   h_k(u0, u1, u2) = h_k(u0, u1) + u2 h_(k-1)(u0, u1, u2)
    // The sum stops at the first term n whose successor's bound,
    // |h_(n-1)|/(n+1) <= n/2 U^(n-1) with U = max |u_i|, is below 1e-20
    // (the sum is about -1/2): all 20 terms at w = 0.1, 8 at w = 1e-3.
    const double u0 = (a - m)/m, u1 = (b - m)/m, u2 = (c - m)/m;
    const double U = std::max(std::abs(u0), std::max(std::abs(u1), std::abs(u2)));
    double h1 = 1, h2 = 1, h3 = 1;      // degree 0
    double sum = -0.5;                  // n = 2: (-1)^1/2 h_0
    double power = U;                   // U^(n-1) after term n
    for (int n = 3; n <= nSeries; ++n)
    {
        h1 *= u0;
        h2 = h1 + u1*h2;
        h3 = h2 + u2*h3;
        sum += series.c[n]*h3;
        power *= U;
        if (0.5*n*power < 1e-20) break;
    }
    return sum/(2*m*m);
}


//- Spectral decomposition C = Q diag(lambda) Q^T with lambda ascending,
//  checking that C is finite and numerically positive definite
void spectralDecomposition(const mat3& C, vec3& lambda, mat3& Q)
{
    if (!C.allFinite())
    {
        throw numericalError("logStrain: C has non-finite entries");
    }

    // Iterative (tridiagonal QR) solver: backward stable, Q orthogonal to
    // working precision also for clustered eigenvalues, where the
    // closed-form computeDirect loses accuracy. Reads the lower triangle.
    Eigen::SelfAdjointEigenSolver<mat3> solver;
    solver.compute(C, Eigen::ComputeEigenvectors);
    if (solver.info() != Eigen::Success)
    {
        throw numericalError("logStrain: eigen-decomposition of C failed");
    }
    lambda = solver.eigenvalues();
    Q = solver.eigenvectors();

    // The smallest eigenvalue is known to ~eps*lambda_max in absolute
    // terms; below a few such units its logarithm is meaningless
    if (!(lambda(0) > 0) || !(lambda(0) > 16*machineEps*lambda(2)))
    {
        std::ostringstream msg;
        msg << "logStrain: C is not (numerically) positive definite,"
            << " eigenvalues " << lambda(0) << " " << lambda(1) << " "
            << lambda(2);
        throw numericalError(msg.str());
    }
}


//- Table of first divided differences F1(i, j) = f[lambda_i, lambda_j]
mat3 firstDifferences(const vec3& lambda)
{
    mat3 F1;
    for (int i = 0; i < 3; ++i)
    {
        for (int j = i; j < 3; ++j)
        {
            F1(i, j) = F1(j, i) = logDividedDifference(lambda(i), lambda(j));
        }
    }
    return F1;
}

//- Table of second divided differences F2[i][k][j] = f[l_i, l_k, l_j]
//  (lambda ascending, F1 its first differences): (i <= k <= j) lists
//  each multiset once, sorted
void secondDifferences(const vec3& lambda, const mat3& F1, double F2[3][3][3])
{
    for (int i = 0; i < 3; ++i)
    {
        for (int k = i; k < 3; ++k)
        {
            for (int j = k; j < 3; ++j)
            {
                const double v = secondDividedDifferenceSorted
                (
                    lambda(i), lambda(k), lambda(j), F1(i, k), F1(k, j)
                );
                F2[i][k][j] = F2[i][j][k] = F2[k][i][j] =
                F2[k][j][i] = F2[j][i][k] = F2[j][k][i] = v;
            }
        }
    }
}


//- (T : L)~_pqrs in the eigenbasis (Tt = T~ symmetric). The bilinear
//  form sum_ij T_ij d2E_ij[H, K] in the eigenbasis,
//    B = sum_(i,k,j) T~_ij F2_ikj (H~_ik K~_kj + K~_ik H~_kj),
//  has the unsymmetrised second derivative d2B/dH~_pq dK~_rs
//    L0_pqrs = d_qr T~_ps F2_pqs + d_ps T~_rq F2_rpq;
//  for symmetric perturbations 4 sym_(pq) sym_(rs) L0 is the sum of the
//  four index swaps
double tlEntry
(
    const mat3& Tt,
    const double F2[3][3][3],
    int a, int b, int c, int d
)
{
    auto L0 = [&](int p, int q, int r, int s)
    {
        double v = 0;
        if (q == r) v += Tt(p, s)*F2[p][q][s];
        if (p == s) v += Tt(r, q)*F2[r][p][q];
        return v;
    };
    return L0(a, b, c, d) + L0(b, a, c, d) + L0(a, b, d, c) + L0(b, a, d, c);
}


//- Kronecker product K(3 i + j, 3 I + J) = F_iI F_jJ, so that
//  (K A K^T)_ijkl = F_iI F_jJ F_kK F_lL A_IJKL
tensor4 kron(const mat3& F)
{
    tensor4 K;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int I = 0; I < 3; ++I)
                for (int J = 0; J < 3; ++J)
                    K(3*i + j, 3*I + J) = F(i, I)*F(j, J);
    return K;
}

//- Average of the eight copies A_ijkl, A_jikl, A_ijlk, A_jilk and their
//  major transposes: removes the rounding-level asymmetry left by the
//  rotation, so that toVoigt/fromVoigt round trips are exact
tensor4 symmetrise(const tensor4& A)
{
    mat6 M;
    for (int a = 0; a < 6; ++a)
    {
        for (int b = a; b < 6; ++b)
        {
            const int i = voigtI[a], j = voigtJ[a];
            const int k = voigtI[b], l = voigtJ[b];
            M(a, b) = M(b, a) = 0.125*
            (
                A(3*i + j, 3*k + l) + A(3*j + i, 3*k + l)
              + A(3*i + j, 3*l + k) + A(3*j + i, 3*l + k)
              + A(3*k + l, 3*i + j) + A(3*k + l, 3*j + i)
              + A(3*l + k, 3*i + j) + A(3*l + k, 3*j + i)
            );
        }
    }
    return fromVoigt(M);
}

} // namespace


double logDividedDifference(double a, double b)
{
    // f[a,b] = ln(a/b)/(2(a - b)) = atanh(d)/(d (a + b)), d = (a-b)/(a+b);
    // ordered arguments make the result bitwise symmetric
    if (a < b) std::swap(a, b);
    const double s = a + b;
    const double d = (a - b)/s;
    if (std::abs(d) < atanhFormLimit)
    {
        return phi(d)/s;
    }
    // a/b outside (1/3, 3): 1 -+ d would lose digits to cancellation
    // inside atanh, whereas ln(a/b) (|ln(a/b)| > ln 3) is accurate
    return std::log(a/b)/(2*(a - b));
}


double logDividedDifference(double a, double b, double c)
{
    // Sort a <= b <= c (the divided difference is symmetric)
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return secondDividedDifferenceSorted
    (
        a, b, c, logDividedDifference(a, b), logDividedDifference(b, c)
    );
}


void logStrain(const mat3& C, mat3& E, tensor4& P)
{
    vec3 lambda;
    mat3 Q;
    spectralDecomposition(C, lambda, Q);

    const vec3 f = 0.5*lambda.array().log().matrix();
    E = Q*f.asDiagonal()*Q.transpose();
    E = 0.5*(E + E.transpose());

    // Eigenbasis: P~_pqrs = f[l_p, l_q] (d_pr d_qs + d_ps d_qr)
    const mat3 F1 = firstDifferences(lambda);
    tensor4 Pt = tensor4::Zero();
    for (int p = 0; p < 3; ++p)
    {
        for (int q = 0; q < 3; ++q)
        {
            Pt(3*p + q, 3*p + q) += F1(p, q);
            Pt(3*p + q, 3*q + p) += F1(p, q);
        }
    }
    P = symmetrise(pushForward(Pt, Q));
}


tensor4 logStrainSecond(const mat3& C, const mat3& T)
{
    if (!T.allFinite())
    {
        throw numericalError("logStrainSecond: T has non-finite entries");
    }
    vec3 lambda;
    mat3 Q;
    spectralDecomposition(C, lambda, Q);

    const mat3 F1 = firstDifferences(lambda);
    double F2[3][3][3];
    secondDifferences(lambda, F1, F2);
    const mat3 Tt = Q.transpose()*(0.5*(T + T.transpose()))*Q;
    tensor4 Lt;
    for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q)
            for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s)
                    Lt(3*p + q, 3*r + s) = tlEntry(Tt, F2, p, q, r, s);

    return symmetrise(pushForward(Lt, Q));
}


logStrainMap::logStrainMap(const mat3& C)
{
    spectralDecomposition(C, lambda_, Q_);
    const vec3 f = 0.5*lambda_.array().log().matrix();
    E_ = Q_*f.asDiagonal()*Q_.transpose();
    E_ = 0.5*(E_ + E_.transpose());
    F1_ = firstDifferences(lambda_);
    for (int a = 0; a < 6; ++a) p_(a) = 2*F1_(voigtI[a], voigtJ[a]);
}


mat3 logStrainMap::stress(const mat3& T) const
{
    // S~_rs = 2 f[l_r, l_s] T~_rs
    mat3 St = Q_.transpose()*(0.5*(T + T.transpose()))*Q_;
    for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s)
            St(r, s) *= 2*F1_(r, s);
    const mat3 S = Q_*St*Q_.transpose();
    return 0.5*(S + S.transpose());
}


mat6 logStrainMap::tangent(const mat6& A, const mat3& T) const
{
    if (!T.allFinite())
    {
        throw numericalError("logStrainMap: T has non-finite entries");
    }
    double F2[3][3][3];
    secondDifferences(lambda_, F1_, F2);
    const mat3 Tt = Q_.transpose()*(0.5*(T + T.transpose()))*Q_;

    // Eigenbasis: diag(p) A~ diag(p) + (T : L)~ (the symmetric part of the
    // latter, as logStrainSecond symmetrises)
    const mat6 R = voigtTransform(Q_);
    const mat6 Rt = voigtTransform(Q_.transpose());
    mat6 M = p_.asDiagonal()*(Rt*A*Rt.transpose())*p_.asDiagonal();
    mat6 L;
    for (int a = 0; a < 6; ++a)
    {
        const int p = voigtI[a], q = voigtJ[a];
        for (int b = 0; b < 6; ++b)
        {
            const int r = voigtI[b], s = voigtJ[b];
            L(a, b) = tlEntry(Tt, F2, p, q, r, s);
        }
    }
    M += 0.5*(L + L.transpose());
    return R*M*R.transpose();
}


mat6 toVoigt(const tensor4& A)
{
    mat6 M;
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
            M(a, b) = A(3*voigtI[a] + voigtJ[a], 3*voigtI[b] + voigtJ[b]);
    return M;
}


tensor4 fromVoigt(const mat6& M)
{
    tensor4 A;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    A(3*i + j, 3*k + l) =
                        M(voigtIndex[i][j], voigtIndex[k][l]);
    return A;
}


tensor4 pushForward(const tensor4& A, const mat3& F)
{
    const tensor4 K = kron(F);
    return K*A*K.transpose();
}


mat3 contract(const tensor4& A, const mat3& T)
{
    mat3 R = mat3::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    R(i, j) += A(3*i + j, 3*k + l)*T(k, l);
    return R;
}


mat3 contractLeft(const mat3& T, const tensor4& A)
{
    mat3 R = mat3::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    R(k, l) += T(i, j)*A(3*i + j, 3*k + l);
    return R;
}

} // namespace form
