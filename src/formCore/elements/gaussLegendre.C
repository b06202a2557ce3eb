/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of gaussLegendre.H: Gauss-Legendre quadrature on [-1, 1]
    with n = 1..5 points (exact for polynomials of degree 2n - 1) and its
    tensor product on [-1, 1]^2.
\*---------------------------------------------------------------------------*/
#include "gaussLegendre.H"
#include <cmath>
#include <stdexcept>

namespace form
{

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
            throw std::invalid_argument
            (
                "gaussLegendre1D: " + std::to_string(n)
              + " points requested; available 1..5"
            );
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

} // namespace form
