/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of neoHookean.H: compressible neo-Hookean
    hyperelasticity with the isochoric/volumetric split (Simo & Hughes,
    Computational Inelasticity, 1998).
\*---------------------------------------------------------------------------*/
#include "neoHookean.H"
#include <cmath>

namespace form
{

const char* neoHookean::typeName = "neoHookean";

namespace
{
addMaterialToRegistry<neoHookean> addNeoHookean
(
    "compressible neo-Hookean, Psi = G/2 (tr bbar - 3) + kappa/2 (ln J)^2"
);
}


neoHookean::neoHookean(const parameterMap& p)
:
    isotropicElastic(p)
{}


bool neoHookean::deviatoric
(
    const mat3& F,
    const materialState& committed,
    materialState& trial,
    mat3& tauDev,
    mat6& cDev
) const
{
    trial = committed;
    const double J = F.determinant();
    if (!(J > 0)) return false;

    const mat3 bbar = std::pow(J, -2.0/3.0)*F*F.transpose();
    const double trBbar = bbar.trace();
    tauDev = G_*(bbar - trBbar/3*mat3::Identity());

    // Voigt (engineering strain in, stress out): I_sym = diag(1,1,1,1/2,..),
    // 1 = m = (1,1,1,0,0,0); (tau (x) 1):d = tau tr d, (1 (x) tau):d = 1 tau:d
    vec6 m;
    m << 1, 1, 1, 0, 0, 0;
    const vec6 t = toVoigtStress(tauDev);
    mat6 iDev = -m*m.transpose()/3;
    iDev.diagonal() += (vec6() << 1, 1, 1, 0.5, 0.5, 0.5).finished();

    cDev = 2.0/3.0*G_*trBbar*iDev
         - 2.0/3.0*(t*m.transpose() + m*t.transpose());
    return true;
}

} // namespace form
