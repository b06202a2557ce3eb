// rigidProfile: closed-form gap / normal / xi on lines, convex and concave
// fillets, sharp vertices and end points of a U-channel die; central
// differences of dgap/dy = n, dxi/dy and dn/dy at random points; arc-length
// consistency, fillet lengths, tangent continuity, sampling and input
// errors naming the vertex / radius; a point on the medial axis of two
// pieces keeps one of them.
#include "rigidProfile.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolGap = 2e-8;
constexpr double fdTolN = 5e-8;
constexpr double fdTolXi = 3e-8;
}

using namespace form;

namespace
{

using vec2 = Eigen::Vector2d;

const double pi = 3.14159265358979323846;

//- Half of a U-channel die (die below/right, blank above/inside): top
//  face, convex shoulder r = 5 at (40 0), wall, concave bottom corner
//  r = 3 at (40 -50), bottom to the axis x = 0. Pieces: 0 start point,
//  1 top line, 2 shoulder arc, 3 wall, 4 bottom fillet, 5 bottom, 6 end
rigidProfile die(std::vector<double> radii = {5, 3})
{
    return rigidProfile({{100, 0}, {40, 0}, {40, -50}, {0, -50}}, radii);
}

//- A punch corner (punch above/left): bottom face, side
rigidProfile punch(double r)
{
    return rigidProfile({{0, 0}, {30, 0}, {30, 50}}, {r});
}

//- A zig-zag with general angles, convex and concave fillets
rigidProfile zigzag()
{
    return rigidProfile
    (
        {{0, 0}, {20, 3}, {35, -10}, {50, -8}, {60, 10}},
        {4, 2, 3}
    );
}

void expectNear(const vec2& a, const vec2& b, double tol, const char* what)
{
    EXPECT_LT((a - b).norm(), tol)
        << what << ": (" << a.transpose() << ") vs (" << b.transpose() << ")";
}

//- Expect the constructor to throw inputError naming entry, with a
//  message containing `contains`
void expectInputError
(
    const std::vector<vec2>& pts,
    const std::vector<double>& radii,
    const std::string& entry,
    const std::string& contains
)
{
    try
    {
        rigidProfile p(pts, radii);
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), entry) << e.what();
        EXPECT_NE(std::string(e.what()).find(contains), std::string::npos)
            << "message '" << e.what() << "' lacks '" << contains << "'";
        return;
    }
    ADD_FAILURE() << "no inputError (expected '" << contains << "')";
}

//- Kinds of pieces a finite-difference check has visited
enum kind { lineKind, convexArcKind, concaveArcKind, convexVertexKind,
            concaveVertexKind };

kind kindOf(const profileProjection& p)
{
    if (p.dNormalDY.norm() == 0) return lineKind;
    const double c = p.tangent.dot(p.dNormalDY*p.tangent);
    if (p.dXidY.norm() == 0)
    {
        return c > 0 ? convexVertexKind : concaveVertexKind;
    }
    return c > 0 ? convexArcKind : concaveArcKind;
}

//- Relative error with a floor on the reference norm
double relErr(double errNorm, double refNorm)
{
    return errNorm/std::max(refNorm, 1e-12);
}

