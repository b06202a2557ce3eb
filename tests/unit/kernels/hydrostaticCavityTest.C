// The hydrostatic fluid cavity (hydrostaticCavity.H): its volume against
// exact volumes, the derivatives of the volume and the block's tangent
// against central differences, and bad input.
#include "hydrostaticCavity.H"
#include "contactTestTools.H"
#include "structuredQuadMesh.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <random>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolCavityG = 5e-9;
constexpr double fdTolCavityH = 5e-9;
constexpr double fdTolCavityK = 5e-8;
}

using namespace form;

namespace
{

// A plate [0, R] x [h, h + t], 8 x 1 nine-node elements; its bottom runs
// in +x (counter-clockwise around the plate), the cavity below it
feMesh plate(double R = 50, double h = 2, double t = 1)
{
    return structuredQuadMesh
    (
        {{{0, h}, {R, h}, {R, h + t}, {0, h + t}}}, 8, 1, 9, "Q9P3", "steel"
    );
}

hydrostaticCavitySpec spec(bool volumeControl)
{
    hydrostaticCavitySpec s;
    s.faceSets = {"bottom"};
    s.bulkModulus = 1500;
    s.initialVolume = 2e4;
    if (volumeControl) s.injectedVolume = [](double t) { return 300*t; };
    else s.pressure = [](double t) { return 2*t; };
    s.referenceModulus = 2e5;
    return s;
}

} // namespace


// Flat: V = pi R^2 h (axisymmetric), R h (plane strain). Bulged by the
// paraboloid u_y = c (1 - r^2/R^2), which the quadratic edges reproduce
// exactly: + c pi R^2/2 (axisymmetric), + 2 c R/3 (plane strain)
TEST(hydrostaticCavity, volumeOfFlatAndBulgedSurfaces)
{
    const double R = 50, h = 2, c = 3;
    const feMesh mesh = plate(R, h);
    vecX U = vecX::Zero(2*mesh.nNodes());
    for (int a = 0; a < mesh.nNodes(); ++a)
    {
        const double r = mesh.X(a, 0)/R;
        U(2*a + 1) = c*(1 - r*r);
    }
    const hydrostaticCavity axi
        (mesh, analysisType::axisymmetric, spec(true));
    const hydrostaticCavity pln
        (mesh, analysisType::planeStrain, spec(true));
    const vecX zero = vecX::Zero(U.size());
    EXPECT_NEAR(axi.wettedVolume(zero), M_PI*R*R*h, 1e-9*R*R*h);
    EXPECT_NEAR(pln.wettedVolume(zero), R*h, 1e-12*R*h);
    EXPECT_NEAR(axi.volume(U) - axi.volume(zero), c*M_PI*R*R/2, 1e-9*R*R*c);
    EXPECT_NEAR(pln.volume(U) - pln.volume(zero), 2*c*R/3, 1e-12*R*c);
    EXPECT_NEAR(axi.volume(zero), 2e4, 1e-9);
    EXPECT_NEAR(axi.wettedArea(zero), M_PI*R*R, 1e-9*R*R);
}


