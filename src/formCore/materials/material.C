/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Run-time selection, parameter checking and the default equivalent strain
    of form::material (see material.H).
\*---------------------------------------------------------------------------*/
#include "material.H"
#include "materialInput.H"
#include "formError.H"
#include <cmath>
#include <limits>
#include <sstream>

namespace form
{


void parameterSpec::check(double value) const
{
    const bool belowMin = minInclusive ? value < min : value <= min;
    const bool aboveMax = maxInclusive ? value > max : value >= max;
    if (std::isnan(value) || belowMin || aboveMax)
    {
        throw inputError
        (
            name,
            "parameter '" + name + "' = " + formatNumber(value, 12)
          + " is out of range " + (minInclusive ? "[" : "(")
          + formatNumber(min, 12) + ", " + formatNumber(max, 12)
          + (maxInclusive ? "]" : ")")
          + (description.empty() ? "" : " (" + description + ")")
        );
    }
}


double checkedParameter(const parameterMap& p, const parameterSpec& spec)
{
    const auto it = p.find(spec.name);
    if (it == p.end())
    {
        throw inputError
        (
            spec.name,
            "missing parameter '" + spec.name + "'"
          + (spec.description.empty() ? "" : " (" + spec.description + ")")
        );
    }
    spec.check(it->second);
    return it->second;
}


double checkedParameter
(
    const parameterMap& p,
    const std::vector<parameterSpec>& specs,
    const std::string& name
)
{
    for (const auto& s : specs)
    {
        if (s.name == name) return checkedParameter(p, s);
    }
    throw inputError(name, "no parameter '" + name + "' is declared");
}


std::map<std::string, material::registryEntry>& material::registry()
{
    // Function-local static: safe against static-initialisation order of
    // the addMaterialToRegistry objects in other translation units
    static std::map<std::string, registryEntry> table;
    return table;
}


std::string material::validTypes()
{
    std::string names;
    for (const auto& entry : registry())
    {
        names += (names.empty() ? "" : " ") + entry.first;
    }
    return names;
}


std::unique_ptr<material> material::New
(
    const std::string& type,
    const materialInput& input
)
{
    const auto it = registry().find(type);
    if (it == registry().end())
    {
        throw inputError
        (
            "type",
            "unknown material type '" + type + "'; valid: " + validTypes()
        );
    }
    for (const auto& spec : it->second.parameters)
    {
        input.scalar(spec);
    }
    return it->second.factory(input);
}


std::unique_ptr<material> material::New
(
    const std::string& type,
    const parameterMap& parameters
)
{
    return New(type, materialInput(parameters));
}


bool material::secondPiola
(
    const mat3& C,
    const materialState& committed,
    materialState& trial,
    mat3& S,
    mat6& CC
) const
{
    if (!C.allFinite()) return false;
    const Eigen::LLT<mat3> llt(C);
    if (llt.info() != Eigen::Success) return false;
    const mat3 F = llt.matrixU();           // F^T F = C
    const double J = F.determinant();
    if (!(J > 0)) return false;
    mat3 tau;
    mat6 c;
    if (!deviatoric(F, committed, trial, tau, c)) return false;
    const double kappa = bulkModulus();
    const double p = kappa*std::log(J);
    const vec6 m = (vec6() << 1, 1, 1, 0, 0, 0).finished();
    const vec6 iSym = (vec6() << 1, 1, 1, 0.5, 0.5, 0.5).finished();
    tau.diagonal().array() += p;
    c += kappa*m*m.transpose();
    c.diagonal() -= 2*p*iSym;
    const mat3 A = F.inverse();
    S = A*tau*A.transpose();
    S = 0.5*(S + S.transpose());
    const mat6 R = voigtTransform(A);
    CC = R*c*R.transpose();
    return S.allFinite() && CC.allFinite();
}


materialState material::initialState() const
{
    materialState s;
    s.history = vecX::Zero(nHistory());
    return s;
}


double material::equivalentStrain
(
    const mat3& F,
    const materialState&
) const
{
    // Logarithmic (Hencky) strain e = 1/2 ln(F F^T), or eps = sym(F - I)
    // for small-strain models; von Mises equivalent sqrt(2/3 e':e')
    mat3 e;
    if (geometricallyLinear())
    {
        e = 0.5*(F + F.transpose()) - mat3::Identity();
    }
    else
    {
        Eigen::SelfAdjointEigenSolver<mat3> eig(F*F.transpose());
        const vec3 lnLambda = 0.5*eig.eigenvalues().array().log().matrix();
        e = eig.eigenvectors()*lnLambda.asDiagonal()
           *eig.eigenvectors().transpose();
    }
    const mat3 eDev = e - e.trace()/3.0*mat3::Identity();
    return std::sqrt(2.0/3.0*eDev.cwiseProduct(eDev).sum());
}

} // namespace form
