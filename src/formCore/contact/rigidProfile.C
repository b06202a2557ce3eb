/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Rigid tool outline of lines and fillet arcs (see rigidProfile.H):
    construction with input checks, brute-force closest-point projection
    with the curvature terms, arc-length evaluation and sampling.
\*---------------------------------------------------------------------------*/
#include "rigidProfile.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <string>

namespace form
{

namespace
{

using vec2 = Eigen::Vector2d;

const double pi = 3.14159265358979323846;

//- Angles closer than this to a 180-degree turn are rejected
const double reversalTol = 1e-9;

//- Relative tolerance of the foot-inside-piece tests
const double relTol = 1e-10;

//- Relative tie of two distances (project): far from the tool, where only
//  the constraint function's tail acts (contactModel.H), a point on the
//  medial axis of two pieces keeps one of them
const double medialTol = 1e-6;

//- Outward normal of the unit tangent t: (t_y, -t_x)
inline vec2 rightOf(const vec2& t)
{
    return vec2(t(1), -t(0));
}

//- t rotated by +90 degrees: (-t_y, t_x)
inline vec2 leftOf(const vec2& t)
{
    return vec2(-t(1), t(0));
}

inline double cross(const vec2& a, const vec2& b)
{
    return a(0)*b(1) - a(1)*b(0);
}

inline vec2 polar(double phi)
{
    return vec2(std::cos(phi), std::sin(phi));
}

inline std::string pointName(const vec2& p)
{
    return "(" + formatNumber(p(0)) + " " + formatNumber(p(1)) + ")";
}

inline std::string vertexName(std::size_t k, const vec2& p)
{
    return "vertex " + std::to_string(k) + " " + pointName(p);
}

} // anonymous namespace


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

rigidProfile::rigidProfile
(
    std::vector<Eigen::Vector2d> points,
    std::vector<double> radii
)
{
    const std::size_t n = points.size();
    if (n < 2)
    {
        throw inputError
        (
            "points",
            "a rigid profile needs at least 2 points, got "
          + std::to_string(n)
        );
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!points[i].allFinite())
        {
            throw inputError
            (
                "points",
                "point " + std::to_string(i) + " of the rigid profile is "
                "not finite"
            );
        }
    }

    // Length scale: bounding-box diagonal
    vec2 lo = points[0], hi = points[0];
    for (const vec2& p : points)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double scale = (hi - lo).norm();
    tol_ = relTol*scale;

    // Segments
    const std::size_t nSeg = n - 1;
    std::vector<vec2> dir(nSeg);
    std::vector<double> segLen(nSeg);
    for (std::size_t i = 0; i < nSeg; ++i)
    {
        const vec2 d = points[i + 1] - points[i];
        segLen[i] = d.norm();
        if (!(segLen[i] > 1e-12*scale))
        {
            throw inputError
            (
                "points",
                "points " + std::to_string(i) + " " + pointName(points[i])
              + " and " + std::to_string(i + 1) + " "
              + pointName(points[i + 1]) + " of the rigid profile coincide"
            );
        }
        dir[i] = d/segLen[i];
    }

    // Radii at the interior vertices 1 ... n-2 (index = vertex number)
    const std::size_t nInterior = n - 2;
    std::vector<double> r(n, 0.0);
    if (radii.size() == 1)
    {
        for (std::size_t k = 1; k + 1 < n; ++k) r[k] = radii[0];
    }
    else if (radii.size() == nInterior)
    {
        for (std::size_t k = 1; k + 1 < n; ++k) r[k] = radii[k - 1];
    }
    else if (!radii.empty())
    {
        throw inputError
        (
            "radii",
            "a rigid profile of " + std::to_string(n) + " points takes "
          + std::to_string(nInterior) + " fillet radii (one per interior "
            "vertex), one radius for all or none; got "
          + std::to_string(radii.size())
        );
    }
    for (std::size_t k = 1; k + 1 < n; ++k)
    {
        if (!std::isfinite(r[k]) || r[k] < 0)
        {
            throw inputError
            (
                "radii",
                "fillet radius " + formatNumber(r[k]) + " at "
              + vertexName(k, points[k]) + " is negative or not finite"
            );
        }
    }

    // Turning angles and tangent lengths
    std::vector<double> theta(n, 0.0), e(n, 0.0);
    for (std::size_t k = 1; k + 1 < n; ++k)
    {
        const vec2& a = dir[k - 1];
        const vec2& b = dir[k];
        theta[k] = std::atan2(cross(a, b), a.dot(b));
        if (pi - std::abs(theta[k]) < reversalTol)
        {
            throw inputError
            (
                r[k] > 0 ? "radii" : "points",
                "the rigid profile turns back on itself (180-degree turn) "
                "at " + vertexName(k, points[k])
              + (r[k] > 0 ? "; such a corner cannot be filleted" : "")
            );
        }
        e[k] = r[k]*std::tan(0.5*std::abs(theta[k]));
    }

