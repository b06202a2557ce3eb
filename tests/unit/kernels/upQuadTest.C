// upQuad (Q4, Q9, Q4P1, Q9P3): consistent tangent against central
// differences of f_int for every element type x {planeStrain, axisymmetric}
// x {linearElastic, neoHookean} at random distorted geometry and random large
// displacements; exact linearity for linearElastic; rigid-body invariance;
// mass matrix; averaged results; inversion detection; the tracked pressure
// of the mixed elements (trackedPressureCheck.H).
#include "solidElement.H"
#include "formError.H"
#include "materialInput.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include "../fdCheck.H"
#include "trackedPressureCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolElemElastic = 2e-8;
constexpr double fdTolElemPlastic = 1e-8;
constexpr double fdTolTracked = 2e-8;
}

using namespace form;

namespace
{
const std::vector<std::string> types{"Q4", "Q9", "Q4P1", "Q9P3"};
const std::vector<analysisType> analyses
{
    analysisType::planeStrain, analysisType::axisymmetric
};

matX randomElement(int nNodes, std::mt19937& rng)
{
    // x0 = 1: the element lies at R in about [0.8, 2.2] (axisymmetric)
    return nNodes == 4
        ? test::randomQuad<4>(rng, 1.0, -0.5, 1.0)
        : test::randomQuad<9>(rng, 1.0, -0.5, 1.0);
}

struct evaluation
{
    vecX f;
    matX K;
};

evaluation evaluate(const solidElement& el, const matX& X, const matX& u,
                    const material& mat, int id = 0)
{
    std::vector<materialState> s0(el.nQuadrature(), mat.initialState()), s1;
    evaluation e;
    EXPECT_TRUE(el.compute(X, u, mat, s0, s1, e.f, &e.K, id));
    return e;
}

// Central differences of f_int with respect to the nodal displacements
matX fdTangent(const solidElement& el, const matX& X, const matX& u,
               const material& mat, double h)
{
    const int n = el.nNodes();
    matX K(2*n, 2*n);
    std::vector<materialState> s0(el.nQuadrature(), mat.initialState()), s1;
    vecX fp, fm;
    for (int j = 0; j < 2*n; ++j)
    {
        matX up = u, um = u;
        up(j/2, j % 2) += h;
        um(j/2, j % 2) -= h;
        el.compute(X, up, mat, s0, s1, fp, nullptr, 0);
        el.compute(X, um, mat, s0, s1, fm, nullptr, 0);
        K.col(j) = (fp - fm)/(2*h);
    }
    return K;
}

std::unique_ptr<material> makeMaterial(const std::string& type)
{
    return material::New(type, {{"E", 100}, {"nu", 0.3}});
}
}


TEST(upQuad, tangentMatchesFiniteDifferences)
{
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> uni(-1, 1);
    for (const std::string& matType : {"linearElastic", "neoHookean"})
    {
        const auto mat = makeMaterial(matType);
        for (const analysisType a : analyses)
        {
            for (const std::string& type : types)
            {
                const auto el = solidElement::New(type, a);
                for (int sample = 0; sample < 3; ++sample)
                {
                    const matX X = randomElement(el->nNodes(), rng);
                    // Large displacements (25% of the element size) that
                    // keep det F > 0; redraw otherwise
                    matX u;
                    evaluation e;
                    for (int tries = 0; ; ++tries)
                    {
                        ASSERT_LT(tries, 50);
                        u = 0.25*matX::NullaryExpr(el->nNodes(), 2,
                            [&]() { return uni(rng); });
                        try { e = evaluate(*el, X, u, *mat); break; }
                        catch (const inversionError&) {}
                    }
                    const matX Kfd = fdTangent(*el, X, u, *mat, 1e-6);
                    const double err = test::relErr(e.K, Kfd);
                    EXPECT_TRUE(test::fdError("element tangent (elastic)", err, fdTolElemElastic)) << type << " "
                        << analysisTypeName(a) << " " << matType
                        << " sample " << sample;
                    // Hyperelastic (potential): symmetric, also condensed
                    EXPECT_LT((e.K - e.K.transpose()).norm(),
                              1e-12*e.K.norm());
                    if (matType == std::string("linearElastic"))
                    {
                        // Exactly linear: f_int = K u
                        EXPECT_LT((e.f - e.K*u.transpose().reshaped()).norm(),
                                  1e-12*e.f.norm());
                    }
                }
            }
        }
    }
}

