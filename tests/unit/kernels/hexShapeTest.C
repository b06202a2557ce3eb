// Lagrange shape functions of the 8- and 27-node hexahedra (VTK order) and
// their face table: partition of unity, Kronecker property at the nodes,
// completeness (trilinear / triquadratic fields reproduced exactly),
// derivatives against central differences, and faces that are the quads
// of quadShape.H with outward corner order and mid-edge nodes where the
// edges say.
#include "hexShape.H"
#include "quadShape.H"
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

using namespace form;

namespace
{

template<int NN>
void checkShape(int order)
{
    using S = hexShape<NN>;
    typename S::vecN N;
    typename S::matN3 dN;
    // Kronecker property
    for (int a = 0; a < NN; ++a)
    {
        const Eigen::Vector3d x = S::node(a);
        S::eval(x(0), x(1), x(2), N, dN);
        for (int b = 0; b < NN; ++b)
        {
            EXPECT_NEAR(N(b), a == b ? 1.0 : 0.0, 1e-14) << a << " " << b;
        }
    }
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 20; ++k)
    {
        const double r = u(gen), s = u(gen), t = u(gen);
        S::eval(r, s, t, N, dN);
        // Partition of unity, derivatives sum to zero
        EXPECT_NEAR(N.sum(), 1, 1e-14);
        EXPECT_NEAR(dN.colwise().sum().norm(), 0, 1e-13);
        // Completeness: f(r, s, t) of the element's order from nodal values
        const auto f = [order](const Eigen::Vector3d& x)
        {
            const double lin = 0.3 + 1.1*x(0) - 0.7*x(1) + 0.2*x(2)
              + 0.5*x(0)*x(1)*x(2);
            return order == 1 ? lin
              : lin + 0.4*x(0)*x(0)*x(1)*x(1)*x(2)*x(2) - 0.9*x(2)*x(2);
        };
        double fh = 0;
        for (int a = 0; a < NN; ++a) fh += N(a)*f(S::node(a));
        EXPECT_NEAR(fh, f(Eigen::Vector3d(r, s, t)), 1e-13);
        // Derivatives by central differences
        const double h = 1e-6;
        for (int i = 0; i < 3; ++i)
        {
            Eigen::Vector3d xp(r, s, t), xm(r, s, t);
            xp(i) += h;
            xm(i) -= h;
            const vecX Np = hexShapeValues(NN, xp(0), xp(1), xp(2));
            const vecX Nm = hexShapeValues(NN, xm(0), xm(1), xm(2));
            EXPECT_LT(((Np - Nm)/(2*h) - dN.col(i)).norm(), 1e-8);
        }
    }
}

} // namespace


TEST(hexShape, Hex8TrilinearLagrange) { checkShape<8>(1); }
TEST(hexShape, Hex27TriquadraticLagrange) { checkShape<27>(2); }


// Every face: the corners lie on the face's plane r, s or t = +-1 and run
// counter-clockwise seen from outside (their cross product points away
// from the centre); mid-edge nodes sit at the midpoints of their corners,
// the centre node at the face's centre; on the face, the hexahedron's
// functions of the face's nodes are the quad's functions (so a face load
// integrated with quadShape is the element's), the others vanish.
TEST(hexShape, FacesAreOutwardQuads)
{
    for (int face = 0; face < 6; ++face)
    {
        const std::vector<int> f = hexFaceNodes(27, face);
        ASSERT_EQ(f.size(), 9u);
        EXPECT_EQ(f[8], 20 + face);
        const std::vector<int> f8 = hexFaceNodes(8, face);
        EXPECT_EQ(f8, std::vector<int>(f.begin(), f.begin() + 4));
        const Eigen::Vector3d c = hexShape<27>::node(20 + face);
        const auto x = [&f](int k) { return hexShape<27>::node(f[k]); };
        const Eigen::Vector3d n = (x(1) - x(0)).cross(x(3) - x(0));
        EXPECT_GT(n.dot(c), 0) << "face " << face;
        for (int k = 0; k < 4; ++k)
        {
            EXPECT_LT((x(4 + k) - 0.5*(x(k) + x((k + 1) % 4))).norm(), 1e-15)
                << "face " << face << " edge " << k;
        }
        EXPECT_LT((c - 0.25*(x(0) + x(1) + x(2) + x(3))).norm(), 1e-15);
        // Restriction to the face at the quad point (xi, eta)
        const double xi = 0.31, eta = -0.62;
        const vecX Nq = quadShapeValues(9, xi, eta);
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        for (int k = 0; k < 9; ++k)
        {
            p += Nq(k)*x(k);
        }
        const vecX Nh = hexShapeValues(27, p(0), p(1), p(2));
        std::vector<bool> on(27, false);
        for (int k = 0; k < 9; ++k)
        {
            on[f[k]] = true;
            EXPECT_NEAR(Nh(f[k]), Nq(k), 1e-14) << "face " << face;
        }
        for (int a = 0; a < 27; ++a)
        {
            if (!on[a]) EXPECT_NEAR(Nh(a), 0, 1e-14);
        }
    }
    EXPECT_THROW(hexFaceNodes(27, 6), std::invalid_argument);
    EXPECT_THROW(hexFaceNodes(20, 0), std::invalid_argument);
    EXPECT_THROW(hexShapeValues(20, 0, 0, 0), std::invalid_argument);
}
