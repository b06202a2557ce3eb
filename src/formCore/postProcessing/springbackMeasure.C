/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    U-channel springback measures (see springbackMeasure.H): curvature
    segmentation, line and circle fits, theta1, theta2 and rho.
\*---------------------------------------------------------------------------*/
#include "springbackMeasure.H"
#include "formError.H"
#include "formTypes.H"
#include <algorithm>
#include <cmath>
#include <limits>

namespace form
{

namespace
{

using vec2 = Eigen::Vector2d;

const double pi = 3.14159265358979323846;

double cross2(const vec2& a, const vec2& b)
{
    return a.x()*b.y() - a.y()*b.x();
}

//- Signed angle (radians, counter-clockwise positive) from a to b
double signedAngle(const vec2& a, const vec2& b)
{
    return std::atan2(cross2(a, b), a.dot(b));
}

//- Unsigned angle between a and b in degrees, in [0, 180]
double angleDeg(const vec2& a, const vec2& b)
{
    return std::abs(signedAngle(a, b))*180/pi;
}

//- a rotated by +90 degrees
vec2 perp(const vec2& a)
{
    return vec2(-a.y(), a.x());
}


//- Total least-squares line: centroid and unit direction
struct lineFit
{
    vec2 origin = vec2::Zero();
    vec2 dir = vec2::UnitX();
    double rms = 0;

    double distance(const vec2& p) const
    {
        return std::abs(cross2(dir, p - origin));
    }
};

//- Fit a line to pts; dir is oriented along hint
lineFit fitLine(const std::vector<vec2>& pts, const vec2& hint)
{
    lineFit f;
    for (const vec2& p : pts) f.origin += p;
    f.origin /= double(pts.size());
    Eigen::Matrix2d C = Eigen::Matrix2d::Zero();
    for (const vec2& p : pts) C += (p - f.origin)*(p - f.origin).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(C);
    f.dir = eig.eigenvectors().col(1).normalized();
    if (f.dir.dot(hint) < 0) f.dir = -f.dir;
    double sum = 0;
    for (const vec2& p : pts) sum += std::pow(f.distance(p), 2);
    f.rms = std::sqrt(sum/pts.size());
    return f;
}


//- Geometric circle fit in Karimaki's parametrisation (rho, phi, d) in a
//  local frame (origin at the centroid, x along the principal direction
//  oriented along the profile, lengths scaled by L). The circle is the
//  zero set of
//      P(q) = rho/2 |q|^2 - (1 + rho d) q.u + rho/2 d^2 + d,
//      u = (sin phi, -cos phi),
//  centre (d + 1/rho) u, radius 1/|rho|, and the orthogonal distance of q
//  is 2P/(1 + sqrt(1 + 2 rho P)); at rho = 0 it is the line q.u = d.
//  grad P = rho q - (1 + rho d) u is normal to the circle through the foot
//  of q, and regular at rho = 0.
struct circleFit
{
    vec2 origin = vec2::Zero();
    vec2 e1 = vec2::UnitX(), e2 = vec2::UnitY();
    double L = 1;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();    // rho, phi, d (scaled)
    double rms = 0;

    vec2 local(const vec2& p) const
    {
        const vec2 r = (p - origin)/L;
        return vec2(r.dot(e1), r.dot(e2));
    }

    static double P(const Eigen::Vector3d& x, const vec2& q)
    {
        const double rho = x(0), d = x(2);
        const vec2 u(std::sin(x(1)), -std::cos(x(1)));
        return 0.5*rho*q.squaredNorm() - (1 + rho*d)*q.dot(u)
            + 0.5*rho*d*d + d;
    }

    //- Signed orthogonal distance (scaled)
    static double eps(const Eigen::Vector3d& x, const vec2& q)
    {
        const double p = P(x, q);
        return 2*p/(1 + std::sqrt(std::max(0.0, 1 + 2*x(0)*p)));
    }

    //- Orthogonal distance of p in the profile's length unit
    double distance(const vec2& p) const
    {
        return L*std::abs(eps(x, local(p)));
    }

    //- Signed curvature (counter-clockwise positive) along e1
    double curvature() const
    {
        return -x(0)/L*(std::cos(x(1)) >= 0 ? 1 : -1);
    }

    //- Unit tangent, oriented along e1, at the foot of p on the circle
    vec2 tangentAtFoot(const vec2& p) const
    {
        const vec2 q = local(p);
        const vec2 u(std::sin(x(1)), -std::cos(x(1)));
        const vec2 g = x(0)*q - (1 + x(0)*x(2))*u;
        vec2 t = perp(g);
        t = (t.x()*e1 + t.y()*e2).normalized();
        return t.dot(e1) >= 0 ? t : vec2(-t);
    }

