// hardeningLaw: closed-form values, slopes against central differences of
// sigmaY, run-time selection, and input errors (missing / out-of-range /
// unknown keyword / unknown type / bad table) naming the entry path.
#include "hardeningLaw.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolEveryLaw = 1e-7;
constexpr double fdTolSwift = 5e-9;
constexpr double fdTolTabulated = 2e-6;
constexpr double fdTolVoce = 3e-9;
}

using namespace form;

namespace
{

//- A `hardening` sub-dictionary as the OpenFOAM layer would fill it
materialInput hardeningDict
(
    const std::string& type,
    const std::map<std::string, double>& scalars = {}
)
{
    materialInput d;
    d.path = "hardening";
    d.words["type"] = type;
    d.scalars = scalars;
    return d;
}

materialInput tableDict(const materialInput::table& t)
{
    materialInput d = hardeningDict("tabulated");
    d.tables["table"] = t;
    return d;
}

//- Expect New(dict) to throw inputError naming entry; returns the message
std::string expectInputError(const materialInput& d, const std::string& entry)
{
    try
    {
        hardeningLaw::New(d);
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), entry) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no inputError for " << entry;
    return "";
}

//- Central difference of sigmaY at x
double fdSlope(const hardeningLaw& law, double x, double h)
{
    return (law.sigmaY(x + h) - law.sigmaY(x - h))/(2*h);
}

} // anonymous namespace


TEST(hardeningLaw, perfectAndLinearClosedForms)
{
    const auto perfect = hardeningLaw::New(hardeningDict("perfect",
        {{"sigmaY0", 250}}));
    EXPECT_EQ(perfect->type(), "perfect");
    for (const double e : {0.0, 0.1, 3.0})
    {
        EXPECT_EQ(perfect->sigmaY(e), 250);
        EXPECT_EQ(perfect->slope(e), 0);
    }

    const auto linear = hardeningLaw::New(hardeningDict("linear",
        {{"sigmaY0", 250}, {"H", 1200}}));
    EXPECT_EQ(linear->type(), "linear");
    EXPECT_DOUBLE_EQ(linear->sigmaY(0), 250);
    EXPECT_DOUBLE_EQ(linear->sigmaY(0.25), 550);
    EXPECT_DOUBLE_EQ(linear->slope(0.7), 1200);
    EXPECT_NE(linear->summary().find("linear"), std::string::npos);
}

TEST(hardeningLaw, swiftClosedFormAndSlope)
{
    const auto law = hardeningLaw::New(hardeningDict("swift",
        {{"K", 550}, {"eps0", 0.01}, {"n", 0.22}}));
    EXPECT_EQ(law->type(), "swift");
    EXPECT_NEAR(law->sigmaY(0), 550*std::pow(0.01, 0.22), 1e-12);
    EXPECT_NEAR(law->sigmaY(0.3), 550*std::pow(0.31, 0.22), 1e-12);
    // d/de K (e0 + e)^n = K n (e0 + e)^(n-1)
    EXPECT_NEAR(law->slope(0.3), 550*0.22*std::pow(0.31, -0.78), 1e-11);
    for (const double e : {0.0, 1e-4, 0.02, 0.3, 2.0})
    {
        const double h = 1e-6*(0.01 + e);
        EXPECT_TRUE(test::fdError("hardening swift slope", std::abs(law->slope(e) - fdSlope(*law, e, h))/std::abs(law->slope(e)), fdTolSwift)) << "epsP " << e;
        // flowStress: both at once (one power), the same values
        double slope = 0;
        EXPECT_DOUBLE_EQ(law->flowStress(e, slope), law->sigmaY(e)) << e;
        EXPECT_NEAR(slope, law->slope(e), 1e-14*law->slope(e)) << e;
    }
    // n = 0: perfect plasticity at K
    const swiftHardening flat(300, 0.1, 0);
    EXPECT_DOUBLE_EQ(flat.sigmaY(0.5), 300);
    EXPECT_DOUBLE_EQ(flat.slope(0.5), 0);
    double flatSlope = 1;
    EXPECT_DOUBLE_EQ(flat.flowStress(0.5, flatSlope), 300);
    EXPECT_EQ(flatSlope, 0);
}

