/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Face loads of 3D elements (see solidElement.H).

    Dead traction t per unit reference area on a 4- or 9-node face X(xi, eta):
        f_a = int N_a t dA0,   dA0 = |X_xi x X_eta| dxi deta
    integrated with 3 x 3 Gauss points (exact on flat parallelogram faces,
    where |X_xi x X_eta| is constant and N_a of degree <= 2 per direction).
\*---------------------------------------------------------------------------*/
#include "solidElement.H"
#include "gaussLegendre.H"
#include "quadShape.H"
#include "formError.H"

namespace form
{

vecX faceLoad::deadTraction(const matX& X, const vec3& t)
{
    const int n = int(X.rows());
    if ((n != 4 && n != 9) || X.cols() != 3)
    {
        throw numericalError
        (
            "faceLoad::deadTraction: face with " + std::to_string(X.rows())
          + "x" + std::to_string(X.cols()) + " coordinates; expected 4 or 9"
            " nodes x 3"
        );
    }
    vecX f = vecX::Zero(3*n);
    for (const quadraturePoint2D& q : gaussLegendreQuad(3))
    {
        vecX N;
        matX dN;
        if (n == 4)
        {
            quadShape<4>::vecN N4;
            quadShape<4>::matN2 dN4;
            quadShape<4>::eval(q.r, q.s, N4, dN4);
            N = N4;
            dN = dN4;
        }
        else
        {
            quadShape<9>::vecN N9;
            quadShape<9>::matN2 dN9;
            quadShape<9>::eval(q.r, q.s, N9, dN9);
            N = N9;
            dN = dN9;
        }
        const vec3 Xr = X.transpose()*dN.col(0);
        const vec3 Xs = X.transpose()*dN.col(1);
        const double dA = Xr.cross(Xs).norm()*q.w;
        for (int a = 0; a < n; ++a) f.segment<3>(3*a) += N(a)*dA*t;
    }
    return f;
}

} // namespace form
