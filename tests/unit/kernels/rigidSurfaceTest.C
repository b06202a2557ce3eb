// Rigid tool surfaces in 3D (rigidSurface.H): the plane, sphere and
// cylinder in closed form, 2D profiles extruded along a direction and
// revolved about an axis, swept around a rectangular core or along a
// planar path (through the tested rigidProfile projection with exact
// curvature). For each: the gap against a brute-force distance to
// the surface, the normal, and dg/dy = n, dn/dy against central
// differences at random points on both sides of the surface; the
// tangent frame (tangentFrame) and its derivatives. FD tolerances about
// 10 x the largest observed error (fdCheck.H; margins in the log).
#include "rigidSurface.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include <tuple>
#include "../fdCheck.H"
#include "surfaceTestTools.H"

using namespace form;

namespace
{

// dn/dy and dg/dy = n by central differences of step h at y (1e-5 where
// the coordinates are some 50 and round-off, eps |y|/h, would be 5e-9
// at 1e-6)
void checkDerivatives
(
    const rigidSurface& s,
    const vec3& y,
    const std::string& what,
    double h = 1e-6
)
{
    const surfaceProjection P = s.project(y);
    mat3 dN;
    vec3 dG;
    test::surfaceDifferences(s, y, h, dG, dN);
    EXPECT_NEAR(P.normal.norm(), 1, 1e-13) << what;
    EXPECT_TRUE(test::fdError("rigidSurface dg/dy = n", (dG - P.normal).norm()/(1 + y.norm()), 1e-9))
        << what << " y " << y.transpose();
    EXPECT_TRUE(test::fdError("rigidSurface dn/dy", (dN - P.dNormalDY).norm()/(1 + dN.norm()), 3e-9))
        << what << " y " << y.transpose() << "\nFD\n" << dN << "\nanalytic\n" << P.dNormalDY;
    // The closest point y - g n lies on the surface: its gap is zero
    EXPECT_NEAR(s.project(y - P.gap*P.normal).gap, 0, 1e-10) << what;
}

} // anonymous namespace


TEST(rigidSurface, planeSphereCylinderInClosedForm)
{
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto plane = rigidSurface::New
    ("plane", {{"point", vec3(1, 2, 3)}, {"normal", vec3(0.2, -0.3, 1)}}, {});
    const auto sphere = rigidSurface::New
    ("sphere", {{"centre", vec3(0.5, 0, -1)}}, {{"radius", 2.0}});
    const auto cylinder = rigidSurface::New
    ("cylinder", {{"point", vec3(0, 1, 0)}, {"axis", vec3(1, 1, 0)}}, {{"radius", 1.5}});
    for (int k = 0; k < 20; ++k)
    {
        const vec3 y = 3*vec3(u(gen), u(gen), u(gen));
        // gaps against the geometry
        const vec3 nP = vec3(0.2, -0.3, 1).normalized();
        EXPECT_NEAR(plane->project(y).gap, nP.dot(y - vec3(1, 2, 3)), 1e-13);
        EXPECT_NEAR(sphere->project(y).gap, (y - vec3(0.5, 0, -1)).norm() - 2, 1e-13);
        const vec3 a = vec3(1, 1, 0).normalized(), d = y - vec3(0, 1, 0);
        EXPECT_NEAR(cylinder->project(y).gap, (d - a*a.dot(d)).norm() - 1.5, 1e-13);
        checkDerivatives(*plane, y, "plane");
        checkDerivatives(*sphere, y, "sphere");
        checkDerivatives(*cylinder, y, "cylinder");
    }
}

