/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    upQuad: reference geometry, kinematics, internal force and consistent
    (condensed) tangent; registration of Q4, Q9, Q4P1 and Q9P3. Equations
    in upQuad.H.
\*---------------------------------------------------------------------------*/
#include "upQuad.H"
#include "quadShape.H"
#include "upElementTools.H"
#include "formError.H"
#include <cmath>
#include <sstream>

namespace form
{

namespace
{
const double twoPi = 2*M_PI;

} // anonymous namespace


template<int NN, int NP>
upQuad<NN, NP>::upQuad
(
    const std::string& name,
    int nGauss,
    analysisType analysis
)
:
    name_(name),
    analysis_(analysis),
    nGauss_(nGauss),
    qp_(gaussLegendreQuad(nGauss))
{
    if (analysis == analysisType::solid3D)
    {
        throw inputError
        (
            "analysisType",
            "element type '" + name + "' supports planeStrain and"
            " axisymmetric, not solid3D"
        );
    }
}


template<int NN, int NP>
std::vector<int> upQuad<NN, NP>::edgeNodes(int edge) const
{
    return quadEdgeNodes(NN, edge);
}


template<int NN, int NP>
void upQuad<NN, NP>::checkSize(const matX& A, const char* what) const
{
    checkNodeMatrix(name_, A, what, NN, 2);
}


template<int NN, int NP>
typename upQuad<NN, NP>::pointGeometry upQuad<NN, NP>::geometry
(
    const matX& X,
    const quadraturePoint2D& q,
    int elementId
) const
{
    pointGeometry g;
    matN2 dNdr;
    quadShape<NN>::eval(q.r, q.s, g.N, dNdr);

    // J0(i, j) = dX_i/dr_j; dN/dX = dN/dr J0^-1 (Bathe FEP sec. 5.3)
    const Eigen::Matrix2d J0 = X.transpose()*dNdr;
    const double detJ0 = J0.determinant();
    if (!(detJ0 > 0))
    {
        throw numericalError
        (
            "element " + std::to_string(elementId) + " (" + name_
          + "): reference Jacobian det J0 = " + formatNumber(detJ0)
          + " <= 0; the mesh cell is inverted or degenerate"
        );
    }
    g.dNdX = dNdr*J0.inverse();
    g.R = g.N.dot(X.col(0));
    g.dV = q.w*detJ0;
    if (analysis_ == analysisType::axisymmetric)
    {
        if (!(g.R > 0))
        {
            throw numericalError
            (
                "element " + std::to_string(elementId)
              + ": quadrature point at radius R = " + formatNumber(g.R)
              + " <= 0 in an axisymmetric model (x is the radius)"
            );
        }
        g.dV *= twoPi*g.R;
    }
    return g;
}


template<int NN, int NP>
typename upQuad<NN, NP>::vecP upQuad<NN, NP>::pressureShape
(
    double r,
    double s
)
{
    vecP Np;
    if constexpr (NP == 3) Np << 1, r, s;
    else Np.setOnes();
    return Np;
}


template<int NN, int NP>
void upQuad<NN, NP>::kinematics
(
    const matX& X,
    const matX& u,
    bool linear,
    double kappa,
    int elementId,
    elementKinematics& k
) const
{
    checkSize(X, "X");
    checkSize(u, "u");
    const bool axi = analysis_ == analysisType::axisymmetric;
    const Eigen::Matrix<double, NN, 2> uN = u;
    for (std::size_t q = 0; q < qp_.size(); ++q)
    {
        pointKinematics& pk = k.pt[q];
        pk.g = geometry(X, qp_[q], elementId);
        pk.Np = pressureShape(qp_[q].r, qp_[q].s);

        // F = I + Grad u; plane strain F_zz = 1, axisymmetric 1 + u_r/R
        const Eigen::Matrix2d F2 =
            Eigen::Matrix2d::Identity() + uN.transpose()*pk.g.dNdX;
        const double ur = pk.g.N.dot(uN.col(0));
        pk.F.setIdentity();
        pk.F.template topLeftCorner<2, 2>() = F2;
        if (axi) pk.F(2, 2) = 1 + ur/pk.g.R;
        pk.J = pk.F.determinant();

        if (linear)
        {
            pk.dNdx = pk.g.dNdX;
            pk.r = pk.g.R;
            pk.lnJ = pk.F.trace() - 3;    // tr(eps)
        }
        else
        {
            if (!(pk.J > 0))
            {
                throw inversionError
                (
                    elementId,
                    "element " + std::to_string(elementId) + " (" + name_
                  + "): det F = " + formatNumber(pk.J) + " <= 0 at quadrature point "
                  + std::to_string(q)
                );
            }
            pk.dNdx = pk.g.dNdX*F2.inverse();   // dN/dx = dN/dX F^-1
            pk.r = pk.g.R + ur;
            pk.lnJ = std::log(pk.J);
        }

        pk.B.setZero();
        for (int a = 0; a < NN; ++a)
        {
            pk.B(0, elementDof(2, a, 0)) = pk.dNdx(a, 0);
            pk.B(1, elementDof(2, a, 1)) = pk.dNdx(a, 1);
            if (axi) pk.B(2, elementDof(2, a, 0)) = pk.g.N(a)/pk.r;
            pk.B(3, elementDof(2, a, 0)) = pk.dNdx(a, 1);
            pk.B(3, elementDof(2, a, 1)) = pk.dNdx(a, 0);
        }
    }

    if constexpr (NP > 0)
    {
        projectPressure(k, int(qp_.size()), kappa);
    }
}


template<int NN, int NP>
bool upQuad<NN, NP>::compute
(
    const matX& X,
    const matX& u,
    const material& mat,
    const std::vector<materialState>& committed,
    std::vector<materialState>& trial,
    vecX& fint,
    matX* K,
    int elementId,
    const pressureLinearisation* tangentAt,
    pressureLinearisation* linearisation,
    vecX* fTracked
) const
{
    const int nQ = nQuadrature();
    checkStateCount
    (
        "element " + std::to_string(elementId) + " (" + name_ + ")",
        committed.size(), nQ
    );
    trial.resize(nQ);

    const bool linear = mat.geometricallyLinear();
    const bool axi = analysis_ == analysisType::axisymmetric;
    const double kappa = mat.bulkModulus();
    elementKinematics k;
    kinematics(X, u, linear, kappa, elementId, k);

    // The pressure of the tangent's p-terms and of fTracked (solidElement.H,
    // "tracked pressure"); the residual uses p_e(u)
    vecP pTangent = k.pe;
    if constexpr (NP > 0)
    {
        if ((K || fTracked) && !linear) pTangent = trackedPressure(k, u, tangentAt);
        if (K && linearisation) linearisePressure(k, u, kappa, *linearisation);
    }

    // Voigt rows (xx, yy, zz, xy): 1 = m, I_sym = diag(1, 1, 1, 1/2)
    const Eigen::Vector4d m(1, 1, 1, 0);
    const Eigen::Vector4d iSym(1, 1, 1, 0.5);

    Eigen::Matrix<double, nDof, 1> f = Eigen::Matrix<double, nDof, 1>::Zero();
    Eigen::Matrix<double, nDof, 1> fT = Eigen::Matrix<double, nDof, 1>::Zero();
    Eigen::Matrix<double, nDof, nDof> Kt =
        Eigen::Matrix<double, nDof, nDof>::Zero();

    for (int q = 0; q < nQ; ++q)
    {
        const pointKinematics& pk = k.pt[q];
        mat3 tauDev;
        mat6 cDev;
        if (!mat.deviatoric(pk.F, committed[q], trial[q], tauDev, cDev))
        {
            return false;
        }
        const double pR = pressure(k, q, kappa);
        const mat3 tauR = tauDev + pR*mat3::Identity();
        const Eigen::Vector4d tauV(tauR(0, 0), tauR(1, 1), tauR(2, 2), tauR(0, 1));
        const double dV = pk.g.dV;

        f += pk.B.transpose()*tauV*dV;
        const double p = NP > 0 ? double(pk.Np.dot(pTangent)) : pR;
        const mat3 tau = tauDev + p*mat3::Identity();
        if (fTracked)
        {
            fT += pk.B.transpose()
               *Eigen::Vector4d(tau(0, 0), tau(1, 1), tau(2, 2), tau(0, 1))*dV;
        }
        if (!K) continue;

        Eigen::Matrix4d c = cDev.topLeftCorner<4, 4>();
        if (NP == 0) c += kappa*m*m.transpose();
        if (!linear) c.diagonal() -= 2*p*iSym;
        Kt += pk.B.transpose()*c*pk.B*dV;

        if (!linear)
        {
            // Geometric stiffness G^T (tau (x) I) G: in-plane gradients and,
            // axisymmetric, the hoop term tau_zz N_a N_b / r^2
            const matN2& g = pk.dNdx;
            const Eigen::Matrix<double, NN, NN> kg =
                g*tau.topLeftCorner<2, 2>()*g.transpose()*dV;
            for (int a = 0; a < NN; ++a)
            {
                for (int b = 0; b < NN; ++b)
                {
                    Kt(elementDof(2, a, 0), elementDof(2, b, 0)) += kg(a, b);
                    Kt(elementDof(2, a, 1), elementDof(2, b, 1)) += kg(a, b);
                }
            }
            if (axi)
            {
                const vecN Nr = pk.g.N/pk.r;
                const Eigen::Matrix<double, NN, NN> kh =
                    tau(2, 2)*Nr*Nr.transpose()*dV;
                for (int a = 0; a < NN; ++a)
                {
                    for (int b = 0; b < NN; ++b) Kt(elementDof(2, a, 0), elementDof(2, b, 0)) += kh(a, b);
                }
            }
        }
    }

    fint = f;
    if (fTracked) *fTracked = fT;
    if (K)
    {
        if constexpr (NP > 0)
        {
            // Static condensation of p_e (solidElement.H)
            Kt += kappa*k.Kpu.transpose()*k.Mp.ldlt().solve(k.Kpu);
        }
        *K = Kt;
    }
    return true;
}


// * * * * * * * * * * * * * * Instantiation  * * * * * * * * * * * * * * * //

template class upQuad<4, 0>;
template class upQuad<9, 0>;
template class upQuad<4, 1>;
template class upQuad<9, 3>;

namespace
{
template<int NN, int NP>
bool addQuad(const std::string& name, int nGauss)
{
    solidElement::registry()[name] = [name, nGauss](analysisType a)
        -> std::unique_ptr<solidElement>
    {
        return std::make_unique<upQuad<NN, NP>>(name, nGauss, a);
    };
    return true;
}

const bool quadsAdded =
    addQuad<4, 0>("Q4", 2)
 && addQuad<9, 0>("Q9", 3)
 && addQuad<4, 1>("Q4P1", 2)
 && addQuad<9, 3>("Q9P3", 3);
} // anonymous namespace

} // namespace form
