/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Quadratic yield functions von Mises and Hill'48 (see yieldFunction.H).
\*---------------------------------------------------------------------------*/
#include "yieldFunction.H"
#include "formError.H"
#include <cmath>
#include <limits>
#include <sstream>

namespace form
{

namespace
{

const double inf = std::numeric_limits<double>::infinity();

const parameterSpec rSpecs[3] =
{
    {"r0", 0, inf, false, false,
        "Lankford coefficient at 0 deg to rolling (or give F G H L M N)"},
    {"r45", 0, inf, false, false, "Lankford coefficient at 45 deg"},
    {"r90", 0, inf, false, false, "Lankford coefficient at 90 deg"}
};

const char* constantNames[6] = {"F", "G", "H", "L", "M", "N"};

//- F, G, H: any real (positivity is checked on the combination);
//  L, M, N: positive
parameterSpec constantSpec(int i)
{
    return i < 3
        ? parameterSpec{constantNames[i], -inf, inf, false, false,
                        "Hill'48 constant"}
        : parameterSpec{constantNames[i], 0, inf, false, false,
                        "Hill'48 shear constant"};
}

std::string join(const std::string& path, const std::string& key)
{
    return path.empty() ? key : path + "/" + key;
}

//- Voigt index of the symmetric pair (i, j)
int voigtIndex(int i, int j)
{
    if (i == j) return i;
    const int s = i + j;        // (0,1) -> 1, (1,2) -> 3, (0,2) -> 2
    return s == 1 ? 3 : s == 3 ? 4 : 5;
}

const char* axisName(int a)
{
    return a == 0 ? "x" : a == 1 ? "y" : "z";
}

int axisIndex(const std::string& w)
{
    return w == "x" ? 0 : w == "y" ? 1 : 2;
}

//- Check F..N (entry names below path) and the axes
void checkHill
(
    const std::array<double, 6>& c,
    int rolling,
    int normal,
    const std::string& path
)
{
    for (int i = 0; i < 6; ++i)
    {
        parameterSpec s = constantSpec(i);
        s.name = join(path, s.name);
        s.check(c[i]);
    }
    // The normal-stress block of A restricted to deviatoric stresses has
    // the eigenvalues of [[G+H, -H, -G], [-H, F+H, -F], [-G, -F, F+G]]
    // other than 0; both positive iff its trace 2(F+G+H) and the sum of
    // its principal 2x2 minors 3(FG+GH+HF) are positive.
    const double F = c[0], G = c[1], H = c[2];
    if (!(F + G + H > 0) || !(F*G + G*H + H*F > 0))
    {
        const std::string e = join(path, "F");
        throw inputError
        (
            e,
            "Hill'48 constants F = " + formatNumber(F) + ", G = " + formatNumber(G) + ", H = "
          + formatNumber(H) + " (" + join(path, "F") + " ...) do not bound the "
            "deviatoric stresses: need F + G + H > 0 and FG + GH + HF > 0"
        );
    }
    if (rolling < 0 || rolling > 2 || normal < 0 || normal > 2
     || rolling == normal)
    {
        const std::string e = join(path, "normalDirection");
        throw inputError
        (
            e,
            "'" + e + "' must be x, y or z and differ from rollingDirection"
        );
    }
}

} // anonymous namespace


// * * * * * * * * * * * * * * * quadraticYield * * * * * * * * * * * * * //

double quadraticYield::value(const vec6& xi) const
{
    // A is positive semi-definite; clip the roundoff of near-hydrostatic xi
    return std::sqrt(std::max(xi.dot(A_*xi), 0.0));
}


vec6 quadraticYield::gradient(const vec6& xi) const
{
    const vec6 Axi = A_*xi;
    const double phi = std::sqrt(std::max(xi.dot(Axi), 0.0));
    return phi > 0 ? vec6(Axi/phi) : vec6(vec6::Zero());
}


mat6 quadraticYield::hessian(const vec6& xi) const
{
    const vec6 Axi = A_*xi;
    const double phi = std::sqrt(std::max(xi.dot(Axi), 0.0));
    if (!(phi > 0)) return mat6::Zero();
    const vec6 n = Axi/phi;
    return (A_ - n*n.transpose())/phi;
}


// * * * * * * * * * * * * * * * * vonMises * * * * * * * * * * * * * * * //

vonMisesYield::vonMisesYield()
:
    quadraticYield(mat6::Zero())
{
    // phi^2 = 1/2[(x-y)^2 + (y-z)^2 + (z-x)^2] + 3(xy^2 + yz^2 + xz^2)
    for (int a = 0; a < 3; ++a)
    {
        for (int b = 0; b < 3; ++b) A_(a, b) = a == b ? 1 : -0.5;
        A_(a + 3, a + 3) = 3;
    }
}


// * * * * * * * * * * * * * * * * * hill48 * * * * * * * * * * * * * * * //

hill48Yield::hill48Yield
(
    const std::array<double, 6>& c,
    int rolling,
    int normal
)
:
    hill48Yield(c, rolling, normal, "")
{}


hill48Yield::hill48Yield
(
    const std::array<double, 6>& c,
    int rolling,
    int normal,
    const std::string& path
)
:
    quadraticYield(mat6::Zero()),
    FGHLMN_(c),
    rolling_(rolling),
    normal_(normal)
{
    checkHill(c, rolling, normal, path);

    const double F = c[0], G = c[1], H = c[2], L = c[3], M = c[4], N = c[5];
    // A in the sheet axes (1 2 3), Voigt order 11 22 33 12 23 13
    mat6 As = mat6::Zero();
    As(0, 0) = G + H;   As(0, 1) = -H;      As(0, 2) = -G;
    As(1, 0) = -H;      As(1, 1) = F + H;   As(1, 2) = -F;
    As(2, 0) = -G;      As(2, 1) = -F;      As(2, 2) = F + G;
    As(3, 3) = 2*N;
    As(4, 4) = 2*L;
    As(5, 5) = 2*M;

    // Sheet axis k is global axis p[k]; the sheet component (i, j) is the
    // global component (p[i], p[j]) (a permutation, no sign change), so
    // A moves by the induced permutation of the Voigt indices
    const int p[3] = {rolling, 3 - rolling - normal, normal};
    int g[6];
    for (int a = 0; a < 6; ++a)
    {
        g[a] = voigtIndex(p[voigtI[a]], p[voigtJ[a]]);
    }
    for (int a = 0; a < 6; ++a)
    {
        for (int b = 0; b < 6; ++b) A_(g[a], g[b]) = As(a, b);
    }
}


std::array<double, 6> hill48Yield::fromRValues
(
    double r0,
    double r45,
    double r90
)
{
    rSpecs[0].check(r0);
    rSpecs[1].check(r45);
    rSpecs[2].check(r90);
    const double G = 1/(1 + r0);
    const double H = r0/(1 + r0);
    const double F = r0/(r90*(1 + r0));
    const double N = (r0 + r90)*(1 + 2*r45)/(2*r90*(1 + r0));
    return {F, G, H, 1.5, 1.5, N};
}


namespace
{
//- F..N from a hill48 dictionary (r-values or constants, not both)
std::array<double, 6> hillConstants(const materialInput& d)
{
    d.checkKeys({"type", "r0", "r45", "r90", "F", "G", "H", "L", "M", "N",
                 "rollingDirection", "normalDirection"});
    const bool anyR = d.found("r0") || d.found("r45") || d.found("r90");
    std::string firstConstant;
    for (const char* k : constantNames)
    {
        if (firstConstant.empty() && d.found(k)) firstConstant = k;
    }
    if (anyR && !firstConstant.empty())
    {
        const std::string e = d.entryPath(firstConstant);
        throw inputError
        (
            e,
            "'" + e + "': give either the r-values r0 r45 r90 or the "
            "constants F G H L M N of " + d.path + ", not both"
        );
    }
    if (!firstConstant.empty())
    {
        std::array<double, 6> c;
        for (int i = 0; i < 6; ++i) c[i] = d.scalar(constantSpec(i));
        return c;
    }
    const double r0 = d.scalar(rSpecs[0]);
    const double r45 = d.scalar(rSpecs[1]);
    const double r90 = d.scalar(rSpecs[2]);
    return hill48Yield::fromRValues(r0, r45, r90);
}

} // anonymous namespace

//- The dictionary read in a fixed order: constants, then the axes
struct hill48Yield::dictInput
{
    std::array<double, 6> c;
    int rolling, normal;