TEST(hardeningLaw, voceClosedFormAndSlope)
{
    const auto law = hardeningLaw::New(hardeningDict("voce",
        {{"sigmaY0", 250}, {"sigmaInf", 400}, {"b", 12}, {"H", 50}}));
    EXPECT_EQ(law->type(), "voce");
    const double e = 0.08;
    EXPECT_NEAR(law->sigmaY(e),
                250 + 150*(1 - std::exp(-12*e)) + 50*e, 1e-12);
    EXPECT_NEAR(law->slope(e), 150*12*std::exp(-12*e) + 50, 1e-11);
    for (const double x : {0.0, 0.01, 0.1, 0.5, 3.0})
    {
        EXPECT_TRUE(test::fdError("hardening voce slope", std::abs(law->slope(x) - fdSlope(*law, x, 1e-6))/law->slope(x), fdTolVoce)) << "epsP " << x;
    }
    // H is optional (default 0): saturates at sigmaInf
    const auto sat = hardeningLaw::New(hardeningDict("voce",
        {{"sigmaY0", 250}, {"sigmaInf", 400}, {"b", 12}}));
    EXPECT_NEAR(sat->sigmaY(10), 400, 1e-9);
    EXPECT_NEAR(sat->slope(10), 0, 1e-9);
    EXPECT_DOUBLE_EQ(sat->sigmaY(0), 250);
}

TEST(hardeningLaw, tabulatedInterpolatesAndClamps)
{
    const auto law = hardeningLaw::New(tableDict(
        {{0, 250}, {0.05, 320}, {0.3, 410}}));
    EXPECT_EQ(law->type(), "tabulated");
    EXPECT_DOUBLE_EQ(law->sigmaY(0), 250);
    EXPECT_DOUBLE_EQ(law->sigmaY(0.05), 320);
    EXPECT_NEAR(law->sigmaY(0.025), 285, 1e-12);
    EXPECT_NEAR(law->sigmaY(0.175), 365, 1e-12);
    EXPECT_DOUBLE_EQ(law->sigmaY(0.3), 410);
    EXPECT_DOUBLE_EQ(law->sigmaY(5), 410);     // clamped
    EXPECT_NEAR(law->slope(0.01), 70/0.05, 1e-9);
    EXPECT_NEAR(law->slope(0.2), 90/0.25, 1e-9);
    // Right derivative at a knot, zero beyond the last point
    EXPECT_NEAR(law->slope(0.05), 90/0.25, 1e-9);
    EXPECT_EQ(law->slope(0.3), 0);
    EXPECT_EQ(law->slope(1), 0);
    // Slope against differences inside segments
    for (const double x : {0.001, 0.03, 0.1, 0.29, 0.4})
    {
        EXPECT_TRUE(test::fdError("hardening tabulated slope", std::abs(law->slope(x) - fdSlope(*law, x, 1e-7)), fdTolTabulated)) << x;
    }
    // A single point is perfect plasticity
    const auto one = hardeningLaw::New(tableDict({{0, 300}}));
    EXPECT_DOUBLE_EQ(one->sigmaY(0.7), 300);
    EXPECT_EQ(one->slope(0.7), 0);
}

TEST(hardeningLaw, slopesMatchDifferencesAtRandomPoints)
{
    std::vector<std::unique_ptr<hardeningLaw>> laws;
    laws.push_back(std::make_unique<perfectHardening>(200));
    laws.push_back(std::make_unique<linearHardening>(200, 900));
    laws.push_back(std::make_unique<swiftHardening>(600, 0.002, 0.45));
    laws.push_back(std::make_unique<voceHardening>(200, 350, 30, 10));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uni(0, 1);
    for (const auto& law : laws)
    {
        for (int k = 0; k < 50; ++k)
        {
            const double x = std::pow(uni(rng), 3);     // dense near 0
            const double h = 1e-6*(x + 1e-3);
            const double fd = fdSlope(*law, x, h);
            EXPECT_TRUE(test::fdError("hardening every law slope", std::abs(law->slope(x) - fd)/(std::abs(fd) + 1), fdTolEveryLaw))
                << law->type() << " epsP " << x;
            EXPECT_GT(law->sigmaY(x), 0);
        }
    }
}