TEST(rigidSurface, extrudedProfileIsTheProfileInEveryPlane)
{
    // A die shoulder: top face, fillet R = 5, wall; extruded along z
    const auto die = rigidSurface::New
    (
        "extrudedProfile",
        {{"origin", vec3(0, 0, 0)}, {"xAxis", vec3(1, 0, 0)}, {"yAxis", vec3(0, 1, 0)}},
        {},
        std::make_shared<rigidProfile>
        (
            std::vector<Eigen::Vector2d>{{100, 0}, {40, 0}, {40, -50}},
            std::vector<double>{5}
        )
    );
    const rigidProfile outline({{100, 0}, {40, 0}, {40, -50}}, {5});
    std::mt19937 gen(9);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 30; ++k)
    {
        // points around the fillet (centre (45, -5))
        const vec3 y(45 + 8*u(gen), -5 + 8*u(gen), 20*u(gen));
        const surfaceProjection P = die->project(y);
        const profileProjection q = outline.project(Eigen::Vector2d(y(0), y(1)));
        EXPECT_NEAR(P.gap, q.gap, 1e-12);
        EXPECT_NEAR(P.normal(2), 0, 1e-15);
        checkDerivatives(*die, y, "extruded die");
    }
}

TEST(rigidSurface, revolvedProfileMakesASphericalPunch)
{
    // The ball of radius 2 about (0, 0, 1) as a revolved outline in the
    // (r, z) half-plane: (0, -1) -> (2, -1) -> (2, 3) -> (0, 3) with
    // fillets of radius 2 at the two corners (each uses its segments
    // whole): two quarter circles about (0, 1), the tool on the left
    const std::vector<Eigen::Vector2d> pts{{0, -1}, {2, -1}, {2, 3}, {0, 3}};
    const auto ball = rigidSurface::New
    (
        "revolvedProfile",
        {{"origin", vec3(0, 0, 0)}, {"axis", vec3(0, 0, 1)}},
        {},
        std::make_shared<rigidProfile>(pts, std::vector<double>{2, 2})
    );
    const auto sphere = rigidSurface::New
    ("sphere", {{"centre", vec3(0, 0, 1)}}, {{"radius", 2.0}});
    std::mt19937 gen(21);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 30; ++k)
    {
        const vec3 y = vec3(0, 0, 1) + 3.5*vec3(u(gen), u(gen), u(gen));
        const surfaceProjection P = ball->project(y), S = sphere->project(y);
        EXPECT_NEAR(P.gap, S.gap, 1e-12) << y.transpose();
        EXPECT_LT((P.normal - S.normal).norm(), 1e-12) << y.transpose();
        checkDerivatives(*ball, y, "revolved ball");
    }
    // on the axis: finite derivatives, the sphere's
    const vec3 pole(0, 0, 3.5);
    EXPECT_LT((ball->project(pole).dNormalDY - sphere->project(pole).dNormalDY).norm(), 1e-9);
}

