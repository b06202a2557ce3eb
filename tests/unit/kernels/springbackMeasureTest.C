// measureUChannel: synthetic half-channel profiles built from exact pieces
// (bottom line, 5 mm punch bend, straight or circular wall, 5 mm die bend,
// flange line), so theta1 = 180 - punch bend turn, theta2 = die bend
// turn and rho = wall radius are known exactly. Uniform and node-like
// sampling (corner nodes ~1 mm apart with mid-side nodes), 1e-4 mm noise,
// mirrored / rotated copies, duplicate points, options, and errors.
#include "springbackMeasure.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <random>

using namespace form;

namespace
{

using vec2 = Eigen::Vector2d;
const double pi = 3.14159265358979323846;
double rad(double deg) { return deg*pi/180; }

//- A piece of the profile: arc length and signed curvature (CCW > 0)
struct piece
{
    double length;
    double curvature;
};

//- Half-channel profile: pieces laid end to end from (0, 0) with the
//  initial heading psi0, tangent-continuous
struct channel
{
    std::vector<piece> pieces;
    double psi0 = 0;

    double length() const
    {
        double L = 0;
        for (const piece& q : pieces) L += q.length;
        return L;
    }

    //- Arc length at the start of piece k
    double start(int k) const
    {
        double L = 0;
        for (int i = 0; i < k; ++i) L += pieces[i].length;
        return L;
    }

    vec2 at(double s) const
    {
        vec2 p(0, 0);
        double psi = psi0;
        for (const piece& q : pieces)
        {
            const double l = std::min(s, q.length);
            if (q.curvature == 0)
            {
                p += l*vec2(std::cos(psi), std::sin(psi));
            }
            else
            {
                const double k = q.curvature;
                p += vec2
                (
                    (std::sin(psi + k*l) - std::sin(psi))/k,
                    -(std::cos(psi + k*l) - std::cos(psi))/k
                );
                psi += k*l;
            }
            s -= l;
            if (s <= 0) break;
        }
        return p;
    }
};

//- U-channel with the punch bend turning a1, the die bend a2 (degrees),
//  wall radius rhoWall (> 0 curls outwards, 0 straight), bottom heading
//  psi0 (degrees); opens upwards (punch bend counter-clockwise)
channel uChannel(double a1, double a2, double rhoWall, double psi0 = 0)
{
    const double rTool = 5;
    channel c;
    c.psi0 = rad(psi0);
    c.pieces =
    {
        {25, 0},
        {rTool*rad(a1), 1/rTool},
        {60, rhoWall == 0 ? 0 : -1/rhoWall},
        {rTool*rad(a2), -1/rTool},
        {40, 0}
    };
    return c;
}

//- Stations: corner nodes about h apart (relative jitter `jitter`) with
//  mid-side nodes halfway in arc length
std::vector<double> stations(double L, double h, double jitter,
                             unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uni(-1, 1);
    const int ne = int(std::round(L/h));
    std::vector<double> corner(ne + 1);
    for (int e = 0; e <= ne; ++e)
    {
        corner[e] = e*L/ne
            + ((e == 0 || e == ne) ? 0 : jitter*(L/ne)*uni(rng));
    }
    std::vector<double> s;
    for (int e = 0; e < ne; ++e)
    {
        s.push_back(corner[e]);
        s.push_back(0.5*(corner[e] + corner[e + 1]));
    }
    s.push_back(L);
    return s;
}

std::vector<vec2> sample(const channel& c, const std::vector<double>& s,
                         double noise = 0, unsigned seed = 2)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> N(0, 1);
    std::vector<vec2> p;
    for (double si : s) p.push_back(c.at(si) + noise*vec2(N(rng), N(rng)));
    return p;
}

//- Apply x -> A x + b to every point
std::vector<vec2> transform(std::vector<vec2> p, const Eigen::Matrix2d& A,
                            const vec2& b = vec2::Zero())
{
    for (vec2& q : p) q = A*q + b;
    return p;
}

