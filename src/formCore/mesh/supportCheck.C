/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    form::unsupportedPieces (supportCheck.H)
\*---------------------------------------------------------------------------*/
#include "supportCheck.H"
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace form
{

namespace
{

//- Union-find root with path halving
int root(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

std::string num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.6g", std::abs(v) < 1e-12 ? 0.0 : v);
    return buf;
}

} // namespace


std::vector<freePiece> unsupportedPieces
(
    const feMesh& mesh,
    analysisType analysis,
    const std::function<bool(int)>& constrained,
    const std::vector<int>& supportedNodes
)
{
    const int nNodes = mesh.nNodes();
    const int nDim = mesh.nDim;
    const dofMap dofs = dofMap::of(mesh);
    std::vector<int> parent(nNodes);
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<bool> used(nNodes, false);
    for (const elementBlock& b : mesh.blocks)
    {
        for (int e = 0; e < b.nElements(); ++e)
        {
            const int* n = b.nodes(e);
            used[n[0]] = true;
            for (int a = 1; a < b.nodesPerElement; ++a)
            {
                used[n[a]] = true;
                parent[root(parent, n[a])] = root(parent, n[0]);
            }
        }
    }

    // Pieces numbered in the order of their first element
    std::vector<int> pieceOfRoot(nNodes, -1);
    std::vector<int> elementsOf;
    for (const elementBlock& b : mesh.blocks)
    {
        for (int e = 0; e < b.nElements(); ++e)
        {
            int& p = pieceOfRoot[root(parent, b.nodes(e)[0])];
            if (p < 0)
            {
                p = int(elementsOf.size());
                elementsOf.push_back(0);
            }
            ++elementsOf[p];
        }
    }
    const int nPieces = int(elementsOf.size());
    std::vector<std::vector<int>> nodesOf(nPieces);
    for (int n = 0; n < nNodes; ++n)
    {
        if (used[n]) nodesOf[pieceOfRoot[root(parent, n)]].push_back(n);
    }
    std::vector<bool> supported(nPieces, false);
    for (const int n : supportedNodes)
    {
        if (n >= 0 && n < nNodes && used[n])
        {
            supported[pieceOfRoot[root(parent, n)]] = true;
        }
    }

    const bool axi = analysis == analysisType::axisymmetric;
    std::vector<freePiece> result;
    for (int p = 0; p < nPieces; ++p)
    {
        if (supported[p]) continue;
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        for (const int n : nodesOf[p]) c += mesh.X.row(n).head<2>().transpose();
        c /= double(nodesOf[p].size());
        double L = 0;
        for (const int n : nodesOf[p])
        {
            L = std::max(L, (mesh.X.row(n).head<2>().transpose() - c).norm());
        }
        if (L == 0) L = 1;

        // A^T A of the modes at the constrained dofs
        const int nModes = axi ? 1 : 3;
        Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
        for (const int n : nodesOf[p])
        {
            const Eigen::Vector2d r = mesh.X.row(n).head<2>().transpose() - c;
            for (int k = 0; k < 2; ++k)
            {
                if (!constrained(dofs.dof(n, k))) continue;
                Eigen::Vector3d row = Eigen::Vector3d::Zero();
                if (axi)
                {
                    row(0) = k == 1 ? 1 : 0;
                }
                else
                {
                    row(0) = k == 0 ? 1 : 0;
                    row(1) = k == 1 ? 1 : 0;
                    row(2) = (k == 0 ? -r(1) : r(0))/L;
                }
                AtA += row*row.transpose();
            }
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig
        (
            AtA.topLeftCorner(nModes, nModes)
        );
        const Eigen::VectorXd lambda = eig.eigenvalues();   // ascending
        const double tol = 1e-10*(1 + lambda.maxCoeff());
        int nFree = 0;
        while (nFree < nModes && lambda(nFree) <= tol) ++nFree;
        if (nFree == 0) continue;

        freePiece f;
        f.piece = p;
        f.nPieces = nPieces;
        f.nElements = elementsOf[p];
        f.centre = c;
        f.nFreeModes = nFree;
        if (axi)
        {
            f.description = "translation in z (no node held axially)";
        }
        else if (nFree == 3)
        {
            f.description =
                "translations in x and y and rotation (no constraint at all)";
        }
        else if (nFree == 1)
        {
            const Eigen::Vector3d v = eig.eigenvectors().col(0);
            const double rate = v(2)/L;
            if (std::abs(v(2)) < 1e-8)
            {
                const Eigen::Vector2d d = v.head<2>().normalized();
                f.description =
                    std::abs(d(1)) < 1e-8 ? "translation in x"
                  : std::abs(d(0)) < 1e-8 ? "translation in y"
                  : "translation along (" + num(d(0)) + ", " + num(d(1)) + ")";
            }
            else
            {
                // a e_x + b e_y + rate (-(y - c_y), x - c_x) is the rotation
                // about c + (-b, a)/rate
                f.description =
                    "rotation about (" + num(c(0) - v(1)/rate) + ", "
                  + num(c(1) + v(0)/rate) + ")";
            }
        }
        else
        {
            // Two free modes: name those among e_x, e_y, rotation about
            // the centre that are free
            std::vector<std::string> names;
            const char* mode[3] = {"translation in x", "translation in y",
                                   "rotation"};
            for (int m = 0; m < 3; ++m)
            {
                if (AtA(m, m) <= tol) names.push_back(mode[m]);
            }
            f.description = "two rigid-body modes";
            if (!names.empty())
            {
                f.description += " (";
                for (std::size_t i = 0; i < names.size(); ++i)
                {
                    f.description += (i ? ", " : "") + names[i];
                }
                f.description += ")";
            }
        }
        result.push_back(f);
    }
    return result;
}

} // namespace form
