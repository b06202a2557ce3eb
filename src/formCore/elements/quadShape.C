/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of quadShape.H: Lagrange shape functions on the reference
    square [-1, 1]^2 in VTK node order (VTK_QUAD, VTK_BIQUADRATIC_QUAD).
\*---------------------------------------------------------------------------*/
#include "quadShape.H"
#include <cmath>
#include <stdexcept>

namespace form
{

namespace
{
// Natural coordinates of the VTK biquadratic quad; the first four are the
// corners of the bilinear quad
constexpr double rNode[9] = {-1, 1, 1, -1, 0, 1, 0, -1, 0};
constexpr double sNode[9] = {-1, -1, 1, 1, -1, 0, 1, 0, 0};

// Quadratic Lagrange polynomial through -1, 0, 1 that is 1 at xiNode
inline void lagrange3(double xiNode, double x, double& l, double& dl)
{
    if (xiNode < -0.5)      { l = 0.5*x*(x - 1); dl = x - 0.5; }
    else if (xiNode > 0.5)  { l = 0.5*x*(x + 1); dl = x + 0.5; }
    else                    { l = 1 - x*x;       dl = -2*x; }
}
} // anonymous namespace


template<int NN>
double quadShape<NN>::nodeR(int a) { return rNode[a]; }

template<int NN>
double quadShape<NN>::nodeS(int a) { return sNode[a]; }


template<>
void quadShape<4>::eval(double r, double s, vecN& N, matN2& dN)
{
    for (int a = 0; a < 4; ++a)
    {
        const double ra = rNode[a], sa = sNode[a];
        N(a) = 0.25*(1 + ra*r)*(1 + sa*s);
        dN(a, 0) = 0.25*ra*(1 + sa*s);
        dN(a, 1) = 0.25*sa*(1 + ra*r);
    }
}


template<>
void quadShape<9>::eval(double r, double s, vecN& N, matN2& dN)
{
    for (int a = 0; a < 9; ++a)
    {
        double lr, dlr, ls, dls;
        lagrange3(rNode[a], r, lr, dlr);
        lagrange3(sNode[a], s, ls, dls);
        N(a) = lr*ls;
        dN(a, 0) = dlr*ls;
        dN(a, 1) = lr*dls;
    }
}


template struct quadShape<4>;
template struct quadShape<9>;


void quadShapeEval(int nNodes, double r, double s, vecX& N, matX& dN)
{
    if (nNodes == 4)
    {
        quadShape<4>::vecN N4;
        quadShape<4>::matN2 dN4;
        quadShape<4>::eval(r, s, N4, dN4);
        N = N4;
        dN = dN4;
        return;
    }
    if (nNodes == 9)
    {
        quadShape<9>::vecN N9;
        quadShape<9>::matN2 dN9;
        quadShape<9>::eval(r, s, N9, dN9);
        N = N9;
        dN = dN9;
        return;
    }
    throw std::invalid_argument
    (
        "quadShapeValues: " + std::to_string(nNodes) + "-node quad; expected"
        " 4 or 9"
    );
}


vecX quadShapeValues(int nNodes, double r, double s)
{
    vecX N;
    matX dN;
    quadShapeEval(nNodes, r, s, N, dN);
    return N;
}


matX quadShapeSecond(int nNodes, double r, double s)
{
    if (nNodes != 4 && nNodes != 9)
    {
        throw std::invalid_argument
        (
            "quadShapeSecond: " + std::to_string(nNodes) + "-node quad;"
            " expected 4 or 9"
        );
    }
    matX d2(nNodes, 3);
    for (int a = 0; a < nNodes; ++a)
    {
        const double ra = rNode[a], sa = sNode[a];
        if (nNodes == 4)
        {
            // (1 + ra r)(1 + sa s)/4: only the mixed derivative
            d2.row(a) << 0, 0, 0.25*ra*sa;
            continue;
        }
        double lr, dlr, ls, dls;
        lagrange3(ra, r, lr, dlr);
        lagrange3(sa, s, ls, dls);
        // l'' of the quadratic through -1, 0, 1: 1 at the ends, -2 inside
        const double d2r = std::abs(ra) > 0.5 ? 1 : -2;
        const double d2s = std::abs(sa) > 0.5 ? 1 : -2;
        d2.row(a) << d2r*ls, lr*d2s, dlr*dls;
    }
    return d2;
}


std::vector<int> quadEdgeNodes(int nNodes, int edge)
{
    if ((nNodes != 4 && nNodes != 9) || edge < 0 || edge > 3)
    {
        throw std::invalid_argument
        (
            "quadEdgeNodes: edge " + std::to_string(edge) + " of a "
          + std::to_string(nNodes) + "-node quad"
        );
    }
    std::vector<int> nodes{edge, (edge + 1) % 4};
    if (nNodes == 9) nodes.push_back(4 + edge);
    return nodes;
}


vecX lineShapeSecond(int n)
{
    vecX d2 = vecX::Zero(n);
    if (n == 3) d2 << 1, 1, -2;
    return d2;
}


void lineShape(int n, double xi, vecX& N, vecX& dN)
{
    N.resize(n);
    dN.resize(n);
    if (n == 2)
    {
        N << 0.5*(1 - xi), 0.5*(1 + xi);
        dN << -0.5, 0.5;
    }
    else if (n == 3)
    {
        // start (-1), end (+1), middle (0)
        lagrange3(-1, xi, N(0), dN(0));
        lagrange3(1, xi, N(1), dN(1));
        lagrange3(0, xi, N(2), dN(2));
    }
    else
    {
        throw std::invalid_argument
        (
            "lineShape: " + std::to_string(n) + "-node edge; expected 2 or 3"
        );
    }
}

} // namespace form
