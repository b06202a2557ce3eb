// upHex (Hex8, Hex27, Hex8P1, Hex27P4): consistent tangent against central
// differences of f_int (linearElastic, neoHookean, elastoPlastic with von
// Mises and with Hill'48 + Armstrong-Frederick) at random distorted
// geometry and large displacements; exact linearity for linearElastic;
// rigid-body invariance under a finite rotation about an oblique axis;
// the mass matrix; and Hex27P4 extruded under a plane-strain deformation
// reproducing Q9P3 node by node (forces and tangent), elastic and plastic;
// the tracked pressure of the mixed elements (trackedPressureCheck.H).
#include "solidElement.H"
#include "hexShape.H"
#include "formError.H"
#include "materialInput.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include "../fdCheck.H"
#include "trackedPressureCheck.H"

// Tolerances about 10 x the largest error observed (fdCheck.H). The
// elastic check uses h = 3e-7: with 20 % displacements of a distorted
// 27-node cell the truncation error of h = 1e-6 is 2e-8 (it falls as h^2:
// 2e-6 at 1e-5, 2e-9 at 3e-7)
namespace
{
constexpr double fdTolHexElastic = 2e-8;
constexpr double fdTolHexPlastic = 1e-8;
constexpr double fdTolHexTracked = 2e-8;
}

using namespace form;

namespace
{
const std::vector<std::string> hexTypes{"Hex8", "Hex27", "Hex8P1", "Hex27P4"};

// A distorted hexahedron of about unit size: random corners, the other
// nodes on the trilinear map of the corners moved by up to 0.03 (curved
// edges and faces)
matX randomHex(int nNodes, std::mt19937& rng)
{
    std::uniform_real_distribution<double> uni(-1, 1);
    Eigen::Matrix<double, 8, 3> C;
    for (int a = 0; a < 8; ++a)
    {
        const Eigen::Vector3d xi = hexShape<8>::node(a);
        for (int i = 0; i < 3; ++i) C(a, i) = 0.5*(1 + xi(i)) + 0.12*uni(rng);
    }
    matX X(nNodes, 3);
    for (int a = 0; a < nNodes; ++a)
    {
        const Eigen::Vector3d xi = hexShape<27>::node(a);
        const vecX N = hexShapeValues(8, xi(0), xi(1), xi(2));
        X.row(a) = N.transpose()*C;
        if (a >= 8)
        {
            for (int i = 0; i < 3; ++i) X(a, i) += 0.03*uni(rng);
        }
    }
    return X;
}

struct evaluation
{
    vecX f;
    matX K;
};

evaluation evaluate(const solidElement& el, const matX& X, const matX& u,
                    const material& mat)
{
    std::vector<materialState> s0(el.nQuadrature(), mat.initialState()), s1;
    evaluation e;
    EXPECT_TRUE(el.compute(X, u, mat, s0, s1, e.f, &e.K, 0));
    return e;
}

matX fdTangent(const solidElement& el, const matX& X, const matX& u,
               const material& mat, double h)
{
    const int n = el.nNodes();
    matX K(3*n, 3*n);
    std::vector<materialState> s0(el.nQuadrature(), mat.initialState()), s1;
    vecX fp, fm;
    for (int j = 0; j < 3*n; ++j)
    {
        matX up = u, um = u;
        up(j/3, j % 3) += h;
        um(j/3, j % 3) -= h;
        el.compute(X, up, mat, s0, s1, fp, nullptr, 0);
        el.compute(X, um, mat, s0, s1, fm, nullptr, 0);
        K.col(j) = (fp - fm)/(2*h);
    }
    return K;
}

// Large random displacements (scale x element size) with det F > 0
matX admissibleDisplacement(const solidElement& el, const matX& X,
                            const material& mat, double scale,
                            std::mt19937& rng, evaluation& e)
{
    std::uniform_real_distribution<double> uni(-1, 1);
    for (int tries = 0; tries < 50; ++tries)
    {
        const matX u = scale*matX::NullaryExpr(el.nNodes(), 3,
            [&]() { return uni(rng); });
        try { e = evaluate(el, X, u, mat); return u; }
        catch (const inversionError&) {}
    }
    ADD_FAILURE() << "no admissible displacement";
    return matX::Zero(el.nNodes(), 3);
}

materialInput vonMisesSwift()
{
    materialInput vm;
    vm.words["type"] = "elastoPlastic";
    vm.scalars = {{"E", 100}, {"nu", 0.3}};
    vm.dicts["hardening"].path = "hardening";
    vm.dicts["hardening"].words["type"] = "swift";
    vm.dicts["hardening"].scalars = {{"K", 1.5}, {"eps0", 0.01}, {"n", 0.2}};
    return vm;
}
}


