/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Return mapping of form::plasticity for a quadratic yield function
    (von Mises, Hill'48): the scalar consistency equation and the
    consistent tangent in the generalised eigenbasis of (A, W), with no
    6 x 6 solve per iteration. The equations are in returnMapping.H
    ("Quadratic yield functions"); the general form, for any convex phi,
    is in returnMapping.C, and the unit test compares the two.
\*---------------------------------------------------------------------------*/
#include "returnMapping.H"
#include "returnMappingDetail.H"
#include "formError.H"
#include <Eigen/Eigenvalues>

namespace form
{

using namespace returnMappingDetail;

// * * * * * * * * * * * * * * * * Eigenbasis * * * * * * * * * * * * * * * //

void plasticity::initEigenbasis()
{
    // A v = mu W v with V^T W V = I (Eigen's Ax_lBx normalisation)
    const mat6 W = Wv.asDiagonal();
    Eigen::GeneralizedSelfAdjointEigenSolver<mat6> es
    (
        A_, W, Eigen::ComputeEigenvectors | Eigen::Ax_lBx
    );
    V_ = es.eigenvectors();
    mu_ = es.eigenvalues();
    // A is positive semi-definite (zero on the hydrostatic direction):
    // clip the round-off of that eigenvalue
    const double muMax = mu_.cwiseAbs().maxCoeff();
    for (int i = 0; i < 6; ++i)
    {
        if (mu_(i) < 1e-14*muMax) mu_(i) = 0;
    }
    const double errW = (V_.transpose()*W*V_ - mat6::Identity()).norm();
    const double errA =
        (V_.transpose()*A_*V_ - mat6(mu_.asDiagonal())).norm()/muMax;
    if
    (
        es.info() != Eigen::Success || !V_.allFinite()
     || !(errW < 1e-12) || !(errA < 1e-12) || !(mu_.maxCoeff() > 0)
    )
    {
        throw inputError
        (
            "yield",
            "plasticity: the yield function's quadratic form "
            "phi^2 = xi^T A xi has no regular eigenbasis (is it positive "
            "on deviatoric stresses?)"
        );
    }
}


// * * * * * * * * * * * * * * * * * Update * * * * * * * * * * * * * * * * //

bool plasticity::updateQuadratic
(
    const vec6& sTr,
    double syN,
    double fTr,
    const plasticState& committed,
    plasticState& trial,
    vec6& stressDev,
    mat6& tangentDev,
    vec6& dEp,
    int* iterations
) const
{
    // Copies: trial may alias committed
    const double epsPn = committed.epsP;
    const vec6 betaN = committed.backStress;

    // y = ys - a yb, the eigen coordinates of W xiHat (header)
    const vec6 ys = V_.transpose()*Wv.cwiseProduct(sTr);
    const vec6 yb = V_.transpose()*Wv.cwiseProduct(betaN);

    // gs(dgamma) = n.xiHat - sigmaY - dgamma h q and its exact derivative
    // in eigen coordinates; z: z(dgamma) of the last evaluation
    double sy = syN, Hp = 0, P = 0;
    vec6 z = ys - yb;
    auto evaluate = [&](double dgamma, double& gs, double& dgs)
    {
        const double a = 1/(1 + gamma_*dgamma);
        const double h = 2*G_ + 2.0/3*C_*a;
        const double dht = 2*G_ + 2.0/3*C_*a*a;    // (dgamma h)'
        sy = hardening_->flowStress(epsPn + dgamma, Hp);
        const double t = dgamma*h/sy;
        const double dt = (dht - t*Hp)/sy;
        // P = phi^2, N1 = phi n.xiHat, Q2 = phi^2 q and halves of their
        // derivatives
        double N1 = 0, Q2 = 0, dP2 = 0, dN1 = 0, dQ4 = 0;
        P = 0;
        for (int i = 0; i < 6; ++i)
        {
            const double m = mu_(i);
            const double y = ys(i) - a*yb(i);
            const double dy = gamma_*a*a*yb(i);
            const double r = 1/(1 + t*m);
            const double zi = y*r;
            const double dz = (dy - zi*m*dt)*r;
            z(i) = zi;
            P += m*zi*zi;
            N1 += m*zi*y;
            Q2 += m*m*zi*zi;
            dP2 += m*zi*dz;
            dN1 += m*(dz*y + zi*dy);
            dQ4 += m*m*zi*dz;
        }
        if (!(P > 0)) return false;
        const double phi = std::sqrt(P);
        const double q = Q2/P;
        gs = N1/phi - sy - dgamma*h*q;
        const double dphi = dP2/phi;
        const double dq = 2*(dQ4 - q*dP2)/P;
        dgs = (dN1 - N1*dphi/phi)/phi - Hp - dht*q - dgamma*h*dq;
        return std::isfinite(gs) && std::isfinite(dgs);
    };

    // Bracket (0, hi) with gs(0) > 0 > gs(hi) (header)
    const double Xi = normW(sTr) + normW(betaN);
    const double hi = 1.001*Xi*Xi/(2*G_*syN);
    double dgamma = 0;
    int it = 0;
    const bool converged = solveConsistency(evaluate, sy, hi, dgamma, it);
    if (iterations) *iterations = it;
    if (!converged) return false;

    // Converged state: xi = V z, n = A xi/phi = W V M z/phi
    const double phi = std::sqrt(P);
    const vec6 n = Wv.cwiseProduct(V_*mu_.cwiseProduct(z))/phi;
    const vec6 Sn = Sv.cwiseProduct(n);
    const double a = 1/(1 + gamma_*dgamma);
    const double h = 2*G_ + 2.0/3*C_*a;

    dEp = dgamma*n;
    stressDev = sTr - 2*G_*dgamma*Sn;
    trial.epsP = epsPn + dgamma;
    trial.backStress = a*(betaN + 2.0/3*C_*dgamma*Sn);

    // Consistent tangent (header): the 7 x 7 system of returnMapping.C
    // with the consistency row eliminated; B^-1 = V (I + t' M)^-1 V^T W
    const double tJ = dgamma*h/phi;
    const mat6 VW = V_.transpose()*Wv.asDiagonal();
    mat6 VD = V_;
    for (int i = 0; i < 6; ++i) VD.col(i) /= 1 + tJ*mu_(i);
    const mat6 Binv = VD*VW;
    const vec6 c = (-gamma_*a*a*betaN + (2*G_ + 2.0/3*C_*a*a)*Sn)/(2*G_);
    const double k = Hp/(2*G_);
    const vec6 g = Binv*(tJ*k*Sn - c);
    const double den = k - n.dot(g);
    // dlambda/ds_tr (row) and dxi/ds_tr
    const Eigen::Matrix<double, 1, 6> X6 = n.transpose()*Binv/den;
    const mat6 Xxi = Binv + g*X6;
    // ds = ds_tr - S n dlambda - 2G dgamma S d2phi dxi,
    // d2phi = (A - n n^T)/phi
    const mat6 SD2 =
        Sv.asDiagonal()*(A_ - n*n.transpose())*(2*G_*dgamma/phi);
    const mat6 dsdsTr = mat6::Identity() - Sn*X6 - SD2*Xxi;
    tangentDev = fTr <= onSurface*syN ? Ce_ : mat6(dsdsTr*Ce_);

    return stressDev.allFinite() && tangentDev.allFinite()
        && std::isfinite(den);
}

} // namespace form