    explicit dictInput(const materialInput& d)
    :
        c(hillConstants(d)),
        rolling(axisIndex(d.word("rollingDirection", {"x", "y", "z"}))),
        normal(axisIndex(d.word("normalDirection", {"x", "y", "z"})))
    {}
};


hill48Yield::hill48Yield(const materialInput& dict)
:
    hill48Yield(dictInput(dict), dict.path)
{}


hill48Yield::hill48Yield(const dictInput& in, const std::string& path)
:
    hill48Yield(in.c, in.rolling, in.normal, path)
{}


std::string hill48Yield::summary() const
{
    const double F = FGHLMN_[0], G = FGHLMN_[1], H = FGHLMN_[2];
    std::string s = "hill48: F " + formatNumber(F) + ", G " + formatNumber(G) + ", H " + formatNumber(H)
        + ", L " + formatNumber(FGHLMN_[3]) + ", M " + formatNumber(FGHLMN_[4]) + ", N "
        + formatNumber(FGHLMN_[5]) + " (r0 " + formatNumber(H/G) + ", r45 "
        + formatNumber(FGHLMN_[5]/(F + G) - 0.5) + ", r90 " + formatNumber(H/F)
        + "), rolling " + axisName(rolling_) + ", normal "
        + axisName(normal_);
    return s;
}


// * * * * * * * * * * * * * * * * selection * * * * * * * * * * * * * * * //

std::unique_ptr<yieldFunction> yieldFunction::New(const materialInput& dict)
{
    const std::string type = dict.word("type", {"vonMises", "hill48"});
    if (type == "vonMises")
    {
        dict.checkKeys({"type"});
        return std::make_unique<vonMisesYield>();
    }
    return std::make_unique<hill48Yield>(dict);
}

} // namespace form
