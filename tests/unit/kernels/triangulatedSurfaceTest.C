// Rigid tool surfaces from triangles (triangulatedSurface.H, surface type
// triSurface): on a subdivided icosahedron (a closed convex polyhedron)
// and on an open, bent die face, at random points on both sides and near
// faces, edges and vertices:
//   - the gap against an independent brute-force distance (the smallest
//     distance to a triangle's plane, inside it, or to its edges) with the
//     side from the polyhedron's face planes (inside a convex polyhedron:
//     behind every face);
//   - the tree search finds the closest triangle that a search of all
//     triangles finds;
//   - dg/dy = n and dn/dy against central differences (faces, edges and
//     vertices alike);
//   - flipNormals turns the side; bad triangulations are refused with
//     the file named.
#include "triangulatedSurface.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include "../fdCheck.H"
#include "surfaceTestTools.H"

using namespace form;

namespace
{

// An icosahedron with each triangle split into 4, `levels` times, its
// points on the sphere of radius R: outward normals (counter-clockwise
// seen from outside)
triangulation icosphere(int levels, double R)
{
    triangulation T;
    const double f = (1 + std::sqrt(5.0))/2;
    const double v[12][3] =
    {
        {-1, f, 0}, {1, f, 0}, {-1, -f, 0}, {1, -f, 0},
        {0, -1, f}, {0, 1, f}, {0, -1, -f}, {0, 1, -f},
        {f, 0, -1}, {f, 0, 1}, {-f, 0, -1}, {-f, 0, 1}
    };
    for (const auto& p : v) T.points.push_back(R*vec3(p[0], p[1], p[2]).normalized());
    T.triangles =
    {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
        {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
        {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}
    };
    for (int l = 0; l < levels; ++l)
    {
        std::map<std::pair<int, int>, int> mid;
        const auto middle = [&](int a, int b)
        {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            T.points.push_back(R*(T.points[a] + T.points[b]).normalized());
            return mid[key] = int(T.points.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& t : T.triangles)
        {
            const int a = middle(t[0], t[1]), b = middle(t[1], t[2]),
                      c = middle(t[2], t[0]);
            next.push_back({t[0], a, c});
            next.push_back({t[1], b, a});
            next.push_back({t[2], c, b});
            next.push_back({a, b, c});
        }
        T.triangles = next;
    }
    T.source = "icosphere";
    return T;
}

// Distance from y to segment ab
double segmentDistance(const vec3& y, const vec3& a, const vec3& b)
{
    const vec3 e = b - a;
    const double s = std::clamp(e.dot(y - a)/e.squaredNorm(), 0.0, 1.0);
    return (y - a - s*e).norm();
}

// Distance from y to the triangulation: every triangle's plane where the
// foot lies inside it (barycentric signs), else its edges
double bruteDistance(const triangulation& T, const vec3& y)
{
    double best = HUGE_VAL;
    for (const auto& t : T.triangles)
    {
        const vec3 &a = T.points[t[0]], &b = T.points[t[1]], &c = T.points[t[2]];
        const vec3 n = (b - a).cross(c - a).normalized();
        const vec3 q = y - n*n.dot(y - a);
        const bool inside =
            (b - a).cross(q - a).dot(n) >= 0
         && (c - b).cross(q - b).dot(n) >= 0
         && (a - c).cross(q - c).dot(n) >= 0;
        double d = inside ? std::abs(n.dot(y - a)) : HUGE_VAL;
        d = std::min({d, segmentDistance(y, a, b), segmentDistance(y, b, c),
                      segmentDistance(y, c, a)});
        best = std::min(best, d);
    }
    return best;
}

// Inside a convex polyhedron: behind every face plane
bool insideConvex(const triangulation& T, const vec3& y)
{
    for (const auto& t : T.triangles)
    {
        const vec3 &a = T.points[t[0]], &b = T.points[t[1]], &c = T.points[t[2]];
        if ((b - a).cross(c - a).dot(y - a) > 0) return false;
    }
    return true;
}

void checkDerivatives(const rigidSurface& s, const vec3& y, const std::string& what)
{
    const surfaceProjection P = s.project(y);
    mat3 dN;
    vec3 dG;
    test::surfaceDifferences(s, y, 1e-7, dG, dN);
    EXPECT_NEAR(P.normal.norm(), 1, 1e-13) << what;
    EXPECT_TRUE(test::fdError("triSurface dg/dy", (dG - P.dGapDY()).norm(), 2e-8))
        << what << " y " << y.transpose();
    if (!P.hasGapGradient) EXPECT_EQ((P.dGapDY() - P.normal).norm(), 0);
    EXPECT_TRUE(test::fdError("triSurface dn/dy", (dN - P.dNormalDY).norm()/(1 + dN.norm()), 2e-8))
        << what << " y " << y.transpose() << "\nFD\n" << dN << "\nanalytic\n" << P.dNormalDY;
}

} // anonymous namespace


TEST(triangulatedSurface, gapSideAndClosestTriangleOnAPolyhedron)
{
    const triangulation T = icosphere(2, 1.5);     // 320 triangles
    const triangulatedSurface S(T, false);
    EXPECT_EQ(S.nTriangles(), 320);
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int outside = 0, inside = 0;
    for (int k = 0; k < 400; ++k)
    {
        // points from deep inside to well outside, most near the surface
        const vec3 dir = vec3(u(gen), u(gen), u(gen)).normalized();
        const double r = 1.5*(1 + 0.3*u(gen)*std::abs(u(gen)));
        const vec3 y = r*dir;
        const double d = bruteDistance(T, y);
        const bool in = insideConvex(T, y);
        const surfaceProjection P = S.project(y);
        EXPECT_NEAR(P.gap, in ? -d : d, 1e-12) << "y " << y.transpose();
        (in ? inside : outside) += 1;
        // the tree's closest triangle is as close as the closest of all
        int t;
        triangulatedSurface::feature f;
        int l;
        vec3 c;
        S.closest(y, t, f, l, c);
        EXPECT_NEAR((y - c).norm(), d, 1e-12);
        // the closest point is on the surface, the normal is unit
        EXPECT_NEAR(bruteDistance(T, c), 0, 1e-12);
        checkDerivatives(S, y, "icosphere");
    }
    EXPECT_GT(inside, 50);
    EXPECT_GT(outside, 50);
}

TEST(triangulatedSurface, derivativesAtEdgesAndVertices)
{
    const triangulation T = icosphere(1, 2.0);
    const triangulatedSurface S(T, false);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int edges = 0, vertices = 0;
    for (std::size_t i = 0; i < T.points.size(); ++i)
    {
        // outside a vertex: its region; outside an edge midpoint: its region
        const vec3 p = T.points[i];
        const vec3 y = p*(1.05) + 0.002*vec3(u(gen), u(gen), u(gen));
        int t;
        triangulatedSurface::feature f;
        int l;
        vec3 c;
        S.closest(y, t, f, l, c);
        vertices += f == triangulatedSurface::vertex;
        checkDerivatives(S, y, "vertex region");
    }
    for (const auto& t : T.triangles)
    {
        const vec3 m = 0.5*(T.points[t[0]] + T.points[t[1]]);
        const vec3 y = m*1.03 + 0.002*vec3(u(gen), u(gen), u(gen));
        int tt;
        triangulatedSurface::feature f;
        int l;
        vec3 c;
        S.closest(y, tt, f, l, c);
        edges += f == triangulatedSurface::edge;
        EXPECT_GT(S.project(y).gap, 0);
        checkDerivatives(S, y, "edge region");
    }
    EXPECT_EQ(vertices, int(T.points.size()));
    EXPECT_GT(edges, int(T.triangles.size())/2);
}

TEST(triangulatedSurface, openBentDieAndFlippedNormals)
{
    // a die face: the plane z = 0 for x < 0 bent up at 45 degrees for
    // x > 0 (a concave edge along y), 1 x 2 strips of two triangles,
    // normals up (+z side is outside the tool)
    triangulation T;
    T.points = {vec3(-1, -1, 0), vec3(0, -1, 0), vec3(0, 1, 0), vec3(-1, 1, 0),
                vec3(1, -1, 1), vec3(1, 1, 1)};
    T.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
    T.source = "die.stl";
    const triangulatedSurface S(T, false);
    const triangulatedSurface F(T, true);
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    const vec3 nb = vec3(-1, 0, 1).normalized();
    int above = 0, below = 0;
    for (int k = 0; k < 200; ++k)
    {
        const vec3 y(u(gen), 0.9*u(gen), 0.5*u(gen));
        // above both planes: outside the tool; below both: inside; a
        // point above one plane and below the other has no side to test
        double side = 0;
        if (y(2) > 0 && nb.dot(y) > 0) side = 1;
        if (y(2) < 0 && nb.dot(y) < 0) side = -1;
        if (side == 0) continue;
        (side > 0 ? above : below) += 1;
        const surfaceProjection P = S.project(y);
        EXPECT_NEAR(P.gap, side*bruteDistance(T, y), 1e-12) << "y " << y.transpose();
        EXPECT_NEAR(F.project(y).gap, -P.gap, 1e-12);
        checkDerivatives(S, y, "bent die");
    }
    EXPECT_GT(above, 30);
    EXPECT_GT(below, 30);
}

TEST(triangulatedSurface, badTriangulationsNameTheFile)
{
    const auto message = [](const triangulation& T)
    {
        try
        {
            triangulatedSurface S(T, false);
        }
        catch (const inputError& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    triangulation T;
    T.source = "tool.stl";
    EXPECT_NE(message(T).find("tool.stl has no triangles"), std::string::npos)
        << message(T);
    T.points = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
    T.triangles = {{0, 1, 3}};
    EXPECT_NE(message(T).find("refers to point 3"), std::string::npos) << message(T);
    T.triangles = {{0, 1, 1}};
    EXPECT_NE(message(T).find("degenerate"), std::string::npos) << message(T);
    T.triangles = {{0, 1, 2}};
    T.points[1](0) = NAN;
    EXPECT_NE(message(T).find("not finite"), std::string::npos) << message(T);
    // through the registry: a triSurface without triangles
    EXPECT_THROW(rigidSurface::New("triSurface", {}, {}), inputError);
}


TEST(triangulatedSurface, smoothedNormals)
{
    // An icosphere of 320 triangles (neighbouring normals 10-12 deg
    // apart), featureAngle 30: every edge smooth. The smoothed normal is
    // continuous along a path that crosses facets, edges and vertices
    // (the faceted one turns by a facet angle within the round edge
    // regions), closer to the sphere's normal than the facets' normals,
    // and dg/dy, dn/dy match central differences in the face, edge and
    // vertex regions on both sides of the surface.
    const triangulation T = icosphere(2, 1.0);
    const triangulatedSurface smooth(T, false, 30), facets(T, false, 0);
    double jumpSmooth = 0, jumpFacets = 0, errSmooth = 0, errFacets = 0;
    const double step = 1e-4;
    vec3 nS0 = vec3::Zero(), nF0 = vec3::Zero();
    for (int i = 0; i <= 20000; ++i)
    {
        const double a = 0.3 + i*step;
        const vec3 y = 1.02*vec3(std::cos(a)*std::cos(0.4), std::sin(a)*std::cos(0.4),
                                 std::sin(0.4 + 0.1*a));
        const surfaceProjection PS = smooth.project(y), PF = facets.project(y);
        if (i > 0)
        {
            jumpSmooth = std::max(jumpSmooth, (PS.normal - nS0).norm()/step);
            jumpFacets = std::max(jumpFacets, (PF.normal - nF0).norm()/step);
        }
        nS0 = PS.normal;
        nF0 = PF.normal;
        const vec3 r = y.normalized();
        errSmooth = std::max(errSmooth, (PS.normal - r).norm());
        errFacets = std::max(errFacets, (PF.normal - r).norm());
    }
    std::printf("    smoothed normals: largest turn rate %.3g (facets %.3g),"
        " largest deviation from the sphere's normal %.3g (facets %.3g)\n",
        jumpSmooth, jumpFacets, errSmooth, errFacets);
    // the sphere's normal turns at 1/R = 1 per unit length: the smoothed
    // one at about that (observed 0.99); the faceted one at ~angle/gap in
    // the round edges (observed 18); deviation from the sphere's normal
    // 0.015 against 0.16
    EXPECT_LT(jumpSmooth, 1.5);
    EXPECT_GT(jumpFacets, 5);
    EXPECT_LT(errSmooth, 0.2*errFacets);

    std::mt19937 gen(13);
    std::uniform_real_distribution<double> u(-1, 1);
    int regions[3] = {0, 0, 0};
    for (int k = 0; k < 300; ++k)
    {
        // near faces, edge midpoints and vertices, both sides
        const vec3 base = k % 3 == 0
          ? T.points[k % T.points.size()]
          : k % 3 == 1
          ? vec3(0.5*(T.points[T.triangles[k][0]] + T.points[T.triangles[k][1]]))
          : vec3((T.points[T.triangles[k][0]] + T.points[T.triangles[k][1]]
                + T.points[T.triangles[k][2]])/3);
        const vec3 y = base*(1 + 0.04*u(gen)) + 0.003*vec3(u(gen), u(gen), u(gen));
        int t;
        triangulatedSurface::feature f;
        int l;
        vec3 c;
        smooth.closest(y, t, f, l, c);
        ++regions[f];
        checkDerivatives(smooth, y, "smoothed");
        // the side: inside the sphere of the vertices, the gap is negative
        // (beyond the facets' sagitta)
        if (y.norm() < 0.97) EXPECT_LT(smooth.project(y).gap, 0);
        if (y.norm() > 1.0) EXPECT_GT(smooth.project(y).gap, 0);
    }
    EXPECT_GT(regions[triangulatedSurface::face], 30);
    EXPECT_GT(regions[triangulatedSurface::edge], 30);
    EXPECT_GT(regions[triangulatedSurface::vertex], 10);
}


TEST(triangulatedSurface, sharpEdgesStaySharp)
{
    // A cube of 12 triangles, featureAngle 30: its 90 deg edges are sharp
    // (the diagonals of its faces are smooth): above a face the normal is
    // the face's, beside an edge it is the round edge's (y - c)/|y - c|
    triangulation T;
    for (int i = 0; i < 8; ++i)
    {
        T.points.push_back(vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    }
    T.triangles =
    {
        {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},     // z = 0, z = 1
        {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},     // y = 0, y = 1
        {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}      // x = 0, x = 1
    };
    const triangulatedSurface S(T, false, 30);
    const surfaceProjection P = S.project(vec3(0.3, 0.6, 1.2));
    EXPECT_NEAR((P.normal - vec3::UnitZ()).norm(), 0, 1e-14);
    EXPECT_NEAR(P.gap, 0.2, 1e-14);
    EXPECT_NEAR(P.dNormalDY.norm(), 0, 1e-14);
    const vec3 y(0.5, 1.1, 1.1);
    const surfaceProjection E = S.project(y);
    EXPECT_NEAR((E.normal - vec3(0, 1, 1).normalized()).norm(), 0, 1e-14);
    EXPECT_NEAR(E.gap, 0.1*std::sqrt(2.0), 1e-14);
    checkDerivatives(S, y, "cube edge");
    checkDerivatives(S, vec3(0.3, 0.6, 1.2), "cube face");
    EXPECT_THROW(triangulatedSurface(T, false, -1), inputError);
    EXPECT_THROW(triangulatedSurface(T, false, 200), inputError);
}
