/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Isotropic hardening laws (see hardeningLaw.H): range checks, values and
    slopes, run-time selection.
\*---------------------------------------------------------------------------*/
#include "hardeningLaw.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace form
{

namespace
{

const double inf = std::numeric_limits<double>::infinity();

// Admissible ranges; the names are the dictionary keywords
const parameterSpec sigmaY0Spec
    {"sigmaY0", 0, inf, false, false, "initial yield stress"};
const parameterSpec HSpec
    {"H", 0, inf, true, false, "linear hardening modulus"};
const parameterSpec KSpec
    {"K", 0, inf, false, false, "Swift strength coefficient"};
const parameterSpec eps0Spec
    {"eps0", 0, inf, false, false, "Swift pre-strain"};
const parameterSpec nSpec
    {"n", 0, 1, true, true, "Swift hardening exponent"};
const parameterSpec sigmaInfSpec
    {"sigmaInf", 0, inf, false, false, "Voce saturation stress"};
const parameterSpec bSpec
    {"b", 0, inf, false, false, "Voce saturation rate"};

//- Check a value against spec under the entry name `entry`
double checked(const parameterSpec& spec, double value, const std::string& entry)
{
    parameterSpec s = spec;
    s.name = entry;
    s.check(value);
    return value;
}

void checkVoce(double sigmaY0, double sigmaInf, const std::string& entry)
{
    if (sigmaInf < sigmaY0)
    {
        throw inputError
        (
            entry,
            "parameter '" + entry + "' = " + formatNumber(sigmaInf)
          + " is below sigmaY0 = " + formatNumber(sigmaY0)
          + " (softening is not supported)"
        );
    }
}

//- The table of a `tabulated` dictionary, after checking its keywords
const materialInput::table& checkedTable(const materialInput& dict)
{
    dict.checkKeys({"type", "table"});
    return dict.tableEntry("table");
}

} // anonymous namespace


// * * * * * * * * * * * * * * * * perfect * * * * * * * * * * * * * * * * //

perfectHardening::perfectHardening(double sigmaY0)
:
    sigmaY0_(checked(sigmaY0Spec, sigmaY0, "sigmaY0"))
{}


perfectHardening::perfectHardening(const materialInput& dict)
:
    sigmaY0_(0)
{
    dict.checkKeys({"type", "sigmaY0"});
    sigmaY0_ = dict.scalar(sigmaY0Spec);
}


std::string perfectHardening::summary() const
{
    return "perfect: sigmaY = " + formatNumber(sigmaY0_);
}


// * * * * * * * * * * * * * * * * * linear * * * * * * * * * * * * * * * * //

linearHardening::linearHardening(double sigmaY0, double H)
:
    sigmaY0_(checked(sigmaY0Spec, sigmaY0, "sigmaY0")),
    H_(checked(HSpec, H, "H"))
{}


linearHardening::linearHardening(const materialInput& dict)
:
    sigmaY0_(0),
    H_(0)
{
    dict.checkKeys({"type", "sigmaY0", "H"});
    sigmaY0_ = dict.scalar(sigmaY0Spec);
    H_ = dict.scalar(HSpec);
}


std::string linearHardening::summary() const
{
    return "linear: sigmaY = sigmaY0 + H epsP, sigmaY0 = " + formatNumber(sigmaY0_)
         + ", H = " + formatNumber(H_);
}


// * * * * * * * * * * * * * * * * * swift * * * * * * * * * * * * * * * * //

swiftHardening::swiftHardening(double K, double eps0, double n)
:
    K_(checked(KSpec, K, "K")),
    eps0_(checked(eps0Spec, eps0, "eps0")),
    n_(checked(nSpec, n, "n"))
{}


swiftHardening::swiftHardening(const materialInput& dict)
:
    K_(0),
    eps0_(0),
    n_(0)
{
    dict.checkKeys({"type", "K", "eps0", "n"});
    K_ = dict.scalar(KSpec);
    eps0_ = dict.scalar(eps0Spec);
    n_ = dict.scalar(nSpec);
}


double swiftHardening::sigmaY(double epsP) const
{
    return K_*std::pow(eps0_ + epsP, n_);
}


double swiftHardening::slope(double epsP) const
{
    // K n (eps0 + epsP)^(n-1), finite since eps0 > 0
    return n_ == 0 ? 0 : K_*n_*std::pow(eps0_ + epsP, n_ - 1);
}


double swiftHardening::work(double epsP) const
{
    // K/(n + 1) ((eps0 + epsP)^(n+1) - eps0^(n+1))
    return K_/(n_ + 1)
       *(std::pow(eps0_ + epsP, n_ + 1) - std::pow(eps0_, n_ + 1));
}


double swiftHardening::flowStress(double epsP, double& slope) const
{
    // slope = n sigmaY/(eps0 + epsP) = K n (eps0 + epsP)^(n-1)
    const double x = eps0_ + epsP;
    const double s = K_*std::pow(x, n_);
    slope = n_*s/x;
    return s;
}


std::string swiftHardening::summary() const
{
    return "swift: sigmaY = K (eps0 + epsP)^n, K = " + formatNumber(K_)
         + ", eps0 = " + formatNumber(eps0_) + ", n = " + formatNumber(n_);
}


// * * * * * * * * * * * * * * * * * voce * * * * * * * * * * * * * * * * //

voceHardening::voceHardening
(
    double sigmaY0,
    double sigmaInf,
    double b,
    double H
)
:
    sigmaY0_(checked(sigmaY0Spec, sigmaY0, "sigmaY0")),
    sigmaInf_(checked(sigmaInfSpec, sigmaInf, "sigmaInf")),
    b_(checked(bSpec, b, "b")),
    H_(checked(HSpec, H, "H"))
{
    checkVoce(sigmaY0_, sigmaInf_, "sigmaInf");
}


voceHardening::voceHardening(const materialInput& dict)
:
    sigmaY0_(0),
    sigmaInf_(0),
    b_(0),
    H_(0)
{
    dict.checkKeys({"type", "sigmaY0", "sigmaInf", "b", "H"});
    sigmaY0_ = dict.scalar(sigmaY0Spec);
    sigmaInf_ = dict.scalar(sigmaInfSpec);
    checkVoce(sigmaY0_, sigmaInf_, dict.entryPath("sigmaInf"));
    b_ = dict.scalar(bSpec);
    H_ = dict.scalarOrDefault(HSpec, 0);
}


double voceHardening::sigmaY(double epsP) const
{
    // -expm1(-x) = 1 - exp(-x) without cancellation at small epsP
    return sigmaY0_ - (sigmaInf_ - sigmaY0_)*std::expm1(-b_*epsP) + H_*epsP;
}


double voceHardening::slope(double epsP) const
{
    return (sigmaInf_ - sigmaY0_)*b_*std::exp(-b_*epsP) + H_;
}


double voceHardening::work(double epsP) const
{
    // sigmaInf epsP - (sigmaInf - sigmaY0)(1 - exp(-b epsP))/b + H epsP^2/2
    return sigmaInf_*epsP + (sigmaInf_ - sigmaY0_)*std::expm1(-b_*epsP)/b_
         + 0.5*H_*epsP*epsP;
}


std::string voceHardening::summary() const
{
    return "voce: sigmaY = sigmaY0 + (sigmaInf - sigmaY0)(1 - exp(-b epsP))"
           " + H epsP, sigmaY0 = " + formatNumber(sigmaY0_) + ", sigmaInf = "
         + formatNumber(sigmaInf_) + ", b = " + formatNumber(b_) + ", H = " + formatNumber(H_);
}


// * * * * * * * * * * * * * * * * tabulated * * * * * * * * * * * * * * * //

tabulatedHardening::tabulatedHardening
(
    const materialInput::table& points,
    const std::string& entry
)
{
    auto fail = [&](const std::string& why)
    {
        throw inputError(entry, "table '" + entry + "': " + why);
    };
    if (points.empty())
    {
        fail("no points; give ((0 sigmaY0) (epsP1 sigmaY1) ...)");
    }
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const double e = points[i][0], s = points[i][1];
        const std::string at = "point " + std::to_string(i + 1)
            + " (" + formatNumber(e) + " " + formatNumber(s) + ")";
        if (!std::isfinite(e) || !std::isfinite(s))
        {
            fail(at + " is not finite");
        }
        if (i == 0 && e != 0)
        {
            fail("the first point must be at epsP = 0, found " + at);
        }
        if (i > 0 && !(e > eps_.back()))
        {
            fail("epsP must be strictly increasing, " + at);
        }
        if (!(s > 0))
        {
            fail("sigmaY must be positive, " + at);
        }
        if (i > 0 && s < sigma_.back())
        {
            fail("sigmaY must be non-decreasing (softening is not "
                 "supported), " + at);
        }
        eps_.push_back(e);
        sigma_.push_back(s);
    }
}


