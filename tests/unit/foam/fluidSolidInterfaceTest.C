/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Operator-level tests of the fluid-solid interface (fluidSolidInterface.H)
    on a scratch case of two regions whose meshes do not match on the
    interface (3 fluid faces on 2 solid Q9 edges):
    - the interpolations of the interface's points and face centres on the
      solid's edges are partitions of unity (sum_a N_a = 1) with no gap;
    - the interface points follow a solid displacement quadratic along the
      edge exactly (eq. 1: the Q9 edge is quadratic), the fixed walls stay
      and the interior follows by the harmonic extension, between them;
    - the mesh equations (4), assembled per motion unit, are the discrete
      Laplace equations of every free 3D point (checked point by point
      from the mesh's edges), with side walls fixed or sliding; their
      matrix is their exact derivative (they are linear); the mesh
      unknowns of moved points are the unknowns that moved them;
    - the fluid's total force reaches the solid exactly, and the power the
      fluid exerts on the wall (interface face velocities, eq. 2, times the
      face forces) is the power the solid receives (nodal velocities times
      the nodal forces, eq. 3).
\*---------------------------------------------------------------------------*/
#include "fluidSolidInterface.H"
#include "polyMeshToFeMesh.H"
#include "scratchCase.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <random>
#include <sstream>

using namespace form;
using namespace form::test;
using Foam::labelList;

namespace
{

std::string box
(
    double y0, double y1, int nx, int ny,
    const std::string& bottom, const std::string& top, const std::string& sides
)
{
    std::ostringstream os;
    os  << "vertices ((0 " << y0 << " 0) (1 " << y0 << " 0) (1 " << y1
        << " 0) (0 " << y1 << " 0) (0 " << y0 << " 0.1) (1 " << y0
        << " 0.1) (1 " << y1 << " 0.1) (0 " << y1 << " 0.1));\n"
        << "blocks (hex (0 1 2 3 4 5 6 7) (" << nx << ' ' << ny
        << " 1) simpleGrading (1 1 1));\n"
        << "boundary (\n " << bottom << " { type wall; faces ((0 1 5 4)); }\n "
        << top << " { type wall; faces ((3 7 6 2)); }\n "
        << sides << " { type wall; faces ((0 4 7 3) (1 2 6 5)); }\n"
        << " frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }\n);\n";
    return os.str();
}

// The fluid (3 x 3 cells above y = 0, wetted patch 'wet') and the solid
// (2 x 1 Q9 below it, wetted face set 'top')
std::map<std::string, std::string> interfaceCase()
{
    const std::string schemes = foamHeader("dictionary", "fvSchemes")
        + "ddtSchemes { default steadyState; } gradSchemes { default Gauss linear; }"
          " divSchemes { default none; } laplacianSchemes { default Gauss linear corrected; }"
          " interpolationSchemes { default linear; } snGradSchemes { default corrected; }\n";
    const std::string solution = foamHeader("dictionary", "fvSolution");
    return
    {
        {"system/controlDict", foamHeader("dictionary", "controlDict")
            + "application formFoam; startFrom startTime; startTime 0;"
              " stopAt endTime; endTime 1; deltaT 1;"
              " writeControl timeStep; writeInterval 1;\n"},
        {"system/fluid/blockMeshDict", foamHeader("dictionary", "blockMeshDict")
            + box(0, 1, 3, 3, "wet", "top", "walls")},
        {"system/solid/blockMeshDict", foamHeader("dictionary", "blockMeshDict")
            + box(-0.2, 0, 2, 1, "bottom", "top", "sides")},
        {"system/fluid/fvSchemes", schemes},
        {"system/fluid/fvSolution", solution},
        {"system/solid/fvSchemes", schemes},
        {"system/solid/fvSolution", solution}
    };
}

struct interfaceFixture
{
    explicit interfaceFixture
    (
        const Foam::wordList& slip = {},
        const Foam::meshDiffusivity& k = Foam::meshDiffusivity()
    )
    :
        itf(fluid, points0, {"wet"}, solid, {"top"}, slip, "fluidProperties", k)
    {}
    scratchCase c{interfaceCase(), {"fluid", "solid"}};
    Foam::polyMeshToFeMesh solid{c.mesh("solid"), 2, "solidProperties", 9, "Q9P3", "steel"};
    Foam::fvMesh& fluid = c.mesh("fluid");
    Foam::pointField points0{fluid.points()};
    Foam::fluidSolidInterface itf;
};

vecX randomVector(int n, std::mt19937& rng, double a)
{
    std::uniform_real_distribution<double> uni(-a, a);
    vecX v(n);
    for (int i = 0; i < n; ++i) v(i) = uni(rng);
    return v;
}

std::string at(const Foam::point& p)
{
    return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

double sum(const std::vector<double>& v)
{
    double s = 0;
    for (const double x : v) s += x;
    return s;
}

} // namespace


TEST(fluidSolidInterface, InterpolationsArePartitionsOfUnity)
{
    interfaceFixture f;
    ASSERT_EQ(f.itf.faces().size(), 3);
    ASSERT_EQ(f.itf.nPoints(), 4);
    for (const auto& p : f.itf.faceInterpolation())
    {
        EXPECT_NEAR(sum(p.N), 1, 1e-14);
        EXPECT_LT(p.gap, 1e-12);
    }
    for (const auto& p : f.itf.pointInterpolation())
    {
        EXPECT_NEAR(sum(p.N), 1, 1e-14);
        EXPECT_LT(p.gap, 1e-12);
    }
}


TEST(fluidSolidInterface, MeshFollowsAQuadraticDisplacementExactly)
{
    interfaceFixture f;
    const matX& X = f.solid.feMesh().X;
    const auto ux = [](double x) { return 0.01*(x*x - 0.3*x); };
    const auto uy = [](double x) { return 0.02*(1 + x - x*x); };
    vecX U(2*X.rows());
    for (int a = 0; a < X.rows(); ++a)
    {
        U(2*a) = ux(X(a, 0));
        U(2*a + 1) = uy(X(a, 0));
    }
    const Foam::pointField moved(f.itf.points(U, f.itf.harmonicDisplacement(U)));
    int onInterface = 0, onWalls = 0, inside = 0;
    for (Foam::label p = 0; p < moved.size(); ++p)
    {
        const Foam::point& x0 = f.points0[p];
        const Foam::vector d = moved[p] - x0;
        if (x0.y() < 1e-12)
        {
            ++onInterface;
            EXPECT_NEAR(d.x(), ux(x0.x()), 1e-15) << "point " << at(x0);
            EXPECT_NEAR(d.y(), uy(x0.x()), 1e-15) << "point " << at(x0);
        }
        else if (x0.x() < 1e-12 || x0.x() > 1 - 1e-12 || x0.y() > 1 - 1e-12)
        {
            ++onWalls;
            EXPECT_EQ(Foam::mag(d), 0) << "point " << at(x0);
        }
        else
        {
            ++inside;
            // harmonic: between the walls' 0 and the interface's values
            EXPECT_GT(d.y(), 0) << "point " << at(x0);
            EXPECT_LT(d.y(), 0.02*1.25) << "point " << at(x0);
        }
        EXPECT_EQ(d.z(), 0);
    }
    EXPECT_EQ(onInterface, 8);      // 4 in-plane points, front and back
    EXPECT_EQ(inside, 8);
    EXPECT_EQ(onWalls, 16);
}


TEST(fluidSolidInterface, ForcesAndPowerReachTheSolidExactly)
{
    interfaceFixture f;
    const int nDofs = 2*int(f.solid.feMesh().X.rows());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    Foam::vectorField F(f.itf.faces().size());
    for (Foam::vector& v : F) v = Foam::vector(uni(rng), uni(rng), 0);
    vecX v(nDofs);
    for (int i = 0; i < nDofs; ++i) v(i) = uni(rng);

    vecX fn = vecX::Zero(nDofs);
    f.itf.addForces(F, 1, fn);
    const Foam::vector total = Foam::sum(F);
    EXPECT_NEAR(fn(Eigen::seq(0, nDofs - 1, 2)).sum(), total.x(), 1e-14);
    EXPECT_NEAR(fn(Eigen::seq(1, nDofs - 1, 2)).sum(), total.y(), 1e-14);

    const Foam::vectorField uf(f.itf.faceVelocities(v));
    double fluidPower = 0;
    forAll(uf, j) fluidPower += uf[j] & F[j];
    EXPECT_NEAR(v.dot(fn), fluidPower, 1e-14*(1 + std::abs(fluidPower)));
    // nodes off the interface receive nothing
    for (int d = 0; d < nDofs; ++d)
    {
        const auto dofs = f.itf.dofs();
        if (std::find(dofs.begin(), dofs.end(), d) == dofs.end())
        {
            EXPECT_EQ(fn(d), 0) << "dof " << d;
        }
    }
}


TEST(fluidSolidInterface, MeshEquationsAreEveryFreePointsLaplaceEquation)
{
    // uniform diffusivity, and the inverse distance (exponent 1.5) from the
    // interface y = 0 (r_0 = 1/3, its faces' length): k = (r_0/max(y, r_0))^1.5
    // at the edge's midpoint
    Foam::meshDiffusivity inverse;
    inverse.type = "inverseDistance";
    inverse.exponent = 1.5;
    for (const int variant : {0, 1, 2})
    {
        const bool slip = variant == 1;
        const bool stiff = variant == 2;
        interfaceFixture f
        (
            slip ? Foam::wordList{"walls"} : Foam::wordList{},
            stiff ? inverse : Foam::meshDiffusivity()
        );
        SCOPED_TRACE
        (
            stiff ? "inverse distance" : slip ? "side walls sliding" : "side walls fixed"
        );
        const int nDofs = 2*int(f.solid.feMesh().X.rows());
        std::mt19937 rng(11);
        const vecX U = randomVector(nDofs, rng, 0.05);
        const vecX d = f.itf.harmonicDisplacement(U);
        EXPECT_EQ(d.size(), f.itf.nMeshUnknowns());
        // 8 interior points' 4 units (x, y), and 2 x 2 side wall units
        // sliding in y
        EXPECT_EQ(f.itf.nMeshUnknowns(), slip ? 12 : 8);
        const Foam::pointField x(f.itf.points(U, d));
        const double r0 = f.itf.minFaceLength();
        EXPECT_NEAR(r0, 1/3.0, 1e-6);
        // Every free 3D point p, component c: sum over its edges of
        // (d_q - d_p) . e_c / |edge|^2 = 0 (the reference's edge lengths)
        labelList unitOfPoint(x.size(), -1);
        forAll(f.itf.motionUnits(), u)
        {
            for (const Foam::label p : f.itf.motionUnits()[u]) unitOfPoint[p] = u;
        }
        int checked = 0;
        forAll(x, p)
        {
            for (Foam::label c = 0; c < 2; ++c)
            {
                if (f.itf.meshUnknown(unitOfPoint[p], c) < 0) continue;
                double sum = 0, size = 0;
                for (const Foam::label e : f.fluid.pointEdges()[p])
                {
                    const Foam::label q = f.fluid.edges()[e].otherVertex(p);
                    Foam::vector l = f.points0[q] - f.points0[p];
                    l.z() = 0;
                    if (Foam::mag(l) < 1e-12) continue;
                    const double y = 0.5*(f.points0[p].y() + f.points0[q].y());
                    const double k =
                        stiff ? std::pow(r0/std::max(y, r0), 1.5) : 1;
                    const double term =
                        k*((x[q] - f.points0[q]) - (x[p] - f.points0[p]))
                      & f.itf.direction(p, c);
                    sum += term/Foam::magSqr(l);
                    size += std::abs(term)/Foam::magSqr(l);
                }
                EXPECT_LT(std::abs(sum), 1e-13*size) << "point " << at(f.points0[p]);
                ++checked;
            }
        }
        EXPECT_EQ(checked, 2*f.itf.nMeshUnknowns());
        vecX r;
        f.itf.meshEquations(U, d, r, nDofs, nullptr);
        EXPECT_LT(r.norm(), 1e-14*U.norm());
        // (points of size 1: their round-off)
        EXPECT_LT((f.itf.meshUnknowns(x) - d).lpNorm<Eigen::Infinity>(), 1e-15);
    }
}


TEST(fluidSolidInterface, MeshEquationsMatrixIsTheirDerivative)
{
    interfaceFixture f({"walls"});
    const int nDofs = 2*int(f.solid.feMesh().X.rows());
    const int nM = f.itf.nMeshUnknowns();
    std::mt19937 rng(5);
    const vecX U = randomVector(nDofs, rng, 0.05);
    const vecX d = randomVector(nM, rng, 0.05);
    const vecX dU = randomVector(nDofs, rng, 0.01);
    const vecX dd = randomVector(nM, rng, 0.01);
    vecX r0, r1;
    std::vector<Eigen::Triplet<double>> K;
    f.itf.meshEquations(U, d, r0, nDofs, &K);
    f.itf.meshEquations(U + dU, d + dd, r1, nDofs, nullptr);
    Eigen::SparseMatrix<double> Km(nDofs + nM, nDofs + nM);
    Km.setFromTriplets(K.begin(), K.end());
    vecX dq(nDofs + nM);
    dq << dU, dd;
    const vecX Kdq = (Km*dq).tail(nM);
    // r linear: r1 - r0 = -K dq exactly (to round-off)
    EXPECT_LT((r1 - r0 + Kdq).norm(), 1e-14*Kdq.norm());
    EXPECT_GT(Kdq.norm(), 0);
    // the rows of the mesh unknowns only
    EXPECT_EQ((Km*dq).head(nDofs).norm(), 0);
}
