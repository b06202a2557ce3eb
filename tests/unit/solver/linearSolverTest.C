// Unit tests of form::linearSolver: cholmod, umfpack and sparseLU against a
// dense LU solve of the same system.
#include "linearSolver.H"
#include "cholmodSolver.H"
#include "umfpackSolver.H"
#include "autoSolver.H"
#include <sstream>
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <vector>

using namespace form;

namespace
{

// 5-point Laplacian on an n x n grid (SPD), plus shift*I, plus an
// unsymmetric convection term c (u_{i+1} - u_{i-1}) along x
sparseMatrix gridMatrix(int n, double shift, double c)
{
    std::vector<Eigen::Triplet<double>> t;
    auto id = [n](int i, int j) { return i + n*j; };
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            const int k = id(i, j);
            t.emplace_back(k, k, 4.0 + shift);
            if (i > 0) t.emplace_back(k, id(i - 1, j), -1.0 - c);
            if (i < n - 1) t.emplace_back(k, id(i + 1, j), -1.0 + c);
            if (j > 0) t.emplace_back(k, id(i, j - 1), -1.0);
            if (j < n - 1) t.emplace_back(k, id(i, j + 1), -1.0);
        }
    }
    sparseMatrix K(n*n, n*n);
    K.setFromTriplets(t.begin(), t.end());
    K.makeCompressed();
    return K;
}

// K's entries appended to t, shifted by offset along the diagonal
void appendTriplets
(
    std::vector<Eigen::Triplet<double>>& t,
    const sparseMatrix& K,
    int offset = 0
)
{
    for (int k = 0; k < K.outerSize(); ++k)
    {
        for (sparseMatrix::InnerIterator it(K, k); it; ++it)
        {
            t.emplace_back(offset + it.row(), offset + it.col(), it.value());
        }
    }
}

vecX denseSolve(const sparseMatrix& K, const vecX& r)
{
    return matX(K).fullPivLu().solve(r);
}

vecX rhs(int n)
{
    vecX r(n);
    for (int i = 0; i < n; ++i) r(i) = std::sin(0.37*i) + 0.1*i;
    return r;
}

} // namespace


TEST(linearSolver, NewListsValidNamesForUnknownSolver)
{
    try
    {
        linearSolver::New("pardiso");
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "linearSolver");
        const std::string msg = e.what();
        EXPECT_NE(msg.find("pardiso"), std::string::npos) << msg;
        EXPECT_NE(msg.find("valid: cholmod umfpack sparseLU"), std::string::npos)
            << msg;
    }
}


TEST(linearSolver, TypesAndSPDFlags)
{
    EXPECT_EQ(linearSolver::New("cholmod")->type(), "cholmod");
    EXPECT_TRUE(linearSolver::New("cholmod")->requiresSPD());
    EXPECT_EQ(linearSolver::New("umfpack")->type(), "umfpack");
    EXPECT_FALSE(linearSolver::New("umfpack")->requiresSPD());
    EXPECT_EQ(linearSolver::New("sparseLU")->type(), "sparseLU");
    EXPECT_FALSE(linearSolver::New("sparseLU")->requiresSPD());
}


TEST(linearSolver, AllSolversMatchDenseSolveOnSPDSystem)
{
    const sparseMatrix K = gridMatrix(12, 0.01, 0);
    const vecX r = rhs(int(K.rows()));
    const vecX x = denseSolve(K, r);
    for (const char* name : {"cholmod", "umfpack", "sparseLU"})
    {
        auto s = linearSolver::New(name);
        s->analyzePattern(K);
        s->factorize(K);
        const vecX y = s->solve(r);
        EXPECT_LT((y - x).norm(), 1e-10*x.norm()) << name;

        // Refactorise with new values on the same pattern
        sparseMatrix K2 = K;
        for (int k = 0; k < K2.nonZeros(); ++k) K2.valuePtr()[k] *= 2;
        s->factorize(K2);
        EXPECT_LT((s->solve(r) - 0.5*x).norm(), 1e-10*x.norm()) << name;
    }
}


