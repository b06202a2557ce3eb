/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    polyMeshToFeMesh (polyMeshToFeMesh.H): the shell upgrade. A sheet
    meshed one cell thick becomes a mesh of shell elements on its
    mid-surface: hexahedra (blockMesh) 4-node elements (MITC4, MITC4+),
    prisms (extrudeMesh from a triangulated surface) 3-node elements
    (MITC3+):
      - the thickness direction of a hexahedron is the pair of its
        opposite faces that both lie on the boundary and are closest to
        each other, the four cell edges joining them its through-thickness
        edges; a prism's are the three edges joining its triangles, which
        must both lie on the boundary;
      - every through-thickness edge becomes one shell node at its
        midpoint (shared by the cells around it); both of its polyMesh
        points map to that node;
      - the elements are oriented alike (their lamina normals on the same
        side of the sheet) by a walk across shared element edges; an edge
        shared by more than two elements (a branch) or a sheet that cannot
        be oriented (a Moebius strip) stops the run;
      - a node's initial director is its through-thickness edge (the
        exact normal of a curved sheet whose faces blockMesh puts on the
        geometry, also on its edges and symmetry planes);
      - the thickness is the length of the through-thickness edges, which
        must agree to 1 % unless the solidProperties give it;
      - every patch becomes a node set and a face set: a side face of the
        sheet the shell edge it covers (2 nodes: tractions on it act on
        the edge's length times the thickness), a face of the sheet its
        element's mid-surface quadrilateral or triangle, ordered so that
        its normal is the patch's outward one (tractions per unit area and
        follower pressures act on the mid-surface).
\*---------------------------------------------------------------------------*/
#include "polyMeshToFeMesh.H"
#include "cellModel.H"
#include "edge.H"
#include "HashTable.H"
#include "shellSet.H"
#include <algorithm>
#include <deque>

namespace
{

// For each direction of a hexahedron (r, s, t): its two faces' local
// corners and the through-thickness edges in the cyclic order of the
// first face
constexpr int throughEdges[3][4][2] =
{
    {{0, 1}, {3, 2}, {7, 6}, {4, 5}},   // r: faces 0 3 7 4 and 1 2 6 5
    {{0, 3}, {1, 2}, {5, 6}, {4, 7}},   // s: faces 0 1 5 4 and 3 2 6 7
    {{0, 4}, {1, 5}, {2, 6}, {3, 7}}    // t: faces 0 1 2 3 and 4 5 6 7
};

// A prism (OpenFOAM's model: triangles 0 1 2 and 3 4 5): its through-
// thickness edges (the fourth repeats the first: unused)
constexpr int prismEdges[4][2] = {{0, 3}, {1, 4}, {2, 5}, {0, 3}};

} // anonymous namespace