TEST(upQuad, rigidBodyMotionIsStressFree)
{
    // neoHookean: a finite rotation plus translation (plane strain) and an
    // axial translation (axisymmetric) give f_int = 0
    std::mt19937 rng(8);
    const auto mat = makeMaterial("neoHookean");
    Eigen::Matrix2d R;
    R << std::cos(0.9), -std::sin(0.9), std::sin(0.9), std::cos(0.9);
    for (const std::string& type : types)
    {
        const auto ps = solidElement::New(type, analysisType::planeStrain);
        const matX X = randomElement(ps->nNodes(), rng);
        matX u = X*(R.transpose() - Eigen::Matrix2d::Identity());
        u.col(0).array() += 0.3;
        u.col(1).array() -= 1.1;
        EXPECT_LT(evaluate(*ps, X, u, *mat).f.norm(), 1e-12) << type;

        const auto ax = solidElement::New(type, analysisType::axisymmetric);
        matX uz = matX::Zero(X.rows(), 2);
        uz.col(1).array() = 0.7;
        EXPECT_LT(evaluate(*ax, X, uz, *mat).f.norm(), 1e-12) << type;
    }
}

TEST(upQuad, massMatrixIntegratesVolume)
{
    // Straight-sided quad: sum of M over one dof direction = area (plane
    // strain, unit depth) or 2 pi int R dA (Pappus, axisymmetric)
    Eigen::Matrix<double, 4, 2> c;
    c << 1.0, 0.0, 2.5, 0.2, 2.2, 1.4, 1.1, 0.9;
    double area = 0, firstMoment = 0;
    for (int i = 0; i < 4; ++i)
    {
        const int j = (i + 1) % 4;
        const double cr = c(i, 0)*c(j, 1) - c(j, 0)*c(i, 1);
        area += cr/2;
        firstMoment += (c(i, 0) + c(j, 0))*cr/6;    // int x dA
    }
    for (const std::string& type : types)
    {
        for (const analysisType a : analyses)
        {
            const auto el = solidElement::New(type, a);
            const matX X = el->nNodes() == 4 ? test::quadNodes<4>(c)
                                             : test::quadNodes<9>(c);
            const matX M = el->massMatrix(X);
            const double expected = a == analysisType::planeStrain
                ? area : 2*M_PI*firstMoment;
            EXPECT_NEAR(M.sum(), 2*expected, 1e-12*expected) << type;
            EXPECT_LT((M - M.transpose()).norm(), 1e-14);
            // no coupling between x and y dofs
            EXPECT_EQ(M(0, 1), 0.0);
            // positive definite
            EXPECT_GT(Eigen::SelfAdjointEigenSolver<matX>(M)
                      .eigenvalues().minCoeff(), 0.0);
        }
    }
}

// The reference volume of each quadrature point (the weights of volume
// integrals of point values, e.g. the plastic dissipation of the effect
// report): positive, one per point, summing to the element's volume
TEST(upQuad, pointVolumesSumToTheVolume)
{
    Eigen::Matrix<double, 4, 2> c;
    c << 1.0, 0.0, 2.5, 0.2, 2.2, 1.4, 1.1, 0.9;
    for (const std::string& type : types)
    {
        for (const analysisType a : analyses)
        {
            const auto el = solidElement::New(type, a);
            const matX X = el->nNodes() == 4 ? test::quadNodes<4>(c)
                                             : test::quadNodes<9>(c);
            const test::volumeSum v = test::sumVolumes(el->pointVolumes(X));
            EXPECT_EQ(v.n, el->nQuadrature()) << type;
            EXPECT_GT(v.smallest, 0) << type;
            const double volume = el->massMatrix(X).sum()/2;
            EXPECT_NEAR(v.sum, volume, 1e-12*volume) << type;
        }
    }
}

