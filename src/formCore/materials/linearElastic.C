#include "linearElastic.H"
#include <limits>

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


std::vector<parameterSpec> linearElastic::parameterSpecs()
{
    const double inf = std::numeric_limits<double>::infinity();
    return
    {
        {"E", 0, inf, false, false, "Young's modulus"},
        {"nu", -1, 0.5, false, false, "Poisson's ratio"}
    };
}


linearElastic::linearElastic(const parameterMap& p)
:
    E_(checkedParameter(p, parameterSpecs(), "E")),
    nu_(checkedParameter(p, parameterSpecs(), "nu")),
    G_(E_/(2*(1 + nu_))),
    kappa_(E_/(3*(1 - 2*nu_)))
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