TEST(rigidSurface, sweptProfileIsExtrudedAlongSidesAndRevolvedAtCorners)
{
    // A rounded-rectangle punch: the core [-3, 3] x [-2, 2] about the
    // axis z, its sides along e1 = (1, 1, 0)/sqrt 2; in the (r, z)
    // half-plane the wall r = 4 and the face z = 0 with a nose radius 1.5
    // (the tool below the face and inside the wall). Along a side it is
    // the outline extruded (r = the distance from that side), at a
    // corner the outline revolved about the corner's axis.
    const std::vector<Eigen::Vector2d> pts{{4, -10}, {4, 0}, {0, 0}};
    const auto outline = std::make_shared<rigidProfile>(pts, std::vector<double>{1.5});
    const vec3 a(0, 0, 1), e1 = vec3(1, 1, 0).normalized(), e2 = a.cross(e1);
    const vec3 o(1, -2, 0.5);
    const auto punch = rigidSurface::New
    (
        "sweptProfile",
        {{"origin", o}, {"axis", a}, {"xAxis", vec3(1, 1, 0.3)}},
        {{"coreX", 3.0}, {"coreY", 2.0}},
        outline
    );
    const auto corner = rigidSurface::New
    (
        "revolvedProfile",
        {{"origin", vec3(o + 3*e1 + 2*e2)}, {"axis", a}},
        {},
        outline
    );
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 40; ++k)
    {
        const double z = -3 + 5*u(gen);
        // along the side x1 = 3 (|x2| < 2) and beyond the corner (3, 2)
        const double x1 = 3.05 + 3*u(gen);
        const double xSide = -1.9 + 3.8*u(gen), xCorner = 2.05 + 3*u(gen);
        const vec3 ySide = o + x1*e1 + xSide*e2 + z*a;
        const vec3 yCorner = o + x1*e1 + xCorner*e2 + z*a;
        const surfaceProjection S = punch->project(ySide);
        const profileProjection q = outline->project(Eigen::Vector2d(x1 - 3, z));
        EXPECT_NEAR(S.gap, q.gap, 1e-12);
        EXPECT_LT((S.normal - (q.normal(0)*e1 + q.normal(1)*a)).norm(), 1e-12);
        checkDerivatives(*punch, ySide, "swept punch, side");
        const surfaceProjection C = punch->project(yCorner), R = corner->project(yCorner);
        EXPECT_NEAR(C.gap, R.gap, 1e-12);
        EXPECT_LT((C.normal - R.normal).norm(), 1e-12);
        EXPECT_LT((C.dNormalDY - R.dNormalDY).norm(), 1e-12*(1 + R.dNormalDY.norm()));
        checkDerivatives(*punch, yCorner, "swept punch, corner");
    }
    // Over the core: the flat face, gap = height
    const surfaceProjection top = punch->project(o + 1.0*e1 - 0.5*e2 + 0.7*a);
    EXPECT_NEAR(top.gap, 0.7, 1e-12);
    EXPECT_LT((top.normal - a).norm(), 1e-12);
    // ... and inside the tool under the face: a negative gap, the face's
    // normal and no curvature (the outline's end point, whose foot is the
    // same, gave |gap| and a curvature 1/|gap| across the face: Newton
    // stalled on the square cup's bottom, 2026-11-27)
    // The same with the outline starting on the core (the face walked
    // outwards, the tool above it: a punch pressing down, as a case
    // writes it), where the start point ties with the face
    const auto upper = rigidSurface::New
    (
        "sweptProfile",
        {{"origin", o}, {"axis", a}, {"xAxis", vec3(1, 1, 0.3)}},
        {{"coreX", 3.0}, {"coreY", 2.0}},
        std::make_shared<rigidProfile>
        (
            std::vector<Eigen::Vector2d>{{0, 0}, {4, 0}, {4, 10}},
            std::vector<double>{1.5}
        )
    );
    for (const double h : {0.7, -0.3, -1e-9})
    {
        const vec3 yCore = o - 2.0*e1 + 1.5*e2 + h*a;
        for (const auto* s : {punch.get(), upper.get()})
        {
            const double sign = s == punch.get() ? 1 : -1;
            const surfaceProjection in = s->project(yCore);
            EXPECT_NEAR(in.gap, sign*h, 1e-12) << "h " << h;
            EXPECT_LT((in.normal - sign*a).norm(), 1e-12) << "h " << h;
            EXPECT_EQ(in.dNormalDY.norm(), 0) << "h " << h;
            checkDerivatives(*s, yCore, "swept profile, over the core");
        }
    }
    // A core of zero size is the revolved outline
    const auto point = rigidSurface::New
    (
        "sweptProfile",
        {{"origin", vec3(o + 3*e1 + 2*e2)}, {"axis", a}, {"xAxis", e1}},
        {{"coreX", 0.0}, {"coreY", 0.0}},
        outline
    );
    const vec3 y = o + 4*e1 + 3.5*e2 - 0.3*a;
    EXPECT_NEAR(point->project(y).gap, corner->project(y).gap, 1e-14);
    // Bad input names the entry
    for (const auto& bad : std::vector<std::pair<std::string, std::map<std::string, double>>>
         {{"coreX", {{"coreX", -1.0}, {"coreY", 2.0}}}, {"coreY", {{"coreX", 1.0}}}})
    {
        try
        {
            rigidSurface::New
            (
                "sweptProfile", {{"origin", o}, {"axis", a}, {"xAxis", e1}},
                bad.second, outline
            );
            ADD_FAILURE() << "no error for " << bad.first;
        }
        catch (const inputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(bad.first), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW
    (
        rigidSurface::New
        (
            "sweptProfile", {{"origin", o}, {"axis", a}, {"xAxis", vec3(0, 0, 2)}},
            {{"coreX", 1.0}, {"coreY", 1.0}}, outline
        ),
        inputError
    );
}

TEST(rigidSurface, pathProfileIsTheProfileSweptAlongAnSBend)
{
    // A hat punch (the cross-section in (s, z): walls s = -+3, face z = 0,
    // nose radii 1) swept along an S-shaped path in the plane normal to
    // the axis: a line along e1 from (-50, 0), a left turn (fillet radius
    // 20 about the centre (0, 20)), a line at 45 degrees and a right turn
    // back (fillet 20), a line along e1 to the end. s is the distance from
    // the path, positive on its left (e2 where the path runs along e1).
    // Reference: along a line the profile extruded; along a fillet the
    // profile revolved about the fillet's axis, r = R - s (left turn) or
    // R + s (right turn).
    const std::vector<Eigen::Vector2d> hat{{-3, 10}, {-3, 0}, {3, 0}, {3, 10}};
    const auto outline = std::make_shared<rigidProfile>(hat, std::vector<double>{1, 1});
    const double R = 20, k = std::tan(M_PI/8);   // e = R tan(22.5 deg)
    const auto path = std::make_shared<rigidProfile>
    (
        std::vector<Eigen::Vector2d>{{-50, 0}, {R*k, 0}, {R*k + 40, 40}, {200, 40}},
        std::vector<double>{R, R}
    );
    const vec3 a = vec3(0.2, -0.1, 1).normalized();
    const vec3 e1 = (vec3(1, 0.3, 0) - a*a.dot(vec3(1, 0.3, 0))).normalized();
    const vec3 e2 = a.cross(e1);
    const vec3 o(1, -2, 0.5);
    const auto punch = rigidSurface::New
    (
        "pathProfile",
        {{"origin", o}, {"axis", a}, {"xAxis", vec3(1, 0.3, 0)}},
        {}, outline, nullptr, path
    );
    // The references: mirror a profile in s (the walking order reversed
    // keeps the tool on the left)
    auto shifted = [&](double shift, double sign)
    {
        std::vector<Eigen::Vector2d> p;
        for (const auto& v : hat) p.emplace_back(shift + sign*v(0), v(1));
        if (sign < 0) std::reverse(p.begin(), p.end());
        return std::make_shared<rigidProfile>(p, std::vector<double>{1, 1});
    };
    const auto straight = rigidSurface::New
    (
        "extrudedProfile",
        {{"origin", o}, {"xAxis", e2}, {"yAxis", a}}, {}, outline
    );
    const vec3 cLeft = o + 20*e2;                       // first fillet's centre
    const auto leftTurn = rigidSurface::New
    ("revolvedProfile", {{"origin", cLeft}, {"axis", a}}, {}, shifted(R, -1));
    // the second fillet's centre: under its end on the last line
    const Eigen::Vector2d c2(2*R*k + 40, 40 - R);
    const vec3 cRight = o + c2(0)*e1 + c2(1)*e2;
    const auto rightTurn = rigidSurface::New
    ("revolvedProfile", {{"origin", cRight}, {"axis", a}}, {}, shifted(R, 1));
    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 40; ++i)
    {
        const double s = -6 + 12*u(gen), z = -2 + 6*u(gen);
        // on the first line (x1 < 0), on the fillets (a quarter of their
        // sweep in)
        const vec3 yLine = o + (-40 + 35*u(gen))*e1 + s*e2 + z*a;
        const double phi = (0.1 + 0.8*u(gen))*M_PI/4;
        const vec3 yLeft =
            cLeft + (R - s)*(std::sin(phi)*e1 - std::cos(phi)*e2) + z*a;
        const vec3 yRight =
            cRight + (R + s)*(-std::sin(phi)*e1 + std::cos(phi)*e2) + z*a;
        for
        (
            const auto& [y, ref, what] :
            std::vector<std::tuple<vec3, const rigidSurface*, std::string>>
            {
                {yLine, straight.get(), "line"},
                {yLeft, leftTurn.get(), "left turn"},
                {yRight, rightTurn.get(), "right turn"}
            }
        )
        {
            const surfaceProjection P = punch->project(y), Q = ref->project(y);
            EXPECT_NEAR(P.gap, Q.gap, 1e-11) << what << " s " << s << " z " << z;
            EXPECT_LT((P.normal - Q.normal).norm(), 1e-11) << what;
            EXPECT_LT((P.dNormalDY - Q.dNormalDY).norm(), 1e-10*(1 + Q.dNormalDY.norm()))
                << what << "\n" << P.dNormalDY << "\nreference\n" << Q.dNormalDY;
            checkDerivatives(*punch, y, "path profile, " + what, 1e-5);
        }
    }
    // Everywhere along the S (the 45-degree line and the joints too),
    // within |s| < 10 (the sweep is smooth where |s| < R)
    for (int i = 0; i < 60; ++i)
    {
        const Eigen::Vector2d p = path->pointAt(5 + (path->length() - 10)*u(gen));
        const Eigen::Vector2d x = p - (-10 + 20*u(gen))*path->project(p).normal;
        const vec3 y = o + x(0)*e1 + x(1)*e2 + (-2 + 6*u(gen))*a;
        checkDerivatives(*punch, y, "path profile, anywhere", 1e-5);
    }
    // Beyond the end of the path: an error that says so
    try
    {
        punch->project(o - 60*e1);
        ADD_FAILURE() << "no error beyond the path's start";
    }
    catch (const numericalError& e)
    {
        EXPECT_NE(std::string(e.what()).find("beyond"), std::string::npos) << e.what();
    }
    // Bad input names the entry
    try
    {
        rigidSurface::New
        ("pathProfile", {{"origin", o}, {"axis", a}, {"xAxis", e1}}, {}, outline);
        ADD_FAILURE() << "no error without a path";
    }
    catch (const inputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("path"), std::string::npos) << e.what();
    }
}

