/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Face loads of 3D elements (see solidElement.H).

    Faces: 4- and 9-node quadrilaterals (3 x 3 Gauss points) and 3-node
    triangles (the mid-surface faces of MITC3+ shells; 7 points,
    gaussLegendre.H: exact, their integrands being of degree <= 2).

    Dead traction t per unit reference area on a face X(xi, eta):
        f_a = int N_a t dA0,   dA0 = |X_xi x X_eta| dxi deta
    integrated with 3 x 3 Gauss points (exact on flat parallelogram faces,
    where |X_xi x X_eta| is constant and N_a of degree <= 2 per direction).

    Follower pressure p on the current face x = X + u (outward normal
    n da = x_xi x x_eta dxi deta, the face's corners counter-clockwise seen
    from outside):
        f_a = -p int N_a (x_xi x x_eta) dxi deta
    and its load stiffness K = -df/du: with d(x_xi x x_eta)/dx_b . v =
    N_b,xi (v x x_eta) + N_b,eta (x_xi x v) = (N_b,eta [x_xi]_x -
    N_b,xi [x_eta]_x) v, where [a]_x v = a x v,
        K_ab = p int N_a (N_b,eta [x_xi]_x - N_b,xi [x_eta]_x) dxi deta
    (Bonet & Wood, Nonlinear Continuum Mechanics for FEA, 2nd ed.,
    sec. 8.4.2; unsymmetric per face, symmetric when assembled over a
    closed surface: W = -p V is a potential). 3 x 3 Gauss points integrate
    the 9-node face's polynomial integrand exactly.
\*---------------------------------------------------------------------------*/
#include "solidElement.H"
#include "gaussLegendre.H"
#include "quadShape.H"
#include "formError.H"

namespace form
{

namespace
{

//- The face's quadrature rule and shape functions (3, 4 or 9 nodes)
const std::vector<quadraturePoint2D>& faceRule(int n)
{
    static const std::vector<quadraturePoint2D> quad = gaussLegendreQuad(3);
    static const std::vector<quadraturePoint2D> tri = gaussTriangle7();
    return n == 3 ? tri : quad;
}

void faceShape(int n, double r, double s, vecX& N, matX& dN)
{
    if (n != 3)
    {
        quadShapeEval(n, r, s, N, dN);
        return;
    }
    N.resize(3);
    N << 1 - r - s, r, s;
    dN.resize(3, 2);
    dN << -1, -1, 1, 0, 0, 1;
}

} // anonymous namespace


vecX faceLoad::deadTraction(const matX& X, const vec3& t)
{
    const int n = int(X.rows());
    if ((n != 3 && n != 4 && n != 9) || X.cols() != 3)
    {
        throw numericalError
        (
            "faceLoad::deadTraction: face with " + std::to_string(X.rows())
          + "x" + std::to_string(X.cols()) + " coordinates; expected 3, 4"
            " or 9 nodes x 3"
        );
    }
    vecX f = vecX::Zero(3*n);
    for (const quadraturePoint2D& q : faceRule(n))
    {
        vecX N;
        matX dN;
        faceShape(n, q.r, q.s, N, dN);
        const vec3 Xr = X.transpose()*dN.col(0);
        const vec3 Xs = X.transpose()*dN.col(1);
        const double dA = Xr.cross(Xs).norm()*q.w;
        for (int a = 0; a < n; ++a) f.segment<3>(elementDof(3, a, 0)) += N(a)*dA*t;
    }
    return f;
}


void faceLoad::followerPressure
(
    const matX& X,
    const matX& u,
    double p,
    vecX& f,
    matX* K
)
{
    const int n = int(X.rows());
    if
    (
        (n != 3 && n != 4 && n != 9) || X.cols() != 3
     || u.rows() != n || u.cols() != 3
    )
    {
        throw numericalError
        (
            "faceLoad::followerPressure: face with " + std::to_string(X.rows())
          + "x" + std::to_string(X.cols()) + " coordinates and "
          + std::to_string(u.rows()) + "x" + std::to_string(u.cols())
          + " displacements; expected 3, 4 or 9 nodes x 3"
        );
    }
    const matX x = X + u;
    const auto skew = [](const vec3& a)
    {
        mat3 W;
        W << 0, -a(2), a(1), a(2), 0, -a(0), -a(1), a(0), 0;
        return W;
    };
    f = vecX::Zero(3*n);
    if (K) *K = matX::Zero(3*n, 3*n);
    vecX N;
    matX dN;
    for (const quadraturePoint2D& q : faceRule(n))
    {
        faceShape(n, q.r, q.s, N, dN);
        const vec3 xr = x.transpose()*dN.col(0);
        const vec3 xs = x.transpose()*dN.col(1);
        const vec3 nda = xr.cross(xs)*q.w;
        for (int a = 0; a < n; ++a) f.segment<3>(elementDof(3, a, 0)) += -p*N(a)*nda;
        if (!K) continue;
        const mat3 Wr = skew(xr)*(p*q.w);
        const mat3 Ws = skew(xs)*(p*q.w);
        for (int b = 0; b < n; ++b)
        {
            const mat3 Gb = dN(b, 1)*Wr - dN(b, 0)*Ws;
            for (int a = 0; a < n; ++a)
            {
                K->block<3, 3>(elementDof(3, a, 0), elementDof(3, b, 0)) += N(a)*Gb;
            }
        }
    }
}

} // namespace form