TEST(upQuad, resultOfHomogeneousDeformation)
{
    // Homogeneous plane deformation F0: every element type returns the
    // material's Cauchy stress (tau_dev + kappa ln J I)/J, -p/J, min det F
    const auto mat = makeMaterial("neoHookean");
    std::mt19937 rng(9);
    mat3 F0 = mat3::Identity();
    F0.topLeftCorner<2, 2>() << 1.2, 0.3, -0.1, 0.9;
    materialState s0, s1;
    mat3 tauDev;
    mat6 c;
    mat->deviatoric(F0, s0, s1, tauDev, c);
    const double J = F0.determinant();
    const double p = mat->bulkModulus()*std::log(J);
    const mat3 sigma = (tauDev + p*mat3::Identity())/J;
    for (const std::string& type : types)
    {
        const auto el = solidElement::New(type, analysisType::planeStrain);
        const matX X = randomElement(el->nNodes(), rng);
        const matX u = X*(F0.topLeftCorner<2, 2>().transpose()
                        - Eigen::Matrix2d::Identity());
        const std::vector<materialState> st(el->nQuadrature());
        const elementResult r = el->result(X, u, *mat, st);
        EXPECT_LT((r.cauchy - sigma).norm(), 1e-12*sigma.norm()) << type;
        EXPECT_NEAR(r.pressure, -p/J, 1e-12) << type;
        EXPECT_NEAR(r.pressure, -sigma.trace()/3, 1e-12) << type;
        EXPECT_NEAR(r.minDetF, J, 1e-13) << type;
        EXPECT_NEAR(r.equivalentStrain, mat->equivalentStrain(F0, s0), 1e-13);
    }
}

TEST(upQuad, inversionThrowsWithElementId)
{
    const auto nh = makeMaterial("neoHookean");
    const auto le = makeMaterial("linearElastic");
    for (const std::string& type : types)
    {
        const auto el = solidElement::New(type, analysisType::planeStrain);
        std::mt19937 rng(1);
        const matX X = randomElement(el->nNodes(), rng);
        // Mirror x -> -x: det F = -1 everywhere
        matX u = matX::Zero(X.rows(), 2);
        u.col(0) = -2*X.col(0);
        std::vector<materialState> s0(el->nQuadrature()), s1;
        vecX f;
        matX K;
        try
        {
            el->compute(X, u, *nh, s0, s1, f, &K, 42);
            FAIL() << type << ": no inversionError";
        }
        catch (const inversionError& e)
        {
            EXPECT_EQ(e.element(), 42);
            const std::string msg = e.what();
            EXPECT_NE(msg.find("element 42"), std::string::npos) << msg;
            EXPECT_NE(msg.find("det F = -1"), std::string::npos) << msg;
        }
        // Small-strain model: linear theory, no inversion check
        EXPECT_TRUE(el->compute(X, u, *le, s0, s1, f, &K, 42));
    }
}

TEST(upQuad, typeProperties)
{
    const int nodes[] = {4, 9, 4, 9}, pressures[] = {0, 0, 1, 3},
              points[] = {4, 9, 4, 9};
    for (int k = 0; k < 4; ++k)
    {
        const auto el = solidElement::New(types[k], analysisType::axisymmetric);
        EXPECT_EQ(el->type(), types[k]);
        EXPECT_EQ(el->analysis(), analysisType::axisymmetric);
        EXPECT_EQ(el->nDim(), 2);
        EXPECT_EQ(el->nNodes(), nodes[k]);
        EXPECT_EQ(el->nCorners(), 4);
        EXPECT_EQ(el->nPressure(), pressures[k]);
        EXPECT_EQ(el->nQuadrature(), points[k]);
        EXPECT_EQ(el->nEdges(), 4);
        const std::vector<int> e3 = el->edgeNodes(3);
        EXPECT_EQ(e3[0], 3);
        EXPECT_EQ(e3[1], 0);
        if (nodes[k] == 9) EXPECT_EQ(e3.at(2), 7);
        else EXPECT_EQ(e3.size(), 2u);
    }
}

TEST(upQuad, badInputThrowsInsteadOfCrashing)
{
    const auto mat = makeMaterial("neoHookean");
    const auto q9 = solidElement::New("Q9P3", analysisType::axisymmetric);
    std::vector<materialState> s0(q9->nQuadrature()), s1;
    vecX f;
    matX K;
    // 4 nodes given to a 9-node element
    Eigen::Matrix<double, 4, 2> c;
    c << 1, 0, 2, 0, 2, 1, 1, 1;
    const matX X4 = test::quadNodes<4>(c);
    EXPECT_THROW(q9->compute(X4, matX::Zero(4, 2), *mat, s0, s1, f, &K, 3),
                 numericalError);
    EXPECT_THROW(q9->massMatrix(X4), numericalError);
    // Wrong number of material states
    const matX X9 = test::quadNodes<9>(c);
    std::vector<materialState> few(2);
    EXPECT_THROW(q9->compute(X9, matX::Zero(9, 2), *mat, few, s1, f, &K, 3),
                 numericalError);
    // Clockwise (inverted) reference cell
    matX Xcw = X9;
    Xcw.col(1) *= -1;
    Xcw.col(1).array() += 1;
    EXPECT_THROW(q9->compute(Xcw, matX::Zero(9, 2), *mat, s0, s1, f, &K, 3),
                 numericalError);
    // Axisymmetric cell crossing the axis
    matX Xneg = X9;
    Xneg.col(0).array() -= 1.5;
    EXPECT_THROW(q9->massMatrix(Xneg), numericalError);
}


