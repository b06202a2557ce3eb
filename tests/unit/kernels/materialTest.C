// material base class: run-time selection, parameter range checks, initial
// state, default (Hencky) equivalent strain.
#include "materialInput.H"
#include "formError.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace form;

TEST(material, registryHoldsAllModels)
{
    EXPECT_EQ(material::validTypes(), "elastoPlastic linearElastic neoHookean stVenantKirchhoff");
    const auto& reg = material::registry();
    ASSERT_EQ(reg.count("neoHookean"), 1u);
    ASSERT_EQ(reg.at("neoHookean").parameters.size(), 2u);
    EXPECT_EQ(reg.at("neoHookean").parameters[0].name, "E");
    EXPECT_EQ(reg.at("neoHookean").parameters[1].name, "nu");
}

TEST(material, newUnknownTypeListsValidNames)
{
    try
    {
        material::New("neoHooke", {{"E", 1}, {"nu", 0.3}});
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "type");
        const std::string msg = e.what();
        EXPECT_NE(msg.find("'neoHooke'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("valid: elastoPlastic linearElastic neoHookean stVenantKirchhoff"), std::string::npos)
            << msg;
    }
}

TEST(material, newOutOfRangeOrMissingParameterNamesIt)
{
    for (const std::string type : {"linearElastic", "neoHookean"})
    {
        try
        {
            material::New(type, {{"E", -1}, {"nu", 0.3}});
            FAIL() << "E = -1 accepted";
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), "E");
            EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos);
        }
        try
        {
            material::New(type, {{"E", 1}, {"nu", 0.5}});
            FAIL() << "nu = 0.5 accepted";
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), "nu");
            // value and the open range (-1, 0.5)
            EXPECT_NE(std::string(e.what()).find("0.5"), std::string::npos);
            EXPECT_NE(std::string(e.what()).find("(-1, 0.5)"), std::string::npos)
                << e.what();
        }
        try
        {
            material::New(type, {{"E", 1}});
            FAIL() << "missing nu accepted";
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), "nu");
            EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
        }
        // The constructors re-check (callers that bypass New)
        parameterMap bad{{"E", 0}, {"nu", 0.3}};
        EXPECT_THROW(material::registry().at(type).factory(bad), inputError);
        // A valid set constructs
        EXPECT_EQ(material::New(type, {{"E", 1}, {"nu", -0.99}})->type(), type);
    }
}

TEST(material, parameterSpecInclusiveAndExclusiveBounds)
{
    const parameterSpec closed{"a", 0, 1, true, true, ""};
    EXPECT_NO_THROW(closed.check(0));
    EXPECT_NO_THROW(closed.check(1));
    EXPECT_THROW(closed.check(1 + 1e-12), inputError);
    const parameterSpec open{"b", 0, 1, false, false, "a fraction"};
    EXPECT_THROW(open.check(0), inputError);
    EXPECT_THROW(open.check(1), inputError);
    EXPECT_THROW(open.check(std::nan("")), inputError);
    EXPECT_NO_THROW(open.check(0.5));
    try
    {
        closed.check(2);
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "a");
        EXPECT_NE(std::string(e.what()).find("[0, 1]"), std::string::npos);
    }
}

TEST(material, initialStateSizedByHistory)
{
    const auto m = material::New("neoHookean", {{"E", 1}, {"nu", 0.3}});
    EXPECT_EQ(m->nHistory(), 0);
    EXPECT_EQ(m->initialState().history.size(), 0);
}

TEST(material, equivalentStrainIsHenckyVonMises)
{
    const auto nh = material::New("neoHookean", {{"E", 1}, {"nu", 0.3}});
    const materialState s = nh->initialState();

    // Isochoric uniaxial stretch: e = diag(ln l, -ln l/2, -ln l/2),
    // sqrt(2/3 e:e) = |ln l|; also after a rotation (R F has the same b
    // up to rotation) and with a superposed volume change (deviator only)
    const double l = 1.7;
    mat3 F = mat3::Zero();
    F.diagonal() << l, 1/std::sqrt(l), 1/std::sqrt(l);
    EXPECT_NEAR(nh->equivalentStrain(F, s), std::log(l), 1e-14);
    const mat3 R = test::rotation(vec3(1, 2, 3), 0.8);
    EXPECT_NEAR(nh->equivalentStrain(R*F*1.2, s), std::log(l), 1e-13);

    // Simple shear F = I + g e1 x e2: principal stretches of b are
    // (sqrt(1 + g^2/4) +- g/2)^2, e = +-asinh(g/2) in-plane, 0 out of plane
    const double g = 0.9;
    F.setIdentity();
    F(0, 1) = g;
    EXPECT_NEAR(nh->equivalentStrain(F, s),
                2/std::sqrt(3.0)*std::asinh(g/2), 1e-14);

    // Small-strain model: eps = sym(F - I), simple shear eps_xy = g/2
    const auto le = material::New("linearElastic", {{"E", 1}, {"nu", 0.3}});
    EXPECT_NEAR(le->equivalentStrain(F, s), g/std::sqrt(3.0), 1e-14);
}
