/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Edge loads of 2D elements (see solidElement.H).

    Dead traction t per unit reference length (area):
        f_a = int N_a t dS0,   dS0 = |dX/dxi| dxi  (x 2 pi R if axisymmetric)
    Follower pressure p on the current edge x(xi), edge running counter-
    clockwise so that n ds = (y_xi, -x_xi) dxi is the outward normal:
        f_a = -p int N_a n ds  (x 2 pi r, r current, if axisymmetric)
    and the load stiffness K = -df/du (Simo, Taylor & Wriggers 1991;
    Bonet & Wood, Nonlinear Continuum Mechanics for FEA, sec. 8.5).
    Both integrands are polynomials of degree <= 5 in xi for straight or
    curved 3-node edges, so 3 Gauss points integrate them exactly.
\*---------------------------------------------------------------------------*/
#include "solidElement.H"
#include "gaussLegendre.H"
#include "quadShape.H"
#include "formError.H"
#include <cmath>

namespace form
{

namespace
{

//- The entry of component i (0: x or r, 1: y or z) of edge node b in the
//  edge's own force vector and matrix (2 entries per node, node by node;
//  the element maps them to its dofs)
constexpr int at(int b, int i) { return elementDof(2, b, i); }

void checkEdge(const matX& X, const char* where)
{
    if ((X.rows() != 2 && X.rows() != 3) || X.cols() != 2)
    {
        throw numericalError
        (
            std::string(where) + ": edge with " + std::to_string(X.rows())
          + "x" + std::to_string(X.cols()) + " coordinates; expected 2 or 3"
            " nodes x 2"
        );
    }
}
} // anonymous namespace


vecX edgeLoad::deadTraction
(
    const matX& X,
    const Eigen::Vector2d& t,
    analysisType a
)
{
    checkEdge(X, "edgeLoad::deadTraction");
    const int n = int(X.rows());
    const bool axi = a == analysisType::axisymmetric;
    std::vector<double> xi, w;
    gaussLegendre1D(3, xi, w);

    vecX f = vecX::Zero(2*n);
    vecX N, dN;
    for (std::size_t q = 0; q < xi.size(); ++q)
    {
        lineShape(n, xi[q], N, dN);
        const Eigen::Vector2d dXdxi = X.transpose()*dN;
        double dS = dXdxi.norm()*w[q];
        if (axi) dS *= 2*M_PI*N.dot(X.col(0));
        for (int b = 0; b < n; ++b) f.segment<2>(at(b, 0)) += N(b)*t*dS;
    }
    return f;
}


void edgeLoad::followerPressure
(
    const matX& X,
    const matX& u,
    double p,
    analysisType a,
    vecX& f,
    matX* K
)
{
    checkEdge(X, "edgeLoad::followerPressure");
    const int n = int(X.rows());
    if (u.rows() != n || u.cols() != 2)
    {
        throw numericalError
        (
            "edgeLoad::followerPressure: displacements are "
          + std::to_string(u.rows()) + "x" + std::to_string(u.cols())
          + ", coordinates " + std::to_string(n) + "x2"
        );
    }
    const bool axi = a == analysisType::axisymmetric;
    const matX x = X + u;
    std::vector<double> xi, w;
    gaussLegendre1D(3, xi, w);

    f = vecX::Zero(2*n);
    if (K) *K = matX::Zero(2*n, 2*n);
    vecX N, dN;
    for (std::size_t q = 0; q < xi.size(); ++q)
    {
        lineShape(n, xi[q], N, dN);
        const Eigen::Vector2d dxdxi = x.transpose()*dN;
        // Weight W = 2 pi r (current radius) or 1; dW/dx_b = 2 pi N_b
        const double W = axi ? 2*M_PI*N.dot(x.col(0)) : 1.0;
        const double c = p*w[q];
        for (int b = 0; b < n; ++b)
        {
            // f_b = -p N_b (y_xi, -x_xi) W
            f(at(b, 0)) += -c*N(b)*dxdxi(1)*W;
            f(at(b, 1)) += c*N(b)*dxdxi(0)*W;
        }
        if (!K) continue;
        for (int b = 0; b < n; ++b)
        {
            for (int d = 0; d < n; ++d)
            {
                // K = -df/du
                (*K)(at(b, 0), at(d, 1)) += c*N(b)*dN(d)*W;
                (*K)(at(b, 1), at(d, 0)) += -c*N(b)*dN(d)*W;
                if (axi)
                {
                    (*K)(at(b, 0), at(d, 0)) += c*N(b)*dxdxi(1)*2*M_PI*N(d);
                    (*K)(at(b, 1), at(d, 0)) += -c*N(b)*dxdxi(0)*2*M_PI*N(d);
                }
            }
        }
    }
}

} // namespace form
