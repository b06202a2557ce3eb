/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of upHex.H: the u/p hexahedra (Hex8, Hex27, Hex8P1,
    Hex27P4): kinematics, internal force and consistent tangent, mass
    matrix, inf-sup test matrices and averaged results.
\*---------------------------------------------------------------------------*/
#include "upHex.H"
#include "hexShape.H"
#include "upElementTools.H"
#include "formError.H"
#include <cmath>

namespace form
{

template<int NN, int NP>
upHex<NN, NP>::upHex
(
    const std::string& name,
    int nGauss,
    analysisType analysis
)
:
    name_(name),
    nGauss_(nGauss),
    qp_(gaussLegendreHex(nGauss))
{
    if (analysis != analysisType::solid3D)
    {
        throw inputError
        (
            "analysisType",
            "element type " + name + " is a hexahedron: it needs"
            " analysisType solid3D, not " + analysisTypeName(analysis)
        );
    }
}


template<int NN, int NP>
std::vector<int> upHex<NN, NP>::edgeNodes(int face) const
{
    return hexFaceNodes(NN, face);
}


template<int NN, int NP>
void upHex<NN, NP>::checkSize(const matX& A, const char* what) const
{
    checkNodeMatrix(name_, A, what, NN, 3);
}


template<int NN, int NP>
typename upHex<NN, NP>::pointGeometry upHex<NN, NP>::geometry
(
    const matX& X,
    const quadraturePoint3D& q,
    int elementId
) const
{
    pointGeometry g;
    matN3 dNdr;
    hexShape<NN>::eval(q.r, q.s, q.t, g.N, dNdr);

    // J0(i, j) = dX_i/dr_j; dN/dX = dN/dr J0^-1 (Bathe FEP sec. 5.3)
    const mat3 J0 = X.transpose()*dNdr;
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
    g.dV = q.w*detJ0;
    return g;
}


template<int NN, int NP>
typename upHex<NN, NP>::vecP upHex<NN, NP>::pressureShape
(
    const quadraturePoint3D& q
)
{
    vecP Np;
    if constexpr (NP == 4) Np << 1, q.r, q.s, q.t;
    else Np.setOnes();
    return Np;
}


template<int NN, int NP>
void upHex<NN, NP>::kinematics
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
    const matN3 uN = u;
    for (std::size_t q = 0; q < qp_.size(); ++q)
    {
        pointKinematics& pk = k.pt[q];
        pk.g = geometry(X, qp_[q], elementId);
        pk.Np = pressureShape(qp_[q]);
        pk.F = mat3::Identity() + uN.transpose()*pk.g.dNdX;
        pk.J = pk.F.determinant();
        if (linear)
        {
            pk.dNdx = pk.g.dNdX;
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
                  + "): det F = " + formatNumber(pk.J)
                  + " <= 0 at quadrature point " + std::to_string(q)
                );
            }
            pk.dNdx = pk.g.dNdX*pk.F.inverse();   // dN/dx = dN/dX F^-1
            pk.lnJ = std::log(pk.J);
        }

        // Voigt rows (xx, yy, zz, xy, yz, xz), engineering shears
        pk.B.setZero(6, nDof);
        for (int a = 0; a < NN; ++a)
        {
            const double gx = pk.dNdx(a, 0);
            const double gy = pk.dNdx(a, 1);
            const double gz = pk.dNdx(a, 2);
            pk.B(0, elementDof(3, a, 0)) = gx;
            pk.B(1, elementDof(3, a, 1)) = gy;
            pk.B(2, elementDof(3, a, 2)) = gz;
            pk.B(3, elementDof(3, a, 0)) = gy;
            pk.B(3, elementDof(3, a, 1)) = gx;
            pk.B(4, elementDof(3, a, 1)) = gz;
            pk.B(4, elementDof(3, a, 2)) = gy;
            pk.B(5, elementDof(3, a, 0)) = gz;
            pk.B(5, elementDof(3, a, 2)) = gx;
        }
    }

    if constexpr (NP > 0)
    {
        projectPressure(k, int(qp_.size()), kappa);
    }
}


