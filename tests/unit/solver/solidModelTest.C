// Unit tests of form::solidModel with the test bar element: assembly into
// the fixed pattern against a dense reference assembly, tangent against
// finite differences, constraints, commit/revert, failure reporting.
#include "solidModel.H"
#include "testElements.H"
#include <gtest/gtest.h>
#include <omp.h>
#include "../fdCheck.H"

// Finite-difference tolerances (fdCheck.H: about 10 x the largest error
// observed over the samples; the log prints each margin)
namespace
{
constexpr double fdTolModel = 2e-10;
}

using namespace form;
using namespace form::test;

namespace
{

// Braced 3x3 frame: nodes on a unit grid, bars along grid lines and one
// diagonal per cell; node 9 is an orphan (in no element)
feMesh frameMesh()
{
    matX X(10, 2);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            X.row(i + 3*j) << i, j;
    X.row(9) << 5, 5;
    std::vector<std::pair<int, int>> bars;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 2; ++i)
            bars.push_back({i + 3*j, i + 1 + 3*j});
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
            bars.push_back({i + 3*j, i + 3*(j + 1)});
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
            bars.push_back({i + 3*j, i + 1 + 3*(j + 1)});
    return trussMesh(X, bars);
}

std::map<std::string, std::shared_ptr<material>> barMaterial
(
    double EA = 100, double Fs = 0, double c3 = 0
)
{
    auto m = std::make_shared<trussMaterial>();
    m->svk = (Fs == 0 && c3 == 0);
    m->EA = EA;
    m->Fs = Fs;
    m->c3 = c3;
    return {{"bar", m}};
}

solidModel frameModel()
{
    registerTestElements();
    solidModel model(frameMesh(), analysisType::planeStrain, barMaterial());
    model.addConstraint({0}, 0);
    model.addConstraint({0}, 1);
    model.addConstraint({2}, 1, [](double t) { return 0.1*t; });
    model.finalise();
    return model;
}

vecX someDisplacement(int n)
{
    vecX U(n);
    for (int i = 0; i < n; ++i) U(i) = 0.05*std::sin(1.3*i + 0.4);
    return U;
}

// Dense f_int and K over all dofs, element by element
void denseAssembly
(
    const solidModel& model,
    const material& mat,
    vecX& fint,
    matX& K
)
{
    const feMesh& mesh = model.mesh();
    const int n = model.nDofs();
    fint = vecX::Zero(n);
    K = matX::Zero(n, n);
    testTruss bar;
    const elementBlock& b = mesh.blocks[0];
    for (int e = 0; e < b.nElements(); ++e)
    {
        const int* nodes = b.nodes(e);
        matX X(2, 2), u(2, 2);
        for (int a = 0; a < 2; ++a)
        {
            X.row(a) = mesh.X.row(nodes[a]);
            u(a, 0) = model.U()(2*nodes[a]);
            u(a, 1) = model.U()(2*nodes[a] + 1);
        }
        std::vector<materialState> c(1, mat.initialState()), t = c;
        vecX fe;
        matX Ke;
        ASSERT_TRUE(bar.compute(X, u, mat, c, t, fe, &Ke, e));
        for (int a = 0; a < 4; ++a)
        {
            const int ga = 2*nodes[a/2] + a%2;
            fint(ga) += fe(a);
            for (int bb = 0; bb < 4; ++bb)
            {
                K(ga, 2*nodes[bb/2] + bb%2) += Ke(a, bb);
            }
        }
    }
}

} // namespace


TEST(solidModel, NumberingSeparatesFreePrescribedAndOrphanDofs)
{
    solidModel model = frameModel();
    EXPECT_EQ(model.nDofs(), 20);
    // node 0 (2 dofs), node 2 y, orphan node 9 (2 dofs) are not free
    EXPECT_EQ(model.nPrescribedDofs(), 5);
    EXPECT_EQ(model.nFreeDofs(), 15);
    EXPECT_EQ(model.prescribedDofs(), (std::vector<int>{0, 1, 5, 18, 19}));
    EXPECT_FALSE(model.unsymmetric());
}