//- Central differences of gap, xi and normal at random points around the
//  profile (box [lo, hi]); points within h of a change of piece, or
//  nearer than 0.5 to a centre of curvature, are skipped. Returns the
//  number of points checked and records the kinds visited.
int fdCheck
(
    const rigidProfile& prof,
    const vec2& lo,
    const vec2& hi,
    int nPoints,
    unsigned seed,
    std::set<int>& kinds
)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(lo(0), hi(0)), uy(lo(1), hi(1));
    const double h = 1e-4;  // ~1e-6 relative to the profile size ~100
    int checked = 0;

    for (int k = 0; k < nPoints; ++k)
    {
        const vec2 y(ux(rng), uy(rng));
        const profileProjection p = prof.project(y);

        // Skip points near a switch between pieces (8 directions; the
        // axis directions are the stencil points below)
        bool nearSwitch = false;
        for (int a = 0; a < 8 && !nearSwitch; ++a)
        {
            const vec2 dy = h*vec2(std::cos(a*pi/4), std::sin(a*pi/4));
            nearSwitch = prof.project(y + dy).piece != p.piece;
        }
        // ... and points near a centre of curvature, |dn/dy| = 1/rho
        if (nearSwitch || p.dNormalDY.norm() > 2) continue;
        ++checked;
        kinds.insert(kindOf(p));

        vec2 dGap, dXi;
        Eigen::Matrix2d dN;
        for (int j = 0; j < 2; ++j)
        {
            vec2 dy = vec2::Zero();
            dy(j) = h;
            const profileProjection pp = prof.project(y + dy);
            const profileProjection pm = prof.project(y - dy);
            dGap(j) = (pp.gap - pm.gap)/(2*h);
            dXi(j) = (pp.xi - pm.xi)/(2*h);
            dN.col(j) = (pp.normal - pm.normal)/(2*h);
        }
        EXPECT_TRUE(test::fdError("rigidProfile gap gradient", relErr((dGap - p.normal).norm(), 1), fdTolGap))
            << "dgap/dy at y = " << y.transpose() << " piece " << p.piece;
        EXPECT_TRUE(test::fdError("rigidProfile dxi/dy", relErr((dXi - p.dXidY).norm(), p.dXidY.norm()), fdTolXi))
            << "dxi/dy at y = " << y.transpose() << " piece " << p.piece
            << ": fd " << dXi.transpose() << " vs " << p.dXidY.transpose();
        EXPECT_TRUE(test::fdError("rigidProfile dn/dy", relErr((dN - p.dNormalDY).norm(), p.dNormalDY.norm()), fdTolN))
            << "dn/dy at y = " << y.transpose() << " piece " << p.piece
            << ":\nfd\n" << dN << "\nvs\n" << p.dNormalDY;

        // Frame: unit normal and tangent, normal = (t_y, -t_x)
        EXPECT_NEAR(p.normal.norm(), 1, 1e-12);
        expectNear(p.normal, vec2(p.tangent(1), -p.tangent(0)), 1e-12,
                   "normal = (t_y, -t_x)");
    }
    return checked;
}

} // anonymous namespace


TEST(rigidProfile, dieLength)
{
    EXPECT_NEAR(die().length(), 134 + 4*pi, 1e-12);
    EXPECT_NEAR(die({}).length(), 60 + 50 + 40, 1e-12);
}


TEST(rigidProfile, straightLine)
{
    const rigidProfile d = die();

    // Above the top face (walking in -x, die below)
    profileProjection p = d.project(vec2(70, 2));
    EXPECT_EQ(p.piece, 1);
    EXPECT_NEAR(p.gap, 2, 1e-12);
    expectNear(p.point, vec2(70, 0), 1e-12, "point");
    expectNear(p.normal, vec2(0, 1), 1e-15, "normal");
    expectNear(p.tangent, vec2(-1, 0), 1e-15, "tangent");
    EXPECT_NEAR(p.xi, 30, 1e-12);
    expectNear(p.dXidY, vec2(-1, 0), 1e-15, "dXidY");
    EXPECT_EQ(p.dNormalDY.norm(), 0);

    // Penetrating the top face
    p = d.project(vec2(70, -1));
    EXPECT_EQ(p.piece, 1);
    EXPECT_NEAR(p.gap, -1, 1e-12);

    // In the channel, next to the wall: normal towards -x
    p = d.project(vec2(37, -25));
    EXPECT_EQ(p.piece, 3);
    EXPECT_NEAR(p.gap, 3, 1e-12);
    expectNear(p.normal, vec2(-1, 0), 1e-15, "wall normal");
    EXPECT_NEAR(p.xi, 55 + 2.5*pi + 20, 1e-12);
}