TEST(linearSolver, LUSolversMatchDenseSolveOnUnsymmetricSystem)
{
    const sparseMatrix K = gridMatrix(10, 0.0, 0.4);
    const vecX r = rhs(int(K.rows()));
    const vecX x = denseSolve(K, r);
    ASSERT_GT((matX(K) - matX(K).transpose()).norm(), 1);
    for (const char* name : {"umfpack", "sparseLU"})
    {
        auto s = linearSolver::New(name);
        s->analyzePattern(K);
        s->factorize(K);
        EXPECT_LT((s->solve(r) - x).norm(), 1e-10*x.norm()) << name;
    }
}


TEST(linearSolver, CholmodThrowsOnIndefiniteMatrix)
{
    // Laplacian eigenvalues lie in (0, 8): a shift of -2.1 makes it indefinite (and non-singular)
    const sparseMatrix K = gridMatrix(8, -2.1, 0);
    auto s = linearSolver::New("cholmod");
    s->analyzePattern(K);
    try
    {
        s->factorize(K);
        FAIL() << "no exception";
    }
    catch (const numericalError& e)
    {
        EXPECT_NE(std::string(e.what()).find("not positive definite"),
            std::string::npos) << e.what();
    }
    EXPECT_THROW(s->solve(rhs(int(K.rows()))), numericalError);

    // umfpack solves the same (non-singular) indefinite system
    const vecX r = rhs(int(K.rows()));
    auto u = linearSolver::New("umfpack");
    u->factorize(K);
    EXPECT_LT((u->solve(r) - denseSolve(K, r)).norm(),
        1e-8*denseSolve(K, r).norm());
}


TEST(linearSolver, AutoSwitchesToUmfpackAtTheFirstIndefiniteMatrix)
{
    // linearSolver auto (autoSolver.H): CHOLMOD while the tangent is
    // positive definite, UMFPACK from the first indefinite one on, said
    // once in the log, no solve lost
    std::ostringstream log;
    autoSolver s(&log);
    const sparseMatrix spd = gridMatrix(8, 0.5, 0);
    const sparseMatrix indefinite = gridMatrix(8, -2.1, 0);
    const vecX r = rhs(int(spd.rows()));
    s.analyzePattern(spd);
    s.factorize(spd);
    EXPECT_EQ(s.type(), "auto (cholmod)");
    EXPECT_FALSE(s.switched());
    EXPECT_LT((s.solve(r) - denseSolve(spd, r)).norm(), 1e-10*denseSolve(spd, r).norm());
    EXPECT_TRUE(log.str().empty()) << log.str();

    // the first indefinite matrix: factorised by UMFPACK at once
    s.factorize(indefinite);
    EXPECT_TRUE(s.switched());
    EXPECT_EQ(s.type(), "auto (umfpack)");
    EXPECT_LT((s.solve(r) - denseSolve(indefinite, r)).norm(), 1e-8*denseSolve(indefinite, r).norm());
    EXPECT_NE(log.str().find("switching from cholmod to umfpack for the rest of the run"), std::string::npos) << log.str();

    // the switch is permanent, and reported once
    s.factorize(spd);
    EXPECT_EQ(s.type(), "auto (umfpack)");
    EXPECT_LT((s.solve(r) - denseSolve(spd, r)).norm(), 1e-10*denseSolve(spd, r).norm());
    s.factorize(indefinite);
    std::size_t n = 0;
    for (std::size_t k = log.str().find("switching"); k != std::string::npos; k = log.str().find("switching", k + 1)) ++n;
    EXPECT_EQ(n, 1u);
}


TEST(linearSolver, LUSolversThrowOnSingularMatrix)
{
    sparseMatrix K = gridMatrix(6, 0, 0);
    // Zero a whole row and column: structurally singular
    for (int k = 0; k < K.outerSize(); ++k)
    {
        for (sparseMatrix::InnerIterator it(K, k); it; ++it)
        {
            if (it.row() == 7 || it.col() == 7) it.valueRef() = 0;
        }
    }
    for (const char* name : {"umfpack", "sparseLU", "cholmod"})
    {
        auto s = linearSolver::New(name);
        s->analyzePattern(K);
        EXPECT_THROW(s->factorize(K), numericalError) << name;
    }
}


