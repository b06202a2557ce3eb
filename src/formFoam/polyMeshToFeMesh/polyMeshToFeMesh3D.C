/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    polyMeshToFeMesh (polyMeshToFeMesh.H): the 3D upgrade. Every hexahedral
    cell becomes an 8- or 27-node element in VTK order (hexShape.H); patch
    faces become element faces (hexFaceNodes order).
\*---------------------------------------------------------------------------*/
#include "polyMeshToFeMesh.H"
#include "cellModel.H"
#include "edge.H"
#include "HashTable.H"
#include "hexShape.H"

namespace
{

// The 12 edges of a hexahedron in the order of its mid-edge nodes 8-19
constexpr int hexEdges[12][2] =
{
    {0, 1}, {1, 2}, {2, 3}, {3, 0},
    {4, 5}, {5, 6}, {6, 7}, {7, 4},
    {0, 4}, {1, 5}, {2, 6}, {3, 7}
};

} // anonymous namespace


void Foam::polyMeshToFeMesh::build3D
(
    label nodesPerElement,
    const word& elementType,
    const word& materialName
)
{
    const polyMesh& mesh = mesh_;
    const word region = mesh.name();
    const pointField& pts = mesh.points();
    const faceList& faces = mesh.faces();
    const cellModel& hex = cellModel::ref(cellModel::HEX);
    const cellShapeList& shapes = mesh.cellShapes();

    fe_.nDim = 3;
    form::elementBlock block;
    block.name = region;
    block.elementType = elementType;
    block.materialName = materialName;
    block.nodesPerElement = nodesPerElement;
    block.connectivity.reserve(mesh.nCells()*nodesPerElement);

    DynamicList<Eigen::Vector3d> X;
    const auto at = [&pts](label p)
    {
        return Eigen::Vector3d(pts[p].x(), pts[p].y(), pts[p].z());
    };

    // Corners, checked: hexahedra with a positive Jacobian of the
    // trilinear map at every corner
    Eigen::Matrix<double, 8, 3> C;
    form::hexShape<8>::vecN N;
    form::hexShape<8>::matN3 dN;
    forAll(shapes, celli)
    {
        const cellShape& cs = shapes[celli];
        if (cs.model() != hex)
        {
            FatalErrorInFunction
                << "Cell " << celli << " of solid region '" << region
                << "' is not a hexahedron but a "
                << (cs.model().name() == "unknown" ? word("polyhedron")
                  : cs.model().name())
                << " with " << mesh.cells()[celli].size() << " faces"
                << " (cell centre " << mesh.cellCentres()[celli] << ")." << nl
                << "    3D solid elements (" << elementType << ") need a"
                << " mesh of hexahedra, e.g. from blockMesh."
                << exit(FatalError);
        }
        for (label k = 0; k < 8; ++k) C.row(k) = at(cs[k]).transpose();
        for (label k = 0; k < 8; ++k)
        {
            const Eigen::Vector3d xi = form::hexShape<8>::node(k);
            form::hexShape<8>::eval(xi(0), xi(1), xi(2), N, dN);
            const double detJ = (C.transpose()*dN).determinant();
            if (!(detJ > 0))
            {
                FatalErrorInFunction
                    << "Cell " << celli << " of solid region '" << region
                    << "' is inverted or degenerate: its Jacobian is "
                    << detJ << " at corner " << k << " (point "
                    << cs[k] << " at " << pts[cs[k]] << ")." << nl
                    << "    Check the mesh (checkMesh -region " << region
                    << ") and the blockMesh vertices and their order."
                    << exit(FatalError);
            }
        }
        for (label k = 0; k < 8; ++k)
        {
            if (pointToNode_[cs[k]] < 0)
            {
                pointToNode_[cs[k]] = X.size();
                X.append(at(cs[k]));
            }
        }
    }

    // Connectivity; 27 nodes: shared mid-edge nodes (by edge), mid-face
    // nodes (by polyMesh face), one centre node per cell
    HashTable<label, edge, Hash<edge>> midEdge;
    labelList midFace(mesh.nFaces(), -1);
    // polyMesh face of each local hex face of each cell (face sets)
    List<FixedList<label, 6>> cellFaces(mesh.nCells());
    forAll(shapes, celli)
    {
        const cellShape& cs = shapes[celli];
        for (label k = 0; k < 8; ++k) block.connectivity.push_back(pointToNode_[cs[k]]);

        // Local face k -> the cell's polyMesh face with the same corners
        for (label k = 0; k < 6; ++k)
        {
            const std::vector<int> fn = form::hexFaceNodes(8, k);
            cellFaces[celli][k] = -1;
            for (const label facei : mesh.cells()[celli])
            {
                const face& f = faces[facei];
                bool all = f.size() == 4;
                for (const int a : fn) all = all && f.found(cs[a]);
                if (all) cellFaces[celli][k] = facei;
            }
            if (cellFaces[celli][k] < 0)
            {
                FatalErrorInFunction
                    << "Cell " << celli << " of solid region '" << region
                    << "': no quadrilateral face matches its hexahedron"
                    << " face " << k << " (a split face?)."
                    << exit(FatalError);
            }
        }
        if (nodesPerElement != 27) continue;

        for (const auto& e : hexEdges)
        {
            const edge ed(cs[e[0]], cs[e[1]]);
            auto iter = midEdge.find(ed);
            if (iter.found())
            {
                block.connectivity.push_back(*iter);
                continue;
            }
            const label n = X.size();
            point m;
            X.append
            (
                latticePoint(celli, {ed[0], ed[1]}, m)
              ? Eigen::Vector3d(m.x(), m.y(), m.z())
              : Eigen::Vector3d(0.5*(at(ed[0]) + at(ed[1])))
            );
            midEdge.insert(ed, n);
            block.connectivity.push_back(n);
        }
        for (label k = 0; k < 6; ++k)
        {
            const label facei = cellFaces[celli][k];
            if (midFace[facei] < 0)
            {
                Eigen::Vector3d c = Eigen::Vector3d::Zero();
                for (const label p : faces[facei]) c += 0.25*at(p);
                const face& f = faces[facei];
                point m;
                if (latticePoint(celli, {f[0], f[1], f[2], f[3]}, m))
                {
                    c = Eigen::Vector3d(m.x(), m.y(), m.z());
                }
                midFace[facei] = X.size();
                X.append(c);
            }
            block.connectivity.push_back(midFace[facei]);
        }
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (label k = 0; k < 8; ++k) c += 0.125*at(cs[k]);
        point m;
        if
        (
            latticePoint
            (
                celli, {cs[0], cs[1], cs[2], cs[3], cs[4], cs[5], cs[6], cs[7]}, m
            )
        )
        {
            c = Eigen::Vector3d(m.x(), m.y(), m.z());
        }
        block.connectivity.push_back(X.size());
        X.append(c);
    }

    fe_.X.resize(X.size(), 3);
    forAll(X, i) fe_.X.row(i) = X[i].transpose();

    // Boundary patches -> face sets (element faces) and node sets
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        std::vector<form::feFace>& faceSet = fe_.faceSets[pp.name()];
        std::vector<int>& nodeSet = fe_.nodeSets[pp.name()];
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const label celli = mesh.faceOwner()[facei];
            label local = -1;
            for (label k = 0; k < 6; ++k)
            {
                if (cellFaces[celli][k] == facei) local = k;
            }
            addBoundaryFace
            (
                block, celli, local,
                form::hexFaceNodes(nodesPerElement, local),
                faceSet, nodeSet
            );
        }
        uniqueNodes(nodeSet);
    }

    fe_.blocks.push_back(std::move(block));
}