template<int NN, int NP>
bool upHex<NN, NP>::compute
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

    // 1 = m, I_sym = diag(1, 1, 1, 1/2, 1/2, 1/2) in Voigt form
    vec6 m;
    m << 1, 1, 1, 0, 0, 0;
    vec6 iSym;
    iSym << 1, 1, 1, 0.5, 0.5, 0.5;

    vecX f = vecX::Zero(nDof);
    vecX fT;
    if (fTracked) fT.setZero(nDof);
    matX Kt;
    if (K) Kt.setZero(nDof, nDof);

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
        const double dV = pk.g.dV;

        f += pk.B.transpose()*toVoigtStress(tauR)*dV;
        const double p = NP > 0 ? double(pk.Np.dot(pTangent)) : pR;
        const mat3 tau = tauDev + p*mat3::Identity();
        if (fTracked) fT += pk.B.transpose()*toVoigtStress(tau)*dV;
        if (!K) continue;

        mat6 c = cDev;
        if (NP == 0) c += kappa*m*m.transpose();
        if (!linear) c.diagonal() -= 2*p*iSym;
        Kt.noalias() += pk.B.transpose()*(c*pk.B)*dV;

        if (!linear)
        {
            // Geometric stiffness G^T (tau (x) I) G
            const Eigen::Matrix<double, NN, NN> kg =
                pk.dNdx*tau*pk.dNdx.transpose()*dV;
            for (int a = 0; a < NN; ++a)
            {
                for (int b = 0; b < NN; ++b)
                {
                    for (int i = 0; i < 3; ++i) Kt(elementDof(3, a, i), elementDof(3, b, i)) += kg(a, b);
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
        *K = std::move(Kt);
    }
    return true;
}


template<int NN, int NP>
matX upHex<NN, NP>::massMatrix(const matX& X) const
{
    // One more point per direction than the stiffness rule: exact for
    // N_a N_b on parallelepipeds
    checkSize(X, "X");
    matX M = matX::Zero(nDof, nDof);
    for (const quadraturePoint3D& q : gaussLegendreHex(nGauss_ + 1))
    {
        const pointGeometry g = geometry(X, q, -1);
        const Eigen::Matrix<double, NN, NN> mq = g.N*g.N.transpose()*g.dV;
        for (int a = 0; a < NN; ++a)
        {
            for (int b = 0; b < NN; ++b)
            {
                for (int i = 0; i < 3; ++i) M(elementDof(3, a, i), elementDof(3, b, i)) += mq(a, b);
            }
        }
    }
    return M;
}


template<int NN, int NP>
std::vector<double> upHex<NN, NP>::pointVolumes(const matX& X) const
{
    checkSize(X, "X");
    std::vector<double> v;
    for (const quadraturePoint3D& q : qp_) v.push_back(geometry(X, q, -1).dV);
    return v;
}


template<int NN, int NP>
infSupMatrices upHex<NN, NP>::infSup(const matX& X) const
{
    checkSize(X, "X");
    infSupMatrices s;
    s.Kpu = matX::Zero(NP, nDof);
    s.Mp = matX::Zero(NP, NP);
    s.T = matX::Zero(nDof, nDof);
    for (const quadraturePoint3D& q : qp_)
    {
        const pointGeometry g = geometry(X, q, -1);
        const double dV = g.dV;
        // H1: grad u : grad u + u . u
        const Eigen::Matrix<double, NN, NN> t =
            (g.dNdX*g.dNdX.transpose() + g.N*g.N.transpose())*dV;
        Eigen::RowVectorXd div(nDof);
        for (int a = 0; a < NN; ++a)
        {
            for (int i = 0; i < 3; ++i)
            {
                div(elementDof(3, a, i)) = g.dNdX(a, i);
                for (int b = 0; b < NN; ++b) s.T(elementDof(3, a, i), elementDof(3, b, i)) += t(a, b);
            }
        }
        if constexpr (NP > 0)
        {
            const vecP Np = pressureShape(q);
            s.Kpu += Np*div*dV;
            s.Mp += Np*Np.transpose()*dV;
        }
    }
    return s;
}


template<int NN, int NP>
elementResult upHex<NN, NP>::result
(
    const matX& X,
    const matX& u,
    const material& mat,
    const std::vector<materialState>& states
) const
{
    const int nQ = nQuadrature();
    checkStateCount(name_ + " result", states.size(), nQ);
    const double kappa = mat.bulkModulus();
    elementKinematics k;
    kinematics(X, u, mat.geometricallyLinear(), kappa, -1, k);
    return averageResult
    (
        name_, k, nQ, mat, states,
        [&](int q) { return pressure(k, q, kappa); }
    );
}


// * * * * * * * * * * * * * * Instantiation  * * * * * * * * * * * * * * * //

template class upHex<8, 0>;
template class upHex<27, 0>;
template class upHex<8, 1>;
template class upHex<27, 4>;

namespace
{
template<int NN, int NP>
bool addHex(const std::string& name, int nGauss)
{
    solidElement::registry()[name] = [name, nGauss](analysisType a)
        -> std::unique_ptr<solidElement>
    {
        return std::make_unique<upHex<NN, NP>>(name, nGauss, a);
    };
    return true;
}

const bool hexesAdded =
    addHex<8, 0>("Hex8", 2)
 && addHex<27, 0>("Hex27", 3)
 && addHex<8, 1>("Hex8P1", 2)
 && addHex<27, 4>("Hex27P4", 3);
} // anonymous namespace

} // namespace form