TEST(linearSolver, MetisOrderingAndFactorMemory)
{
    const sparseMatrix K = gridMatrix(30, 0.01, 0);
    cholmodSolver c;
    c.analyzePattern(K);
    c.factorize(K);
    EXPECT_TRUE(c.usedMetis());
    // nnz(L) of a 900-dof 2D grid lies between nnz(tril K) and dense
    const double nnzLower = (K.nonZeros() + K.rows())/2.0;
    EXPECT_GT(c.factorMemory(), nnzLower*sizeof(double));
    EXPECT_LT(c.factorMemory(), 0.5*K.rows()*K.rows()*sizeof(double));

    umfpackSolver u(umfpackSolver::ordering::metis);
    u.analyzePattern(K);
    u.factorize(K);
    EXPECT_TRUE(u.usedMetis());
    EXPECT_GT(u.factorMemory(), K.nonZeros()*sizeof(double));
    EXPECT_LT(u.factorMemory(), double(K.rows())*K.rows()*sizeof(double));
}


// The automatic ordering keeps the ordering of fewer flops at the first
// factorisation: on 2D grids (a 5-point and a wide 2-layer stencil) it is
// the cheaper of METIS and AMD, factorised both ways, and stays for the
// next factorisations and patterns of about that size; the solutions
// agree
TEST(linearSolver, UmfpackKeepsTheCheaperOrdering)
{
    for (const int width : {0, 2})
    {
        SCOPED_TRACE("stencil width " + std::to_string(width));
        sparseMatrix K = gridMatrix(40, 0.01, 0.3);
        if (width)
        {
            // couple every node to its neighbours two layers away
            std::vector<Eigen::Triplet<double>> t;
            appendTriplets(t, K);
            const int n = 40;
            for (int i = 0; i < n; ++i)
            {
                for (int j = 0; j < n; ++j)
                {
                    for (int di = -width; di <= width; ++di)
                    {
                        for (int dj = -width; dj <= width; ++dj)
                        {
                            const int a = i + di, b = j + dj;
                            if (a < 0 || b < 0 || a >= n || b >= n) continue;
                            t.emplace_back(i*n + j, a*n + b, 1e-3*std::sin(i + 2.0*j + 3.0*a + b));
                        }
                    }
                }
            }
            K.setFromTriplets(t.begin(), t.end());
            K.makeCompressed();
        }
        const vecX r = vecX::LinSpaced(K.rows(), -1, 2);
        double flops[3];
        vecX x[3];
        int k = 0;
        for
        (
            const auto o :
            {
                umfpackSolver::ordering::amd, umfpackSolver::ordering::metis,
                umfpackSolver::ordering::automatic
            }
        )
        {
            umfpackSolver u(o);
            u.analyzePattern(K);
            u.factorize(K);
            flops[k] = u.stats().flops;
            x[k] = u.solve(r);
            // the choice stays for the next factorisations and patterns
            const bool metis = u.usedMetis();
            u.factorize(K);
            EXPECT_EQ(u.stats().flops, flops[k]);
            u.analyzePattern(K);
            u.factorize(K);
            EXPECT_EQ(u.stats().flops, flops[k]);
            EXPECT_EQ(u.usedMetis(), metis);
            ++k;
        }
        EXPECT_NE(flops[0], flops[1]);
        EXPECT_EQ(flops[2], std::min(flops[0], flops[1]));
        EXPECT_LT((x[2] - x[0]).norm(), 1e-10*x[0].norm());
        EXPECT_LT((x[2] - x[1]).norm(), 1e-10*x[0].norm());
    }
}


