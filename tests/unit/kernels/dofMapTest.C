// Unit tests of form::dofMap (src/formCore/core/dofMap.H): where each
// node's dofs sit, for uniform (solid) and mixed (solid + shell) counts
#include "feMesh.H"
#include <gtest/gtest.h>
#include <stdexcept>

using namespace form;

// Uniform counts reproduce the numbering nDim*node + c exactly (every
// 2D result of formFoam depends on it being unchanged)
TEST(dofMap, uniformIsTheFormerNumbering)
{
    const dofMap d(5, 2);
    EXPECT_TRUE(d.uniform());
    EXPECT_EQ(d.nNodes(), 5);
    EXPECT_EQ(d.nDofs(), 10);
    for (int a = 0; a < 5; ++a)
    {
        EXPECT_EQ(d.count(a), 2);
        for (int c = 0; c < 2; ++c)
        {
            EXPECT_EQ(d.dof(a, c), 2*a + c);
            EXPECT_EQ(d.node(2*a + c), a);
            EXPECT_EQ(d.component(2*a + c), c);
        }
    }
    // A list of equal counts is stored as uniform
    EXPECT_TRUE(dofMap(std::vector<int>{3, 3, 3}).uniform());
}


// Mixed counts (a solid node with 3 dofs beside shell nodes with 5 and 6):
// consecutive blocks in node order; node() and component() invert dof()
TEST(dofMap, mixedCountsAreConsecutiveBlocks)
{
    const std::vector<int> counts{3, 5, 6, 3};
    const dofMap d(counts);
    EXPECT_FALSE(d.uniform());
    EXPECT_EQ(d.nDofs(), 17);
    int i = 0;
    for (int a = 0; a < 4; ++a)
    {
        EXPECT_EQ(d.first(a), i);
        EXPECT_EQ(d.count(a), counts[a]);
        for (int c = 0; c < counts[a]; ++c, ++i)
        {
            EXPECT_EQ(d.dof(a, c), i);
            EXPECT_EQ(d.node(i), a);
            EXPECT_EQ(d.component(i), c);
        }
    }
    vecX U = vecX::LinSpaced(17, 0, 16);
    EXPECT_EQ(d.vector2(U, 2)(0), 8);
    EXPECT_EQ(d.vector2(U, 2)(1), 9);
    vecX F = vecX::Zero(17);
    d.add2(F, 3, Eigen::Vector2d(1, 2));
    EXPECT_EQ(F(14), 1);
    EXPECT_EQ(F(15), 2);
    EXPECT_EQ(F.sum(), 3);
}


// The map of a mesh: nDim dofs per node
TEST(dofMap, ofAMeshHasNDimPerNode)
{
    feMesh mesh;
    mesh.nDim = 3;
    mesh.X = matX::Zero(4, 3);
    const dofMap d = dofMap::of(mesh);
    EXPECT_EQ(d.nDofs(), 12);
    EXPECT_EQ(d.dof(2, 1), 7);
}


TEST(dofMap, nonPositiveCountsAreRejected)
{
    EXPECT_THROW(dofMap(3, 0), std::invalid_argument);
    EXPECT_THROW(dofMap(std::vector<int>{2, 0, 2}), std::invalid_argument);
    EXPECT_EQ(dofMap(std::vector<int>{}).nDofs(), 0);
}


// A mesh that lists its nodes' counts (shell nodes) is mapped by them; a
// list of the wrong length is an error, not a silent misnumbering
TEST(dofMap, ofAMeshWithNodeCounts)
{
    feMesh mesh;
    mesh.nDim = 3;
    mesh.X = matX::Zero(3, 3);
    mesh.nodeDofs = {3, 5, 6};
    const dofMap d = dofMap::of(mesh);
    EXPECT_EQ(d.nDofs(), 14);
    EXPECT_EQ(d.dof(2, 0), 8);
    mesh.nodeDofs = {3, 5};
    EXPECT_THROW(dofMap::of(mesh), std::invalid_argument);
}