Eigen::Matrix2d mirrorX() { return vec2(-1, 1).asDiagonal(); }
Eigen::Matrix2d mirrorY() { return vec2(1, -1).asDiagonal(); }
Eigen::Matrix2d rotation(double deg)
{
    return Eigen::Rotation2Dd(rad(deg)).toRotationMatrix();
}

//- theta1, theta2 within tolAngle degrees, rho within relTol
void expectMeasures(const uChannelSpringback& r, double theta1,
                    double theta2, double rho, double tolAngle = 0.05,
                    double relTol = 0.01)
{
    EXPECT_NEAR(r.theta1, theta1, tolAngle);
    EXPECT_NEAR(r.theta2, theta2, tolAngle);
    if (std::isinf(rho))
    {
        EXPECT_GT(std::abs(r.rho), 1e6) << r.rho;
    }
    else
    {
        EXPECT_NEAR(r.rho, rho, relTol*std::abs(rho));
    }
}

//- Every classified point lies on its exact piece
void expectSegmentation(const uChannelSpringback& r, const channel& c,
                        const std::vector<double>& s)
{
    const double tol = 1e-9;
    const int n = int(s.size());
    ASSERT_TRUE(0 < r.bottomEnd && r.bottomEnd < r.wallBegin
        && r.wallBegin < r.wallEnd && r.wallEnd < r.flangeBegin
        && r.flangeBegin < n);
    for (int i = 0; i < r.bottomEnd; ++i)
    {
        EXPECT_LE(s[i], c.start(1) + tol) << i;
    }
    for (int i = r.wallBegin; i < r.wallEnd; ++i)
    {
        EXPECT_GE(s[i], c.start(2) - tol) << i;
        EXPECT_LE(s[i], c.start(3) + tol) << i;
    }
    for (int i = r.flangeBegin; i < n; ++i)
    {
        EXPECT_GE(s[i], c.start(4) - tol) << i;
    }
    // each bend holds at least the points strictly inside it
    auto inside = [&](int k)
    {
        int m = 0;
        for (double si : s) m += si > c.start(k) && si < c.start(k + 1);
        return m;
    };
    EXPECT_GE(r.wallBegin - r.bottomEnd, inside(1));
    EXPECT_GE(r.flangeBegin - r.wallEnd, inside(3));
}

template<class F>
std::string expectNumericalError(F f)
{
    try
    {
        f();
    }
    catch (const inputError& e)
    {
        ADD_FAILURE() << "inputError instead of numericalError: " << e.what();
        return "";
    }
    catch (const numericalError& e)
    {
        return e.what();
    }
    ADD_FAILURE() << "no numericalError";
    return "";
}

template<class F>
std::string expectInputError(F f, const std::string& entry)
{
    try
    {
        f();
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), entry) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no inputError for " << entry;
    return "";
}

} // anonymous namespace


TEST(springbackMeasure, perfectChannel)
{
    const channel c = uChannel(90, 90, 0);
    const auto s = stations(c.length(), 1.0, 0);
    const uChannelSpringback r = measureUChannel(sample(c, s));
    expectMeasures(r, 90, 90, std::numeric_limits<double>::infinity(), 1e-6);
    EXPECT_TRUE(std::isinf(r.rho) && r.rho > 0) << r.rho;
    expectSegmentation(r, c, s);
}

TEST(springbackMeasure, sprungBackChannel)
{
    // theta1 = 103.7, theta2 = 97.5, wall curled outwards, radius 150,
    // bottom tilted by -2.5 deg
    const channel c = uChannel(180 - 103.7, 97.5, 150, -2.5);
    const auto s = stations(c.length(), 1.0, 0);
    const uChannelSpringback r = measureUChannel(sample(c, s));
    expectMeasures(r, 103.7, 97.5, 150, 1e-6, 1e-6);
    expectSegmentation(r, c, s);
}

TEST(springbackMeasure, wallCurledInwards)
{
    const channel c = uChannel(180 - 96.2, 84.1, -150, 1.5);
    const auto s = stations(c.length(), 1.0, 0);
    const uChannelSpringback r = measureUChannel(sample(c, s));
    expectMeasures(r, 96.2, 84.1, -150, 1e-6, 1e-6);
    expectSegmentation(r, c, s);
}

