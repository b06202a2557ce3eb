// Unit tests of form::unsupportedPieces: rigid-body modes that the
// constraints of a mesh's pieces leave free (supportCheck.H).
#include "supportCheck.H"
#include "structuredQuadMesh.H"
#include <gtest/gtest.h>
#include <set>

using namespace form;

namespace
{

const std::array<Eigen::Vector2d, 4> square{{{0, 0}, {2, 0}, {2, 1}, {0, 1}}};

//- Constrained dofs from (node set, component) pairs
std::function<bool(int)> fixed
(
    const feMesh& m,
    const std::vector<std::pair<std::string, int>>& sets
)
{
    std::set<int> dofs;
    for (const auto& s : sets)
    {
        for (const int n : m.nodeSets.at(s.first)) dofs.insert(2*n + s.second);
    }
    return [dofs](int d) { return dofs.count(d) > 0; };
}

//- Two squares side by side that share no node: pieces 0 and 1
feMesh twoPieces()
{
    feMesh a = structuredQuadMesh(square, 2, 1, 9, "Q9P3", "steel");
    const std::array<Eigen::Vector2d, 4> right
    {{{3, 0}, {5, 0}, {5, 1}, {3, 1}}};
    const feMesh b = structuredQuadMesh(right, 2, 1, 9, "Q9P3", "steel");
    const int n0 = a.nNodes();
    a.X.conservativeResize(n0 + b.nNodes(), 2);
    a.X.bottomRows(b.nNodes()) = b.X;
    for (const int n : b.blocks[0].connectivity)
    {
        a.blocks[0].connectivity.push_back(n + n0);
    }
    for (const int n : b.nodeSets.at("left")) a.nodeSets["rightLeft"].push_back(n + n0);
    return a;
}

} // namespace


TEST(supportCheck, NoConstraintLeavesAllThreeModes)
{
    const feMesh m = structuredQuadMesh(square, 2, 1, 9, "Q9P3", "steel");
    const auto free = unsupportedPieces
    (
        m, analysisType::planeStrain, [](int) { return false; }, {}
    );
    ASSERT_EQ(free.size(), 1u);
    EXPECT_EQ(free[0].nFreeModes, 3);
    EXPECT_NEAR(free[0].centre(0), 1, 1e-12);
    EXPECT_NEAR(free[0].centre(1), 0.5, 1e-12);
}


TEST(supportCheck, ClampedEdgeSupports)
{
    const feMesh m = structuredQuadMesh(square, 2, 1, 9, "Q9P3", "steel");
    EXPECT_TRUE
    (
        unsupportedPieces
        (
            m, analysisType::planeStrain, fixed(m, {{"left", 0}, {"left", 1}}), {}
        ).empty()
    );
}


TEST(supportCheck, RollerEdgeLeavesTranslationAlongIt)
{
    // left edge held in x only: the body slides in y
    const feMesh m = structuredQuadMesh(square, 2, 1, 9, "Q9P3", "steel");
    const auto free = unsupportedPieces
    (
        m, analysisType::planeStrain, fixed(m, {{"left", 0}}), {}
    );
    ASSERT_EQ(free.size(), 1u);
    EXPECT_EQ(free[0].nFreeModes, 1);
    EXPECT_NE(free[0].description.find("translation in y"), std::string::npos)
        << free[0].description;
}


TEST(supportCheck, OnePinnedNodeLeavesRotationAboutIt)
{
    const feMesh m = structuredQuadMesh(square, 2, 1, 9, "Q9P3", "steel");
    const int corner = nearestNode(m, Eigen::Vector2d(2, 1));
    const auto free = unsupportedPieces
    (
        m, analysisType::planeStrain,
        [corner](int d) { return d/2 == corner; }, {}
    );
    ASSERT_EQ(free.size(), 1u);
    EXPECT_EQ(free[0].nFreeModes, 1);
    EXPECT_NE(free[0].description.find("rotation about (2, 1)"), std::string::npos)
        << free[0].description;
}


TEST(supportCheck, AxisymmetricNeedsOnlyAnAxialSupport)
{
    const feMesh m = structuredQuadMesh(square, 2, 1, 9, "Q9P3", "steel");
    EXPECT_TRUE
    (
        unsupportedPieces
        (
            m, analysisType::axisymmetric, fixed(m, {{"bottom", 1}}), {}
        ).empty()
    );
    const auto free = unsupportedPieces
    (
        m, analysisType::axisymmetric, fixed(m, {{"left", 0}}), {}
    );
    ASSERT_EQ(free.size(), 1u);
    EXPECT_NE(free[0].description.find("translation in z"), std::string::npos)
        << free[0].description;
}


TEST(supportCheck, SecondPieceWithoutSupportIsFound)
{
    const feMesh m = twoPieces();
    const auto c = fixed(m, {{"left", 0}, {"left", 1}});
    const auto free = unsupportedPieces(m, analysisType::planeStrain, c, {});
    ASSERT_EQ(free.size(), 1u);
    EXPECT_EQ(free[0].piece, 1);
    EXPECT_EQ(free[0].nPieces, 2);
    EXPECT_EQ(free[0].nElements, 2);
    EXPECT_NEAR(free[0].centre(0), 4, 1e-12);
    // a piece touched by contact (or a fluid) counts as supported
    const std::vector<int> contact(m.nodeSets.at("rightLeft"));
    EXPECT_TRUE
    (
        unsupportedPieces(m, analysisType::planeStrain, c, contact).empty()
    );
}
