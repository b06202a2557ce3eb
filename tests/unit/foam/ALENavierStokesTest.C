/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Operator-level tests of the ALE fluid (ALENavierStokes.H) on scratch
    meshes of a few cells, so that a failure points at the fluid's
    equations, not at a tutorial:
    - the Newton matrix K = -dr/dq against central differences of the
      residual r(q), scaled per row (max_j |K_ij - K_fd,ij| / max_j
      |K_ij|), on a skewed mesh (non-orthogonal faces), for the transient
      compressible equations with linear convection and corrected
      Laplacian on a moving mesh, and for the steady incompressible ones
      with upwind convection and the uncorrected Laplacian;
    - a uniform flow on a moving mesh leaves every residual at round-off
      (the space conservation law: the mesh fluxes sum to the volume
      change of each cell; slip walls carry no shear);
    - a uniform pressure in an axisymmetric wedge is in equilibrium: the
      hoop term p/r balances the net pressure force on the wedge faces,
      cell by cell.
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "scratchCase.H"
#include "fluidTestMeshes.H"
#include "../fdCheck.H"
#include <gtest/gtest.h>
#include <random>

using namespace form;
using namespace form::test;

namespace
{

// Dense Newton matrix of the fluid alone (no solid: indices from 0)
matX denseMatrix(const std::vector<coupledBlock::triplet>& K, int n)
{
    matX A = matX::Zero(n, n);
    for (const auto& t : K) A(t.row(), t.col()) += t.value();
    return A;
}

// The largest row-scaled difference between K and central differences of
// -r (step h), at the fluid's current unknowns
double newtonMatrixError(Foam::ALENavierStokes& f, double t, double h)
{
    const vecX none;
    vecX fext, r;
    std::vector<coupledBlock::triplet> triplets;
    f.evaluate(t, none, fext, r, &triplets);
    const int n = f.nUnknowns();
    const matX K = denseMatrix(triplets, n);
    matX Kfd(n, n);
    for (int j = 0; j < n; ++j)
    {
        vecX e = vecX::Zero(n);
        e(j) = h;
        vecX rp, rm;
        f.addToUnknowns(e);
        f.evaluate(t, none, fext, rp, nullptr);
        f.addToUnknowns(-2*e);
        f.evaluate(t, none, fext, rm, nullptr);
        f.addToUnknowns(e);
        Kfd.col(j) = -(rp - rm)/(2*h);
    }
    double err = 0;
    for (int i = 0; i < n; ++i)
    {
        const double scale = K.row(i).cwiseAbs().maxCoeff();
        EXPECT_GT(scale, 0) << f.unknownName(i);
        err = std::max(err, (K.row(i) - Kfd.row(i)).cwiseAbs().maxCoeff()/scale);
    }
    return err;
}

// Settings of a laminar fluid (incompressible, no mesh motion)
Foam::ALEFluidSettings laminar(double rho, double mu)
{
    Foam::ALEFluidSettings s;
    s.rho = rho;
    s.mu = mu;
    return s;
}

// A random state: velocities and pressures of order 1
vecX randomState(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uni(-1, 1);
    vecX x(n);
    for (int i = 0; i < n; ++i) x(i) = uni(rng);
    return x;
}

} // namespace


TEST(ALENavierStokes, NewtonMatrixTransientCompressibleMovingMesh)
{
    scratchCase c
    (
        fluidCaseFiles("fluid", skewedMesh, "Euler", "Gauss linear",
                       "Gauss linear corrected", channelU, channelP),
        {"fluid"}
    );
    Foam::ALEFluidSettings set = laminar(1.3, 0.1);
    set.incompressible = false;
    set.bulkModulus = 50;
    set.meshMotion = "oscillating";
    set.amplitude = Foam::vector(0.05, 0.04, 0);
    set.period = 1;
    Foam::ALENavierStokes f(c.runTime(), c.mesh(), set);
    ASSERT_FALSE(f.steady());
    const int n = f.nUnknowns();
    ASSERT_EQ(n, 12*3);
    // a committed state, then a trial state of the step 0.1 -> 0.2
    f.addToUnknowns(randomState(n, 1));
    f.commit(vecX());
    f.beginIncrement(0.1, 0.2, vecX());
    f.addToUnknowns(0.3*randomState(n, 2));
    const double err = newtonMatrixError(f, 0.2, 1e-6);
    EXPECT_TRUE(test::fdError("ALE fluid Newton matrix (transient, compressible, moving mesh)", err, 5e-9));
}


TEST(ALENavierStokes, NewtonMatrixSteadyIncompressibleUpwind)
{
    scratchCase c
    (
        fluidCaseFiles("fluid", skewedMesh, "steadyState", "Gauss upwind",
                       "Gauss linear uncorrected", channelU, channelP),
        {"fluid"}
    );
    Foam::ALEFluidSettings set = laminar(1, 0.05);
    Foam::ALENavierStokes f(c.runTime(), c.mesh(), set);
    ASSERT_TRUE(f.steady());
    const int n = f.nUnknowns();
    f.commit(vecX());
    f.beginIncrement(0, 1, vecX());
    // velocities away from zero flux (upwind switches there)
    vecX x = randomState(n, 3);
    for (int i = 0; i < n; i += 3) x(i) += 2;
    f.addToUnknowns(x);
    const double err = newtonMatrixError(f, 1, 1e-6);
    EXPECT_TRUE(test::fdError("ALE fluid Newton matrix (steady, incompressible, upwind)", err, 5e-9));
}


