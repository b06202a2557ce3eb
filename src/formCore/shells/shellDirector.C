/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Large rotations of a shell director (shellDirector.H).
\*---------------------------------------------------------------------------*/
#include "shellDirector.H"
#include "formError.H"
#include <cmath>

namespace form
{

void shellDirector::coefficients
(
    double q,
    double& c,
    double& s,
    double& dc,
    double& ds,
    double& d2c,
    double& d2s
)
{
    if (q < 1)
    {
        // c = sum (-q)^n/(2n)!, s = sum (-q)^n/(2n+1)! and their
        // derivatives term by term: 16 terms leave less than 1e-17 for
        // q < 1 (no cancellation near q = 0)
        c = s = dc = ds = d2c = d2s = 0;
        double fc = 1, fs = 1;      // 1/(2n)!, 1/(2n+1)!
        double q0 = 1, q1 = 0, q2 = 0;  // q^n, n q^(n-1), n(n-1) q^(n-2)
        for (int n = 0; n < 16; ++n)
        {
            if (n > 0)
            {
                fc /= (2.0*n - 1)*(2.0*n);
                fs /= (2.0*n)*(2.0*n + 1);
                q2 = n >= 2 ? n*(n - 1)*std::pow(q, n - 2) : 0;
                q1 = n*std::pow(q, n - 1);
                q0 = std::pow(q, n);
            }
            const double sign = n % 2 ? -1 : 1;
            c += sign*fc*q0;
            s += sign*fs*q0;
            dc += sign*fc*q1;
            ds += sign*fs*q1;
            d2c += sign*fc*q2;
            d2s += sign*fs*q2;
        }
        return;
    }
    const double phi = std::sqrt(q);
    c = std::cos(phi);
    s = std::sin(phi)/phi;
    dc = -0.5*s;
    ds = 0.5*(c - s)/q;
    d2c = -0.5*ds;
    d2s = 0.5*(dc - ds)/q - 0.5*(c - s)/(q*q);
}


double shellDirector::cosMinusOne(double q)
{
    if (q < 1)
    {
        // sum over n >= 1 of (-q)^n/(2n)!
        double sum = 0, term = 1;
        for (int n = 1; n < 16; ++n)
        {
            term *= -q/((2.0*n - 1)*(2.0*n));
            sum += term;
        }
        return sum;
    }
    const double h = std::sin(0.5*std::sqrt(q));
    return -2*h*h;
}


shellDirector shellDirector::of(const vec3& V0)
{
    const double L = V0.norm();
    if (!(L > 0) || !V0.allFinite())
    {
        throw numericalError("shellDirector: a zero or non-finite director");
    }
    shellDirector d;
    d.V = V0/L;
    int i = 0;
    for (int j = 1; j < 3; ++j)
    {
        if (std::abs(d.V(j)) < std::abs(d.V(i))) i = j;
    }
    vec3 e = vec3::Zero();
    e(i) = 1;
    d.V1 = (e - d.V*d.V.dot(e)).normalized();
    d.V2 = d.V.cross(d.V1);
    return d;
}


directorState shellDirector::at(double alpha, double beta) const
{
    const double q = alpha*alpha + beta*beta;
    double c, s, dc, ds, d2c, d2s;
    coefficients(q, c, s, dc, ds, d2c, d2s);
    const vec3 w = beta*V1 - alpha*V2;
    const vec3 u = dc*V + ds*w;             // c' V_n + s' w
    const vec3 u2 = d2c*V + d2s*w;          // c'' V_n + s'' w

    directorState D;
    D.V = c*V + s*w;
    D.dVc = cosMinusOne(q)*V + s*w;
    D.dV.col(0) = 2*alpha*u - s*V2;
    D.dV.col(1) = 2*beta*u + s*V1;
    D.d2V[0] = 4*alpha*alpha*u2 + 2*u - 4*alpha*ds*V2;
    D.d2V[1] = 4*alpha*beta*u2 + 2*alpha*ds*V1 - 2*beta*ds*V2;
    D.d2V[2] = 4*beta*beta*u2 + 2*u + 4*beta*ds*V1;
    return D;
}


void shellDirector::commit(double alpha, double beta)
{
    const double q = alpha*alpha + beta*beta;
    if (q == 0) return;
    double c, s, dc, ds, d2c, d2s;
    coefficients(q, c, s, dc, ds, d2c, d2s);
    // (1 - c)/q without cancellation: 1 - cos(phi) = 2 sin^2(phi/2), so
    // (1 - c)/q = s(q/4)^2/2
    double ch, sh, dch, dsh, d2ch, d2sh;
    coefficients(0.25*q, ch, sh, dch, dsh, d2ch, d2sh);
    const double k = 0.5*sh*sh;
    const vec3 theta = alpha*V1 + beta*V2;
    const auto rotate = [&](const vec3& v)
    {
        return vec3(c*v + s*theta.cross(v) + k*theta*theta.dot(v));
    };
    const vec3 V1r = rotate(V1);
    V = at(alpha, beta).V.normalized();
    // Re-orthonormalise against round-off drift
    V1 = (V1r - V*V.dot(V1r)).normalized();
    V2 = V.cross(V1);
}

} // namespace form
