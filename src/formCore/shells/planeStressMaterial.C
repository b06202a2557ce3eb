/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    A 3D material as a plane-stress shell law (planeStressMaterial.H).
\*---------------------------------------------------------------------------*/
#include "planeStressMaterial.H"
#include <algorithm>
#include <cmath>
#include <limits>

namespace form
{

namespace
{

//- Symmetric tensor of an engineering Voigt strain vector
mat3 fromVoigtStrain(const vec6& e)
{
    mat3 E;
    for (int a = 0; a < 6; ++a)
    {
        const double f = a < 3 ? 1 : 0.5;
        E(voigtI[a], voigtJ[a]) = f*e(a);
        E(voigtJ[a], voigtI[a]) = f*e(a);
    }
    return E;
}

//- Local Voigt index (11 22 33 12 23 13) of the shell strains
//  (11 22 12 13 23)
constexpr int shellIndex[5] = {0, 1, 3, 5, 4};

} // anonymous namespace


planeStressMaterial::planeStressMaterial
(
    std::shared_ptr<const material> mat,
    double kappa
)
:
    mat_(std::move(mat)),
    kappa_(kappa),
    nHistory_(mat_ ? mat_->nHistory() : 0)
{
    if (!mat_)
    {
        throw numericalError("planeStressMaterial: no material");
    }
    if (!(kappa > 0 && kappa <= 1))
    {
        throw inputError
        (
            "shearCorrection",
            "the transverse shear correction factor must lie in (0, 1], not "
          + formatNumber(kappa)
        );
    }
}


materialState planeStressMaterial::initialState() const
{
    materialState s;
    s.history = vecX::Zero(nHistory_ + nPredictor + 1);
    s.history.head(nHistory_) = mat_->initialState().history;
    return s;
}


materialState planeStressMaterial::materialPart(const materialState& s) const
{
    materialState m;
    m.history = s.history.head(nHistory_);
    return m;
}


bool planeStressMaterial::response
(
    const mat3& Q,
    const vec6& E,
    const materialState& committed,
    materialState& trial,
    vec6& S,
    mat6& C
) const
{
    const mat3 El = fromVoigtStrain(E);
    mat3 Sl;
    if (mat_->geometricallyLinear())
    {
        // F = I + Q E Q^T, S = Q^T sigma Q (small strain)
        const double kappa = mat_->bulkModulus();
        const vec6 m = (vec6() << 1, 1, 1, 0, 0, 0).finished();
        const mat3 F = mat3::Identity() + Q*El*Q.transpose();
        mat3 tau;
        mat6 c;
        if (!mat_->deviatoric(F, committed, trial, tau, c)) return false;
        tau.diagonal().array() += kappa*El.trace();
        c += kappa*m*m.transpose();
        Sl = Q.transpose()*tau*Q;
        const mat6 R = voigtTransform(Q.transpose());
        C = R*c*R.transpose();
    }
    else
    {
        // The response at C = Q (I + 2 E) Q^T in global coordinates,
        // rotated into the lamina frame (false if C is not positive
        // definite: material.H)
        const mat3 Cl = mat3::Identity() + 2*El;
        mat3 Sg;
        mat6 CCg;
        if
        (
            !mat_->secondPiola
            (
                Q*Cl*Q.transpose(), committed, trial, Sg, CCg
            )
        )
        {
            return false;
        }
        Sl = Q.transpose()*Sg*Q;
        const mat6 R = voigtTransform(Q.transpose());
        C = R*CCg*R.transpose();
    }
    for (int a = 0; a < 6; ++a) S(a) = Sl(voigtI[a], voigtJ[a]);
    return S.allFinite() && C.allFinite();
}


vec6 planeStressMaterial::localStrain(const vec5& eps, double E33) const
{
    const double rk = std::sqrt(kappa_);
    const double scale[5] = {1, 1, 1, rk, rk};
    vec6 E;
    for (int a = 0; a < 5; ++a) E(shellIndex[a]) = scale[a]*eps(a);
    E(2) = E33;
    return E;
}


planeStressMaterial::pointOutput planeStressMaterial::output
(
    const mat3& Q,
    const vec5& eps,
    const materialState& state
) const
{
    // The stress is an exact function of the strain and the converged
    // history (elastoPlastic.H), so re-evaluating from the converged
    // state returns the converged stress
    const double E33 = thicknessStrain(state);
    const vec6 E = localStrain(eps, E33);
    const materialState m = materialPart(state);
    materialState scratch = m;
    vec6 S;
    mat6 C;
    pointOutput o;
    o.thicknessStretch = std::sqrt(std::max(1 + 2*E33, 0.0));
    if (!response(Q, E, m, scratch, S, C)) return o;
    const mat3 El = fromVoigtStrain(E);
    mat3 Fl;
    if (mat_->geometricallyLinear())
    {
        Fl = mat3::Identity() + El;
    }
    else
    {
        const Eigen::LLT<mat3> llt(mat3::Identity() + 2*El);
        Fl = llt.matrixU();
    }
    mat3 Sl;
    for (int a = 0; a < 6; ++a)
    {
        Sl(voigtI[a], voigtJ[a]) = Sl(voigtJ[a], voigtI[a]) = S(a);
    }
    const mat3 F = Q*Fl*Q.transpose();
    const mat3 tau = mat_->geometricallyLinear()
      ? mat3(Q*Sl*Q.transpose())
      : mat3(F*(Q*Sl*Q.transpose())*F.transpose());
    o.cauchy = mat_->geometricallyLinear() ? tau : mat3(tau/F.determinant());
    o.equivalentStrain = mat_->equivalentStrain(F, m);
    return o;
}


double planeStressMaterial::predictedThicknessStrain
(
    const materialState& s,
    const vec5& eps
) const
{
    // E33_s + dE33/deps . (eps - eps_s), stored as the slopes and
    // -dE33/deps . eps_s (zero data: E33_s itself)
    const vecX& h = s.history;
    double E33 = h(nHistory_ + nPredictor) + h(nHistory_ + 5);
    for (int b = 0; b < 5; ++b) E33 += h(nHistory_ + b)*eps(b);
    return E33;
}


bool planeStressMaterial::stress
(
    const mat3& Q,
    const vec5& eps,
    const materialState& committed,
    materialState& trial,
    vec5& S,
    mat5& D
) const
{
    return stress(Q, eps, committed, trial, S, D, nullptr);
}


bool planeStressMaterial::stress
(
    const mat3& Q,
    const vec5& eps,
    const materialState& committed,
    materialState& trial,
    vec5& S,
    mat5& D,
    int* evaluations
) const
{
    if (committed.history.size() != nHistory_ + nPredictor + 1)
    {
        throw numericalError
        (
            "planeStressMaterial: a state with "
          + std::to_string(committed.history.size()) + " entries, expected "
          + std::to_string(nHistory_ + nPredictor + 1)
        );
    }
    const double rk = std::sqrt(kappa_);
    const double scale[5] = {1, 1, 1, rk, rk};
    const materialState mc = materialPart(committed);
    materialState mt = mc;
    vec6 E, S6;
    mat6 C6;
    // Converged at a residual of a strain error of 1e-15 at the
    // material's initial stiffness, or when the last correction was at
    // round-off: the answer must not depend on the start (below) beyond
    // round-off, or the tangent's finite-difference checks see the start.
    // S33(E33) increases: the iterates bracket the root, a Newton step
    // that leaves the bracket is replaced by bisection, and a bracket of a
    // few ulps is convergence at round-off. (Newton alone cycled there:
    // the stress's round-off, 3e-10 at 500 MPa, exceeds tol, and each
    // correction, 1.2e-15, just missed the step criterion; the S-rail's
    // steps failed one iteration after convergence, 2026-11-27.)
    // An evaluation whose Newton correction is below linearTol is
    // accepted with the correction applied to first order (header).
    const double tol = 1e-15*(mat_->bulkModulus() + mat_->shearModulus());
    const double inf = std::numeric_limits<double>::infinity();
    const double machEps = std::numeric_limits<double>::epsilon();
    int count = 0;
    auto solve = [&](double E33)
    {
        E = localStrain(eps, E33);
        double dE33 = 1, lo = -inf, hi = inf;
        for (int it = 0; it < 60; ++it)
        {
            ++count;
            if (!response(Q, E, mc, mt, S6, C6)) return false;
            const double roundOff = 8*machEps*(1 + std::abs(E(2)));
            if
            (
                std::abs(S6(2)) <= tol
             || std::abs(dE33) <= 1e-15*(1 + std::abs(E(2)))
            )
            {
                return true;
            }
            if
            (
                C6(2, 2) > 0
             && std::abs(S6(2)) <= linearTol*C6(2, 2)*(1 + std::abs(E(2)))
            )
            {
                // The last Newton correction to first order: its
                // remainder, C33' dE33^2/2, is below round-off
                const double d = -S6(2)/C6(2, 2);
                S6 += d*C6.col(2);
                E(2) += d;
                return true;
            }
            (S6(2) > 0 ? hi : lo) = E(2);
            if (hi - lo <= roundOff) return true;
            if (!(C6(2, 2) > 0)) return false;
            double next = E(2) - S6(2)/C6(2, 2);
            if (!(next > lo && next < hi))
            {
                if (!(std::isfinite(lo) && std::isfinite(hi))) return false;
                next = 0.5*(lo + hi);
            }
            dE33 = next - E(2);
            E(2) = next;
        }
        return false;
    };
    // Starts: the thickness strain predicted from a state's stored strain
    // and slope, E33 + dE33/deps . (eps - eps_s), first from the trial
    // state (the previous Newton iteration's: its answer to second order
    // in the change of the strains, one evaluation once the global
    // iteration converges), then from the committed state; a failure is
    // retried from the next start and finally from the committed E33
    // itself, so the start never decides failure
    auto admissible = [](double E33)
    {
        return std::isfinite(E33) && 1 + 2*E33 > 0;
    };
    const double E33c = thicknessStrain(committed);
    const double E33cp = predictedThicknessStrain(committed, eps);
    const bool fromTrial =
        trial.history.size() == nHistory_ + nPredictor + 1
     && admissible(thicknessStrain(trial))
     && thicknessStrain(trial) != E33c;
    const double E33tp =
        fromTrial ? predictedThicknessStrain(trial, eps) : E33cp;
    if
    (
        !(fromTrial && admissible(E33tp) && solve(E33tp))
     && !(admissible(E33cp) && solve(E33cp))
     && !(E33cp != E33c && solve(E33c))
    )
    {
        return false;
    }
    if (evaluations) *evaluations = count;

    for (int a = 0; a < 5; ++a)
    {
        const int i = shellIndex[a];
        S(a) = scale[a]*S6(i);
        for (int b = 0; b < 5; ++b)
        {
            const int j = shellIndex[b];
            D(a, b) = scale[a]*scale[b]*(C6(i, j) - C6(i, 2)*C6(2, j)/C6(2, 2));
        }
    }
    trial.history.resize(nHistory_ + nPredictor + 1);
    trial.history.head(nHistory_) = mt.history;
    // The predictor's data: dE33/deps (the condensation's row:
    // dS33 = C_3b deps_b + C_33 dE33 = 0) and -dE33/deps . eps
    double offset = 0;
    for (int b = 0; b < 5; ++b)
    {
        const int j = shellIndex[b];
        const double slope = -scale[b]*C6(2, j)/C6(2, 2);
        trial.history(nHistory_ + b) = slope;
        offset -= slope*eps(b);
    }
    trial.history(nHistory_ + 5) = offset;
    trial.history(nHistory_ + nPredictor) = E(2);
    return true;
}

} // namespace form
