/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of triangulatedSurface.H: pseudonormals, a bounding-box
    tree over the triangles, the closest point on a triangle by its
    Voronoi regions and the projection built from it.
\*---------------------------------------------------------------------------*/
#include "triangulatedSurface.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <functional>
#include <map>

namespace form
{

namespace
{

// Closest point of y on triangle (a, b, c) and its feature: the Voronoi
// regions of the vertices, the edges and the face (Ericson, sec. 5.1.5).
// local: the vertex (0, 1, 2) or the edge (0: ab, 1: bc, 2: ca)
vec3 closestOnTriangle
(
    const vec3& y,
    const vec3& a,
    const vec3& b,
    const vec3& c,
    triangulatedSurface::feature& kind,
    int& local
)
{
    using T = triangulatedSurface;
    const vec3 ab = b - a, ac = c - a, ay = y - a;
    const double d1 = ab.dot(ay), d2 = ac.dot(ay);
    if (d1 <= 0 && d2 <= 0) { kind = T::vertex; local = 0; return a; }
    const vec3 by = y - b;
    const double d3 = ab.dot(by), d4 = ac.dot(by);
    if (d3 >= 0 && d4 <= d3) { kind = T::vertex; local = 1; return b; }
    const double vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        kind = T::edge; local = 0;
        return a + ab*(d1/(d1 - d3));
    }
    const vec3 cy = y - c;
    const double d5 = ab.dot(cy), d6 = ac.dot(cy);
    if (d6 >= 0 && d5 <= d6) { kind = T::vertex; local = 2; return c; }
    const double vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        kind = T::edge; local = 2;
        return a + ac*(d2/(d2 - d6));
    }
    const double va = d3*d6 - d5*d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    {
        kind = T::edge; local = 1;
        return b + (c - b)*((d4 - d3)/((d4 - d3) + (d5 - d6)));
    }
    kind = T::face; local = -1;
    const double den = 1/(va + vb + vc);
    return a + ab*(vb*den) + ac*(vc*den);
}


// Squared distance from y to an axis-aligned box
double boxDistance2(const vec3& y, const vec3& lo, const vec3& hi)
{
    double s = 0;
    for (int k = 0; k < 3; ++k)
    {
        const double d = std::max({lo(k) - y(k), 0.0, y(k) - hi(k)});
        s += d*d;
    }
    return s;
}

} // namespace