void Foam::polyMeshToFeMesh::buildShell
(
    const word& elementType,
    const word& materialName,
    const form::shellSection& section,
    const fileName& properties
)
{
    const polyMesh& mesh = mesh_;
    const word region = mesh.name();
    const pointField& pts = mesh.points();
    const cellModel& hex = cellModel::ref(cellModel::HEX);
    const cellShapeList& shapes = mesh.cellShapes();
    const label nCells = mesh.nCells();

    const cellModel& prism = cellModel::ref(cellModel::PRISM);
    // Nodes per element: 3 (MITC3+: a sheet of prisms), else 4 (hexahedra)
    const int npe = form::shellSet::nodesPerElement(elementType);

    // The boundary face of cell celli whose npe corners are the given
    // side (0, 1) of the through-thickness edges e (-1: none)
    const auto boundaryFace =
        [&](label celli, const int (&e)[4][2], int side)
    {
        const cellShape& cs = shapes[celli];
        for (const label facei : mesh.cells()[celli])
        {
            if (mesh.isInternalFace(facei)) continue;
            const face& f = mesh.faces()[facei];
            if (f.size() != npe) continue;
            bool all = true;
            for (int k = 0; k < npe; ++k) all = all && f.found(cs[e[k][side]]);
            if (all) return facei;
        }
        return label(-1);
    };

    fe_.nDim = 3;
    form::elementBlock block;
    block.name = region;
    block.elementType = elementType;
    block.materialName = materialName;
    block.nodesPerElement = npe;
    block.shell = section;
    block.connectivity.reserve(npe*nCells);

    HashTable<label, edge, Hash<edge>> midNode;
    DynamicList<Eigen::Vector3d> X;
    DynamicList<scalar> edgeLength;
    // Per cell: its thickness direction's two boundary faces
    List<FixedList<label, 2>> sheetFaces(nCells);

    forAll(shapes, celli)
    {
        const cellShape& cs = shapes[celli];
        if (cs.model() != (npe == 3 ? prism : hex))
        {
            FatalErrorInFunction
                << "Cell " << celli << " of solid region '" << region
                << "' is not a " << (npe == 3 ? "prism" : "hexahedron")
                << " (cell centre " << mesh.cellCentres()[celli] << ")."
                << nl << "    Shell elements (" << elementType << ") take"
                << " the mid-surface of a sheet meshed one "
                << (npe == 3 ? "prism" : "hexahedron") << " thick ("
                << (npe == 3
                    ? "MITC3+: prisms, e.g. extrudeMesh from a triangulated"
                      " surface; MITC4, MITC4+: hexahedra"
                    : "MITC4, MITC4+: hexahedra; MITC3+: prisms")
                << ")." << exit(FatalError);
        }
        int best = -1;
        scalar bestLength = GREAT;
        for (int d = 0; d < (npe == 3 ? 1 : 3); ++d)
        {
            const int (&te)[4][2] = npe == 3 ? prismEdges : throughEdges[d];
            const label fa = boundaryFace(celli, te, 0);
            const label fb = boundaryFace(celli, te, 1);
            if (fa < 0 || fb < 0) continue;
            scalar length = 0;
            for (int k = 0; k < npe; ++k)
            {
                length += mag(pts[cs[te[k][1]]] - pts[cs[te[k][0]]])/npe;
            }
            if (length < bestLength)
            {
                best = d;
                bestLength = length;
                sheetFaces[celli] = {fa, fb};
            }
        }
        if (best < 0)
        {
            FatalErrorInFunction
                << "Cell " << celli << " of solid region '" << region
                << "' (centre " << mesh.cellCentres()[celli] << ") has no"
                << " two opposite faces on the boundary: the sheet is not"
                << " meshed one cell thick." << nl
                << "    Shell elements (" << elementType << ") need a sheet"
                << " of one cell through its thickness."
                << exit(FatalError);
        }
        const int (&te)[4][2] = npe == 3 ? prismEdges : throughEdges[best];
        for (int k = 0; k < npe; ++k)
        {
            const auto& e = te[k];
            const edge ed(cs[e[0]], cs[e[1]]);
            auto iter = midNode.find(ed);
            label n;
            if (iter.found())
            {
                n = *iter;
            }
            else
            {
                n = X.size();
                const point m = 0.5*(pts[ed[0]] + pts[ed[1]]);
                X.append(Eigen::Vector3d(m.x(), m.y(), m.z()));
                edgeLength.append(mag(pts[ed[1]] - pts[ed[0]]));
                midNode.insert(ed, n);
            }
            for (const label p : {ed[0], ed[1]})
            {
                if (pointToNode_[p] >= 0 && pointToNode_[p] != n)
                {
                    FatalErrorInFunction
                        << "Solid region '" << region << "': point " << p
                        << " at " << pts[p] << " lies on two through-"
                        << "thickness edges (cell " << celli << "): the"
                        << " sheet is not meshed one cell thick."
                        << exit(FatalError);
                }
                pointToNode_[p] = n;
            }
            block.connectivity.push_back(n);
        }
    }

    // Orientation: a walk across shared element edges; neighbours must
    // run their shared edge in opposite directions
    HashTable<DynamicList<label>, edge, Hash<edge>> edgeElements;
    const auto nodesOf = [&block, npe](label e, int k)
    {
        return block.connectivity[npe*e + (k % npe)];
    };
    // The normal of element e's mid-surface (its orientation)
    const auto normalOf = [&](label e)
    {
        return
            npe == 3
          ? Eigen::Vector3d
            (
                (X[nodesOf(e, 1)] - X[nodesOf(e, 0)]).cross
                (
                    X[nodesOf(e, 2)] - X[nodesOf(e, 0)]
                )
            )
          : Eigen::Vector3d
            (
                (X[nodesOf(e, 2)] - X[nodesOf(e, 0)]).cross
                (
                    X[nodesOf(e, 3)] - X[nodesOf(e, 1)]
                )
            );
    };
    for (label e = 0; e < nCells; ++e)
    {
        for (int k = 0; k < npe; ++k)
        {
            const edge ed(nodesOf(e, k), nodesOf(e, k + 1));
            edgeElements(ed).append(e);
        }
    }
    const auto toPoint = [&X](label n)
    {
        return point(X[n](0), X[n](1), X[n](2));
    };
    forAllConstIters(edgeElements, iter)
    {
        if (iter.val().size() > 2)
        {
            const edge& ed = iter.key();
            FatalErrorInFunction
                << "Solid region '" << region << "': the sheet branches at"
                << " the shell edge between " << toPoint(ed[0]) << " and "
                << toPoint(ed[1]) << " (" << iter.val().size()
                << " elements meet there); branched shells are not"
                << " supported." << exit(FatalError);
        }
    }
    labelList flip(nCells, -1);
    const auto runs = [&](label e, label a, label b)
    {
        // Does element e (as flipped) run from node a to node b?
        for (int k = 0; k < npe; ++k)
        {
            const label p = nodesOf(e, k), q = nodesOf(e, k + 1);
            if (p == a && q == b) return flip[e] == 0;
            if (p == b && q == a) return flip[e] == 1;
        }
        return false;
    };
    for (label seed = 0; seed < nCells; ++seed)
    {
        if (flip[seed] >= 0) continue;
        // The seed's director points away from its sheet face on the
        // patch of lower index (the sheet side met first in the boundary
        // file)
        {
            const label fa = sheetFaces[seed][0], fb = sheetFaces[seed][1];
            const label pa = mesh.boundaryMesh().whichPatch(fa);
            const label pb = mesh.boundaryMesh().whichPatch(fb);
            const label from = pa <= pb ? fa : fb;
            const label to = pa <= pb ? fb : fa;
            const vector up =
                mesh.faceCentres()[to] - mesh.faceCentres()[from];
            const Eigen::Vector3d d = normalOf(seed);
            flip[seed] = (d(0)*up.x() + d(1)*up.y() + d(2)*up.z()) < 0;
        }
        std::deque<label> queue{seed};
        while (!queue.empty())
        {
            const label e = queue.front();
            queue.pop_front();
            for (int k = 0; k < npe; ++k)
            {
                const label a = nodesOf(e, k), b = nodesOf(e, k + 1);
                // directed as e runs it
                const label from = runs(e, a, b) ? a : b;
                const label to = from == a ? b : a;
                for (const label f : edgeElements[edge(a, b)])
                {
                    if (f == e) continue;
                    if (flip[f] < 0)
                    {
                        flip[f] = 0;
                        if (runs(f, from, to)) flip[f] = 1;
                        queue.push_back(f);
                    }
                    else if (runs(f, from, to))
                    {
                        FatalErrorInFunction
                            << "Solid region '" << region << "': the sheet"
                            << " cannot be oriented (cells " << e << " and "
                            << f << " disagree on which side is up: a"
                            << " Moebius strip?)" << exit(FatalError);
                    }
                }
            }
        }
    }
    for (label e = 0; e < nCells; ++e)
    {
        if (flip[e] == 1)
        {
            std::swap
            (
                block.connectivity[npe*e + 1], block.connectivity[npe*e + npe - 1]
            );
        }
    }

    // Thickness: from the solidProperties, else from the mesh
    const scalar tMin = min(edgeLength), tMax = max(edgeLength);
    const scalar tMean = sum(edgeLength)/edgeLength.size();
    if (!(block.shell.thickness > 0))
    {
        if (tMax - tMin > 0.01*tMean)
        {
            FatalErrorInFunction
                << "The sheet of solid region '" << region << "' varies in"
                << " thickness from " << tMin << " to " << tMax
                << " across its cells; give the shell's thickness in "
                << properties << " (shell { thickness ...; })"
                << exit(FatalError);
        }
        block.shell.thickness = tMean;
    }
    Info<< "Solid region '" << region << "': " << nCells << " "
        << elementType << " shell elements on the mid-surface of the sheet,"
        << " thickness " << block.shell.thickness
        << (section.thickness > 0 ? " (solidProperties)" : " (mesh)")
        << ", " << block.shell.points
        << (block.shell.lobatto ? " Gauss-Lobatto" : " Gauss")
        << " points through it" << endl;

    fe_.X.resize(X.size(), 3);
    forAll(X, i) fe_.X.row(i) = X[i].transpose();
    // The directors: the through-thickness edges (shellSet orients them)
    fe_.directors.setZero(X.size(), 3);
    forAllConstIters(midNode, iter)
    {
        const edge& ed = iter.key();
        const vector d = pts[ed[1]] - pts[ed[0]];
        fe_.directors.row(*iter) << d.x(), d.y(), d.z();
    }

    // Patches -> node sets (the shell nodes of their faces) and face sets:
    // a side face of the sheet becomes the shell edge between its two
    // through-thickness edges (2 nodes, localFace = the element's edge),
    // a sheet face the element's mid-surface quadrilateral or triangle
    // (ordered counter-clockwise seen from outside the patch, so that its
    // normal is the patch's outward normal, localFace = -1)
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        std::vector<int>& nodeSet = fe_.nodeSets[pp.name()];
        std::vector<form::feFace>& faceSet = fe_.faceSets[pp.name()];
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const label celli = mesh.faceOwner()[facei];
            const face& f = pp[i];
            const int* el = block.connectivity.data() + npe*celli;
            if (facei == sheetFaces[celli][0] || facei == sheetFaces[celli][1])
            {
                const Eigen::Vector3d d = normalOf(celli);
                const vector& n = mesh.faceAreas()[facei];
                const bool along = d(0)*n.x() + d(1)*n.y() + d(2)*n.z() > 0;
                std::vector<int> nodes(el, el + npe);
                if (!along) std::reverse(nodes.begin() + 1, nodes.end());
                faceSet.push_back({0, int(celli), -1, nodes});
                nodeSet.insert(nodeSet.end(), nodes.begin(), nodes.end());
                continue;
            }
            std::vector<int> nodes;
            forAll(f, k)
            {
                auto iter = midNode.find(edge(f[k], f.nextLabel(k)));
                if (iter.found()) nodes.push_back(*iter);
            }
            if (nodes.size() != 2) continue;
            int local = -1;
            for (int k = 0; k < npe; ++k)
            {
                const edge ek(el[k], el[(k + 1) % npe]);
                if (ek == edge(nodes[0], nodes[1])) local = k;
            }
            if (local >= 0)
            {
                // In the element's sense of its edge
                nodes = {el[local], el[(local + 1) % npe]};
            }
            faceSet.push_back({0, int(celli), local, nodes});
            nodeSet.insert(nodeSet.end(), nodes.begin(), nodes.end());
        }
        uniqueNodes(nodeSet);
    }

    fe_.blocks.push_back(std::move(block));
    form::shellSet::assignNodeDofs(fe_);
}
