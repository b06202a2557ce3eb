/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    upQuad: mass matrix, point volumes, inf-sup test matrices and averaged
    results (the internal force and tangent are in upQuad.C).
\*---------------------------------------------------------------------------*/
#include "upQuad.H"
#include "upElementTools.H"
#include "formError.H"

namespace form
{

template<int NN, int NP>
matX upQuad<NN, NP>::massMatrix(const matX& X) const
{
    // One more point per direction than the stiffness rule: exact for
    // N_a N_b on parallelograms also with the 2 pi R factor
    checkSize(X, "X");
    matX M = matX::Zero(nDof, nDof);
    for (const quadraturePoint2D& q : gaussLegendreQuad(nGauss_ + 1))
    {
        const pointGeometry g = geometry(X, q, -1);
        const Eigen::Matrix<double, NN, NN> mq = g.N*g.N.transpose()*g.dV;
        for (int a = 0; a < NN; ++a)
        {
            for (int b = 0; b < NN; ++b)
            {
                M(elementDof(2, a, 0), elementDof(2, b, 0)) += mq(a, b);
                M(elementDof(2, a, 1), elementDof(2, b, 1)) += mq(a, b);
            }
        }
    }
    return M;
}


template<int NN, int NP>
std::vector<double> upQuad<NN, NP>::pointVolumes(const matX& X) const
{
    checkSize(X, "X");
    std::vector<double> v;
    for (const quadraturePoint2D& q : qp_) v.push_back(geometry(X, q, -1).dV);
    return v;
}


template<int NN, int NP>
infSupMatrices upQuad<NN, NP>::infSup(const matX& X) const
{
    checkSize(X, "X");
    const bool axi = analysis_ == analysisType::axisymmetric;
    infSupMatrices s;
    s.Kpu = matX::Zero(NP, nDof);
    s.Mp = matX::Zero(NP, NP);
    s.T = matX::Zero(nDof, nDof);
    for (const quadraturePoint2D& q : qp_)
    {
        const pointGeometry g = geometry(X, q, -1);
        const double dV = g.dV;

        // H1: grad u : grad u + u . u (+ (u_r/R)^2, the hoop gradient)
        const Eigen::Matrix<double, NN, NN> t =
            (g.dNdX*g.dNdX.transpose() + g.N*g.N.transpose())*dV;
        Eigen::Matrix<double, 1, nDof> div;
        for (int a = 0; a < NN; ++a)
        {
            div(elementDof(2, a, 0)) = g.dNdX(a, 0) + (axi ? g.N(a)/g.R : 0.0);
            div(elementDof(2, a, 1)) = g.dNdX(a, 1);
            for (int b = 0; b < NN; ++b)
            {
                s.T(elementDof(2, a, 0), elementDof(2, b, 0)) += t(a, b)
                  + (axi ? g.N(a)*g.N(b)/(g.R*g.R)*dV : 0.0);
                s.T(elementDof(2, a, 1), elementDof(2, b, 1)) += t(a, b);
            }
        }
        if constexpr (NP > 0)
        {
            const vecP Np = pressureShape(q.r, q.s);
            s.Kpu += Np*div*dV;
            s.Mp += Np*Np.transpose()*dV;
        }
    }
    return s;
}


template<int NN, int NP>
elementResult upQuad<NN, NP>::result
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

// Members defined in this file, for the four registered element types
template matX upQuad<4, 0>::massMatrix(const matX&) const;
template std::vector<double> upQuad<4, 0>::pointVolumes(const matX&)
const;
template infSupMatrices upQuad<4, 0>::infSup(const matX&) const;
template elementResult upQuad<4, 0>::result
(const matX&, const matX&, const material&, const std::vector<materialState>&)
const;
template matX upQuad<9, 0>::massMatrix(const matX&) const;
template std::vector<double> upQuad<9, 0>::pointVolumes(const matX&)
const;
template infSupMatrices upQuad<9, 0>::infSup(const matX&) const;
template elementResult upQuad<9, 0>::result
(const matX&, const matX&, const material&, const std::vector<materialState>&)
const;
template matX upQuad<4, 1>::massMatrix(const matX&) const;
template std::vector<double> upQuad<4, 1>::pointVolumes(const matX&)
const;
template infSupMatrices upQuad<4, 1>::infSup(const matX&) const;
template elementResult upQuad<4, 1>::result
(const matX&, const matX&, const material&, const std::vector<materialState>&)
const;
template matX upQuad<9, 3>::massMatrix(const matX&) const;
template std::vector<double> upQuad<9, 3>::pointVolumes(const matX&)
const;
template infSupMatrices upQuad<9, 3>::infSup(const matX&) const;
template elementResult upQuad<9, 3>::result
(const matX&, const matX&, const material&, const std::vector<materialState>&)
const;

} // namespace form
