/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of structuredQuadMesh.H: Structured nx x ny mesh of 4- or
    9-node quads (VTK node order) on the bilinear patch x(xi, eta) =
    (1-xi)(1-eta) c0 + xi (1-eta) c1 + xi eta c2 + (1-xi) eta c3 of the unit
    square, corners counter-clockwise.
\*---------------------------------------------------------------------------*/
#include "structuredQuadMesh.H"
#include "quadShape.H"
#include "formError.H"

form::feMesh form::structuredQuadMesh
(
    const std::array<Eigen::Vector2d, 4>& c,
    int nx,
    int ny,
    int nodesPerElement,
    const std::string& elementType,
    const std::string& materialName
)
{
    if (nodesPerElement != 4 && nodesPerElement != 9)
    {
        throw inputError
        (
            "nodesPerElement",
            "structuredQuadMesh: nodesPerElement must be 4 or 9, not "
          + std::to_string(nodesPerElement)
        );
    }
    if (nx < 1 || ny < 1)
    {
        throw inputError
        (
            "divisions",
            "structuredQuadMesh: need at least one element per direction"
        );
    }
    const int order = nodesPerElement == 9 ? 2 : 1;
    const int NI = order*nx + 1;
    const int NJ = order*ny + 1;
    auto id = [NI](int i, int j) { return i + j*NI; };

    feMesh mesh;
    mesh.nDim = 2;
    mesh.X.resize(NI*NJ, 2);
    for (int j = 0; j < NJ; ++j)
    {
        const double eta = double(j)/(NJ - 1);
        for (int i = 0; i < NI; ++i)
        {
            const double xi = double(i)/(NI - 1);
            const Eigen::Vector2d x =
                (1 - xi)*(1 - eta)*c[0] + xi*(1 - eta)*c[1]
              + xi*eta*c[2] + (1 - xi)*eta*c[3];
            mesh.X.row(id(i, j)) = x.transpose();
        }
    }

    elementBlock b;
    b.name = "patch";
    b.elementType = elementType;
    b.materialName = materialName;
    b.nodesPerElement = nodesPerElement;
    b.connectivity.reserve(std::size_t(nx)*ny*nodesPerElement);
    for (int ey = 0; ey < ny; ++ey)
    {
        for (int ex = 0; ex < nx; ++ex)
        {
            const int i = order*ex, j = order*ey;
            // Corners counter-clockwise from (xi, eta) = (0, 0)
            b.connectivity.insert
            (
                b.connectivity.end(),
                {
                    id(i, j), id(i + order, j),
                    id(i + order, j + order), id(i, j + order)
                }
            );
            if (order == 2)
            {
                // Mid-side nodes of edges 0-1, 1-2, 2-3, 3-0, then centre
                b.connectivity.insert
                (
                    b.connectivity.end(),
                    {
                        id(i + 1, j), id(i + 2, j + 1), id(i + 1, j + 2),
                        id(i, j + 1), id(i + 1, j + 1)
                    }
                );
            }
        }
    }
    mesh.blocks.push_back(b);

    for (int j = 0; j < NJ; ++j)
    {
        mesh.nodeSets["left"].push_back(id(0, j));
        mesh.nodeSets["right"].push_back(id(NI - 1, j));
    }
    for (int i = 0; i < NI; ++i)
    {
        mesh.nodeSets["bottom"].push_back(id(i, 0));
        mesh.nodeSets["top"].push_back(id(i, NJ - 1));
    }

    // Boundary edges: local edge k of an element runs from corner k to
    // corner k+1 (plus mid-side node 4+k for 9-node elements)
    const elementBlock& blk = mesh.blocks[0];
    auto face = [&](int ex, int ey, int edge)
    {
        const int e = ex + ey*nx;
        const int* n = blk.nodes(e);
        feFace f;
        f.block = 0;
        f.element = e;
        f.localFace = edge;
        for (const int a : quadEdgeNodes(order == 2 ? 9 : 4, edge))
        {
            f.nodes.push_back(n[a]);
        }
        return f;
    };
    for (int ex = 0; ex < nx; ++ex)
    {
        mesh.faceSets["bottom"].push_back(face(ex, 0, 0));
        mesh.faceSets["top"].push_back(face(ex, ny - 1, 2));
    }
    for (int ey = 0; ey < ny; ++ey)
    {
        mesh.faceSets["right"].push_back(face(nx - 1, ey, 1));
        mesh.faceSets["left"].push_back(face(0, ey, 3));
    }
    return mesh;
}


int form::nearestNode(const feMesh& mesh, const Eigen::Vector2d& x)
{
    int best = -1;
    double dBest = 0;
    for (int n = 0; n < mesh.nNodes(); ++n)
    {
        const double d = (mesh.X.row(n).transpose() - x).squaredNorm();
        if (best < 0 || d < dBest)
        {
            best = n;
            dBest = d;
        }
    }
    return best;
}