TEST(ALENavierStokes, UniformFlowOnAMovingMeshStaysUniform)
{
    const std::string U =
        "internalField uniform (1 0 0);\nboundaryField {\n"
        " inlet { type fixedValue; value uniform (1 0 0); }\n"
        " outlet { type zeroGradient; }\n"
        " walls { type slip; }\n"
        " frontAndBack { type empty; }\n}\n";
    const std::string p =
        "internalField uniform 0;\nboundaryField {\n"
        " inlet { type zeroGradient; }\n"
        " outlet { type fixedValue; value uniform 0; }\n"
        " walls { type zeroGradient; }\n"
        " frontAndBack { type empty; }\n}\n";
    // a rectangle (slip walls must be straight for a uniform flow along them)
    const std::string box =
        "vertices ((0 0 0) (2 0 0) (2 1 0) (0 1 0)"
        " (0 0 0.1) (2 0 0.1) (2 1 0.1) (0 1 0.1));\n"
        "blocks (hex (0 1 2 3 4 5 6 7) (5 4 1) simpleGrading (1 1 1));\n"
        "boundary (\n"
        " inlet { type patch; faces ((0 4 7 3)); }\n"
        " outlet { type patch; faces ((1 2 6 5)); }\n"
        " walls { type wall; faces ((0 1 5 4) (3 7 6 2)); }\n"
        " frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }\n);\n";
    scratchCase c
    (
        fluidCaseFiles("fluid", box, "Euler", "Gauss linear",
                       "Gauss linear corrected", U, p),
        {"fluid"}
    );
    Foam::ALEFluidSettings set = laminar(1, 0.1);
    set.meshMotion = "oscillating";
    set.amplitude = Foam::vector(0.1, 0.08, 0);
    set.period = 1;
    Foam::ALENavierStokes f(c.runTime(), c.mesh(), set);
    const Foam::pointField before(c.mesh().points());
    f.commit(vecX());
    double worst = 0;
    for (const double t1 : {0.1, 0.2, 0.3})
    {
        f.beginIncrement(t1 - 0.1, t1, vecX());
        vecX fext, r;
        f.evaluate(t1, vecX(), fext, r, nullptr);
        ASSERT_GT(f.residualScale(), 0);
        worst = std::max(worst, r.cwiseAbs().maxCoeff()/f.residualScale());
        f.commit(vecX());
    }
    // the mesh moved (by up to 0.1)
    EXPECT_GT(Foam::max(Foam::mag(c.mesh().points() - before)), 0.05);
    std::cout << "    uniform flow on a moving mesh: largest residual / scale "
              << worst << '\n';
    EXPECT_LT(worst, 1e-13);     // round-off
}


TEST(ALENavierStokes, UniformPressureInAWedgeIsInEquilibrium)
{
    // An axisymmetric wedge (axis x, 5 degrees), 0.5 <= r <= 2
    const std::string wedge =
        "vertices ((0.5 0.49952411 -0.02180969) (0.5 1.99809644 -0.08723877)"
        " (0 1.99809644 -0.08723877) (0 0.49952411 -0.02180969)"
        " (0.5 0.49952411 0.02180969) (0.5 1.99809644 0.08723877)"
        " (0 1.99809644 0.08723877) (0 0.49952411 0.02180969));\n"
        "blocks (hex (0 1 2 3 4 5 6 7) (6 3 1) simpleGrading (1 1 1));\n"
        "boundary (\n"
        " inlet { type patch; faces ((0 4 7 3)); }\n"
        " outlet { type patch; faces ((1 2 6 5)); }\n"
        " walls { type wall; faces ((0 1 5 4) (3 7 6 2)); }\n"
        " front { type wedge; faces ((0 3 2 1)); }\n"
        " back { type wedge; faces ((4 5 6 7)); }\n);\n";
    const std::string U =
        "internalField uniform (0 0 0);\nboundaryField {\n"
        " inlet { type noSlip; }\n outlet { type noSlip; }\n"
        " walls { type noSlip; }\n"
        " front { type wedge; }\n back { type wedge; }\n}\n";
    const std::string p =
        "internalField uniform 5;\nboundaryField {\n"
        " inlet { type fixedValue; value uniform 5; }\n"
        " outlet { type zeroGradient; }\n walls { type zeroGradient; }\n"
        " front { type wedge; }\n back { type wedge; }\n}\n";
    scratchCase c
    (
        fluidCaseFiles("fluid", wedge, "steadyState", "Gauss linear",
                       "Gauss linear corrected", U, p),
        {"fluid"}
    );
    Foam::ALEFluidSettings set = laminar(1, 0.1);
    Foam::ALENavierStokes f(c.runTime(), c.mesh(), set);
    f.commit(vecX());
    f.beginIncrement(0, 1, vecX());
    vecX fext, r;
    f.evaluate(1, vecX(), fext, r, nullptr);
    // the pressure force on one cell's faces (its scale): p |S| ~ 5 x face area
    const double scale = 5*Foam::max(c.mesh().magSf()).value()*f.depthFactor();
    std::cout << "    uniform pressure in a wedge: largest residual / (p |S_f|) "
              << r.cwiseAbs().maxCoeff()/scale << '\n';
    EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-12*scale);
}