TEST(rigidProfile, convexFillet)
{
    const rigidProfile d = die();
    const vec2 C(45, -5);
    const vec2 u = vec2(-1, 1).normalized();

    // Outside, 2 from the shoulder at 45 degrees
    profileProjection p = d.project(C + 7*u);
    EXPECT_EQ(p.piece, 2);
    EXPECT_NEAR(p.gap, 2, 1e-12);
    expectNear(p.point, C + 5*u, 1e-12, "point");
    expectNear(p.normal, u, 1e-12, "normal");
    EXPECT_NEAR(p.xi, 55 + 5*pi/4, 1e-12);
    const vec2 t(-u(1), u(0));
    expectNear(p.tangent, t, 1e-12, "tangent");
    expectNear(p.dXidY, t*5.0/7.0, 1e-12, "dXidY");
    EXPECT_LT((p.dNormalDY - t*t.transpose()/7).norm(), 1e-12);

    // Penetrating the shoulder by 1
    p = d.project(C + 4*u);
    EXPECT_EQ(p.piece, 2);
    EXPECT_NEAR(p.gap, -1, 1e-12);
    expectNear(p.dXidY, t*5.0/4.0, 1e-12, "dXidY inside");
}


TEST(rigidProfile, concaveFillet)
{
    const rigidProfile d = die();
    const vec2 C(37, -47);                      // outside the die
    const vec2 u = vec2(1, -1).normalized();    // towards the corner

    // In the channel, 2 from the bottom fillet (rho = 1)
    profileProjection p = d.project(C + u);
    EXPECT_EQ(p.piece, 4);
    EXPECT_NEAR(p.gap, 2, 1e-12);
    expectNear(p.point, C + 3*u, 1e-12, "point");
    expectNear(p.normal, -u, 1e-12, "normal");
    EXPECT_NEAR(p.xi, 97 + 2.5*pi + 0.75*pi, 1e-12);
    const vec2 t(-p.normal(1), p.normal(0));    // n = (t_y, -t_x)
    expectNear(p.tangent, vec2(u(1), -u(0)), 1e-12, "tangent");
    expectNear(p.dXidY, t*3.0, 1e-12, "dXidY = t R/(R - g)");
    EXPECT_LT((p.dNormalDY + t*t.transpose()).norm(), 1e-12);

    // Penetrating the fillet by 0.5
    p = d.project(C + 3.5*u);
    EXPECT_EQ(p.piece, 4);
    EXPECT_NEAR(p.gap, -0.5, 1e-12);
}


TEST(rigidProfile, endPoints)
{
    const rigidProfile d = die();

    // Beyond the start point (100 0)
    profileProjection p = d.project(vec2(103, 4));
    EXPECT_EQ(p.piece, 0);
    EXPECT_NEAR(p.gap, 5, 1e-12);
    expectNear(p.point, vec2(100, 0), 1e-12, "start point");
    expectNear(p.normal, vec2(0.6, 0.8), 1e-12, "start normal");
    EXPECT_EQ(p.xi, 0);
    EXPECT_EQ(p.dXidY.norm(), 0);
    const vec2 t0 = p.tangent;
    EXPECT_LT((p.dNormalDY - t0*t0.transpose()/5).norm(), 1e-12);

    // Beyond the start point on the die's side: still outside (gap > 0)
    p = d.project(vec2(104, -3));
    EXPECT_EQ(p.piece, 0);
    EXPECT_NEAR(p.gap, 5, 1e-12);

    // On the edge of the start point's normal cone (the normal line of
    // the top face through it): the top face and the start point have
    // the same foot; the face wins, so that a point inside the tool has a
    // negative gap and no vertex curvature (a swept profile maps a
    // whole punch face over its core onto this line: rigidSurface.H)
    for (const double h : {4.0, -0.5})
    {
        p = d.project(vec2(100, h));
        EXPECT_EQ(p.piece, 1) << "y = (100 " << h << ")";
        EXPECT_NEAR(p.gap, h, 1e-12);
        expectNear(p.normal, vec2(0, 1), 1e-12, "top face normal at the start");
        EXPECT_EQ(p.dNormalDY.norm(), 0);
    }

    // Just before the start point: the top face
    p = d.project(vec2(99.5, 4));
    EXPECT_EQ(p.piece, 1);
    EXPECT_NEAR(p.xi, 0.5, 1e-12);

    // Beyond the end point (0 -50)
    p = d.project(vec2(-3, -46));
    EXPECT_EQ(p.piece, 6);
    EXPECT_NEAR(p.gap, 5, 1e-12);
    expectNear(p.normal, vec2(-0.6, 0.8), 1e-12, "end normal");
    EXPECT_NEAR(p.xi, d.length(), 1e-12);
    expectNear(d.pointAt(p.xi), vec2(0, -50), 1e-12, "end point");
}