TEST(upQuad, elastoPlasticTangentMatchesFiniteDifferences)
{
    // The u/p elements with finite-strain plasticity (the deviatoric part
    // from the return mapping, the pressure from the element's field): von
    // Mises + Swift (symmetric) and Hill'48 + Armstrong-Frederick
    // (unsymmetric), plastic at every Gauss point (yield strain 0.01, large
    // displacements), every element type and analysis
    materialInput vm;
    vm.words["type"] = "elastoPlastic";
    vm.scalars = {{"E", 100}, {"nu", 0.3}};
    vm.dicts["hardening"].path = "hardening";
    vm.dicts["hardening"].words["type"] = "swift";
    vm.dicts["hardening"].scalars = {{"K", 1.5}, {"eps0", 0.01}, {"n", 0.2}};
    materialInput hill = vm;
    hill.dicts["yield"].path = "yield";
    hill.dicts["yield"].words = {{"type", "hill48"}, {"rollingDirection", "x"},
                                 {"normalDirection", "y"}};
    hill.dicts["yield"].scalars = {{"r0", 1.8}, {"r45", 1.2}, {"r90", 2.3}};
    hill.dicts["kinematicHardening"].path = "kinematicHardening";
    hill.dicts["kinematicHardening"].words["type"] = "armstrongFrederick";
    hill.dicts["kinematicHardening"].scalars = {{"C", 20}, {"gamma", 10}};

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    for (const materialInput* in : {&vm, &hill})
    {
        const auto mat = material::New("elastoPlastic", *in);
        for (const analysisType a : analyses)
        {
            for (const std::string& type : types)
            {
                const auto el = solidElement::New(type, a);
                const matX X = randomElement(el->nNodes(), rng);
                matX u;
                evaluation e;
                for (int tries = 0; ; ++tries)
                {
                    ASSERT_LT(tries, 50);
                    u = 0.2*matX::NullaryExpr(el->nNodes(), 2,
                        [&]() { return uni(rng); });
                    try { e = evaluate(*el, X, u, *mat); break; }
                    catch (const inversionError&) {}
                }
                const matX Kfd = fdTangent(*el, X, u, *mat, 1e-7);
                EXPECT_TRUE(test::fdError("element tangent (elastoPlastic)", test::relErr(e.K, Kfd), fdTolElemPlastic)) << type << " "
                    << analysisTypeName(a) << " "
                    << (in == &vm ? "vonMises" : "hill48 AF");
            }
        }
    }
}


TEST(upQuad, trackedPressureTangent)
{
    // Q4P1 and Q9P3, plane strain and axisymmetric, neoHookean (nearly
    // incompressible and not), at random distorted geometry and large
    // displacements
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    for (const double nu : {0.3, 0.4999})
    {
        const auto mat = material::New("neoHookean", {{"E", 100}, {"nu", nu}});
        for (const analysisType a : analyses)
        {
            for (const std::string type : {"Q4P1", "Q9P3"})
            {
                const auto el = solidElement::New(type, a);
                const matX X = randomElement(el->nNodes(), rng);
                matX u;
                for (int tries = 0; ; ++tries)
                {
                    ASSERT_LT(tries, 50);
                    u = 0.25*matX::NullaryExpr(el->nNodes(), 2,
                        [&]() { return uni(rng); });
                    try { evaluate(*el, X, u, *mat); break; }
                    catch (const inversionError&) {}
                }
                test::checkTrackedPressure
                (
                    *el, X, u, *mat, fdTolTracked,
                    type + " " + analysisTypeName(a) + " nu " + std::to_string(nu)
                );
            }
        }
    }
}