TEST(rigidSurface, tangentFrameAndItsDerivatives)
{
    std::mt19937 gen(4);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto sphere = rigidSurface::New
    ("sphere", {{"centre", vec3(0.5, 0, -1)}}, {{"radius", 2.0}});
    const vec3 ref(0.3, 0.9, -0.2);
    for (int k = 0; k < 20; ++k)
    {
        const vec3 y = 3*vec3(u(gen), u(gen), u(gen));
        const surfaceProjection P = sphere->project(y);
        const tangentFrame F = tangentFrame::of(P, ref);
        EXPECT_NEAR(F.t1.dot(P.normal), 0, 1e-14);
        EXPECT_NEAR(F.t2.dot(P.normal), 0, 1e-14);
        EXPECT_NEAR(F.t1.dot(F.t2), 0, 1e-14);
        EXPECT_LT((F.t1.cross(F.t2) - P.normal).norm(), 1e-14);
        const double h = 1e-6;
        mat3 d1, d2;
        for (int j = 0; j < 3; ++j)
        {
            vec3 yp = y, ym = y;
            yp(j) += h;
            ym(j) -= h;
            const tangentFrame a = tangentFrame::of(sphere->project(yp), ref);
            const tangentFrame b = tangentFrame::of(sphere->project(ym), ref);
            d1.col(j) = (a.t1 - b.t1)/(2*h);
            d2.col(j) = (a.t2 - b.t2)/(2*h);
        }
        EXPECT_TRUE(test::fdError("tangentFrame dt1/dy", (d1 - F.dT1DY).norm()/(1 + d1.norm()), 3e-9));
        EXPECT_TRUE(test::fdError("tangentFrame dt2/dy", (d2 - F.dT2DY).norm()/(1 + d2.norm()), 3e-9));
    }
}

TEST(rigidSurface, badInputNamesTheEntry)
{
    EXPECT_THROW(rigidSurface::New("torus", {}, {}), inputError);
    EXPECT_THROW
    (
        rigidSurface::New("sphere", {{"centre", vec3(0, 0, 0)}}, {{"radius", -1.0}}),
        inputError
    );
    EXPECT_THROW
    (
        rigidSurface::New("plane", {{"point", vec3(0, 0, 0)}, {"normal", vec3(0, 0, 0)}}, {}),
        inputError
    );
    EXPECT_THROW(rigidSurface::New("sphere", {}, {{"radius", 1.0}}), inputError);
}