TEST(rigidProfile, sharpVertices)
{
    // All sharp: 0 start, 1 top, 2 vertex (40 0), 3 wall,
    // 4 vertex (40 -50), 5 bottom, 6 end
    const rigidProfile d = die({});

    // Convex corner, in its normal cone
    profileProjection p = d.project(vec2(37, 4));
    EXPECT_EQ(p.piece, 2);
    EXPECT_NEAR(p.gap, 5, 1e-12);
    expectNear(p.normal, vec2(-0.6, 0.8), 1e-12, "convex vertex normal");
    EXPECT_NEAR(p.xi, 60, 1e-12);
    EXPECT_EQ(p.dXidY.norm(), 0);
    const vec2 t(-0.8, -0.6);
    expectNear(p.tangent, t, 1e-12, "convex vertex tangent");
    EXPECT_LT((p.dNormalDY - t*t.transpose()/5).norm(), 1e-12);

    // Convex corner, outside its normal cone: the top face
    p = d.project(vec2(43, 4));
    EXPECT_EQ(p.piece, 1);
    EXPECT_NEAR(p.gap, 4, 1e-12);

    // Concave corner, in the channel: one of the two lines
    p = d.project(vec2(38.5, -48));
    EXPECT_EQ(p.piece, 3);
    EXPECT_NEAR(p.gap, 1.5, 1e-12);
    p = d.project(vec2(38, -48.5));
    EXPECT_EQ(p.piece, 5);
    EXPECT_NEAR(p.gap, 1.5, 1e-12);

    // Concave corner, inside the die behind both lines: the vertex
    p = d.project(vec2(41, -51));
    EXPECT_EQ(p.piece, 4);
    EXPECT_NEAR(p.gap, -std::sqrt(2.0), 1e-12);
    expectNear(p.normal, vec2(-1, 1).normalized(), 1e-12,
               "concave vertex normal");
    EXPECT_NEAR(p.xi, 110, 1e-12);
    EXPECT_EQ(p.dXidY.norm(), 0);
    EXPECT_LT
    (
        (p.dNormalDY + p.tangent*p.tangent.transpose()/std::sqrt(2.0)).norm(),
        1e-12
    );

    // Penetrating near a concave corner, inside the wedge of the lines
    p = d.project(vec2(40.2, -49.5));
    EXPECT_EQ(p.piece, 3);
    EXPECT_NEAR(p.gap, -0.2, 1e-12);
}


TEST(rigidProfile, medialAxisKeepsOnePiece)
{
    // A die's channel, walls x = +-26, floor y = -60 (the S-rail's die in
    // its (s, z) plane). A point on the channel's middle line is as far
    // from both walls; wandering across it by round-off it must keep one
    // wall (the first in the outline's order), or the far walls' tail
    // force flips from side to side and Newton stalls at its size (the
    // S-rail's middle node, 2026-11-27). Away from the middle line by
    // more than 1e-6 of the distance the nearer wall wins.
    const rigidProfile c
    (
        {{200, 0}, {26, 0}, {26, -60}, {-26, -60}, {-26, 0}, {-200, 0}},
        {8, 5, 5, 8}
    );
    const profileProjection mid = c.project(vec2(0, -11));
    const vec2 right(-1, 0);        // the wall x = 26, first in the outline
    expectNear(mid.normal, right, 1e-15, "middle: the first wall");
    EXPECT_EQ(mid.gap, 26);
    for (const double e : {-1e-6, -1e-9, -1e-14, 1e-14, 1e-9, 1e-6})
    {
        const profileProjection p = c.project(vec2(e, -11));
        EXPECT_EQ(p.piece, mid.piece) << "x = " << e;
        expectNear(p.normal, right, 1e-15, "near the middle: the same wall");
        // the gap of the wall kept: longer than the distance by 2|e| at most
        EXPECT_NEAR(p.gap, 26 - e, 1e-12) << "x = " << e;
    }
    for (const double e : {-1e-3, 1e-3})
    {
        const profileProjection p = c.project(vec2(e, -11));
        EXPECT_NEAR(p.gap, 26 - std::abs(e), 1e-12) << "x = " << e;
        expectNear(p.normal, vec2(e > 0 ? -1 : 1, 0), 1e-15, "off the middle: the nearer wall");
    }
}


