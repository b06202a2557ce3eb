/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of hexShape.H: Lagrange shape functions on the
    reference cube in VTK node order and the face-node table.
\*---------------------------------------------------------------------------*/
#include "hexShape.H"
#include <stdexcept>
#include <string>

namespace form
{

namespace
{

// Natural coordinates of the VTK triquadratic hexahedron; the first eight
// are the corners of the trilinear one
constexpr double rNode[27] =
{
    -1,  1,  1, -1, -1,  1,  1, -1,
     0,  1,  0, -1,  0,  1,  0, -1, -1,  1,  1, -1,
    -1,  1,  0,  0,  0,  0,
     0
};
constexpr double sNode[27] =
{
    -1, -1,  1,  1, -1, -1,  1,  1,
    -1,  0,  1,  0, -1,  0,  1,  0, -1, -1,  1,  1,
     0,  0, -1,  1,  0,  0,
     0
};
constexpr double tNode[27] =
{
    -1, -1, -1, -1,  1,  1,  1,  1,
    -1, -1, -1, -1,  1,  1,  1,  1,  0,  0,  0,  0,
     0,  0,  0,  0, -1,  1,
     0
};

// Faces: corners counter-clockwise seen from outside, mid-edge nodes of
// the face's edges (0-1, 1-2, 2-3, 3-0), centre
constexpr int faceTable[6][9] =
{
    {0, 4, 7, 3, 16, 15, 19, 11, 20},   // r = -1
    {1, 2, 6, 5,  9, 18, 13, 17, 21},   // r = +1
    {0, 1, 5, 4,  8, 17, 12, 16, 22},   // s = -1
    {2, 3, 7, 6, 10, 19, 14, 18, 23},   // s = +1
    {0, 3, 2, 1, 11, 10,  9,  8, 24},   // t = -1
    {4, 5, 6, 7, 12, 13, 14, 15, 25}    // t = +1
};

// Quadratic Lagrange polynomial through -1, 0, 1 that is 1 at xiNode
inline void lagrange3(double xiNode, double x, double& l, double& dl)
{
    if (xiNode < -0.5)      { l = 0.5*x*(x - 1); dl = x - 0.5; }
    else if (xiNode > 0.5)  { l = 0.5*x*(x + 1); dl = x + 0.5; }
    else                    { l = 1 - x*x;       dl = -2*x; }
}

} // anonymous namespace


template<int NN>
Eigen::Vector3d hexShape<NN>::node(int a)
{
    return Eigen::Vector3d(rNode[a], sNode[a], tNode[a]);
}


template<>
void hexShape<8>::eval(double r, double s, double t, vecN& N, matN3& dN)
{
    for (int a = 0; a < 8; ++a)
    {
        const double lr = 1 + rNode[a]*r;
        const double ls = 1 + sNode[a]*s;
        const double lt = 1 + tNode[a]*t;
        N(a) = 0.125*lr*ls*lt;
        dN(a, 0) = 0.125*rNode[a]*ls*lt;
        dN(a, 1) = 0.125*lr*sNode[a]*lt;
        dN(a, 2) = 0.125*lr*ls*tNode[a];
    }
}


template<>
void hexShape<27>::eval(double r, double s, double t, vecN& N, matN3& dN)
{
    for (int a = 0; a < 27; ++a)
    {
        double lr, dlr, ls, dls, lt, dlt;
        lagrange3(rNode[a], r, lr, dlr);
        lagrange3(sNode[a], s, ls, dls);
        lagrange3(tNode[a], t, lt, dlt);
        N(a) = lr*ls*lt;
        dN(a, 0) = dlr*ls*lt;
        dN(a, 1) = lr*dls*lt;
        dN(a, 2) = lr*ls*dlt;
    }
}


template struct hexShape<8>;
template struct hexShape<27>;


vecX hexShapeValues(int nNodes, double r, double s, double t)
{
    if (nNodes == 8)
    {
        hexShape<8>::vecN N;
        hexShape<8>::matN3 dN;
        hexShape<8>::eval(r, s, t, N, dN);
        return N;
    }
    if (nNodes == 27)
    {
        hexShape<27>::vecN N;
        hexShape<27>::matN3 dN;
        hexShape<27>::eval(r, s, t, N, dN);
        return N;
    }
    throw std::invalid_argument
    (
        "hexShapeValues: " + std::to_string(nNodes) + "-node hexahedron;"
        " expected 8 or 27"
    );
}


std::vector<int> hexFaceNodes(int nNodes, int face)
{
    if ((nNodes != 8 && nNodes != 27) || face < 0 || face > 5)
    {
        throw std::invalid_argument
        (
            "hexFaceNodes: face " + std::to_string(face) + " of a "
          + std::to_string(nNodes) + "-node hexahedron"
        );
    }
    const int n = nNodes == 27 ? 9 : 4;
    return std::vector<int>(faceTable[face], faceTable[face] + n);
}

} // namespace form