TEST(upHex, tangentMatchesFiniteDifferences)
{
    std::mt19937 rng(11);
    for (const std::string matType : {"linearElastic", "neoHookean"})
    {
        const auto mat = material::New(matType, {{"E", 100}, {"nu", 0.3}});
        for (const std::string& type : hexTypes)
        {
            const auto el = solidElement::New(type, analysisType::solid3D);
            for (int sample = 0; sample < 2; ++sample)
            {
                const matX X = randomHex(el->nNodes(), rng);
                evaluation e;
                const matX u = admissibleDisplacement(*el, X, *mat, 0.2, rng, e);
                const matX Kfd = fdTangent(*el, X, u, *mat, 3e-7);
                EXPECT_TRUE(test::fdError("hexahedron tangent (elastic)", test::relErr(e.K, Kfd), fdTolHexElastic))
                    << type << " " << matType << " sample " << sample;
                EXPECT_LT((e.K - e.K.transpose()).norm(), 1e-12*e.K.norm());
                if (matType == std::string("linearElastic"))
                {
                    EXPECT_LT((e.f - e.K*u.transpose().reshaped()).norm(),
                              1e-12*e.f.norm());
                }
            }
        }
    }
}


TEST(upHex, elastoPlasticTangentMatchesFiniteDifferences)
{
    // Plastic at every point (yield strain 0.01, displacements 0.15):
    // von Mises + Swift (symmetric), Hill'48 + Armstrong-Frederick
    // (unsymmetric)
    materialInput vm = vonMisesSwift();
    materialInput hill = vm;
    hill.dicts["yield"].path = "yield";
    hill.dicts["yield"].words = {{"type", "hill48"}, {"rollingDirection", "x"},
                                 {"normalDirection", "z"}};
    hill.dicts["yield"].scalars = {{"r0", 1.8}, {"r45", 1.2}, {"r90", 2.3}};
    hill.dicts["kinematicHardening"].path = "kinematicHardening";
    hill.dicts["kinematicHardening"].words["type"] = "armstrongFrederick";
    hill.dicts["kinematicHardening"].scalars = {{"C", 20}, {"gamma", 10}};
    std::mt19937 rng(12);
    for (const materialInput* in : {&vm, &hill})
    {
        const auto mat = material::New("elastoPlastic", *in);
        for (const std::string type : {"Hex8", "Hex27P4"})
        {
            const auto el = solidElement::New(type, analysisType::solid3D);
            const matX X = randomHex(el->nNodes(), rng);
            evaluation e;
            const matX u = admissibleDisplacement(*el, X, *mat, 0.15, rng, e);
            const matX Kfd = fdTangent(*el, X, u, *mat, 1e-7);
            EXPECT_TRUE(test::fdError("hexahedron tangent (elastoPlastic)", test::relErr(e.K, Kfd), fdTolHexPlastic))
                << type << " " << (in == &vm ? "vonMises" : "hill48 AF");
        }
    }
}