triangulatedSurface::triangulatedSurface
(
    const triangulation& T,
    bool flipNormals,
    double featureAngle
)
:
    p_(T.points),
    tri_(T.triangles),
    featureAngle_(featureAngle)
{
    if (!(featureAngle >= 0 && featureAngle <= 180))
    {
        throw inputError
        (
            "featureAngle",
            "featureAngle must lie in [0, 180] degrees, got "
          + std::to_string(featureAngle)
        );
    }
    const std::string src = T.source.empty() ? "the surface" : T.source;
    if (tri_.empty())
    {
        throw inputError("file", src + " has no triangles");
    }
    vec3 lo = vec3::Constant(HUGE_VAL), hi = -lo;
    for (std::size_t i = 0; i < p_.size(); ++i)
    {
        if (!p_[i].allFinite())
        {
            throw inputError
            (
                "file", src + ": point " + std::to_string(i) + " is not finite"
            );
        }
        lo = lo.cwiseMin(p_[i]);
        hi = hi.cwiseMax(p_[i]);
    }
    size_ = (hi - lo).norm();
    const int nP = int(p_.size());
    faceNormal_.resize(tri_.size());
    for (std::size_t t = 0; t < tri_.size(); ++t)
    {
        std::array<int, 3>& f = tri_[t];
        for (int k = 0; k < 3; ++k)
        {
            if (f[k] < 0 || f[k] >= nP)
            {
                throw inputError
                (
                    "file", src + ": triangle " + std::to_string(t)
                  + " refers to point " + std::to_string(f[k]) + " of "
                  + std::to_string(nP)
                );
            }
        }
        if (flipNormals) std::swap(f[1], f[2]);
        const vec3 n = (p_[f[1]] - p_[f[0]]).cross(p_[f[2]] - p_[f[0]]);
        if (!(n.norm() > 1e-14*size_*size_))
        {
            throw inputError
            (
                "file", src + ": triangle " + std::to_string(t)
              + " has no area (degenerate)"
            );
        }
        faceNormal_[t] = n.normalized();
    }

    // Pseudonormals: an edge's is the sum of its triangles' normals, a
    // vertex's the sum weighted by the triangles' angles at it
    std::map<std::pair<int, int>, vec3> edgeSum;
    vertexNormal_.assign(p_.size(), vec3::Zero());
    for (std::size_t t = 0; t < tri_.size(); ++t)
    {
        const std::array<int, 3>& f = tri_[t];
        for (int k = 0; k < 3; ++k)
        {
            const int a = f[k], b = f[(k + 1)%3], c = f[(k + 2)%3];
            // (an Eigen vector is not zeroed by its default constructor)
            edgeSum.try_emplace
            (
                {std::min(a, b), std::max(a, b)}, vec3::Zero()
            ).first->second += faceNormal_[t];
            const vec3 u = (p_[b] - p_[a]).normalized();
            const vec3 v = (p_[c] - p_[a]).normalized();
            const double angle =
                std::atan2(u.cross(v).norm(), u.dot(v));
            vertexNormal_[a] += angle*faceNormal_[t];
        }
    }
    edgeNormal_.resize(tri_.size());
    for (std::size_t t = 0; t < tri_.size(); ++t)
    {
        const std::array<int, 3>& f = tri_[t];
        for (int k = 0; k < 3; ++k)
        {
            const int a = f[k], b = f[(k + 1)%3];
            edgeNormal_[t][k] = edgeSum[{std::min(a, b), std::max(a, b)}];
        }
    }

    smoothNormals();

    order_.resize(tri_.size());
    for (std::size_t t = 0; t < tri_.size(); ++t) order_[t] = int(t);
    tree_.reserve(2*tri_.size());
    build(0, int(tri_.size()));
}


int triangulatedSurface::build(int first, int count)
{
    const int id = int(tree_.size());
    tree_.push_back(box());
    vec3 lo = vec3::Constant(HUGE_VAL), hi = -lo;
    for (int i = first; i < first + count; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            lo = lo.cwiseMin(p_[tri_[order_[i]][k]]);
            hi = hi.cwiseMax(p_[tri_[order_[i]][k]]);
        }
    }
    tree_[id].lo = lo;
    tree_[id].hi = hi;
    if (count <= 4)
    {
        tree_[id].first = first;
        tree_[id].count = count;
        return id;
    }
    // split at the median centroid along the box's longest axis
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const auto centroid = [this, axis](int t)
    {
        return p_[tri_[t][0]](axis) + p_[tri_[t][1]](axis)
             + p_[tri_[t][2]](axis);
    };
    const int half = count/2;
    std::nth_element
    (
        order_.begin() + first, order_.begin() + first + half,
        order_.begin() + first + count,
        [&centroid](int s, int t) { return centroid(s) < centroid(t); }
    );
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    tree_[id].left = left;
    tree_[id].right = right;
    return id;
}


void triangulatedSurface::closest
(
    const vec3& y,
    int& triangle,
    feature& kind,
    int& local,
    vec3& point
) const
{
    double best = std::numeric_limits<double>::infinity();
    triangle = -1;
    std::vector<int> stack{0};
    while (!stack.empty())
    {
        const box& B = tree_[stack.back()];
        stack.pop_back();
        if (boxDistance2(y, B.lo, B.hi) >= best) continue;
        if (B.left < 0)
        {
            for (int i = B.first; i < B.first + B.count; ++i)
            {
                const int t = order_[i];
                feature k;
                int l;
                const vec3 c = closestOnTriangle
                (
                    y, p_[tri_[t][0]], p_[tri_[t][1]], p_[tri_[t][2]], k, l
                );
                const double d2 = (y - c).squaredNorm();
                if (d2 < best)
                {
                    best = d2;
                    triangle = t;
                    kind = k;
                    local = l;
                    point = c;
                }
            }
            continue;
        }
        // the nearer child last on the stack: searched first
        const double dl =
            boxDistance2(y, tree_[B.left].lo, tree_[B.left].hi);
        const double dr =
            boxDistance2(y, tree_[B.right].lo, tree_[B.right].hi);
        if (dl < dr)
        {
            stack.push_back(B.right);
            stack.push_back(B.left);
        }
        else
        {
            stack.push_back(B.left);
            stack.push_back(B.right);
        }
    }
}