TEST(rigidProfile, finiteDifferences)
{
    std::set<int> kinds;
    int n = 0;
    n += fdCheck(die(), vec2(-10, -65), vec2(110, 15), 300, 1, kinds);
    n += fdCheck(die({}), vec2(-10, -65), vec2(110, 15), 300, 2, kinds);
    n += fdCheck(die({5, 0}), vec2(30, -60), vec2(50, -40), 200, 3, kinds);
    n += fdCheck(zigzag(), vec2(-10, -20), vec2(70, 20), 300, 4, kinds);
    n += fdCheck(punch(4), vec2(20, -10), vec2(40, 10), 200, 5, kinds);
    EXPECT_GT(n, 900);
    for (const int k : {lineKind, convexArcKind, concaveArcKind,
                        convexVertexKind, concaveVertexKind})
    {
        EXPECT_TRUE(kinds.count(k)) << "piece kind " << k << " not checked";
    }
}


TEST(rigidProfile, arcLengthConsistency)
{
    for (const rigidProfile& prof : {die(), die({}), zigzag()})
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> ux(-10, 110), uy(-65, 20);
        for (int k = 0; k < 200; ++k)
        {
            const vec2 y(ux(rng), uy(rng));
            const profileProjection p = prof.project(y);
            expectNear(prof.pointAt(p.xi), p.point, 1e-10,
                       "pointAt(project(y).xi)");
            EXPECT_NEAR(p.gap, (y - p.point).dot(p.normal), 1e-10);
            EXPECT_NEAR(std::abs(p.gap), (y - p.point).norm(), 1e-10);
        }
        for (int k = 0; k <= 100; ++k)
        {
            const double xi = prof.length()*k/100;
            const profileProjection p = prof.project(prof.pointAt(xi));
            EXPECT_NEAR(p.xi, xi, 1e-10);
            EXPECT_NEAR(p.gap, 0, 1e-10);
        }
        // Clamped
        expectNear(prof.pointAt(-1), prof.pointAt(0), 1e-15, "clamp below");
        expectNear
        (
            prof.pointAt(prof.length() + 1), prof.pointAt(prof.length()), 1e-15,
            "clamp above"
        );
    }
}


TEST(rigidProfile, filletedCornerLength)
{
    // Right-angle corner
    const double r = 4;
    EXPECT_NEAR(punch(r).length(), 30 + 50 - 2*r*std::tan(pi/4) + r*pi/2,
                1e-12);
    EXPECT_NEAR(punch(0).length(), 80, 1e-12);

    // 60-degree left turn and 60-degree right turn
    const double th = pi/3;
    const vec2 c(30 + 20*std::cos(th), 20*std::sin(th));
    const double expected = 30 + 20 - 2*r*std::tan(th/2) + r*th;
    EXPECT_NEAR(rigidProfile({{0, 0}, {30, 0}, c}, {r}).length(),
                expected, 1e-12);
    EXPECT_NEAR(rigidProfile({{0, 0}, {30, 0}, vec2(c(0), -c(1))}, {r})
                .length(), expected, 1e-12);

    // The fillet's tangent points and its middle lie as constructed
    const rigidProfile p = punch(r);
    expectNear(p.pointAt(26), vec2(26, 0), 1e-12, "tangent point 1");
    expectNear(p.pointAt(26 + r*pi/2), vec2(30, 4), 1e-12, "tangent point 2");
    expectNear(p.pointAt(26 + r*pi/4), vec2(26, 4) + r*vec2(1, -1)
               .normalized(), 1e-12, "fillet middle");
}