// The plastic work of the yield surface, W(epsP) = int_0^epsP sigmaY de
// (the dissipation of the effect report, material.H), against a composite
// Simpson rule of sigmaY with 20000 intervals (split at the table's knots,
// where the tabulated law's integrand has kinks)
TEST(hardeningLaw, workIsTheIntegralOfTheFlowStress)
{
    std::vector<std::unique_ptr<hardeningLaw>> laws;
    laws.push_back(std::make_unique<perfectHardening>(200));
    laws.push_back(std::make_unique<linearHardening>(200, 900));
    laws.push_back(std::make_unique<swiftHardening>(600, 0.002, 0.45));
    laws.push_back(std::make_unique<voceHardening>(200, 350, 30, 10));
    laws.push_back
    (
        hardeningLaw::New(tableDict({{0, 200}, {0.05, 260}, {0.2, 300}}))
    );
    const auto simpson = [](const hardeningLaw& law, double a, double b)
    {
        const int n = 20000;
        const double h = (b - a)/n;
        double s = law.sigmaY(a) + law.sigmaY(b);
        for (int i = 1; i < n; ++i)
        {
            s += (i % 2 ? 4 : 2)*law.sigmaY(a + i*h);
        }
        return s*h/3;
    };
    for (const auto& law : laws)
    {
        EXPECT_EQ(law->work(0), 0) << law->type();
        for (double x : {1e-4, 0.03, 0.05, 0.12, 0.2, 0.7})
        {
            // Knots of the table (and 0.7: beyond its last, constant)
            double ref = 0, a = 0;
            for (double knot : {0.05, 0.2})
            {
                if (knot < x) { ref += simpson(*law, a, knot); a = knot; }
            }
            ref += simpson(*law, a, x);
            EXPECT_NEAR(law->work(x), ref, 1e-10*ref)
                << law->type() << " epsP " << x;
        }
        // Increasing, and sigmaY is its derivative
        const double x = 0.1, h = 1e-6;
        EXPECT_NEAR
        (
            (law->work(x + h) - law->work(x - h))/(2*h), law->sigmaY(x),
            1e-6*law->sigmaY(x)
        ) << law->type();
    }
}

TEST(hardeningLaw, unknownOrMissingTypeNamesTheEntry)
{
    const std::string msg =
        expectInputError(hardeningDict("johnsonCook"), "hardening/type");
    EXPECT_NE(msg.find("johnsonCook"), std::string::npos) << msg;
    EXPECT_NE(msg.find("perfect linear swift voce tabulated"),
              std::string::npos) << msg;
    materialInput noType;
    noType.path = "hardening";
    noType.scalars["sigmaY0"] = 1;
    expectInputError(noType, "hardening/type");
}

TEST(hardeningLaw, missingParametersNameTheEntry)
{
    expectInputError(hardeningDict("perfect"), "hardening/sigmaY0");
    expectInputError(hardeningDict("linear", {{"sigmaY0", 1}}), "hardening/H");
    expectInputError(hardeningDict("swift", {{"K", 1}, {"n", 0.2}}),
                     "hardening/eps0");
    expectInputError(hardeningDict("voce", {{"sigmaY0", 1}, {"b", 1}}),
                     "hardening/sigmaInf");
    expectInputError(hardeningDict("tabulated"), "hardening/table");
    expectInputError(tableDict({}), "hardening/table");
}

