/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    St. Venant-Kirchhoff hyperelasticity (stVenantKirchhoff.H).
\*---------------------------------------------------------------------------*/
#include "stVenantKirchhoff.H"
#include <cmath>

namespace form
{

const char* stVenantKirchhoff::typeName = "stVenantKirchhoff";

namespace
{
addMaterialToRegistry<stVenantKirchhoff> addStVenantKirchhoff
(
    "St. Venant-Kirchhoff, S = lambda tr(E) I + 2 mu E (Green-Lagrange E)"
);
}


stVenantKirchhoff::stVenantKirchhoff(const parameterMap& p)
:
    isotropicElastic(p)
{}


bool stVenantKirchhoff::deviatoric
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
    const double mu = G_;
    const double lambda = kappa_ - 2*mu/3;
    const mat3 b = F*F.transpose();
    const double trE = (b.trace() - 3)/2;
    const double p = kappa_*std::log(J);
    tauDev = lambda*trE*b + mu*(b*b - b) - p*mat3::Identity();

    // Voigt (engineering strain in, stress out): entry (ij, kl) is c_ijkl
    const vec6 bv = toVoigtStress(b);
    for (int A = 0; A < 6; ++A)
    {
        const int i = voigtI[A], j = voigtJ[A];
        for (int B = 0; B < 6; ++B)
        {
            const int k = voigtI[B], l = voigtJ[B];
            cDev(A, B) = lambda*bv(A)*bv(B) + mu*(b(i, k)*b(j, l) + b(i, l)*b(j, k));
        }
    }
    // minus the volumetric tangent kappa 1 (x) 1 - 2 p I_sym
    cDev.topLeftCorner<3, 3>().array() -= kappa_;
    cDev.diagonal().head<3>().array() += 2*p;
    cDev.diagonal().tail<3>().array() += p;
    return true;
}

} // namespace form