TEST(solidModel, AssembledMatricesEqualDenseReferenceAssembly)
{
    solidModel model = frameModel();
    model.setDisplacement(someDisplacement(model.nDofs()));
    vecX r;
    ASSERT_TRUE(model.evaluate(0.5, r, true));

    vecX fint;
    matX K;
    denseAssembly(model, *barMaterial().at("bar"), fint, K);
    ASSERT_GT(K.norm(), 100);

    const auto& f = model.freeDofs();
    const auto& p = model.prescribedDofs();
    const matX Kff = matX(model.Kff());
    const matX Kfp = matX(model.Kfp());
    for (std::size_t i = 0; i < f.size(); ++i)
    {
        EXPECT_NEAR(r(i), -fint(f[i]), 1e-12);
        for (std::size_t j = 0; j < f.size(); ++j)
        {
            EXPECT_NEAR(Kff(i, j), K(f[i], f[j]), 1e-12) << i << " " << j;
        }
        for (std::size_t j = 0; j < p.size(); ++j)
        {
            EXPECT_NEAR(Kfp(i, j), K(f[i], p[j]), 1e-12) << i << " " << j;
        }
    }
}


TEST(solidModel, TangentIsTheDerivativeOfMinusTheResidual)
{
    auto mats = barMaterial(100, 3, 40);   // S-shaped law, large rotations
    registerTestElements();
    solidModel model(frameMesh(), analysisType::planeStrain, mats);
    model.addConstraint({0, 1}, 0);
    model.addConstraint({0, 1}, 1);
    model.finalise();
    model.setDisplacement(3*someDisplacement(model.nDofs()));
    vecX r;
    ASSERT_TRUE(model.evaluate(0, r, true));
    const matX K = matX(model.Kff());
    const double h = 1e-6;
    for (int j = 0; j < model.nFreeDofs(); ++j)
    {
        vecX e = vecX::Zero(model.nFreeDofs());
        e(j) = h;
        vecX rp, rm;
        model.addToFree(e);
        ASSERT_TRUE(model.evaluate(0, rp, false));
        model.addToFree(-2*e);
        ASSERT_TRUE(model.evaluate(0, rm, false));
        model.addToFree(e);
        const vecX fd = -(rp - rm)/(2*h);
        EXPECT_TRUE(test::fdError("solidModel assembled tangent (column)", (fd - K.col(j)).norm()/K.norm(), fdTolModel)) << "column " << j;
    }
}


TEST(solidModel, PatternAndValueArraysAreNotRebuiltBetweenEvaluations)
{
    solidModel model = frameModel();
    vecX r;
    ASSERT_TRUE(model.evaluate(0, r, true));
    const double* values = model.Kff().valuePtr();
    const int* inner = model.Kff().innerIndexPtr();
    const double* fpValues = model.Kfp().valuePtr();
    const auto nnz = model.Kff().nonZeros();
    const int revision = model.patternRevision();
    const matX K0 = matX(model.Kff());

    model.setDisplacement(someDisplacement(model.nDofs()));
    ASSERT_TRUE(model.evaluate(1, r, true));
    EXPECT_EQ(model.Kff().valuePtr(), values);
    EXPECT_EQ(model.Kff().innerIndexPtr(), inner);
    EXPECT_EQ(model.Kfp().valuePtr(), fpValues);
    EXPECT_EQ(model.Kff().nonZeros(), nnz);
    EXPECT_EQ(model.patternRevision(), revision);
    EXPECT_GT((matX(model.Kff()) - K0).norm(), 1e-3);  // values did change

    // Values are zeroed, not accumulated, between evaluations
    const matX K1 = matX(model.Kff());
    ASSERT_TRUE(model.evaluate(1, r, true));
    EXPECT_EQ((matX(model.Kff()) - K1).norm(), 0.0);

    // Releasing a constraint renumbers and rebuilds
    model.releaseConstraint({2}, 1);
    EXPECT_EQ(model.patternRevision(), revision + 1);
    EXPECT_EQ(model.nFreeDofs(), 16);
    ASSERT_TRUE(model.evaluate(1, r, true));
    EXPECT_EQ(model.Kff().rows(), 16);
}


