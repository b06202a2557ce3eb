/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Return mapping of form::plasticity: safeguarded Newton on the scalar
    equation g(dgamma) = 0, inner solve for xi(dgamma), consistent tangent
    from the Jacobian of the backward-Euler equations, plane-stress wrapper.
    The equations and their derivation are in returnMapping.H.
\*---------------------------------------------------------------------------*/
#include "returnMapping.H"
#include "returnMappingDetail.H"
#include "formError.H"
#include <cmath>
#include <limits>
#include <sstream>

namespace form
{

using namespace returnMappingDetail;

namespace
{

const double inf = std::numeric_limits<double>::infinity();

//- Damped Newton iterations of the inner (non-quadratic) problem
const int maxInner = 50;

//- Plane stress: |sigma_zz| <= tolPlaneStress max(sigmaY_n, |K tr e|)
const double tolPlaneStress = 1e-10;
const int maxPlaneStress = 50;

const parameterSpec CSpec
    {"C", 0, inf, true, false, "kinematic hardening modulus"};
const parameterSpec gammaSpec
    {"gamma", 0, inf, true, false, "Armstrong-Frederick recall coefficient"};

} // anonymous namespace


// * * * * * * * * * * * * * * * * Constructors * * * * * * * * * * * * * * //

plasticity::plasticity(const materialInput& materialDict, double G)
:
    G_(G),
    yield_
    (
        materialDict.found("yield")
      ? yieldFunction::New(materialDict.dict("yield"))
      : std::make_unique<vonMisesYield>()
    ),
    hardening_(hardeningLaw::New(materialDict.dict("hardening"))),
    C_(0),
    gamma_(0)
{
    if (materialDict.found("kinematicHardening"))
    {
        const materialInput& k = materialDict.dict("kinematicHardening");
        const std::string type =
            k.word("type", {"none", "prager", "armstrongFrederick"});
        if (type == "none")
        {
            k.checkKeys({"type"});
        }
        else if (type == "prager")
        {
            k.checkKeys({"type", "C"});
            C_ = k.scalar(CSpec);
        }
        else
        {
            k.checkKeys({"type", "C", "gamma"});
            C_ = k.scalar(CSpec);
            gamma_ = k.scalar(gammaSpec);
        }
    }
    init();
}


plasticity::plasticity
(
    double G,
    std::unique_ptr<yieldFunction> yield,
    std::unique_ptr<hardeningLaw> hardening,
    double C,
    double gamma
)
:
    G_(G),
    yield_(std::move(yield)),
    hardening_(std::move(hardening)),
    C_(C),
    gamma_(gamma)
{
    init();
}


void plasticity::init()
{
    if (!(G_ > 0) || !std::isfinite(G_))
    {
        throw inputError
        (
            "G",
            "plasticity: shear modulus G = " + formatNumber(G_) + " must be positive"
        );
    }
    CSpec.check(C_);
    gammaSpec.check(gamma_);
    if (!yield_ || !hardening_)
    {
        throw inputError("", "plasticity: no yield function or hardening law");
    }

    Ce_.setZero();
    for (int a = 0; a < 3; ++a)
    {
        for (int b = 0; b < 3; ++b)
        {
            Ce_(a, b) = 2*G_*((a == b ? 1.0 : 0.0) - 1.0/3);
        }
        Ce_(a + 3, a + 3) = 2*G_*0.5;
    }

    // psi = phi^2/2 has the constant Hessian n n^T + phi d2phi = A for a
    // quadratic phi; evaluate it at any non-hydrostatic stress, and its
    // generalised eigenbasis with respect to W (header)
    A_.setZero();
    V_.setZero();
    mu_.setZero();
    if (yield_->quadratic())
    {
        vec6 x;
        x << 2, -1, -1, 1, 1, 1;
        const double phi = yield_->value(x);
        const vec6 n = yield_->gradient(x);
        A_ = n*n.transpose() + phi*yield_->hessian(x);
        A_ = 0.5*(A_ + A_.transpose()).eval();
        initEigenbasis();
    }
}


// * * * * * * * * * * * * * * * * Inner problem * * * * * * * * * * * * * //

bool plasticity::solveInner
(
    const vec6& xiHat,
    double t,
    vec6& xi,
    Eigen::LDLT<mat6>& K
) const
{
    const mat6 W = Wv.asDiagonal();

    // Damped Newton on the strongly convex
    //     Pi(x) = 1/2 (x - xiHat).W.(x - xiHat) + t phi(x)^2/2,
    // gradient r = W(x - xiHat) + t phi n, Hessian W + t(n n^T + phi d2phi)
    // (symmetric positive definite: W > 0 and psi convex)
    auto Pi = [&](const vec6& x)
    {
        const vec6 d = x - xiHat;
        const double phi = yield_->value(x);
        return 0.5*d.dot(Wv.cwiseProduct(d)) + 0.5*t*phi*phi;
    };
    const double floor = 16*machEps*xiHat.cwiseAbs().maxCoeff();
    vec6 x = xi.allFinite() ? xi : xiHat;
    for (int it = 0; it < maxInner; ++it)
    {
        const double phi = yield_->value(x);
        const vec6 n = yield_->gradient(x);
        const vec6 r = Wv.cwiseProduct(x - xiHat) + t*phi*n;
        K.compute(W + t*(n*n.transpose() + phi*yield_->hessian(x)));
        const vec6 d = -K.solve(r);
        const double dNorm = d.cwiseAbs().maxCoeff();
        if (!std::isfinite(dNorm)) return false;
        const double scale = x.cwiseAbs().maxCoeff();
        if (dNorm <= 1e-13*scale + floor)
        {
            xi = x + d;
            return true;
        }
        // Armijo backtracking far from the solution; near it (quadratic
        // convergence) differences of Pi are roundoff and the full step is
        // taken
        double alpha = 1;
        if (dNorm > 1e-6*scale)
        {
            const double Pi0 = Pi(x), slope = r.dot(d);
            while (Pi(x + alpha*d) > Pi0 + 1e-4*alpha*slope && alpha > 1e-10)
            {
                alpha *= 0.5;
            }
        }
        x += alpha*d;
    }
    return false;
}


// * * * * * * * * * * * * * * * * * Update * * * * * * * * * * * * * * * * //

bool plasticity::update
(
    const vec6& eTrial,
    const plasticState& committed,
    plasticState& trial,
    vec6& stressDev,
    mat6& tangentDev,
    vec6& dEp,
    int* iterations
) const
{
    if (iterations) *iterations = 0;

    // Copies: trial may alias committed
    const double epsPn = committed.epsP;
    const vec6 betaN = committed.backStress;

    const vec6 sTr = Ce_*eTrial;
    const double syN = hardening_->sigmaY(epsPn);
    const double fTr = yield_->value(sTr - betaN) - syN;
    if (!std::isfinite(fTr) || !sTr.allFinite() || !betaN.allFinite())
    {
        return false;
    }

    if (fTr <= 0)
    {
        trial.epsP = epsPn;
        trial.backStress = betaN;
        stressDev = sTr;
        tangentDev = Ce_;
        dEp.setZero();
        return true;
    }
    if (yield_->quadratic())
    {
        return updateQuadratic
        (
            sTr, syN, fTr, committed, trial, stressDev, tangentDev, dEp,
            iterations
        );
    }

    // Scaled residual gs(dgamma) = (1 + t n.S.n) g and its derivative;
    // xi: in warm start, out xi(dgamma). With xiHat = xi + t S grad psi,
    //     n.xiHat = phi (1 + t q),   q = n.S.n,   t sigmaY = dgamma h,
    // so gs = n.xiHat - sigmaY - dgamma h q, evaluated in this form (no
    // cancellation against the large trial stress).
    // sy, Hp: sigmaY and its slope at the last iterate
    double sy = syN, Hp = 0;
    auto evaluate = [&](double dgamma, vec6& xi, double& gs, double& dgs)
    {
        const double a = 1/(1 + gamma_*dgamma);
        const double h = 2*G_ + 2.0/3*C_*a;
        sy = hardening_->flowStress(epsPn + dgamma, Hp);
        const vec6 xiHat = sTr - a*betaN;
        const double t = dgamma*h/sy;
        Eigen::LDLT<mat6> K;
        if (!solveInner(xiHat, t, xi, K)) return false;
        const double phi = yield_->value(xi);
        const vec6 n = yield_->gradient(xi);
        const mat6 d2phi = yield_->hessian(xi);
        const vec6 Sn = Sv.cwiseProduct(n);
        const double q = n.dot(Sn);
        gs = n.dot(xiHat) - sy - dgamma*h*q;

        // xi'(dgamma) from (W + t grad2 psi) xi' = W xiHat' - grad psi t'
        const vec6 dxiHat = gamma_*a*a*betaN;
        const double dht = 2*G_ + 2.0/3*C_*a*a;    // (dgamma h)'
        const double dt = dht/sy - t*Hp/sy;
        const vec6 dxi = K.solve(Wv.cwiseProduct(dxiHat) - phi*dt*n);
        // gs' = xiHat.d2phi.xi' + n.xiHat' - sigmaY' - (dgamma h)' q
        //     - 2 dgamma h n.S.d2phi.xi'
        const vec6 d2phiDxi = d2phi*dxi;
        dgs = xiHat.dot(d2phiDxi) + n.dot(dxiHat) - Hp - dht*q
            - 2*dgamma*h*Sn.dot(d2phiDxi);
        return std::isfinite(gs) && std::isfinite(dgs);
    };

    // Bracket (0, hi) with gs(0) > 0 > gs(hi) (header)
    const double Xi = normW(sTr) + normW(betaN);
    const double hi = 1.001*Xi*Xi/(2*G_*syN);
    vec6 xi = sTr - betaN;
    double x = 0;
    int it = 0;
    const bool converged = solveConsistency
    (
        [&](double dgamma, double& gs, double& dgs)
        {
            return evaluate(dgamma, xi, gs, dgs);
        },
        sy, hi, x, it
    );
    if (iterations) *iterations = it;
    if (!converged) return false;

    // Converged state
    const double dgamma = x;
    const double a = 1/(1 + gamma_*dgamma);
    const vec6 n = yield_->gradient(xi);
    const mat6 d2phi = yield_->hessian(xi);
    const vec6 Sn = Sv.cwiseProduct(n);

    dEp = dgamma*n;
    stressDev = sTr - 2*G_*dgamma*Sn;
    trial.epsP = epsPn + dgamma;
    trial.backStress = a*(betaN + 2.0/3*C_*dgamma*Sn);

    // Consistent tangent: Jacobian of (R_xi, R_f) in (xi, lambda = 2G dgamma)
    using mat7 = Eigen::Matrix<double, 7, 7>;
    using mat76 = Eigen::Matrix<double, 7, 6>;
    const double h = 2*G_ + 2.0/3*C_*a;
    mat7 J;
    J.topLeftCorner<6, 6>() =
        mat6::Identity() + dgamma*h*Sv.asDiagonal()*d2phi;
    J.topRightCorner<6, 1>() =
        (-gamma_*a*a*betaN + (2*G_ + 2.0/3*C_*a*a)*Sn)/(2*G_);
    J.bottomLeftCorner<1, 6>() = n.transpose();
    J(6, 6) = -Hp/(2*G_);                  // at the last iterate, dgamma
    mat76 rhs = mat76::Zero();
    rhs.topRows<6>().setIdentity();
    const mat76 X = J.partialPivLu().solve(rhs);

    // ds = ds_tr - S n dlambda - 2G dgamma S d2phi dxi
    const mat6 dsdsTr = mat6::Identity() - Sn*X.row(6)
        - 2*G_*dgamma*Sv.asDiagonal()*d2phi*X.topRows<6>();
    tangentDev = fTr <= onSurface*syN ? Ce_ : mat6(dsdsTr*Ce_);

    return stressDev.allFinite() && tangentDev.allFinite();
}


// * * * * * * * * * * * * * * * Plane stress * * * * * * * * * * * * * * * //

bool plasticity::updatePlaneStress
(
    double K,
    const vec6& eTrial,
    const plasticState& committed,
    plasticState& trial,
    vec6& stress,
    mat6& tangent,
    vec6& dEp,
    double& eZZ,
    int* iterations
) const
{
    if (iterations) *iterations = 0;
    if (!(K > 0)) return false;
    const plasticState c = committed;       // trial may alias committed
    const double scale0 = hardening_->sigmaY(c.epsP);

    // Elastic guess: K tr e + 2G (e_zz - tr e/3) = 0
    vec6 e = eTrial;
    e(2) = -(K - 2*G_/3)*(e(0) + e(1))/(K + 4*G_/3);

    // sigma_zz(e_zz) is increasing; bracket lo < root < hi once known
    double lo = -inf, hi = inf;
    vec6 sDev;
    mat6 T;
    for (int it = 1; it <= maxPlaneStress; ++it)
    {
        if (iterations) *iterations = it;
        if (!update(e, c, trial, sDev, T, dEp)) return false;
        const double p = K*(e(0) + e(1) + e(2));
        const double szz = p + sDev(2);
        if (std::abs(szz) <= tolPlaneStress*std::max(scale0, std::abs(p)))
        {
            eZZ = e(2);
            stress = sDev;
            stress.head<3>().array() += p;
            stress(2) = 0;
            // Full tangent K 1(x)1 + T, condensed for sigma_zz = 0
            mat6 Cf = T;
            Cf.topLeftCorner<3, 3>().array() += K;
            tangent = Cf - Cf.col(2)*Cf.row(2)/Cf(2, 2);
            tangent.row(2).setZero();
            tangent.col(2).setZero();
            return tangent.allFinite();
        }
        if (szz > 0) hi = e(2);
        else lo = e(2);
        // Newton; the elastic slope if the tangent is not positive (it
        // should be); bisection if the step leaves a closed bracket
        double slope = K + T(2, 2);
        if (!(slope > 0)) slope = K + 4*G_/3;
        double next = e(2) - szz/slope;
        if (!(next > lo && next < hi))
        {
            if (std::isfinite(lo) && std::isfinite(hi)) next = 0.5*(lo + hi);
            else return false;
        }
        e(2) = next;
    }
    return false;
}


// * * * * * * * * * * * * * * * * * Access * * * * * * * * * * * * * * * * //

double plasticity::initialYieldStress() const
{
    return hardening_->sigmaY(0);
}


std::string plasticity::summary() const
{
    std::string kin = "none";
    if (C_ > 0)
    {
        kin = gamma_ > 0
            ? "armstrongFrederick C = " + formatNumber(C_) + ", gamma = " + formatNumber(gamma_)
            : "prager C = " + formatNumber(C_);
    }
    return "yield " + yield_->summary() + "; hardening "
         + hardening_->summary() + "; kinematic hardening " + kin
         + "; G = " + formatNumber(G_);
}

} // namespace form