TEST(upHex, rigidBodyMotionIsStressFree)
{
    // A finite rotation of 50 deg about an oblique axis plus a translation
    std::mt19937 rng(13);
    const auto mat = material::New("neoHookean", {{"E", 100}, {"nu", 0.3}});
    const mat3 R = test::rotation(vec3(1, 2, -0.5), 0.87);
    for (const std::string& type : hexTypes)
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        const matX X = randomHex(el->nNodes(), rng);
        matX u = X*(R.transpose() - mat3::Identity());
        u.col(0).array() += 0.3;
        u.col(2).array() -= 1.1;
        EXPECT_LT(evaluate(*el, X, u, *mat).f.norm(), 1e-12) << type;
    }
}


TEST(upHex, massMatrixIntegratesVolume)
{
    // Unit density: each component's mass sums to the volume; the
    // volume of a trilinear (straight-edged) cell by the corners' map
    std::mt19937 rng(14);
    for (const std::string& type : hexTypes)
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        const matX X = randomHex(el->nNodes(), rng);
        const matX M = el->massMatrix(X);
        EXPECT_LT((M - M.transpose()).norm(), 1e-14*M.norm());
        // Volume from the element's own geometry: sum of the x-rows
        double Vx = 0, Vz = 0;
        for (int a = 0; a < el->nNodes(); ++a)
        {
            for (int b = 0; b < el->nNodes(); ++b)
            {
                Vx += M(3*a, 3*b);
                Vz += M(3*a + 2, 3*b + 2);
                EXPECT_EQ(M(3*a, 3*b + 1), 0);
            }
        }
        EXPECT_NEAR(Vx, Vz, 1e-14);
        EXPECT_GT(Vx, 0.5);
        EXPECT_LT(Vx, 1.6);
    }
    // The unit cube: volume 1 exactly
    for (const std::string type : {"Hex8", "Hex27P4"})
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        matX X(el->nNodes(), 3);
        for (int a = 0; a < el->nNodes(); ++a)
        {
            X.row(a) = 0.5*(hexShape<27>::node(a) + vec3::Ones()).transpose();
        }
        EXPECT_NEAR(el->massMatrix(X).sum(), 3, 1e-13);
    }
}


// The reference volume of each quadrature point: positive, one per point,
// summing to the element's volume (as its mass matrix integrates it)
TEST(upHex, pointVolumesSumToTheVolume)
{
    std::mt19937 rng(15);
    for (const std::string& type : hexTypes)
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        const matX X = randomHex(el->nNodes(), rng);
        const test::volumeSum v = test::sumVolumes(el->pointVolumes(X));
        EXPECT_EQ(v.n, el->nQuadrature()) << type;
        EXPECT_GT(v.smallest, 0) << type;
        const double volume = el->massMatrix(X).sum()/3;
        EXPECT_NEAR(v.sum, volume, 1e-12*volume) << type;
    }
}