// dV/du and d2V/du2 against central differences of V (both analyses,
// a random wavy surface)
TEST(hydrostaticCavity, volumeDerivativesMatchFiniteDifferences)
{
    const feMesh mesh = plate();
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-1, 1);
    vecX U(2*mesh.nNodes());
    for (int q = 0; q < U.size(); ++q) U(q) = 0.3*u(gen);
    for (const analysisType a :
        {analysisType::axisymmetric, analysisType::planeStrain})
    {
        const hydrostaticCavity cav(mesh, a, spec(true));
        std::vector<int> dofs;
        vecX g;
        matX H;
        cav.wettedVolume(U, &dofs, &g, &H);
        const double eps = 1e-5;
        double errG = 0, errH = 0;
        for (std::size_t i = 0; i < dofs.size(); ++i)
        {
            vecX Up = U, Um = U;
            Up(dofs[i]) += eps;
            Um(dofs[i]) -= eps;
            errG = std::max
            (
                errG,
                std::abs
                (
                    g(i) - (cav.wettedVolume(Up) - cav.wettedVolume(Um))/(2*eps)
                )
            );
            std::vector<int> d;
            vecX gp, gm;
            cav.wettedVolume(Up, &d, &gp);
            cav.wettedVolume(Um, &d, &gm);
            errH = std::max
            (
                errH, ((gp - gm)/(2*eps) - H.col(i)).cwiseAbs().maxCoeff()
            );
        }
        EXPECT_TRUE(test::fdError("hydrostaticCavity volume gradient", errG/g.cwiseAbs().maxCoeff(), fdTolCavityG)) << analysisTypeName(a);
        EXPECT_TRUE(test::fdError("hydrostaticCavity volume Hessian", errH/H.cwiseAbs().maxCoeff(), fdTolCavityH)) << analysisTypeName(a);
        EXPECT_GT(H.cwiseAbs().maxCoeff(), 0);
    }
}


// The block's tangent (pressure load stiffness, the volume equation, the
// compressibility) against central differences, volume and pressure
// control; the pressure load is p dV/du
TEST(hydrostaticCavity, tangentMatchesFiniteDifferences)
{
    const feMesh mesh = plate();
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    vecX U(2*mesh.nNodes());
    for (int q = 0; q < U.size(); ++q) U(q) = 0.3*u(gen);
    for (const bool volumeControl : {true, false})
    {
        hydrostaticCavity cav
            (mesh, analysisType::axisymmetric, spec(volumeControl));
        vecX dp(1);
        dp << 3.7;
        cav.addToUnknowns(dp);
        const double t = 0.6;
        vecX R;
        matX K;
        test::contactResidual(cav, t, U, R, &K);
        const matX Kfd = test::contactTangentFD(cav, t, U, 1e-6);
        const double scale = K.cwiseAbs().maxCoeff();
        EXPECT_TRUE(test::fdError("hydrostaticCavity tangent", (K - Kfd).cwiseAbs().maxCoeff()/scale, fdTolCavityK))
            << "volume control " << volumeControl;
        // Symmetric under volume control (a conservative load)
        if (volumeControl)
        {
            EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12*scale);
            EXPECT_NEAR
            (
                R(R.size() - 1),
                cav.volume(U) - 2.018e4*std::exp(-3.7/1500), 1e-8
            );
        }
        // The nodal forces are p dV/du
        std::vector<int> dofs;
        vecX g;
        cav.wettedVolume(U, &dofs, &g);
        for (std::size_t i = 0; i < dofs.size(); ++i)
        {
            EXPECT_NEAR(R(dofs[i]), 3.7*g(i), 1e-12*scale);
        }
    }
}


TEST(hydrostaticCavity, badInputIsAnInputError)
{
    const feMesh mesh = plate();
    const auto make = [&](hydrostaticCavitySpec s,
                          analysisType a = analysisType::axisymmetric)
    {
        hydrostaticCavity c(mesh, a, std::move(s));
    };
    hydrostaticCavitySpec s = spec(true);
    s.faceSets.clear();
    EXPECT_THROW(make(s), inputError);          // no interface with a solid
    s = spec(true);
    s.faceSets = {"nowhere"};
    EXPECT_THROW(make(s), inputError);
    s = spec(true);
    s.bulkModulus = 0;
    EXPECT_THROW(make(s), inputError);
    s.bulkModulus = -5;
    EXPECT_THROW(make(s), inputError);
    s = spec(true);
    s.initialVolume = -1;
    EXPECT_THROW(make(s), inputError);
    s = spec(true);
    s.injectedVolume = nullptr;
    EXPECT_THROW(make(s), inputError);          // neither volume nor pressure
    s = spec(true);
    s.bulkModulus = std::numeric_limits<double>::infinity();
    EXPECT_NO_THROW(make(s));                   // incompressible
    EXPECT_THROW(make(spec(true), analysisType::solid3D), inputError);
}
