// Unit tests of form::structuredQuadMesh on Cook's membrane geometry.
#include "structuredQuadMesh.H"
#include "formError.H"
#include "solidElement.H"
#include <gtest/gtest.h>

using namespace form;

namespace
{
const std::array<Eigen::Vector2d, 4> cook{{{0, 0}, {48, 44}, {48, 60}, {0, 44}}};
}


TEST(structuredQuadMesh, Q4NodesElementsAndSets)
{
    const feMesh m = structuredQuadMesh(cook, 4, 2, 4, "Q4", "steel");
    EXPECT_EQ(m.nNodes(), 5*3);
    EXPECT_EQ(m.nElements(), 8);
    EXPECT_EQ(m.blocks[0].elementType, "Q4");
    EXPECT_EQ(m.blocks[0].materialName, "steel");
    EXPECT_EQ(m.nodeSets.at("left").size(), 3u);
    EXPECT_EQ(m.nodeSets.at("right").size(), 3u);
    EXPECT_EQ(m.nodeSets.at("bottom").size(), 5u);
    EXPECT_EQ(m.faceSets.at("right").size(), 2u);
    EXPECT_EQ(m.faceSets.at("top").size(), 4u);
    // Corners of the patch
    EXPECT_EQ(m.X.row(0), Eigen::RowVector2d(0, 0));
    EXPECT_EQ(m.X.row(4), Eigen::RowVector2d(48, 44));
    EXPECT_EQ(m.X.row(14), Eigen::RowVector2d(48, 60));
    EXPECT_EQ(m.X.row(10), Eigen::RowVector2d(0, 44));
    // Every element is counter-clockwise (positive signed area)
    for (int e = 0; e < m.nElements(); ++e)
    {
        const int* n = m.blocks[0].nodes(e);
        double a = 0;
        for (int k = 0; k < 4; ++k)
        {
            const auto p = m.X.row(n[k]), q = m.X.row(n[(k + 1) % 4]);
            a += p(0)*q(1) - q(0)*p(1);
        }
        EXPECT_GT(a, 0) << e;
    }
}


TEST(structuredQuadMesh, Q9MidNodesAtMappedMidpointsAndFacesFollowEdgeNodes)
{
    const feMesh m = structuredQuadMesh(cook, 16, 16, 9, "Q9P3", "steel");
    EXPECT_EQ(m.nNodes(), 33*33);
    EXPECT_EQ(m.nElements(), 256);
    const int* n = m.blocks[0].nodes(37);
    for (int k = 0; k < 4; ++k)
    {
        const Eigen::RowVector2d mid =
            0.5*(m.X.row(n[k]) + m.X.row(n[(k + 1) % 4]));
        EXPECT_LT((m.X.row(n[4 + k]) - mid).norm(), 1e-12) << k;
    }
    const Eigen::RowVector2d centre =
        0.25*(m.X.row(n[0]) + m.X.row(n[1]) + m.X.row(n[2]) + m.X.row(n[3]));
    EXPECT_LT((m.X.row(n[8]) - centre).norm(), 1e-12);

    // The probe point (48, 52) of Cook's membrane is a node
    const int p = nearestNode(m, {48, 52});
    EXPECT_LT((m.X.row(p) - Eigen::RowVector2d(48, 52)).norm(), 1e-12);

    // Faces list the element's edge nodes; a unit traction on the right
    // edge integrates to its length 16, on the bottom edge to |(48, 44)|
    auto q9 = solidElement::New("Q9P3", analysisType::planeStrain);
    double right = 0, bottom = 0;
    for (const char* set : {"right", "bottom", "left", "top"})
    {
        for (const feFace& f : m.faceSets.at(set))
        {
            const int* en = m.blocks[0].nodes(f.element);
            const std::vector<int> local = q9->edgeNodes(f.localFace);
            ASSERT_EQ(f.nodes.size(), local.size());
            for (std::size_t a = 0; a < local.size(); ++a)
            {
                EXPECT_EQ(f.nodes[a], en[local[a]]);
            }
            matX X(3, 2);
            for (int a = 0; a < 3; ++a) X.row(a) = m.X.row(f.nodes[a]);
            const vecX F = edgeLoad::deadTraction
            (
                X, Eigen::Vector2d(0, 1), analysisType::planeStrain
            );
            if (std::string(set) == "right") right += F.sum();
            if (std::string(set) == "bottom") bottom += F.sum();
        }
    }
    EXPECT_NEAR(right, 16, 1e-12);
    EXPECT_NEAR(bottom, std::hypot(48, 44), 1e-12);
}


TEST(structuredQuadMesh, RejectsUnsupportedElements)
{
    EXPECT_THROW(structuredQuadMesh(cook, 2, 2, 8, "Q8", "s"), inputError);
    EXPECT_THROW(structuredQuadMesh(cook, 0, 2, 4, "Q4", "s"), inputError);
}
