/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of gaussLegendre.H: Gauss-Legendre quadrature on [-1, 1]
    with n = 1..10 points (exact for polynomials of degree 2n - 1), its
    tensor products, and Gauss-Lobatto quadrature with n = 2..10 points.
\*---------------------------------------------------------------------------*/
#include "gaussLegendre.H"
#include <cmath>
#include <stdexcept>

namespace form
{

namespace
{

//- P_n(z) and P_n'(z) by the three-term recurrence
void legendre(int n, double z, double& P, double& dP)
{
    double p0 = 1, p1 = z;
    if (n == 0)
    {
        P = 1;
        dP = 0;
        return;
    }
    for (int k = 2; k <= n; ++k)
    {
        const double p2 = ((2*k - 1)*z*p1 - (k - 1)*p0)/k;
        p0 = p1;
        p1 = p2;
    }
    P = p1;
    dP = n*(z*p1 - p0)/(z*z - 1);
}

} // anonymous namespace


void gaussLegendre1D(int n, std::vector<double>& x, std::vector<double>& w)
{
    // Closed forms of the roots of the Legendre polynomials P_n
    switch (n)
    {
        case 1:
            x = {0};
            w = {2};
            break;
        case 2:
        {
            const double a = 1/std::sqrt(3.0);
            x = {-a, a};
            w = {1, 1};
            break;
        }
        case 3:
        {
            const double a = std::sqrt(0.6);
            x = {-a, 0, a};
            w = {5.0/9, 8.0/9, 5.0/9};
            break;
        }
        case 4:
        {
            const double r = 2*std::sqrt(1.2);
            const double a = std::sqrt((3 - r)/7), b = std::sqrt((3 + r)/7);
            const double wa = (18 + std::sqrt(30.0))/36;
            const double wb = (18 - std::sqrt(30.0))/36;
            x = {-b, -a, a, b};
            w = {wb, wa, wa, wb};
            break;
        }
        case 5:
        {
            const double r = 2*std::sqrt(10.0/7);
            const double a = std::sqrt(5 - r)/3, b = std::sqrt(5 + r)/3;
            const double wa = (322 + 13*std::sqrt(70.0))/900;
            const double wb = (322 - 13*std::sqrt(70.0))/900;
            x = {-b, -a, 0, a, b};
            w = {wb, wa, 128.0/225, wa, wb};
            break;
        }
        default:
        {
            if (n < 1 || n > 10)
            {
                throw std::invalid_argument
                (
                    "gaussLegendre1D: " + std::to_string(n)
                  + " points requested; available 1..10"
                );
            }
            x.assign(n, 0);
            w.assign(n, 0);
            for (int i = 0; i < n; ++i)
            {
                // the i-th root from the top, by Newton's method
                double z = std::cos(M_PI*(i + 0.75)/(n + 0.5));
                double P, dP;
                for (int it = 0; it < 100; ++it)
                {
                    legendre(n, z, P, dP);
                    const double dz = P/dP;
                    z -= dz;
                    if (std::abs(dz) < 1e-16) break;
                }
                legendre(n, z, P, dP);
                x[n - 1 - i] = z;
                w[n - 1 - i] = 2/((1 - z*z)*dP*dP);
            }
        }
    }
}


void gaussLobatto1D(int n, std::vector<double>& x, std::vector<double>& w)
{
    if (n < 2 || n > 10)
    {
        throw std::invalid_argument
        (
            "gaussLobatto1D: " + std::to_string(n)
          + " points requested; available 2..10"
        );
    }
    x.assign(n, 0);
    w.assign(n, 0);
    x[0] = -1;
    x[n - 1] = 1;
    w[0] = w[n - 1] = 2.0/(n*(n - 1));
    // Interior points: the roots of P'_{n-1}, which lie between those of
    // P_{n-1}; Newton on P'_{n-1} with P''_{n-1} from Legendre's equation
    // (1 - z^2) P'' = 2 z P' - m (m + 1) P, m = n - 1
    const int m = n - 1;
    for (int i = 1; i < n - 1; ++i)
    {
        double z = std::cos(M_PI*i/m);     // Chebyshev-Lobatto guess
        double P, dP;
        for (int it = 0; it < 100; ++it)
        {
            legendre(m, z, P, dP);
            const double d2P = (2*z*dP - m*(m + 1)*P)/(1 - z*z);
            const double dz = dP/d2P;
            z -= dz;
            if (std::abs(dz) < 1e-16) break;
        }
        legendre(m, z, P, dP);
        x[n - 1 - i] = z;
        w[n - 1 - i] = 2/(n*(n - 1)*P*P);
    }
}


std::vector<quadraturePoint2D> gaussLegendreQuad(int n)
{
    std::vector<double> x, w;
    gaussLegendre1D(n, x, w);
    std::vector<quadraturePoint2D> pts;
    pts.reserve(n*n);
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            pts.push_back({x[i], x[j], w[i]*w[j]});
        }
    }
    return pts;
}

std::vector<quadraturePoint3D> gaussLegendreHex(int n)
{
    std::vector<double> x, w;
    gaussLegendre1D(n, x, w);
    std::vector<quadraturePoint3D> pts;
    pts.reserve(n*n*n);
    for (int k = 0; k < n; ++k)
    {
        for (int j = 0; j < n; ++j)
        {
            for (int i = 0; i < n; ++i)
            {
                pts.push_back({x[i], x[j], x[k], w[i]*w[j]*w[k]});
            }
        }
    }
    return pts;
}


std::vector<quadraturePoint2D> gaussTriangle7()
{
    // Dunavant (1985) degree 5; Hammer, Marlowe & Stroud (1956): the
    // centroid and two orbits of three points, weights summing to the
    // triangle's area 1/2
    const double q = std::sqrt(15.0);
    const double a1 = (6 - q)/21, b1 = (9 + 2*q)/21, w1 = (155 - q)/2400;
    const double a2 = (6 + q)/21, b2 = (9 - 2*q)/21, w2 = (155 + q)/2400;
    return
    {
        {1.0/3, 1.0/3, 9.0/80},
        {a1, a1, w1}, {b1, a1, w1}, {a1, b1, w1},
        {a2, a2, w2}, {b2, a2, w2}, {a2, b2, w2}
    };
}

} // namespace form