// The ALE fluid's coupled matrix in miniature: a flow unknown per node of
// an n x n grid coupled to the nodes two edges away (Rhie-Chow), each
// flow row also depending on the two mesh unknowns of the 5 x 5 nodes
// around it (the mesh derivative), the mesh rows 5-point Laplacians of
// their own component, the first grid line's also of the flow (the
// interface). The pattern is less than half symmetric, so UMFPACK's
// automatic strategy is the unsymmetric one; its symmetric strategy (AMD
// on K + K^T, diagonal pivots preferred) costs fewer flops here (0.79 of
// the unsymmetric strategy's; on turekHronFSI1's matrices 0.64), and the
// automatic choice finds it and keeps it
TEST(linearSolver, UmfpackTriesTheSymmetricStrategy)
{
    const int n = 40, N = 3*n*n;
    const sparseMatrix G = gridMatrix(n, 0.01, 0.3);
    std::vector<Eigen::Triplet<double>> t;
    for (int c = 0; c <= 2; ++c) appendTriplets(t, G, c*n*n);
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            for (int di = -2; di <= 2; ++di)
            {
                for (int dj = -2; dj <= 2; ++dj)
                {
                    const int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= n || b >= n) continue;
                    const double v = 1e-2*std::sin(i + 2.0*j + 3.0*a + b);
                    if (std::abs(di) + std::abs(dj) <= 2)
                    {
                        t.emplace_back(i + n*j, a + n*b, v);
                    }
                    for (int c = 1; c <= 2; ++c)
                    {
                        t.emplace_back(i + n*j, c*n*n + a + n*b, c*v);
                    }
                }
            }
            if (j == 0) t.emplace_back(n*n + i, i, 0.1);
        }
    }
    sparseMatrix K(N, N);
    K.setFromTriplets(t.begin(), t.end());
    K.makeCompressed();
    const vecX r = vecX::LinSpaced(N, -1, 2);

    double flops[4];
    vecX x[4];
    int k = 0;
    for
    (
        const auto o :
        {
            umfpackSolver::ordering::amd, umfpackSolver::ordering::metis,
            umfpackSolver::ordering::symmetricAmd,
            umfpackSolver::ordering::automatic
        }
    )
    {
        umfpackSolver u(o);
        u.analyzePattern(K);
        u.factorize(K);
        flops[k] = u.stats().flops;
        x[k] = u.solve(r);
        EXPECT_EQ(u.usedSymmetricStrategy(), k >= 2) << k;
        // the choice stays for the next patterns of about that size
        u.analyzePattern(K);
        u.factorize(K);
        EXPECT_EQ(u.stats().flops, flops[k]) << k;
        EXPECT_EQ(u.usedSymmetricStrategy(), k >= 2) << k;
        ++k;
    }
    EXPECT_LT(flops[2], 0.9*std::min(flops[0], flops[1]));
    EXPECT_EQ(flops[3], flops[2]);
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_LT((x[3] - x[i]).norm(), 1e-10*x[3].norm()) << i;
    }
}


// A grid matrix bordered by m dense columns and m dense rows (as the ALE
// fluid's mesh derivatives with respect to the interface dofs border the
// FSI Newton matrix): UMFPACK orders it with AMD, which sets the dense
// rows and columns aside, and the solution is the dense LU's
TEST(linearSolver, UmfpackDenseBorderUsesAMD)
{
    const int n = 20, m = 6, N = n*n + m;
    const sparseMatrix G = gridMatrix(n, 0.01, 0.3);
    std::vector<Eigen::Triplet<double>> t;
    appendTriplets(t, G);
    for (int b = 0; b < m; ++b)
    {
        const int c = n*n + b;
        t.emplace_back(c, c, 10.0);
        for (int i = 0; i < n*n; ++i)
        {
            t.emplace_back(i, c, 0.01*std::sin(0.1*i + b));
            t.emplace_back(c, i, 0.02*std::cos(0.3*i - b));
        }
    }
    sparseMatrix K(N, N);
    K.setFromTriplets(t.begin(), t.end());
    K.makeCompressed();
    const vecX r = vecX::LinSpaced(N, -1, 2);

    umfpackSolver u;
    u.analyzePattern(K);
    u.factorize(K);
    EXPECT_FALSE(u.usedMetis());
    const vecX x = u.solve(r);
    EXPECT_LT((x - denseSolve(K, r)).norm(), 1e-10*x.norm());

    // The grid alone (no dense row or column) keeps METIS
    u.analyzePattern(G);
    EXPECT_TRUE(u.usedMetis());
}
