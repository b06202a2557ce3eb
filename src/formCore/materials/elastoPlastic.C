/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of elastoPlastic.H: Finite-strain elasto-plasticity for
    sheet metal with logarithmic (Hencky) strains.
\*---------------------------------------------------------------------------*/
#include "elastoPlastic.H"
#include <cmath>

namespace form
{

const char* elastoPlastic::typeName = "elastoPlastic";

namespace
{
addMaterialToRegistry<elastoPlastic> addElastoPlastic
(
    "finite-strain elasto-plasticity, Hencky elasticity, exponential map;"
    " von Mises / Hill'48, isotropic + kinematic hardening"
);

//- Engineering Voigt vector of a symmetric strain-like tensor
vec6 toVoigtStrain(const mat3& e)
{
    vec6 v;
    v << e(0, 0), e(1, 1), e(2, 2), 2*e(0, 1), 2*e(1, 2), 2*e(0, 2);
    return v;
}

} // anonymous namespace


elastoPlastic::elastoPlastic(const materialInput& input)
:
    isotropicElastic(input.scalars),
    plasticity_
    (
        (input.checkKeys
        (
            {"type", "E", "nu", "yield", "hardening", "kinematicHardening"}
        ), input),
        G_
    )
{}


materialState elastoPlastic::initialState() const
{
    materialState s;
    s.history = vecX::Zero(nHistory());
    return s;
}


bool elastoPlastic::logSpaceUpdate
(
    const mat3& C,
    const materialState& committed,
    materialState& trial,
    std::optional<logStrainMap>& map,
    mat3& T,
    mat6& A
) const
{
    trial = committed;
    plasticState state;
    state.epsP = committed.history(6);
    state.backStress = committed.history.segment<6>(7);

    // Lagrangian logarithmic strain and the trial elastic strain (one
    // spectral decomposition of C serves E, the stress and the tangent)
    try
    {
        map.emplace(C);
    }
    catch (const numericalError&)
    {
        return false;
    }
    const vec6 EpN = committed.history.segment<6>(0);

    // Small-strain return mapping in log space (deviatoric)
    plasticState newState;
    vec6 Tv, dEp;
    if
    (
        !plasticity_.update
        (
            toVoigtStrain(map->strain()) - EpN, state, newState, Tv, A, dEp
        )
    )
    {
        return false;
    }
    T = fromVoigtStress(Tv);
    trial.history.segment<6>(0) = EpN + dEp;
    trial.history(6) = newState.epsP;
    trial.history.segment<6>(7) = newState.backStress;
    return true;
}


bool elastoPlastic::deviatoric
(
    const mat3& F,
    const materialState& committed,
    materialState& trial,
    mat3& tauDev,
    mat6& cDev
) const
{
    if (!(F.determinant() > 0) || !F.allFinite())
    {
        trial = committed;
        return false;
    }
    std::optional<logStrainMap> map;
    mat3 T;
    mat6 A;
    if (!logSpaceUpdate(F.transpose()*F, committed, trial, map, T, A))
    {
        return false;
    }

    // Stress: S = T : P, tau = F S F^T
    tauDev = F*map->stress(T)*F.transpose();
    // Remove the round-off trace (zero in exact arithmetic: P : C = I)
    tauDev -= tauDev.trace()/3*mat3::Identity();

    // Tangent: push-forward of P : A : P + T : L
    const mat6 R = voigtTransform(F);
    cDev = R*map->tangent(A, T)*R.transpose();
    return true;
}


bool elastoPlastic::secondPiola
(
    const mat3& C,
    const materialState& committed,
    materialState& trial,
    mat3& S,
    mat6& CC
) const
{
    if (!C.allFinite())
    {
        trial = committed;
        return false;
    }
    std::optional<logStrainMap> map;
    mat3 T;
    mat6 A;
    if (!logSpaceUpdate(C, committed, trial, map, T, A)) return false;

    // Volumetric: U = kappa/2 (tr E)^2 (tr E = ln J): T_vol = kappa tr(E) 1,
    // dT_vol/dE = kappa 1 (x) 1
    const double kappa = bulkModulus();
    const double p = kappa*map->strain().trace();
    T.diagonal().array() += p;
    const vec6 m = (vec6() << 1, 1, 1, 0, 0, 0).finished();
    A += kappa*m*m.transpose();
    S = map->stress(T);
    CC = map->tangent(A, T);
    return S.allFinite() && CC.allFinite();
}


double elastoPlastic::equivalentStrain
(
    const mat3&,
    const materialState& state
) const
{
    return state.history(6);
}


double elastoPlastic::plasticDissipation(const materialState& state) const
{
    return plasticity_.hardening().work(state.history(6));
}


bool elastoPlastic::symmetricTangent() const
{
    return plasticity_.symmetricTangent();
}


std::string elastoPlastic::summary() const
{
    return plasticity_.summary();
}

} // namespace form
