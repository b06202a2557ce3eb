// Unit tests of form::dofNumbering and form::sparsityPattern: numbering,
// structure against a dense coupling table, scatter codes.
#include "sparsityPattern.H"
#include <gtest/gtest.h>
#include <set>

using namespace form;

namespace
{

// Three overlapping "elements" over 8 dofs, dofs 1 and 6 prescribed
struct smallProblem
{
    std::vector<std::size_t> offsets{0, 3, 7, 10};
    std::vector<int> dofs{0, 1, 2,   2, 3, 4, 6,   7, 6, 5};
    std::vector<bool> constrained
        {false, true, false, false, false, false, true, false};
};

} // namespace


TEST(dofNumbering, FreeAndPrescribedNumberedCompactlyInGlobalOrder)
{
    dofNumbering n;
    n.build({false, true, false, true, true, false});
    EXPECT_EQ(n.nDofs(), 6);
    EXPECT_EQ(n.nFree(), 3);
    EXPECT_EQ(n.nPrescribed(), 3);
    EXPECT_EQ(n.freeDofs, (std::vector<int>{0, 2, 5}));
    EXPECT_EQ(n.prescribedDofs, (std::vector<int>{1, 3, 4}));
    EXPECT_EQ(n.equation, (std::vector<int>{0, -1, 1, -2, -3, 2}));
}


TEST(sparsityPattern, StructureEqualsDenseCouplingTable)
{
    smallProblem p;
    dofNumbering n;
    n.build(p.constrained);
    sparsityPattern pattern;
    sparseMatrix Kff, Kfp;
    pattern.build(n, p.offsets, p.dofs, Kff, Kfp);

    // Dense coupling: dofs i and j couple iff they share an element
    std::set<std::pair<int, int>> coupled;
    for (std::size_t e = 0; e + 1 < p.offsets.size(); ++e)
    {
        for (std::size_t a = p.offsets[e]; a < p.offsets[e + 1]; ++a)
            for (std::size_t b = p.offsets[e]; b < p.offsets[e + 1]; ++b)
                coupled.insert({p.dofs[a], p.dofs[b]});
    }
    ASSERT_EQ(Kff.rows(), n.nFree());
    ASSERT_EQ(Kff.cols(), n.nFree());
    ASSERT_EQ(Kfp.rows(), n.nFree());
    ASSERT_EQ(Kfp.cols(), n.nPrescribed());
    int expectedFF = 0, expectedFP = 0;
    for (const auto& c : coupled)
    {
        const int eqR = n.equation[c.first], eqC = n.equation[c.second];
        if (eqR < 0) continue;
        if (eqC >= 0) ++expectedFF; else ++expectedFP;
    }
    EXPECT_EQ(Kff.nonZeros(), expectedFF);
    EXPECT_EQ(Kfp.nonZeros(), expectedFP);
    for (int j = 0; j < Kff.outerSize(); ++j)
    {
        for (sparseMatrix::InnerIterator it(Kff, j); it; ++it)
        {
            EXPECT_TRUE(coupled.count
                ({n.freeDofs[it.row()], n.freeDofs[it.col()]}));
            EXPECT_EQ(it.value(), 0.0);
        }
    }
    for (int j = 0; j < Kfp.outerSize(); ++j)
    {
        for (sparseMatrix::InnerIterator it(Kfp, j); it; ++it)
        {
            EXPECT_TRUE(coupled.count
                ({n.freeDofs[it.row()], n.prescribedDofs[it.col()]}));
        }
    }
    EXPECT_TRUE(Kff.isCompressed());
}


TEST(sparsityPattern, ScatterCodesPointAtTheRightEntries)
{
    smallProblem p;
    dofNumbering n;
    n.build(p.constrained);
    sparsityPattern pattern;
    sparseMatrix Kff, Kfp;
    pattern.build(n, p.offsets, p.dofs, Kff, Kfp);

    // Scatter element matrices with entries 1000 + 10*row + col (global
    // dofs) and compare with a dense assembly of the same numbers
    matX dense = matX::Zero(8, 8);
    for (int e = 0; e < pattern.nElements(); ++e)
    {
        const int nE = pattern.nElementDofs(e);
        const int* d = p.dofs.data() + p.offsets[e];
        const int* code = pattern.scatter(e);
        for (int b = 0; b < nE; ++b)
        {
            for (int a = 0; a < nE; ++a)
            {
                const double v = 1000 + 10*d[a] + d[b];
                dense(d[a], d[b]) += v;
                const int c = code[a + nE*b];
                if (c >= 0) Kff.valuePtr()[c] += v;
                else if (c <= -2) Kfp.valuePtr()[-2 - c] += v;
                else EXPECT_LT(n.equation[d[a]], 0);
            }
        }
    }
    for (int i = 0; i < n.nFree(); ++i)
    {
        for (int j = 0; j < n.nFree(); ++j)
        {
            EXPECT_EQ(Kff.coeff(i, j), dense(n.freeDofs[i], n.freeDofs[j]));
        }
        for (int j = 0; j < n.nPrescribed(); ++j)
        {
            EXPECT_EQ(Kfp.coeff(i, j),
                dense(n.freeDofs[i], n.prescribedDofs[j]));
        }
    }
    EXPECT_EQ(pattern.memory(), (9 + 16 + 9)*sizeof(int));
}


TEST(sparsityPattern, ColoursCoverAllElementsAndShareNoDof)
{
    // 6 x 4 grid of 4-node "elements" with 1 dof per node
    std::vector<std::size_t> offsets{0};
    std::vector<int> dofs;
    for (int j = 0; j < 4; ++j)
    {
        for (int i = 0; i < 6; ++i)
        {
            const int n0 = i + 7*j;
            dofs.insert(dofs.end(), {n0, n0 + 1, n0 + 8, n0 + 7});
            offsets.push_back(dofs.size());
        }
    }
    dofNumbering n;
    n.build(std::vector<bool>(7*5, false));
    sparsityPattern pattern;
    sparseMatrix Kff, Kfp;
    pattern.build(n, offsets, dofs, Kff, Kfp);

    EXPECT_EQ(pattern.colours().size(), 4u);   // optimal for a quad grid
    std::vector<int> seen(24, 0);
    for (const auto& colour : pattern.colours())
    {
        std::set<int> used;
        for (int e : colour)
        {
            ++seen[e];
            for (std::size_t k = offsets[e]; k < offsets[e + 1]; ++k)
            {
                EXPECT_TRUE(used.insert(dofs[k]).second) << "element " << e;
            }
        }
    }
    for (int e = 0; e < 24; ++e) EXPECT_EQ(seen[e], 1) << e;
}
