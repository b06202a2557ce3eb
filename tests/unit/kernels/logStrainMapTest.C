/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    logStrainMap (the eigenbasis 6 x 6 Voigt evaluation of E = 1/2 ln C,
    S = T : P and P : A : P + T : L) against the 9 x 9 tensor route of
    logStrain and logStrainSecond (whose finite-difference checks are in
    logStrainTest.C), for random C, C = I, a double eigenvalue, clusters
    1e-10 apart and around the series switch-over, and a spread spectrum;
    unsymmetric A (Armstrong-Frederick tangents) included. voigtTransform
    against the 9 x 9 push-forward with a general F.
\*---------------------------------------------------------------------------*/
#include "logStrain.H"
#include "formError.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <limits>
#include <vector>

using namespace form;

namespace
{

std::vector<mat3> testMatrices()
{
    std::mt19937 rng(7);
    std::vector<mat3> Cs;
    const mat3 R = test::rotation(vec3(1, 2, 3), 0.7);
    auto spectral = [&R](double a, double b, double c)
    {
        const mat3 C = R*vec3(a, b, c).asDiagonal()*R.transpose();
        return mat3(0.5*(C + C.transpose()));
    };
    Cs.push_back(mat3::Identity());
    Cs.push_back(spectral(1.3, 1.3, 0.6));              // double eigenvalue
    Cs.push_back(spectral(1.0, 1.0 + 1e-10, 1.0 + 2e-10));
    Cs.push_back(spectral(1.0, 1.05, 1.0999));          // series side
    Cs.push_back(spectral(1.0, 1.05, 1.1001));          // direct side
    Cs.push_back(spectral(1e-2, 1.0, 1e2));
    for (int r = 0; r < 6; ++r)
    {
        const mat3 F = test::randomF(rng);
        Cs.push_back(F.transpose()*F);
    }
    return Cs;
}

mat6 randomMatrix6(std::mt19937& rng, bool symmetric)
{
    std::uniform_real_distribution<double> uni(-1, 1);
    mat6 A;
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b) A(a, b) = uni(rng);
    A += 3*mat6::Identity();
    return symmetric ? mat6(0.5*(A + A.transpose())) : A;
}

} // anonymous namespace


TEST(logStrainMap, matchesTheTensorRoute)
{
    std::mt19937 rng(11);
    double maxE = 0, maxS = 0, maxC = 0;
    for (const mat3& C : testMatrices())
    {
        for (const bool symmetric : {true, false})
        {
            const mat3 T = test::randomSym(rng);
            const mat6 A = randomMatrix6(rng, symmetric);

            mat3 E;
            tensor4 P;
            logStrain(C, E, P);
            const mat3 S = contractLeft(T, P);
            const mat6 Cref =
                toVoigt(P*fromVoigt(A)*P + logStrainSecond(C, T));

            const logStrainMap map(C);
            const double eE = (map.strain() - E).norm()/std::max(E.norm(), 1.0);
            const double eS = test::relErr(map.stress(T), S);
            const double eC = test::relErr(map.tangent(A, T), Cref);
            EXPECT_LT(eE, 1e-14);
            EXPECT_LT(eS, 1e-13);
            EXPECT_LT(eC, 1e-13);
            maxE = std::max(maxE, eE);
            maxS = std::max(maxS, eS);
            maxC = std::max(maxC, eC);
        }
    }
    std::cout << "    logStrainMap vs tensor route: E " << maxE << ", S "
              << maxS << ", tangent " << maxC << std::endl;
}


TEST(logStrainMap, rejectsInvalidInput)
{
    mat3 C = mat3::Identity();
    C(1, 1) = -1;
    EXPECT_THROW(logStrainMap{C}, numericalError);
    C(1, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(logStrainMap{C}, numericalError);
    const logStrainMap map(mat3::Identity());
    mat3 T = mat3::Identity();
    T(0, 1) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(map.tangent(mat6::Identity(), T), numericalError);
}


TEST(voigtTransform, matchesThePushForward)
{
    std::mt19937 rng(5);
    const mat3 F = test::randomF(rng);
    const mat6 R = voigtTransform(F);

    // Stress-like vectors: toVoigtStress(F X F^T) = R toVoigtStress(X)
    const mat3 X = test::randomSym(rng);
    EXPECT_LT
    (
        (toVoigtStress(F*X*F.transpose()) - R*toVoigtStress(X)).norm(),
        1e-14*X.norm()*F.squaredNorm()
    );

    // Tangents: R M R^T = the 9 x 9 push-forward (itself checked against
    // index loops in logStrainTest.C)
    const tensor4 M = fromVoigt(randomMatrix6(rng, false));
    const tensor4 B = pushForward(M, F);
    EXPECT_LT(test::relErr(R*toVoigt(M)*R.transpose(), toVoigt(B)), 1e-14);
}