TEST(hardeningLaw, outOfRangeParametersNameTheEntry)
{
    expectInputError(hardeningDict("perfect", {{"sigmaY0", 0}}),
                     "hardening/sigmaY0");
    expectInputError(hardeningDict("linear", {{"sigmaY0", 1}, {"H", -1}}),
                     "hardening/H");
    const std::string msg = expectInputError(hardeningDict("swift",
        {{"K", 500}, {"eps0", 0.01}, {"n", 1.5}}), "hardening/n");
    EXPECT_NE(msg.find("1.5"), std::string::npos) << msg;
    expectInputError(hardeningDict("swift",
        {{"K", 500}, {"eps0", 0}, {"n", 0.2}}), "hardening/eps0");
    expectInputError(hardeningDict("swift",
        {{"K", -5}, {"eps0", 0.01}, {"n", 0.2}}), "hardening/K");
    expectInputError(hardeningDict("voce",
        {{"sigmaY0", 250}, {"sigmaInf", 400}, {"b", 0}}), "hardening/b");
    // Softening saturation is rejected
    expectInputError(hardeningDict("voce",
        {{"sigmaY0", 250}, {"sigmaInf", 200}, {"b", 5}}),
        "hardening/sigmaInf");
    expectInputError(hardeningDict("voce",
        {{"sigmaY0", 250}, {"sigmaInf", 400}, {"b", 5}, {"H", -2}}),
        "hardening/H");
    const double nan = std::nan("");
    expectInputError(hardeningDict("linear", {{"sigmaY0", nan}, {"H", 1}}),
                     "hardening/sigmaY0");
}

TEST(hardeningLaw, unknownKeywordsNameTheEntry)
{
    expectInputError(hardeningDict("swift",
        {{"K", 500}, {"eps0", 0.01}, {"n", 0.2}, {"sigmaY0", 250}}),
        "hardening/sigmaY0");
    expectInputError(hardeningDict("perfect", {{"sigmaY0", 1}, {"H", 0}}),
                     "hardening/H");
    materialInput d = hardeningDict("linear", {{"sigmaY0", 1}, {"H", 1}});
    d.tables["table"] = {{0, 1}};
    expectInputError(d, "hardening/table");
    materialInput t = tableDict({{0, 250}});
    t.scalars["sigmaY0"] = 250;
    expectInputError(t, "hardening/sigmaY0");
}

TEST(hardeningLaw, badTablesNameTheEntry)
{
    // First point not at zero plastic strain
    std::string msg = expectInputError(tableDict({{0.01, 250}, {0.1, 300}}),
                                       "hardening/table");
    EXPECT_NE(msg.find("0"), std::string::npos);
    // Not strictly increasing strain
    expectInputError(tableDict({{0, 250}, {0.1, 300}, {0.1, 310}}),
                     "hardening/table");
    expectInputError(tableDict({{0, 250}, {0.2, 300}, {0.1, 310}}),
                     "hardening/table");
    // Non-positive or decreasing stress
    expectInputError(tableDict({{0, 0}, {0.1, 300}}), "hardening/table");
    expectInputError(tableDict({{0, 250}, {0.1, 300}, {0.2, 290}}),
                     "hardening/table");
    expectInputError(tableDict({{0, 250}, {0.1, std::nan("")}}),
                     "hardening/table");
}

TEST(hardeningLaw, valueConstructorsCheckTooAndSummariesNameParameters)
{
    EXPECT_THROW(perfectHardening(-1), inputError);
    EXPECT_THROW(linearHardening(1, -1), inputError);
    EXPECT_THROW(swiftHardening(1, 0, 0.2), inputError);
    EXPECT_THROW(voceHardening(300, 200, 1), inputError);
    EXPECT_THROW(tabulatedHardening(materialInput::table{{0.1, 1}}),
                 inputError);
    try
    {
        swiftHardening(1, 0.01, -0.1);
        FAIL();
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "n");
    }
    const swiftHardening s(550, 0.01, 0.22);
    EXPECT_NE(s.summary().find("swift"), std::string::npos) << s.summary();
    EXPECT_NE(s.summary().find("550"), std::string::npos) << s.summary();
    EXPECT_NE(s.summary().find("0.22"), std::string::npos) << s.summary();
    const tabulatedHardening t(materialInput::table{{0, 250}, {0.1, 300}});
    EXPECT_NE(t.summary().find("2 points"), std::string::npos) << t.summary();
    EXPECT_EQ(t.summary().find('\n'), std::string::npos);
}