TEST(solidModel, PrescribedValuesIncrementsAndOverrides)
{
    solidModel model = frameModel();
    vecX dUp = model.prescribedIncrement(2);
    ASSERT_EQ(dUp.size(), 5);
    EXPECT_DOUBLE_EQ(dUp(2), 0.2);   // dof 5 = node 2 y, value 0.1 t
    EXPECT_EQ(dUp.norm(), 0.2);
    model.applyPrescribed(2);
    EXPECT_DOUBLE_EQ(model.U()(5), 0.2);
    EXPECT_EQ(model.prescribedIncrement(2).norm(), 0.0);
    EXPECT_DOUBLE_EQ(model.prescribedIncrement(3)(2), 0.1);

    // A later constraint on the same dof overrides the earlier one
    model.addConstraint({2}, 1, [](double t) { return -t; });
    EXPECT_DOUBLE_EQ(model.prescribedIncrement(1)(2), -1.2);
    EXPECT_EQ(model.displacement()(2, 1), 0.2);
}


TEST(solidModel, ReactionsBalanceTheImposedMotion)
{
    // One bar along x, node 0 fixed, node 1 pulled to u = 0.1: the
    // reaction at node 1 is the bar force N(l = 1.1) along +x, the one at
    // node 0 its opposite
    registerTestElements();
    matX X(2, 2);
    X << 0, 0, 1, 0;
    auto mats = barMaterial(100);
    solidModel model(trussMesh(X, {{0, 1}}), analysisType::planeStrain, mats);
    model.addConstraint({0, 1}, 0, [](double t) { return t*0.0; });
    model.addConstraint({0}, 1);
    model.addConstraint({1}, 0, [](double t) { return 0.1*t; });
    model.addConstraint({1}, 1);
    model.finalise();
    model.applyPrescribed(1);
    vecX r;
    ASSERT_TRUE(model.evaluate(1, r, true));
    EXPECT_EQ(r.size(), 0);
    double N, dN;
    testTruss::law(dynamic_cast<trussMaterial&>(*mats["bar"]), 1, 1.1, N, dN);
    EXPECT_NEAR(model.reaction({1})(0), N, 1e-12);
    EXPECT_NEAR(model.reaction({0})(0), -N, 1e-12);
    EXPECT_NEAR(model.reaction({0, 1}).norm(), 0, 1e-12);
    EXPECT_NEAR(model.reactionNorm(), std::sqrt(2.0)*N, 1e-12);
    EXPECT_EQ(model.externalForceNorm(), 0);
}


TEST(solidModel, CommitAndRevertRestoreDisplacementsAndStates)
{
    solidModel model = frameModel();
    vecX r;
    model.applyPrescribed(1);
    ASSERT_TRUE(model.evaluate(1, r, true));
    model.commit();
    const vecX Uc = model.U();
    const auto resultsC = model.elementResults();

    model.setDisplacement(someDisplacement(model.nDofs()));
    model.applyPrescribed(2);
    ASSERT_TRUE(model.evaluate(2, r, true));
    const auto resultsT = model.elementResults();
    double change = 0;
    for (std::size_t e = 0; e < resultsC.size(); ++e)
    {
        change += std::abs(resultsT[e].equivalentStrain
            - resultsC[e].equivalentStrain);
    }
    ASSERT_GT(change, 1e-3);

    model.revert();
    EXPECT_EQ((model.U() - Uc).norm(), 0.0);
    const auto resultsR = model.elementResults();
    for (std::size_t e = 0; e < resultsC.size(); ++e)
    {
        EXPECT_EQ(resultsR[e].equivalentStrain, resultsC[e].equivalentStrain);
    }
}