    // Fillets must fit on their segments
    for (std::size_t i = 0; i < nSeg; ++i)
    {
        const double L = segLen[i];
        const double allowed = L*(1 + 1e-12);
        const double eStart = e[i];         // vertex i (0 at the start point)
        const double eEnd = e[i + 1];       // vertex i+1 (0 at the end point)
        for (const std::size_t k : {i, i + 1})
        {
            if (e[k] > allowed)
            {
                throw inputError
                (
                    "radii",
                    "fillet radius " + formatNumber(r[k]) + " at "
                  + vertexName(k, points[k]) + " does not fit: its tangent "
                    "length r tan(|theta|/2) = " + formatNumber(e[k])
                  + " exceeds the length " + formatNumber(L)
                  + " of the segment from vertex " + std::to_string(i)
                  + " to vertex " + std::to_string(i + 1)
                );
            }
        }
        if (eStart + eEnd > allowed)
        {
            throw inputError
            (
                "radii",
                "the fillets of radius " + formatNumber(r[i]) + " at "
              + vertexName(i, points[i]) + " and " + formatNumber(r[i + 1])
              + " at " + vertexName(i + 1, points[i + 1]) + " overlap: "
                "their tangent lengths " + formatNumber(eStart) + " + "
              + formatNumber(eEnd) + " exceed the segment length "
              + formatNumber(L)
            );
        }
    }

    // Pieces in the order of the arc length
    double xi = 0;
    auto addPiece = [&](profilePiece p)
    {
        p.xi0 = xi;
        xi += p.len;
        pieces_.push_back(p);
    };

    // Start point: convex "corner" turning by 180 degrees, normal cone
    // from -n_0 counter-clockwise through -dir_0 to n_0
    {
        profilePiece p;
        p.line = false;
        p.origin = points[0];
        const vec2 u0 = -rightOf(dir[0]);
        p.phi0 = std::atan2(u0(1), u0(0));
        p.sweep = pi;
        addPiece(p);
    }

    for (std::size_t i = 0; i < nSeg; ++i)
    {
        // Line between the tangent points of the fillets at its ends
        const double lineLen = std::max(segLen[i] - e[i] - e[i + 1], 0.0);
        if (lineLen > tol_)
        {
            profilePiece p;
            p.line = true;
            p.origin = points[i] + e[i]*dir[i];
            p.dir = dir[i];
            p.len = lineLen;
            addPiece(p);
        }

        // Fillet or sharp vertex at the interior vertex k = i + 1
        const std::size_t k = i + 1;
        if (k + 1 < n && theta[k] != 0)
        {
            const double s = theta[k] > 0 ? 1 : -1;
            const vec2 nA = rightOf(dir[i]);
            const vec2 T1 = points[k] - e[k]*dir[i];
            const vec2 u0 = s*nA;   // (start point - centre)/R

            profilePiece p;
            p.line = false;
            p.R = r[k];
            p.origin = T1 - s*r[k]*nA;
            p.phi0 = std::atan2(u0(1), u0(0));
            p.sweep = theta[k];
            p.len = r[k]*std::abs(theta[k]);
            addPiece(p);
        }
    }

    // End point: normal cone from n_last counter-clockwise to -n_last
    {
        profilePiece p;
        p.line = false;
        p.origin = points[n - 1];
        const vec2 u0 = rightOf(dir[nSeg - 1]);
        p.phi0 = std::atan2(u0(1), u0(0));
        p.sweep = pi;
        addPiece(p);
    }

    length_ = xi;
}


// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

profileProjection rigidProfile::projectOnto
(
    const profilePiece& p,
    const Eigen::Vector2d& y,
    bool& inside
) const
{
    profileProjection res;

    if (p.line)
    {
        double s = (y - p.origin).dot(p.dir);
        inside = s >= -tol_ && s <= p.len + tol_;
        s = std::min(std::max(s, 0.0), p.len);

        res.point = p.origin + s*p.dir;
        res.tangent = p.dir;
        res.normal = rightOf(p.dir);
        res.gap = (y - res.point).dot(res.normal);
        res.xi = p.xi0 + s;
        res.dXidY = res.tangent;
        res.dNormalDY.setZero();
        return res;
    }

    // Arc (R = 0: vertex), sweep sign sg: the polar angle about the centre
    // runs phi0 + sg psi, psi in [0, |sweep|]
    const double sg = p.sweep > 0 ? 1 : -1;
    const double psiMax = std::abs(p.sweep);
    const vec2 d = y - p.origin;
    const double rho = d.norm();

    double psi;
    vec2 u;
    bool regular = rho > tol_;
    if (regular)
    {
        u = d/rho;
        const double phi = std::atan2(u(1), u(0));
        psi = std::fmod(sg*(phi - p.phi0), 2*pi);
        if (psi < 0) psi += 2*pi;
        const double angTol = relTol;
        if (psi > 2*pi - angTol) psi -= 2*pi;   // just before the start
        inside = psi >= -angTol && psi <= psiMax + angTol;
        if (psi < 0 || psi > psiMax)
        {
            // Clamp to the nearer end of the arc (on the circle)
            const double toEnd = psi - psiMax;
            const double toStart = 2*pi - psi;
            psi = (psi < 0 || toStart < toEnd) ? 0 : psiMax;
            u = polar(p.phi0 + sg*psi);
        }
    }
    else
    {
        // y at the centre: every point of the arc is equally near. On a
        // sharp vertex (R = 0) prefer the adjacent pieces, whose foot is
        // there too and whose normal is defined
        inside = p.R > 0;
        psi = 0.5*psiMax;
        u = polar(p.phi0 + sg*psi);
    }

    res.point = p.origin + p.R*u;
    res.normal = sg*u;
    res.tangent = leftOf(res.normal);
    res.gap = (y - res.point).dot(res.normal);
    res.xi = p.xi0 + p.R*psi;

    if (regular && inside)
    {
        // rho = R + g (convex) or R - g (concave)
        res.dXidY = (p.R/rho)*res.tangent;
        res.dNormalDY = (sg/rho)*res.tangent*res.tangent.transpose();
    }
    else
    {
        res.dXidY.setZero();
        res.dNormalDY.setZero();
    }
    return res;
}