// Hex27P4 extruded one element thick (0 <= z <= 1) under a deformation
// that does not depend on z (u_z = 0): plane strain. Every layer of nodes
// carries the Q9P3 forces times int N_k dz (1/6, 2/3, 1/6), and the
// tangent summed over the layers of the columns is the same multiple of
// the Q9P3 tangent: the 27/4 element is the 9/3 element in plane strain
// (the pressure's t term vanishes, the r and s terms are the 9/3's)
TEST(upHex, Hex27P4InPlaneStrainIsQ9P3)
{
    const int layer[3][9] =
    {
        {0, 1, 2, 3, 8, 9, 10, 11, 24},        // z = 0
        {16, 17, 18, 19, 22, 21, 23, 20, 26},  // z = 1/2
        {4, 5, 6, 7, 12, 13, 14, 15, 25}       // z = 1
    };
    const double z[3] = {0, 0.5, 1};
    const double w[3] = {1.0/6, 2.0/3, 1.0/6};
    std::mt19937 rng(15);
    const auto q9 = solidElement::New("Q9P3", analysisType::planeStrain);
    const auto hex = solidElement::New("Hex27P4", analysisType::solid3D);
    const auto neo = material::New("neoHookean", {{"E", 100}, {"nu", 0.45}});
    const auto plastic = material::New("elastoPlastic", vonMisesSwift());
    for (const material* mat : {neo.get(), plastic.get()})
    {
        const matX X2 = test::randomQuad<9>(rng, 1.0, -0.5, 1.0);
        evaluation e2;
        const matX u2 = [&]()
        {
            std::uniform_real_distribution<double> uni(-1, 1);
            for (;;)
            {
                const matX u = 0.15*matX::NullaryExpr(9, 2,
                    [&]() { return uni(rng); });
                try { e2 = evaluate(*q9, X2, u, *mat); return u; }
                catch (const inversionError&) {}
            }
        }();
        matX X3 = matX::Zero(27, 3), u3 = matX::Zero(27, 3);
        for (int k = 0; k < 3; ++k)
        {
            for (int a = 0; a < 9; ++a)
            {
                X3.row(layer[k][a]) << X2(a, 0), X2(a, 1), z[k];
                u3.row(layer[k][a]) << u2(a, 0), u2(a, 1), 0;
            }
        }
        const evaluation e3 = evaluate(*hex, X3, u3, *mat);
        double errF = 0, errK = 0;
        for (int k = 0; k < 3; ++k)
        {
            for (int a = 0; a < 9; ++a)
            {
                for (int i = 0; i < 2; ++i)
                {
                    const int r3 = 3*layer[k][a] + i;
                    errF = std::max
                    (
                        errF, std::abs(e3.f(r3) - w[k]*e2.f(2*a + i))
                    );
                    for (int b = 0; b < 9; ++b)
                    {
                        for (int j = 0; j < 2; ++j)
                        {
                            double Ksum = 0;
                            for (int l = 0; l < 3; ++l)
                            {
                                Ksum += e3.K(r3, 3*layer[l][b] + j);
                            }
                            errK = std::max
                            (
                                errK,
                                std::abs(Ksum - w[k]*e2.K(2*a + i, 2*b + j))
                            );
                        }
                    }
                }
            }
        }
        const char* name = mat == neo.get() ? "neoHookean" : "elastoPlastic";
        EXPECT_LT(errF, 1e-12*e2.f.norm()) << name;
        EXPECT_LT(errK, 1e-12*e2.K.norm()) << name;
    }
}


TEST(upHex, typePropertiesAndBadInput)
{
    const auto h = solidElement::New("Hex27P4", analysisType::solid3D);
    EXPECT_EQ(h->nDim(), 3);
    EXPECT_EQ(h->nNodes(), 27);
    EXPECT_EQ(h->nPressure(), 4);
    EXPECT_EQ(h->nQuadrature(), 27);
    EXPECT_EQ(h->nEdges(), 6);
    EXPECT_EQ(h->edgeNodes(5), hexFaceNodes(27, 5));
    EXPECT_EQ(solidElement::New("Hex8P1", analysisType::solid3D)->nQuadrature(), 8);
    // A hexahedron in a 2D analysis, a quad in 3D: input errors
    EXPECT_THROW(solidElement::New("Hex27P4", analysisType::planeStrain), inputError);
    // An inverted cell: numericalError naming the element
    matX X(8, 3);
    for (int a = 0; a < 8; ++a) X.row(a) = hexShape<8>::node(a).transpose();
    X.col(2) *= -1;
    const auto mat = material::New("neoHookean", {{"E", 100}, {"nu", 0.3}});
    const auto h8 = solidElement::New("Hex8", analysisType::solid3D);
    std::vector<materialState> s0(8, mat->initialState()), s1;
    vecX f;
    EXPECT_THROW(h8->compute(X, matX::Zero(8, 3), *mat, s0, s1, f, nullptr, 3), numericalError);
}


TEST(upHex, trackedPressureTangent)
{
    std::mt19937 rng(11);
    const auto mat = material::New("neoHookean", {{"E", 100}, {"nu", 0.4999}});
    for (const std::string type : {"Hex8P1", "Hex27P4"})
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        const matX X = randomHex(el->nNodes(), rng);
        evaluation e;
        const matX u = admissibleDisplacement(*el, X, *mat, 0.2, rng, e);
        test::checkTrackedPressure(*el, X, u, *mat, fdTolHexTracked, type);
    }
}