TEST(solidModel, MaterialFailureReturnsFalseAndInversionThrows)
{
    registerTestElements();
    auto mats = barMaterial(100);
    std::dynamic_pointer_cast<trussMaterial>(mats["bar"])->strainLimit = 0.2;
    solidModel model(frameMesh(), analysisType::planeStrain, mats);
    model.addConstraint({0}, 0);
    model.addConstraint({0}, 1);
    model.finalise();
    vecX r;
    EXPECT_TRUE(model.evaluate(0, r, true));

    vecX U = vecX::Zero(model.nDofs());
    U(2*8) = 0.5;                         // stretches bars at node 8 by 50%
    model.setDisplacement(U);
    EXPECT_FALSE(model.evaluate(0, r, true));

    U.setZero();
    U(2*1) = -1;                          // node 1 onto node 0: bar 0 collapses
    model.setDisplacement(U);
    try
    {
        model.evaluate(0, r, true);
        FAIL() << "no exception";
    }
    catch (const inversionError& e)
    {
        EXPECT_EQ(e.element(), 0);
    }
}


TEST(solidModel, BadInputThrowsInputErrorNamingTheEntry)
{
    registerTestElements();
    // Unknown material
    try
    {
        solidModel m(frameMesh(), analysisType::planeStrain, {});
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "material");
    }
    // Unknown element type
    feMesh mesh = frameMesh();
    mesh.blocks[0].elementType = "Q5";
    try
    {
        solidModel m(mesh, analysisType::planeStrain, barMaterial());
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "elementType");
    }
    // Unknown face set
    solidModel m(frameMesh(), analysisType::planeStrain, barMaterial());
    try
    {
        m.addPressure("top", [](double) { return 1.0; });
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "top");
    }
    EXPECT_THROW(m.addConstraint({0}, 2), inputError);
    EXPECT_THROW(m.addConstraint({42}, 0), inputError);
    // Dof counts the solid elements cannot carry (a rotation), or a list
    // of the wrong length (dofMap.H)
    for (const bool rotation : {true, false})
    {
        feMesh bad = frameMesh();
        bad.nodeDofs.assign(bad.nNodes(), 2);
        if (rotation) bad.nodeDofs[0] = 3;
        else bad.nodeDofs.pop_back();
        try
        {
            solidModel s(bad, analysisType::planeStrain, barMaterial());
            FAIL() << "no exception";
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), "mesh");
        }
    }
}


// Real elements: Q9P3 / Q4 with neo-Hookean material, a dead traction and a
// follower pressure (unsymmetric load stiffness). The assembled K_ff and
// K_fp must be the derivative of -r_f with respect to the free and the
// prescribed dofs (central differences through setDisplacement).
#include "structuredQuadMesh.H"