    //- Centre in profile coordinates (rho must be non-zero)
    vec2 centre() const
    {
        const vec2 u(std::sin(x(1)), -std::cos(x(1)));
        const vec2 c = (x(2) + 1/x(0))*u;
        return origin + L*(c.x()*e1 + c.y()*e2);
    }
};

//- Fit a circle (or line) to pts; hint orients the local frame
circleFit fitCircle(const std::vector<vec2>& pts, const vec2& hint,
                    const std::string& what)
{
    const int n = int(pts.size());
    const lineFit lf = fitLine(pts, hint);
    circleFit f;
    f.origin = lf.origin;
    f.e1 = lf.dir;
    f.e2 = perp(lf.dir);
    f.L = 0;
    for (const vec2& p : pts) f.L = std::max(f.L, (p - f.origin).norm());
    if (!(f.L > 0))
    {
        throw numericalError("measureUChannel: the " + what
            + " points coincide");
    }
    std::vector<vec2> q(n);
    for (int i = 0; i < n; ++i) q[i] = f.local(pts[i]);

    // Start: parabola v = a + b u + c u^2 at u = 0
    Eigen::MatrixXd A(n, 3);
    Eigen::VectorXd rhs(n);
    for (int i = 0; i < n; ++i)
    {
        A(i, 0) = 1;
        A(i, 1) = q[i].x();
        A(i, 2) = q[i].x()*q[i].x();
        rhs(i) = q[i].y();
    }
    const Eigen::Vector3d abc = A.colPivHouseholderQr().solve(rhs);
    const double phi0 = std::atan(abc(1));
    Eigen::Vector3d x
    (
        -2*abc(2)/std::pow(1 + abc(1)*abc(1), 1.5),
        phi0,
        -abc(0)*std::cos(phi0)
    );

    auto residuals = [&](const Eigen::Vector3d& y)
    {
        Eigen::VectorXd r(n);
        for (int i = 0; i < n; ++i) r(i) = circleFit::eps(y, q[i]);
        return r;
    };

    // Levenberg-Marquardt, central-difference Jacobian
    Eigen::VectorXd r = residuals(x);
    double cost = r.squaredNorm();
    double lambda = 1e-3;
    for (int iter = 0; iter < 200; ++iter)
    {
        Eigen::MatrixXd J(n, 3);
        for (int k = 0; k < 3; ++k)
        {
            const double h = 1e-7*std::max(1.0, std::abs(x(k)));
            Eigen::Vector3d xp = x, xm = x;
            xp(k) += h;
            xm(k) -= h;
            J.col(k) = (residuals(xp) - residuals(xm))/(2*h);
        }
        const Eigen::Matrix3d JtJ = J.transpose()*J;
        const Eigen::Vector3d g = J.transpose()*r;
        bool accepted = false;
        double step = 0;
        for (int tries = 0; tries < 30 && !accepted; ++tries)
        {
            Eigen::Matrix3d M = JtJ;
            for (int k = 0; k < 3; ++k)
            {
                M(k, k) += lambda*std::max(JtJ(k, k), 1e-12);
            }
            const Eigen::Vector3d dx = M.ldlt().solve(-g);
            const Eigen::VectorXd rNew = residuals(x + dx);
            const double costNew = rNew.squaredNorm();
            if (std::isfinite(costNew) && costNew <= cost)
            {
                x += dx;
                r = rNew;
                step = dx.norm();
                const double gain = cost - costNew;
                cost = costNew;
                lambda = std::max(lambda/3, 1e-12);
                accepted = true;
                if (gain <= 1e-15*cost) step = 0;
            }
            else
            {
                lambda *= 4;
            }
        }
        if (!accepted || step < 1e-13) break;
    }
    if (!x.allFinite())
    {
        throw numericalError("measureUChannel: the circle fit of the "
            + what + " failed");
    }
    f.x = x;
    f.rms = f.L*std::sqrt(cost/n);
    return f;
}


struct run
{
    int begin, end;     // inclusive
    double turn;        // radians, counter-clockwise positive
};

} // anonymous namespace


uChannelSpringback measureUChannel
(
    const std::vector<Eigen::Vector2d>& profile,
    const uChannelMeasureOptions& options
)
{
    // Options
    if (!(options.bendCurvature >= 0) || !std::isfinite(options.bendCurvature))
    {
        throw inputError("bendCurvature", "bendCurvature "
            + formatNumber(options.bendCurvature)
            + " must be >= 0 (0: automatic)");
    }
    if
    (
        !(options.curvatureWindow >= 0)
     || !std::isfinite(options.curvatureWindow)
    )
    {
        throw inputError("curvatureWindow", "curvatureWindow "
            + formatNumber(options.curvatureWindow)
            + " must be >= 0 (0: automatic)");
    }
    if (!(options.minBendAngle > 0 && options.minBendAngle < 180))
    {
        throw inputError("minBendAngle", "minBendAngle "
            + formatNumber(options.minBendAngle)
            + " must be in (0, 180) degrees");
    }

    // Distinct points, with their input indices
    for (const vec2& p : profile)
    {
        if (!p.allFinite())
        {
            throw inputError("profile", "profile has a non-finite point");
        }
    }
    const int minPoints = 12;
    if (int(profile.size()) < minPoints)
    {
        throw inputError("profile", "profile has "
            + std::to_string(profile.size()) + " points; at least "
            + std::to_string(minPoints) + " are needed");
    }
    Eigen::AlignedBox2d box;
    for (const vec2& p : profile) box.extend(p);
    const double coincident = 1e-12*box.diagonal().norm();
    std::vector<vec2> p;
    std::vector<int> index;
    for (int i = 0; i < int(profile.size()); ++i)
    {
        if (p.empty() || (profile[i] - p.back()).norm() > coincident)
        {
            p.push_back(profile[i]);
            index.push_back(i);
        }
    }
    const int n = int(p.size());
    if (n < minPoints)
    {
        throw inputError("profile", "profile has " + std::to_string(n)
            + " distinct points; at least " + std::to_string(minPoints)
            + " are needed");
    }

    // Arc length, window
    std::vector<double> s(n, 0.0), ds(n - 1);
    for (int i = 1; i < n; ++i)
    {
        ds[i - 1] = (p[i] - p[i - 1]).norm();
        s[i] = s[i - 1] + ds[i - 1];
    }
    double w = options.curvatureWindow;
    if (w == 0)
    {
        std::vector<double> sorted(ds);
        std::nth_element
        (
            sorted.begin(), sorted.begin() + sorted.size()/2, sorted.end()
        );
        // Two spacings: 9-node meshes alternate corner and mid-side nodes,
        // and a zig-zag between them (a few um where a wall is pressed in
        // a slot) cancels over chords of two spacings
        w = 2*sorted[sorted.size()/2];
    }
    const double wTol = w*(1 - 1e-9);

    // Discrete curvature
    std::vector<double> kappa(n, 0.0);
    for (int i = 1; i < n - 1; ++i)
    {
        int j = i - 1;
        while (j > 0 && s[i] - s[j] < wTol) --j;
        int k = i + 1;
        while (k < n - 1 && s[k] - s[i] < wTol) ++k;
        kappa[i] = signedAngle(p[i] - p[j], p[k] - p[i])/(0.5*(s[k] - s[j]));
    }
    kappa[0] = kappa[1];
    kappa[n - 1] = kappa[n - 2];

    // Threshold
    double threshold = options.bendCurvature;
    if (threshold == 0)
    {
        double kMax = 0;
        for (int i = 1; i < n - 1; ++i)
        {
            double a[3] =
                {std::abs(kappa[i - 1]), std::abs(kappa[i]),
                 std::abs(kappa[i + 1])};
            std::sort(a, a + 3);
            kMax = std::max(kMax, a[1]);
        }
        if (!(kMax > 0) || !std::isfinite(kMax))
        {
            throw numericalError("measureUChannel: the profile has no "
                "curvature (a flat strip?), no bends to segment it by");
        }
        threshold = 0.2*kMax;
    }

    // Runs of bend points, turns, bends
    std::vector<run> bends;
    int nRuns = 0;
    for (int i = 0; i < n; )
    {
        if (std::abs(kappa[i]) <= threshold)
        {
            ++i;
            continue;
        }
        int e = i;
        while (e + 1 < n && std::abs(kappa[e + 1]) > threshold) ++e;
        double turn = 0;
        for (int v = std::max(i, 1); v <= std::min(e, n - 2); ++v)
        {
            turn += signedAngle(p[v] - p[v - 1], p[v + 1] - p[v]);
        }
        ++nRuns;
        if (std::abs(turn) >= options.minBendAngle*pi/180)
        {
            bends.push_back({i, e, turn});
        }
        i = e + 1;
    }
    const std::string thresholdInfo = " (bend curvature threshold "
        + formatNumber(threshold) + ", minBendAngle "
        + formatNumber(options.minBendAngle) + " deg)";
    if (bends.size() != 2)
    {
        throw numericalError("measureUChannel: found "
            + std::to_string(bends.size()) + " bends (of "
            + std::to_string(nRuns) + " curved runs), a U-channel profile "
            "has two: bottom, punch bend, wall, die bend, flange"
            + thresholdInfo + "; a noisy profile may need a larger "
            "curvatureWindow (now " + formatNumber(w) + ")");
    }
    const run& b1 = bends[0];
    const run& b2 = bends[1];
    if (b1.begin < 2 || b2.end > n - 3 || b2.begin - b1.end - 1 < 3)
    {
        throw numericalError("measureUChannel: the two bends leave "
            + std::to_string(b1.begin) + " bottom, "
            + std::to_string(std::max(0, b2.begin - b1.end - 1))
            + " wall and " + std::to_string(std::max(0, n - 1 - b2.end))
            + " flange points; at least 2, 3 and 2 are needed"
            + thresholdInfo);
    }
    if ((b1.turn > 0) == (b2.turn > 0))
    {
        throw numericalError("measureUChannel: both bends turn the same "
            "way; not a U-channel profile" + thresholdInfo);
    }

    // Fits
    auto slice = [&](int b, int e)      // inclusive
    {
        return std::vector<vec2>(p.begin() + b, p.begin() + e + 1);
    };
    const lineFit bottom =
        fitLine(slice(0, b1.begin - 1), p[b1.begin - 1] - p[0]);
    const circleFit wall = fitCircle
    (
        slice(b1.end + 1, b2.begin - 1), p[b2.begin - 1] - p[b1.end + 1],
        "side wall"
    );
    const lineFit flange =
        fitLine(slice(b2.end + 1, n - 1), p[n - 1] - p[b2.end + 1]);

    // Bend centres from the bend points off both neighbours
    const double noiseTol = 1e-9*s[n - 1];
    auto bendCentre = [&](const run& b, auto distBefore, auto distAfter,
                          double rmsBefore, double rmsAfter,
                          const std::string& what)
    {
        const double tol = 5*std::max(rmsBefore, rmsAfter) + noiseTol;
        std::vector<vec2> pts;
        for (int i = b.begin; i <= b.end; ++i)
        {
            if (distBefore(p[i]) > tol && distAfter(p[i]) > tol)
            {
                pts.push_back(p[i]);
            }
        }
        if (pts.size() < 3)
        {
            throw numericalError("measureUChannel: the " + what + " has "
                + std::to_string(pts.size()) + " points off its "
                "neighbouring straight parts; at least 3 are needed to "
                "fit it (refine the profile)" + thresholdInfo);
        }
        const circleFit c =
            fitCircle(pts, pts.back() - pts.front(), what);
        if (!(std::abs(c.x(0)) > 0))
        {
            throw numericalError("measureUChannel: the " + what
                + " is not curved");
        }
        return c.centre();
    };
    const vec2 c1 = bendCentre
    (
        b1,
        [&](const vec2& q) { return bottom.distance(q); },
        [&](const vec2& q) { return wall.distance(q); },
        bottom.rms, wall.rms, "punch bend"
    );
    const vec2 c2 = bendCentre
    (
        b2,
        [&](const vec2& q) { return wall.distance(q); },
        [&](const vec2& q) { return flange.distance(q); },
        wall.rms, flange.rms, "die bend"
    );

    // Measures
    const vec2 tw1 = wall.tangentAtFoot(c1);
    const vec2 tw2 = wall.tangentAtFoot(c2);

    uChannelSpringback r;
    r.theta1 = angleDeg(-bottom.dir, tw1);
    r.theta2 = angleDeg(tw2, flange.dir);

    const double chord = (p[b2.begin - 1] - p[b1.end + 1]).norm();
    const double kw = wall.curvature();
    if (std::abs(kw)*chord < 8e-7)
    {
        r.rho = std::numeric_limits<double>::infinity();
    }
    else
    {
        r.rho = 1/(b2.turn < 0 ? -kw : kw);
    }

    r.bottomEnd = index[b1.begin];
    r.wallBegin = index[b1.end + 1];
    r.wallEnd = index[b2.begin];
    r.flangeBegin = index[b2.end + 1];
    return r;
}

} // namespace form
