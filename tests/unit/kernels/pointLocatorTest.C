// The point locator inverts the isoparametric map of curved quads and
// hexahedra: a point mapped from random natural coordinates is found in
// its element with those coordinates, interpolation reproduces a field
// of the element's order, and points outside every element are not found.
#include "pointLocator.H"
#include "formError.H"
#include "hexShape.H"
#include "quadShape.H"
#include <gtest/gtest.h>
#include <random>

using namespace form;

namespace
{

// Two elements side by side on [0,2] x [0,1] (x [0,1]); the nodes moved
// by a smooth map that curves the edges: X = x + a sin(x) cos(y) ...
feMesh curvedMesh(int nDim, int nn)
{
    feMesh m;
    m.nDim = nDim;
    elementBlock b;
    b.nodesPerElement = nn;
    std::vector<Eigen::VectorXd> pts;
    const auto warp = [nDim](Eigen::VectorXd p)
    {
        Eigen::VectorXd q = p;
        q(0) += 0.1*std::sin(2*p(1)) + 0.05*p(0)*p(0);
        q(1) += 0.08*std::sin(3*p(0));
        if (nDim == 3) q(2) += 0.07*std::cos(2*p(0))*p(1) + 0.1*p(2)*p(2);
        return q;
    };
    for (int e = 0; e < 2; ++e)
    {
        for (int a = 0; a < nn; ++a)
        {
            Eigen::VectorXd xi(nDim);
            if (nDim == 2) xi << quadShape<9>::nodeR(a), quadShape<9>::nodeS(a);
            else xi = nn == 8 ? hexShape<8>::node(a) : hexShape<27>::node(a);
            Eigen::VectorXd p = 0.5*(xi.array() + 1).matrix();
            p(0) += e;
            p = warp(p);
            // shared nodes: merge by position
            int id = -1;
            for (std::size_t k = 0; k < pts.size(); ++k)
            {
                if ((pts[k] - p).norm() < 1e-12) id = int(k);
            }
            if (id < 0)
            {
                id = int(pts.size());
                pts.push_back(p);
            }
            b.connectivity.push_back(id);
        }
    }
    m.X.resize(pts.size(), nDim);
    for (std::size_t k = 0; k < pts.size(); ++k) m.X.row(k) = pts[k];
    m.blocks.push_back(b);
    return m;
}

void checkLocate(int nDim, int nn)
{
    const feMesh m = curvedMesh(nDim, nn);
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-0.999, 0.999);
    vecX N;
    matX dN;
    for (int k = 0; k < 40; ++k)
    {
        const int e = k % 2;
        vecX xi(nDim);
        for (int i = 0; i < nDim; ++i) xi(i) = u(gen);
        elementShape(nDim, nn, xi, N, dN);
        vecX x = vecX::Zero(nDim);
        for (int a = 0; a < nn; ++a)
        {
            x += N(a)*m.X.row(m.blocks[0].nodes(e)[a]).transpose();
        }
        const pointLocation loc = locatePoint(m, x);
        ASSERT_TRUE(loc.found()) << nDim << "D " << nn << " point " << k;
        EXPECT_EQ(loc.element, e);
        EXPECT_NEAR(loc.r, xi(0), 1e-10);
        EXPECT_NEAR(loc.s, xi(1), 1e-10);
        if (nDim == 3) EXPECT_NEAR(loc.t, xi(2), 1e-10);
        // The nodal coordinates interpolate back to the point
        const vecX y = interpolate(m, loc, m.X);
        EXPECT_NEAR((y - x).norm(), 0, 1e-12);
    }
    // Outside: beyond the far end and above
    vecX far = m.X.colwise().maxCoeff().transpose();
    far(0) += 0.5;
    EXPECT_FALSE(locatePoint(m, far).found());
}

} // anonymous namespace


TEST(pointLocator, curvedQuad9)
{
    checkLocate(2, 9);
}

TEST(pointLocator, curvedHex27)
{
    checkLocate(3, 27);
}

TEST(pointLocator, hex8)
{
    checkLocate(3, 8);
}

TEST(pointLocator, unknownShapeThrows)
{
    vecX N;
    matX dN;
    EXPECT_THROW(elementShape(3, 20, vecX::Zero(3), N, dN), numericalError);
}