Eigen::Vector2d rigidProfile::pointOn(const profilePiece& p, double s)
{
    if (p.line)
    {
        return p.origin + s*p.dir;
    }
    if (p.R == 0)
    {
        return p.origin;
    }
    const double sg = p.sweep > 0 ? 1 : -1;
    return p.origin + p.R*polar(p.phi0 + sg*s/p.R);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

profileProjection rigidProfile::project(const Eigen::Vector2d& y) const
{
    profileProjection best;
    bool bestInside = false;
    double bestDist = 0;

    for (std::size_t i = 0; i < pieces_.size(); ++i)
    {
        bool inside = false;
        profileProjection c = projectOnto(pieces_[i], y, inside);
        const double dist = (y - c.point).norm();

        // Feet inside their piece first, then the nearest; on ties a line
        // or fillet before a sharp vertex or end point (their foot is the
        // same point, where the piece's normal is the one-sided limit and
        // its gap signed: a point on the edge of an end point's normal
        // cone inside the tool, as every point over the core of a swept
        // profile, has a negative gap), else the first. Distances within
        // medialTol of each other tie too: a point on the medial axis of
        // two pieces (the middle of a die's channel) keeps the first of
        // them while it wanders across the axis by round-off, instead of
        // a normal that flips with the sign of the last bits (the
        // S-rail's middle node, held on that axis by the part's symmetry,
        // felt the die's far walls, 26 mm away, push it one way and the
        // other in turn: a residual Newton could not remove, 2026-11-27).
        // The gap taken is then longer by at most medialTol of itself
        const bool vertex = !pieces_[i].line && pieces_[i].R == 0;
        const bool tie =
            std::abs(dist - bestDist)
         <= std::max(1e-3*tol_, medialTol*std::min(dist, bestDist));
        const bool better =
            best.piece < 0
         || (inside && !bestInside)
         || (
                inside == bestInside
             && (tie ? best.vertex && !vertex : dist < bestDist)
            );
        if (better)
        {
            best = c;
            best.piece = static_cast<int>(i);
            best.vertex = vertex;
            bestInside = inside;
            bestDist = dist;
        }
    }
    return best;
}


double rigidProfile::length() const
{
    return length_;
}


Eigen::Vector2d rigidProfile::pointAt(double xi) const
{
    xi = std::min(std::max(xi, 0.0), length_);
    const profilePiece* last = nullptr;
    for (const profilePiece& p : pieces_)
    {
        if (p.len <= 0) continue;
        last = &p;
        if (xi <= p.xi0 + p.len)
        {
            return pointOn(p, std::max(xi - p.xi0, 0.0));
        }
    }
    // Rounding at the very end
    return pointOn(*last, last->len);
}


std::vector<Eigen::Vector2d> rigidProfile::sample(double ds) const
{
    if (!(ds > 0) || !std::isfinite(ds))
    {
        throw inputError
        (
            "ds",
            "the sampling distance of a rigid profile must be positive and "
            "finite, got " + formatNumber(ds)
        );
    }
    if (length_/ds > 1e7)
    {
        throw inputError
        (
            "ds",
            "the sampling distance " + formatNumber(ds) + " would give more "
            "than 1e7 points along a profile of length "
          + formatNumber(length_)
        );
    }

    std::vector<vec2> pts;
    pts.push_back(pieces_.front().origin);      // the start point
    for (const profilePiece& p : pieces_)
    {
        if (p.len <= 0) continue;
        const int m = std::max(1, static_cast<int>(std::ceil(p.len/ds)));
        for (int j = 1; j <= m; ++j)
        {
            pts.push_back(pointOn(p, p.len*j/m));
        }
    }
    return pts;
}

} // namespace form
