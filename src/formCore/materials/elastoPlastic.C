/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of elastoPlastic.H: Finite-strain elasto-plasticity for
    sheet metal with logarithmic (Hencky) strains.
\*---------------------------------------------------------------------------*/
#include "elastoPlastic.H"
#include "logStrain.H"
#include <cmath>
#include <optional>

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


bool elastoPlastic::deviatoric
(
    const mat3& F,
    const materialState& committed,
    materialState& trial,
    mat3& tauDev,
    mat6& cDev
) const
{
    trial = committed;
    if (!(F.determinant() > 0) || !F.allFinite()) return false;

    plasticState state;
    state.epsP = committed.history(6);
    state.backStress = committed.history.segment<6>(7);

    // Lagrangian logarithmic strain and the trial elastic strain (one
    // spectral decomposition of C serves E, the stress and the tangent)
    const mat3 C = F.transpose()*F;
    std::optional<logStrainMap> map;
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
    mat6 A;
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
    const mat3 T = fromVoigtStress(Tv);

    // Stress: S = T : P, tau = F S F^T
    tauDev = F*map->stress(T)*F.transpose();
    // Remove the round-off trace (zero in exact arithmetic: P : C = I)
    tauDev -= tauDev.trace()/3*mat3::Identity();

    // Tangent: push-forward of P : A : P + T : L
    const mat6 R = voigtTransform(F);
    cDev = R*map->tangent(A, T)*R.transpose();

    trial.history.segment<6>(0) = EpN + dEp;
    trial.history(6) = newState.epsP;
    trial.history.segment<6>(7) = newState.backStress;
    return true;
}


double elastoPlastic::equivalentStrain
(
    const mat3&,
    const materialState& state
) const
{
    return state.history(6);
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