tabulatedHardening::tabulatedHardening(const materialInput& dict)
:
    tabulatedHardening(checkedTable(dict), dict.entryPath("table"))
{}


std::size_t tabulatedHardening::segment(double epsP) const
{
    // Last knot <= epsP (first segment for epsP < 0), so that a knot
    // belongs to the segment on its right
    const auto it = std::upper_bound(eps_.begin(), eps_.end(), epsP);
    return it == eps_.begin() ? 0 : std::size_t(it - eps_.begin()) - 1;
}


double tabulatedHardening::sigmaY(double epsP) const
{
    if (eps_.size() == 1 || epsP >= eps_.back()) return sigma_.back();
    const std::size_t i = segment(epsP);
    const double w = (epsP - eps_[i])/(eps_[i + 1] - eps_[i]);
    return (1 - w)*sigma_[i] + w*sigma_[i + 1];
}


double tabulatedHardening::slope(double epsP) const
{
    if (eps_.size() == 1 || epsP >= eps_.back()) return 0;
    const std::size_t i = segment(epsP);
    return (sigma_[i + 1] - sigma_[i])/(eps_[i + 1] - eps_[i]);
}


double tabulatedHardening::work(double epsP) const
{
    // Trapezoids of the knots up to epsP (exact: sigmaY is linear between
    // them), the constant last value beyond the table
    double w = 0;
    for (std::size_t i = 0; i + 1 < eps_.size() && eps_[i] < epsP; ++i)
    {
        const double b = std::min(epsP, eps_[i + 1]);
        w += 0.5*(sigma_[i] + sigmaY(b))*(b - eps_[i]);
    }
    if (epsP > eps_.back()) w += sigma_.back()*(epsP - eps_.back());
    return w;
}


std::string tabulatedHardening::summary() const
{
    return "tabulated: " + std::to_string(eps_.size()) + " points, sigmaY "
         + formatNumber(sigma_.front()) + " .. " + formatNumber(sigma_.back()) + " for epsP 0 .. "
         + formatNumber(eps_.back()) + ", piecewise linear, constant beyond";
}


// * * * * * * * * * * * * * * * * selection * * * * * * * * * * * * * * * //

std::unique_ptr<hardeningLaw> hardeningLaw::New(const materialInput& dict)
{
    const std::string type =
        dict.word("type", {"perfect", "linear", "swift", "voce", "tabulated"});
    if (type == "perfect") return std::make_unique<perfectHardening>(dict);
    if (type == "linear") return std::make_unique<linearHardening>(dict);
    if (type == "swift") return std::make_unique<swiftHardening>(dict);
    if (type == "voce") return std::make_unique<voceHardening>(dict);
    return std::make_unique<tabulatedHardening>(dict);
}

} // namespace form
