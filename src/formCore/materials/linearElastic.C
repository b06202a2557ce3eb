/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of linearElastic.H: Isotropic small-strain linear
    elasticity (Hooke's law).
\*---------------------------------------------------------------------------*/
#include "linearElastic.H"

namespace form
{

const char* linearElastic::typeName = "linearElastic";

namespace
{
addMaterialToRegistry<linearElastic> addLinearElastic
(
    "isotropic small-strain linear elasticity (E, nu)"
);
}


linearElastic::linearElastic(const parameterMap& p)
:
    isotropicElastic(p)
{}


bool linearElastic::deviatoric
(
    const mat3& F,
    const materialState& committed,
    materialState& trial,
    mat3& tauDev,
    mat6& cDev
) const
{
    trial = committed;
    const mat3 eps = 0.5*(F + F.transpose()) - mat3::Identity();
    tauDev = 2*G_*(eps - eps.trace()/3*mat3::Identity());

    // 2G (I_sym - 1/3 1 (x) 1) acting on engineering strains: the shear
    // diagonal is 2G * 1/2 = G
    cDev.setZero();
    cDev.topLeftCorner<3, 3>().setConstant(-2*G_/3);
    cDev.diagonal() << 4*G_/3, 4*G_/3, 4*G_/3, G_, G_, G_;
    return true;
}

} // namespace form