void triangulatedSurface::smoothNormals()
{
    const int nT = int(tri_.size());
    cornerNormal_.assign(nT, {vec3::Zero(), vec3::Zero(), vec3::Zero()});
    smoothEdge_.assign(nT, {false, false, false});
    smoothVertex_.assign(p_.size(), false);
    if (featureAngle_ <= 0) return;
    const double cosFeature = std::cos(featureAngle_*M_PI/180);

    // The triangles of each edge
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;
    for (int t = 0; t < nT; ++t)
    {
        for (int k = 0; k < 3; ++k)
        {
            const int a = tri_[t][k], b = tri_[t][(k + 1)%3];
            edges[{std::min(a, b), std::max(a, b)}].push_back({t, k});
        }
    }
    // Corners 3 t + j joined across smooth edges (union-find)
    std::vector<int> parent(3*nT);
    for (int i = 0; i < 3*nT; ++i) parent[i] = i;
    const std::function<int(int)> root = [&](int i)
    {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    std::vector<bool> boundaryVertex(p_.size(), false);
    for (const auto& e : edges)
    {
        const auto& tk = e.second;
        if (tk.size() != 2)
        {
            boundaryVertex[e.first.first] = boundaryVertex[e.first.second] = true;
            continue;
        }
        const int t0 = tk[0].first, k0 = tk[0].second;
        const int t1 = tk[1].first, k1 = tk[1].second;
        if (faceNormal_[t0].dot(faceNormal_[t1]) < cosFeature) continue;
        smoothEdge_[t0][k0] = smoothEdge_[t1][k1] = true;
        // the edge's ends: corners k, k + 1 of t0 are corners k1 + 1, k1
        // of t1 (the edge runs the other way in a consistently oriented
        // neighbour); match them by vertex to be safe
        for (int j0 : {k0, (k0 + 1)%3})
        {
            for (int j1 : {k1, (k1 + 1)%3})
            {
                if (tri_[t0][j0] != tri_[t1][j1]) continue;
                parent[root(3*t0 + j0)] = root(3*t1 + j1);
            }
        }
    }
    // A fan's normal: the angle-weighted mean of its triangles' normals
    std::map<int, vec3> fan;
    for (int t = 0; t < nT; ++t)
    {
        for (int j = 0; j < 3; ++j)
        {
            const int a = tri_[t][j];
            const vec3 u = (p_[tri_[t][(j + 1)%3]] - p_[a]).normalized();
            const vec3 v = (p_[tri_[t][(j + 2)%3]] - p_[a]).normalized();
            const double angle = std::atan2(u.cross(v).norm(), u.dot(v));
            fan.try_emplace(root(3*t + j), vec3::Zero()).first->second +=
                angle*faceNormal_[t];
        }
    }
    std::vector<int> fansAt(p_.size(), -1);
    std::vector<bool> manyFans(p_.size(), false);
    for (int t = 0; t < nT; ++t)
    {
        for (int j = 0; j < 3; ++j)
        {
            const int r = root(3*t + j);
            cornerNormal_[t][j] = fan[r].normalized();
            const int a = tri_[t][j];
            if (fansAt[a] >= 0 && fansAt[a] != r) manyFans[a] = true;
            fansAt[a] = r;
        }
    }
    for (std::size_t a = 0; a < p_.size(); ++a)
    {
        smoothVertex_[a] = fansAt[a] >= 0 && !manyFans[a] && !boundaryVertex[a];
    }
}


surfaceProjection triangulatedSurface::smoothProjection
(
    int t,
    const vec3& y,
    const vec3& c,
    const mat3& dcdy
) const
{
    const std::array<int, 3>& f = tri_[t];
    const vec3& nf = faceNormal_[t];
    const double twiceArea =
        (p_[f[1]] - p_[f[0]]).cross(p_[f[2]] - p_[f[0]]).norm();
    vec3 m = vec3::Zero();
    mat3 dm = mat3::Zero();         // dm/dc
    for (int j = 0; j < 3; ++j)
    {
        // lambda_j = ((p_j+2 - p_j+1) x (c - p_j+1)) . N_f/(2 A), grad
        // lambda_j = N_f x (p_j+2 - p_j+1)/(2 A)
        const vec3& p1 = p_[f[(j + 1)%3]];
        const vec3& p2 = p_[f[(j + 2)%3]];
        const double lambda = (p2 - p1).cross(c - p1).dot(nf)/twiceArea;
        const vec3 grad = nf.cross(p2 - p1)/twiceArea;
        m += lambda*cornerNormal_[t][j];
        dm += cornerNormal_[t][j]*grad.transpose();
    }
    surfaceProjection P;
    const double lm = m.norm();
    P.normal = m/lm;
    const vec3 d = y - c;
    P.gap = d.dot(P.normal);
    P.dNormalDY =
        (mat3::Identity() - P.normal*P.normal.transpose())*dm*dcdy/lm;
    P.hasGapGradient = true;
    P.gapGradient = (mat3::Identity() - dcdy).transpose()*P.normal
      + P.dNormalDY.transpose()*d;
    return P;
}


surfaceProjection triangulatedSurface::project(const vec3& y) const
{
    int t = -1, local = -1;
    feature kind = face;
    vec3 c;
    closest(y, t, kind, local, c);
    surfaceProjection P;
    const vec3 d = y - c;
    if (featureAngle_ > 0)
    {
        if (kind == face)
        {
            const vec3& nf = faceNormal_[t];
            return smoothProjection
            (
                t, y, c, mat3::Identity() - nf*nf.transpose()
            );
        }
        if (kind == edge && smoothEdge_[t][local])
        {
            const vec3 e =
                (p_[tri_[t][(local + 1)%3]] - p_[tri_[t][local]]).normalized();
            return smoothProjection(t, y, c, e*e.transpose());
        }
        if (kind == vertex && smoothVertex_[tri_[t][local]])
        {
            P.normal = cornerNormal_[t][local];
            P.gap = d.dot(P.normal);
            return P;
        }
    }
    if (kind == face)
    {
        P.normal = faceNormal_[t];
        P.gap = P.normal.dot(d);
        return P;
    }
    const vec3 pseudo =
        kind == edge ? edgeNormal_[t][local] : vertexNormal_[tri_[t][local]];
    const double L = d.norm();
    if (!(L > 1e-12*size_))
    {
        // on the edge or vertex itself: the pseudonormal's direction
        P.normal = pseudo.normalized();
        P.gap = 0;
        return P;
    }
    const double s = d.dot(pseudo) >= 0 ? 1.0 : -1.0;
    P.gap = s*L;
    P.normal = s*d/L;
    mat3 A = mat3::Identity() - P.normal*P.normal.transpose();
    if (kind == edge)
    {
        const vec3 e =
            (p_[tri_[t][(local + 1)%3]] - p_[tri_[t][local]]).normalized();
        A -= e*e.transpose();
    }
    P.dNormalDY = A/P.gap;
    return P;
}


std::unique_ptr<rigidSurface> newTriangulatedSurface(const surfaceInput& in)
{
    if (!in.triangles)
    {
        throw inputError("file", "triSurface needs a file of triangles");
    }
    const auto it = in.scalars.find("flipNormals");
    const bool flip = it != in.scalars.end() && it->second != 0;
    const auto fa = in.scalars.find("featureAngle");
    return std::unique_ptr<rigidSurface>
    (
        new triangulatedSurface
        (
            *in.triangles, flip, fa == in.scalars.end() ? 30.0 : fa->second
        )
    );
}

} // namespace form
