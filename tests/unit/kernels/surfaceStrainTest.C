// surfaceStrains (surfaceStrain.H): the principal logarithmic strains of
// a shell element's mid-surface in closed form (uniaxial, equibiaxial,
// pure shear, a rigid rotation, a triangle, an arbitrary element under a
// known homogeneous deformation F: the stretches are the square roots of
// the eigenvalues of the surface part of F^T F); the forming limit curve
// through points and the Keeler-Brazier estimate; errors.
#include "surfaceStrain.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace form;

namespace
{

matX square()
{
    matX X(4, 3);
    X << 0, 0, 0,  2, 0, 0,  2, 1.5, 0,  0, 1.5, 0;
    return X;
}

//- x = F X + c for every row
matX map(const matX& X, const mat3& F, const vec3& c = vec3::Zero())
{
    matX x(X.rows(), 3);
    for (int a = 0; a < X.rows(); ++a) x.row(a) = (F*X.row(a).transpose() + c).transpose();
    return x;
}

mat3 rotation(const vec3& axis, double angle)
{
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

} // anonymous namespace


TEST(surfaceStrain, closedForms)
{
    const matX X = square();
    // uniaxial stretch 1.3 along x (width unchanged)
    mat3 F = mat3::Identity();
    F(0, 0) = 1.3;
    surfaceStrain s = surfaceStrains(X, map(X, F));
    EXPECT_NEAR(s.major, std::log(1.3), 1e-14);
    EXPECT_NEAR(s.minor, 0, 1e-14);
    // drawing: stretch along y, compression along x
    F = mat3::Identity();
    F(0, 0) = 0.8;
    F(1, 1) = 1.4;
    s = surfaceStrains(X, map(X, F));
    EXPECT_NEAR(s.major, std::log(1.4), 1e-14);
    EXPECT_NEAR(s.minor, std::log(0.8), 1e-14);
    // equibiaxial 1.1, then turned and moved as a rigid body: unchanged
    F = 1.1*mat3::Identity();
    const mat3 R = rotation(vec3(1, -2, 0.5), 0.7);
    s = surfaceStrains(X, map(X, R*F, vec3(3, -1, 2)));
    EXPECT_NEAR(s.major, std::log(1.1), 1e-14);
    EXPECT_NEAR(s.minor, std::log(1.1), 1e-14);
    // a rigid rotation alone: no strain
    s = surfaceStrains(X, map(X, R));
    EXPECT_NEAR(s.major, 0, 1e-14);
    EXPECT_NEAR(s.minor, 0, 1e-14);
    // simple shear gamma: stretches sqrt(1 + g^2/4) +- g/2
    F = mat3::Identity();
    const double g = 0.4;
    F(0, 1) = g;
    s = surfaceStrains(X, map(X, F));
    EXPECT_NEAR(s.major, std::log(std::sqrt(1 + g*g/4) + g/2), 1e-14);
    EXPECT_NEAR(s.minor, std::log(std::sqrt(1 + g*g/4) - g/2), 1e-14);
}


TEST(surfaceStrain, homogeneousDeformationOfAnyElement)
{
    // A skew quadrilateral (a parallelogram: homogeneous F maps it
    // exactly) and a triangle, in an inclined plane, under random F: the
    // surface stretches are those of F restricted to the plane
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 50; ++k)
    {
        const mat3 Q = rotation(vec3(u(gen), u(gen), u(gen)), 2*u(gen));
        const vec3 e1 = Q.col(0), e2 = Q.col(1);
        matX quad(4, 3), tri(3, 3);
        const vec3 a = 1.5*e1, b = 0.4*e1 + 0.9*e2;
        quad.row(0) = vec3::Zero().transpose();
        quad.row(1) = a.transpose();
        quad.row(2) = (a + b).transpose();
        quad.row(3) = b.transpose();
        tri.row(0) = vec3::Zero().transpose();
        tri.row(1) = a.transpose();
        tri.row(2) = b.transpose();
        mat3 F;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) F(i, j) = (i == j) + 0.3*u(gen);
        // surface stretches: eigenvalues of P^T F^T F P, P = [e1 e2]
        Eigen::Matrix<double, 3, 2> P;
        P << e1, e2;
        const Eigen::Matrix2d C = P.transpose()*F.transpose()*F*P;
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
        for (const matX& X : {quad, tri})
        {
            const surfaceStrain s = surfaceStrains(X, map(X, F, vec3(1, 2, 3)));
            EXPECT_NEAR(s.major, 0.5*std::log(es.eigenvalues()(1)), 1e-12);
            EXPECT_NEAR(s.minor, 0.5*std::log(es.eigenvalues()(0)), 1e-12);
        }
    }
    // Degenerate elements are numerical errors
    matX flat = square();
    flat.row(2) = flat.row(1);
    flat.row(3) = flat.row(0);
    EXPECT_THROW(surfaceStrains(square(), flat), numericalError);
    EXPECT_THROW(surfaceStrains(square(), matX::Zero(2, 3)), numericalError);
}


TEST(surfaceStrain, formingLimitCurves)
{
    const formingLimit f = formingLimit::table({{-0.2, 0.5}, {0, 0.3}, {0.3, 0.45}});
    EXPECT_NEAR(f(-0.1), 0.4, 1e-15);
    EXPECT_NEAR(f(0.15), 0.375, 1e-15);
    EXPECT_NEAR(f(-1), 0.5, 1e-15);     // held beyond the ends
    EXPECT_NEAR(f(1), 0.45, 1e-15);
    EXPECT_EQ(f.sample(-0.2, 0.3, 5).size(), 6u);
    // Keeler-Brazier for t = 0.78 mm, n = 0.2589 (the mild steel of the
    // square cup): FLC0 = 23.3 + 14.13 x 0.78 = 34.32 % (n/0.21 > 1:
    // capped), ln(1.3432) at plane strain; the left branch keeps
    // eps1 + eps2; the right has slope 0.6 in engineering strains
    const formingLimit kb = formingLimit::keelerBrazier(0.78, 0.2589);
    const double flc0 = 0.01*(23.3 + 14.13*0.78);
    EXPECT_NEAR(kb(0), std::log1p(flc0), 1e-14);
    EXPECT_NEAR(kb(-0.2) + (-0.2), std::log1p(flc0), 1e-14);
    EXPECT_NEAR(kb(std::log1p(0.1)), std::log1p(flc0 + 0.06), 1e-14);
    // n below 0.21 lowers it in proportion
    EXPECT_NEAR
    (
        std::expm1(formingLimit::keelerBrazier(0.78, 0.105)(0)), 0.5*flc0, 1e-14
    );
    // Bad input names the entry
    const auto entryOf = [](auto&& f) -> std::string
    {
        try { f(); }
        catch (const inputError& e) { return e.entry(); }
        return "no error";
    };
    EXPECT_EQ(entryOf([] { formingLimit::table({{0, 0.3}, {0, 0.4}}); }), "points");
    EXPECT_EQ(entryOf([] { formingLimit::table({}); }), "points");
    EXPECT_EQ(entryOf([] { formingLimit::keelerBrazier(-1, 0.2); }), "thickness");
    EXPECT_EQ(entryOf([] { formingLimit::keelerBrazier(1, 1.5); }), "n");
}