TEST(springbackMeasure, nodeLikeSamplingAndNoise)
{
    const channel c = uChannel(180 - 103.7, 97.5, 150, -2.5);
    const auto s = stations(c.length(), 1.0, 0.2);  // non-uniform nodes
    {
        const uChannelSpringback r = measureUChannel(sample(c, s));
        expectMeasures(r, 103.7, 97.5, 150, 1e-6, 1e-6);
        expectSegmentation(r, c, s);
    }
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
        const uChannelSpringback r =
            measureUChannel(sample(c, s, 1e-4, seed));
        expectMeasures(r, 103.7, 97.5, 150);
    }
    // a straight wall stays (nearly) straight under noise
    const channel straight = uChannel(90, 90, 0);
    const uChannelSpringback r = measureUChannel
    (
        sample(straight, stations(straight.length(), 1.0, 0.2), 1e-4)
    );
    expectMeasures(r, 90, 90, std::numeric_limits<double>::infinity());
    EXPECT_GT(std::abs(r.rho), 1e5) << r.rho;
}

TEST(springbackMeasure, cornerMidSideZigZag)
{
    // A 9-node FE line whose mid-side nodes stand 0.01 mm off the line of
    // the corner nodes (a wall pressed between punch and die in a slot of
    // its own thickness), nodes 0.44 mm apart: the default curvature window
    // of two node spacings cancels the zig-zag, so the wall is not taken
    // for a bend (with a window of one spacing it was)
    const channel c = uChannel(180 - 103.7, 97.5, 150, -2.5);
    const auto s = stations(c.length(), 0.875, 0);
    std::vector<vec2> p = sample(c, s);
    for (std::size_t i = 1; i + 1 < p.size(); i += 2)
    {
        const vec2 t = (p[i + 1] - p[i - 1]).normalized();
        p[i] += 0.01*vec2(-t(1), t(0));
    }
    const uChannelSpringback r = measureUChannel(p);
    expectMeasures(r, 103.7, 97.5, 150, 0.05, 0.02);
}


TEST(springbackMeasure, coarseSampling)
{
    // ~100 points in all: about 4 points per bend
    const channel c = uChannel(180 - 103.7, 97.5, 150, -2.5);
    const auto s = stations(c.length(), 3.0, 0.1);
    ASSERT_LT(s.size(), 110u);
    const uChannelSpringback r = measureUChannel(sample(c, s));
    expectMeasures(r, 103.7, 97.5, 150, 1e-6, 1e-6);
    expectSegmentation(r, c, s);
}

TEST(springbackMeasure, orientationIndependent)
{
    for (double rhoWall : {150.0, -150.0})
    {
        const channel c = uChannel(180 - 101.3, 93.4, rhoWall, 0.7);
        const auto s = stations(c.length(), 1.0, 0.2);
        const std::vector<vec2> p = sample(c, s, 1e-4);
        const std::vector<Eigen::Matrix2d> maps =
        {
            Eigen::Matrix2d::Identity(),
            mirrorY(),                      // channel opening downwards
            mirrorX(),                      // symmetry plane on the right
            mirrorX()*mirrorY(),
            rotation(37),
            rotation(-123)*mirrorY()
        };
        for (std::size_t m = 0; m < maps.size(); ++m)
        {
            SCOPED_TRACE("map " + std::to_string(m));
            const uChannelSpringback r =
                measureUChannel(transform(p, maps[m], vec2(-17.5, 240)));
            expectMeasures(r, 101.3, 93.4, rhoWall);
        }
    }
}