TEST(rigidProfile, tangentContinuity)
{
    // At the joints of the die's fillets
    const rigidProfile d = die();
    const double tiny = 1e-9;
    for (const double xiJ : {55.0, 55 + 2.5*pi, 97 + 2.5*pi, 97 + 4*pi})
    {
        const profileProjection a = d.project(d.pointAt(xiJ - tiny));
        const profileProjection b = d.project(d.pointAt(xiJ + tiny));
        EXPECT_NE(a.piece, b.piece) << "xi = " << xiJ;
        expectNear(a.normal, b.normal, 1e-8, "normal across a joint");
        expectNear(a.tangent, b.tangent, 1e-8, "tangent across a joint");
    }

    // Walking along fully filleted profiles: no jump of the normal
    for (const rigidProfile& prof : {die(), zigzag()})
    {
        const double step = 0.02;   // smallest radius 2: turn <= 0.01
        vec2 nPrev = prof.project(prof.pointAt(0)).normal;
        for (double xi = step; xi < prof.length(); xi += step)
        {
            const vec2 n = prof.project(prof.pointAt(xi)).normal;
            EXPECT_LT((n - nPrev).norm(), 0.0101) << "xi = " << xi;
            nPrev = n;
        }
    }
}


TEST(rigidProfile, sample)
{
    const rigidProfile d = die();
    const double ds = 0.7;
    const std::vector<vec2> pts = d.sample(ds);
    expectNear(pts.front(), vec2(100, 0), 1e-12, "first sample");
    expectNear(pts.back(), vec2(0, -50), 1e-12, "last sample");
    double polyLength = 0;
    for (std::size_t i = 1; i < pts.size(); ++i)
    {
        const double l = (pts[i] - pts[i - 1]).norm();
        EXPECT_LE(l, ds + 1e-12);
        EXPECT_GT(l, 0);
        polyLength += l;
        EXPECT_NEAR(d.project(pts[i]).gap, 0, 1e-10);
    }
    EXPECT_NEAR(polyLength, d.length(), 0.05);   // chords of the arcs

    // Sharp corners are kept
    const std::vector<vec2> sharp = die({}).sample(7);
    int corners = 0;
    for (const vec2& q : sharp)
    {
        if ((q - vec2(40, 0)).norm() < 1e-12) ++corners;
        if ((q - vec2(40, -50)).norm() < 1e-12) ++corners;
    }
    EXPECT_EQ(corners, 2);

    EXPECT_THROW(d.sample(0), inputError);
    EXPECT_THROW(d.sample(-1), inputError);
}


TEST(rigidProfile, inputErrors)
{
    const std::vector<vec2> u{{100, 0}, {40, 0}, {40, -50}, {0, -50}};

    expectInputError({{1, 2}}, {}, "points", "at least 2 points, got 1");
    expectInputError({}, {}, "points", "got 0");
    expectInputError({{0, 0}, {1, 0}, {1, 0}, {2, 1}}, {}, "points",
                     "points 1 (1 0) and 2 (1 0)");
    expectInputError({{0, 0}, {NAN, 0}}, {}, "points", "point 1");
    expectInputError(u, {5, -1}, "radii", "-1 at vertex 2 (40 -50)");
    expectInputError(u, {1, 2, 3}, "radii", "takes 2 fillet radii");

    // Too large for a segment: 45 > 40 (bottom segment, end side free)
    expectInputError(u, {5, 45}, "radii", "45 at vertex 2 (40 -50) does not fit");
    // Each fits, together they overlap on the wall (30 + 30 > 50)
    expectInputError(u, {30, 30}, "radii", "overlap");
    // Exactly fitting: the wall degenerates to nothing
    EXPECT_NO_THROW(rigidProfile(u, {25, 25}));
    EXPECT_NEAR(rigidProfile(u, {25, 25}).length(),
                60 + 50 + 40 - 4*25 + 25*pi, 1e-10);

    // A 180-degree turn
    expectInputError({{0, 0}, {10, 0}, {5, 0}}, {1}, "radii",
                     "180-degree turn) at vertex 1 (10 0)");
    expectInputError({{0, 0}, {10, 0}, {5, 0}}, {}, "points", "vertex 1");

    // Valid: one radius for all, collinear interior vertex
    EXPECT_NO_THROW(rigidProfile(u, {2}));
    EXPECT_NEAR(rigidProfile({{0, 0}, {1, 0}, {3, 0}}, {0.5}).length(), 3,
                1e-15);
}