namespace
{

void checkQuadTangent(const std::string& element, int nodes)
{
    feMesh mesh = structuredQuadMesh
    (
        {{{0, 0}, {4, 0.5}, {4, 2}, {0, 1.5}}}, 3, 2, nodes, element, "rubber"
    );
    const std::vector<int> left = mesh.nodeSets.at("left");
    auto mat = material::New("neoHookean", {{"E", 10}, {"nu", 0.45}});
    solidModel model
    (
        mesh, analysisType::planeStrain, {{"rubber", std::move(mat)}}
    );
    model.addConstraint(left, 0);
    model.addConstraint(left, 1);
    // Left edge moved by a prescribed function (nonzero K_fp columns);
    // the ends of the pressure-loaded top edge stay free in y, where the
    // follower load stiffness is unsymmetric
    model.addConstraint({left[0]}, 0, [](double t) { return -0.1*t; });
    model.addTraction("right", [](double t)
    {
        return vec3(0, 0.3*t, 0);
    });
    model.addPressure("top", [](double t) { return 0.5*t; });
    model.finalise();
    ASSERT_TRUE(model.unsymmetric());

    // A deformed state
    vecX U(model.nDofs());
    for (int n = 0; n < model.mesh().nNodes(); ++n)
    {
        const double x = model.mesh().X(n, 0), y = model.mesh().X(n, 1);
        U(2*n) = 0.05*x + 0.02*y*y;
        U(2*n + 1) = 0.03*x*x - 0.04*y;
    }
    model.setDisplacement(U);
    vecX r;
    ASSERT_TRUE(model.evaluate(1, r, true));
    const matX Kff = matX(model.Kff());
    const matX Kfp = matX(model.Kfp());
    EXPECT_GT((Kff - Kff.transpose()).norm(), 1e-6*Kff.norm());

    const double h = 1e-6;
    const auto& f = model.freeDofs();
    const auto& p = model.prescribedDofs();
    double errFF = 0, errFP = 0;
    for (int d = 0; d < model.nDofs(); ++d)
    {
        vecX Up = U, Um = U;
        Up(d) += h;
        Um(d) -= h;
        vecX rp, rm;
        model.setDisplacement(Up);
        ASSERT_TRUE(model.evaluate(1, rp, false));
        model.setDisplacement(Um);
        ASSERT_TRUE(model.evaluate(1, rm, false));
        const vecX col = -(rp - rm)/(2*h);
        const auto fi = std::find(f.begin(), f.end(), d);
        if (fi != f.end())
        {
            errFF = std::max(errFF, (col - Kff.col(fi - f.begin())).norm());
        }
        else
        {
            const auto pi = std::find(p.begin(), p.end(), d);
            errFP = std::max(errFP, (col - Kfp.col(pi - p.begin())).norm());
        }
    }
    EXPECT_LT(errFF, 1e-6*Kff.norm()) << element;
    EXPECT_LT(errFP, 1e-6*Kff.norm()) << element;
    EXPECT_GT(Kfp.norm(), 1e-3*Kff.norm());
}

} // namespace


TEST(solidModel, Q9P3TangentWithFollowerPressureMatchesFiniteDifferences)
{
    checkQuadTangent("Q9P3", 9);
}


TEST(solidModel, Q4TangentWithFollowerPressureMatchesFiniteDifferences)
{
    checkQuadTangent("Q4", 4);
}


TEST(solidModel, AssemblyIsIdenticalForAnyThreadCount)
{
    feMesh mesh = structuredQuadMesh
    (
        {{{0, 0}, {48, 44}, {48, 60}, {0, 44}}}, 12, 10, 9, "Q9P3", "m"
    );
    const std::vector<int> left = mesh.nodeSets.at("left");
    auto mat = material::New("neoHookean", {{"E", 10}, {"nu", 0.49}});
    solidModel model(mesh, analysisType::planeStrain, {{"m", std::move(mat)}});
    model.addConstraint(left, 0);
    model.addConstraint(left, 1);
    model.addPressure("top", [](double) { return 0.01; });
    model.finalise();
    vecX U(model.nDofs());
    for (int d = 0; d < U.size(); ++d) U(d) = 0.01*std::sin(0.1*d);
    model.setDisplacement(U);

    const int threads = omp_get_max_threads();
    vecX r1, r2;
    omp_set_num_threads(1);
    ASSERT_TRUE(model.evaluate(0, r1, true));
    const vecX K1 = Eigen::Map<const vecX>
        (model.Kff().valuePtr(), model.Kff().nonZeros());
    omp_set_num_threads(std::max(2, threads));
    ASSERT_TRUE(model.evaluate(0, r2, true));
    const vecX K2 = Eigen::Map<const vecX>
        (model.Kff().valuePtr(), model.Kff().nonZeros());
    omp_set_num_threads(threads);
    EXPECT_EQ((r1 - r2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((K1 - K2).cwiseAbs().maxCoeff(), 0.0);
}