TEST(springbackMeasure, optionsAndDuplicates)
{
    const channel c = uChannel(180 - 103.7, 97.5, 150, -2.5);
    const auto s = stations(c.length(), 1.0, 0.2);
    const std::vector<vec2> p = sample(c, s, 1e-4);
    const uChannelSpringback ref = measureUChannel(p);

    // explicit threshold and a wider window: same classification regime
    uChannelMeasureOptions opt;
    opt.bendCurvature = 0.05;
    opt.curvatureWindow = 1.0;
    expectMeasures(measureUChannel(p, opt), 103.7, 97.5, 150);

    // repeated points (element-wise node lists) change nothing but indices
    std::vector<vec2> q;
    std::vector<int> map;       // index in q of each point of p
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        map.push_back(int(q.size()));
        q.push_back(p[i]);
        if (i % 2 == 0) q.push_back(p[i]);
    }
    const uChannelSpringback r = measureUChannel(q);
    EXPECT_DOUBLE_EQ(r.theta1, ref.theta1);
    EXPECT_DOUBLE_EQ(r.theta2, ref.theta2);
    EXPECT_DOUBLE_EQ(r.rho, ref.rho);
    EXPECT_EQ(r.bottomEnd, map[ref.bottomEnd]);
    EXPECT_EQ(r.wallBegin, map[ref.wallBegin]);
    EXPECT_EQ(r.wallEnd, map[ref.wallEnd]);
    EXPECT_EQ(r.flangeBegin, map[ref.flangeBegin]);
}

TEST(springbackMeasure, errors)
{
    // flat strip, exact and noisy
    std::vector<vec2> flat;
    for (int i = 0; i <= 300; ++i) flat.push_back(vec2(0.5*i, 0));
    std::string msg = expectNumericalError([&] { measureUChannel(flat); });
    EXPECT_NE(msg.find("flat"), std::string::npos) << msg;
    std::mt19937 rng(3);
    std::normal_distribution<double> N(0, 1e-4);
    for (vec2& q : flat) q += vec2(N(rng), N(rng));
    msg = expectNumericalError([&] { measureUChannel(flat); });
    EXPECT_NE(msg.find("bends"), std::string::npos) << msg;

    // a single bend (L shape)
    channel L;
    L.pieces = {{30, 0}, {5*pi/2, 0.2}, {60, 0}};
    msg = expectNumericalError
    (
        [&] { measureUChannel(sample(L, stations(L.length(), 1.0, 0))); }
    );
    EXPECT_NE(msg.find("found 1 bends"), std::string::npos) << msg;

    // two bends turning the same way (a hook, not a channel)
    channel hook;
    hook.pieces = {{30, 0}, {5*pi/2, 0.2}, {60, 0}, {5*pi/2, 0.2}, {30, 0}};
    msg = expectNumericalError
    (
        [&]
        {
            measureUChannel(sample(hook, stations(hook.length(), 1.0, 0)));
        }
    );
    EXPECT_NE(msg.find("same way"), std::string::npos) << msg;

    // no flange: the profile ends in the die bend
    channel noFlange = uChannel(90, 90, 0);
    noFlange.pieces.pop_back();
    expectNumericalError
    (
        [&]
        {
            measureUChannel
            (
                sample(noFlange, stations(noFlange.length(), 1.0, 0))
            );
        }
    );

    // too few points, non-finite points, bad options
    const channel c = uChannel(90, 90, 0);
    std::vector<vec2> few;
    for (int i = 0; i < 8; ++i) few.push_back(c.at(i*c.length()/7));
    expectInputError([&] { measureUChannel(few); }, "profile");
    std::vector<vec2> p = sample(c, stations(c.length(), 1.0, 0));
    std::vector<vec2> same(20, vec2(1, 2));
    expectInputError([&] { measureUChannel(same); }, "profile");
    std::vector<vec2> bad = p;
    bad[10].x() = std::nan("");
    expectInputError([&] { measureUChannel(bad); }, "profile");
    uChannelMeasureOptions opt;
    opt.bendCurvature = -1;
    expectInputError([&] { measureUChannel(p, opt); }, "bendCurvature");
    opt = uChannelMeasureOptions();
    opt.curvatureWindow = -0.1;
    expectInputError([&] { measureUChannel(p, opt); }, "curvatureWindow");
    opt = uChannelMeasureOptions();
    opt.minBendAngle = 180;
    expectInputError([&] { measureUChannel(p, opt); }, "minBendAngle");
}
