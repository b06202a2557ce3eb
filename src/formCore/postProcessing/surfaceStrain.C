/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    form::surfaceStrains and form::formingLimit (surfaceStrain.H)
\*---------------------------------------------------------------------------*/
#include "surfaceStrain.H"
#include "formError.H"
#include <algorithm>
#include <cmath>

namespace form
{

namespace
{

//- Covariant base vectors at the centre (columns)
Eigen::Matrix<double, 3, 2> bases(const matX& X)
{
    Eigen::Matrix<double, 3, 2> G;
    if (X.rows() == 4)
    {
        const double dxi[4] = {-0.25, 0.25, 0.25, -0.25};
        const double deta[4] = {-0.25, -0.25, 0.25, 0.25};
        G.setZero();
        for (int a = 0; a < 4; ++a)
        {
            G.col(0) += dxi[a]*X.row(a).transpose();
            G.col(1) += deta[a]*X.row(a).transpose();
        }
    }
    else
    {
        G.col(0) = (X.row(1) - X.row(0)).transpose();
        G.col(1) = (X.row(2) - X.row(0)).transpose();
    }
    return G;
}

} // anonymous namespace


surfaceStrain surfaceStrains(const matX& X, const matX& x)
{
    if
    (
        (X.rows() != 4 && X.rows() != 3) || X.rows() != x.rows()
     || X.cols() != 3 || x.cols() != 3
    )
    {
        throw numericalError("surfaceStrains: needs 3 or 4 corners in 3D");
    }
    const Eigen::Matrix<double, 3, 2> G = bases(X), g = bases(x);
    const Eigen::Matrix2d GG = G.transpose()*G, gg = g.transpose()*g;
    const double detG = GG.determinant(), detg = gg.determinant();
    if (!(detG > 0) || !(detg > 0))
    {
        throw numericalError("surfaceStrains: degenerate element");
    }
    // Eigenvalues of G^-1 g: trace and determinant of the 2 x 2 product
    const Eigen::Matrix2d C = GG.inverse()*gg;
    const double tr = C.trace(), det = detg/detG;
    const double disc = std::sqrt(std::max(0.0, 0.25*tr*tr - det));
    const double big = 0.5*tr + disc;
    // the smaller from the product (no cancellation)
    const double small = det/big;
    surfaceStrain s;
    s.major = 0.5*std::log(big);
    s.minor = 0.5*std::log(small);
    return s;
}


formingLimit formingLimit::table
(
    const std::vector<std::pair<double, double>>& points
)
{
    if (points.empty())
    {
        throw inputError("points", "a forming limit curve needs points (minor major)");
    }
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        if (!std::isfinite(points[i].first) || !std::isfinite(points[i].second))
        {
            throw inputError("points", "a forming limit curve's points must be finite");
        }
        if (i && !(points[i].first > points[i - 1].first))
        {
            throw inputError
            (
                "points",
                "the minor strains of a forming limit curve's points must"
                " increase strictly"
            );
        }
    }
    formingLimit f;
    f.points_ = points;
    f.description_ =
        "forming limit curve through " + std::to_string(points.size())
      + " points (minor, major)";
    return f;
}


formingLimit formingLimit::keelerBrazier(double thickness, double n)
{
    if (!(thickness > 0) || !(thickness < 10))
    {
        throw inputError
        (
            "thickness",
            "the Keeler-Brazier estimate needs a sheet thickness in mm,"
            " 0 < t < 10"
        );
    }
    if (!(n > 0) || !(n < 1))
    {
        throw inputError
        (
            "n", "the Keeler-Brazier estimate needs a hardening exponent 0 < n < 1"
        );
    }
    // FLC0 in engineering strain
    const double flc0 = 0.01*(23.3 + 14.13*thickness)*std::min(1.0, n/0.21);
    const double log0 = std::log1p(flc0);
    std::vector<std::pair<double, double>> pts;
    // Left branch: constant thickness in logarithmic strains, to
    // eps2 = -0.4; right branch: slope 0.6 in engineering strains, to
    // e2 = 0.4
    for (int k = -8; k < 0; ++k)
    {
        const double eps2 = 0.05*k;
        pts.emplace_back(eps2, log0 - eps2);
    }
    for (int k = 0; k <= 8; ++k)
    {
        const double e2 = 0.05*k;
        pts.emplace_back(std::log1p(e2), std::log1p(flc0 + 0.6*e2));
    }
    formingLimit f = table(pts);
    f.description_ =
        "Keeler-Brazier estimate (low-carbon steel), t = "
      + std::to_string(thickness) + " mm, n = " + std::to_string(n)
      + ": FLC0 = " + std::to_string(std::log1p(flc0)) + " (log strain)";
    return f;
}


double formingLimit::operator()(double minor) const
{
    const auto& p = points_;
    if (minor <= p.front().first) return p.front().second;
    if (minor >= p.back().first) return p.back().second;
    const auto it = std::upper_bound
    (
        p.begin(), p.end(), minor,
        [](double v, const std::pair<double, double>& q) { return v < q.first; }
    );
    const auto& b = *it;
    const auto& a = *(it - 1);
    const double w = (minor - a.first)/(b.first - a.first);
    return (1 - w)*a.second + w*b.second;
}


std::vector<std::pair<double, double>> formingLimit::sample
(
    double lo,
    double hi,
    int n
) const
{
    std::vector<std::pair<double, double>> s;
    for (int k = 0; k <= n; ++k)
    {
        const double e2 = lo + (hi - lo)*k/std::max(1, n);
        s.emplace_back(e2, (*this)(e2));
    }
    return s;
}

} // namespace form
