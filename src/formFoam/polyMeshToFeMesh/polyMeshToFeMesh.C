/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of polyMeshToFeMesh.H: Upgrades a one-cell-thick 2D
    OpenFOAM polyMesh (from blockMesh) to a finite-element quad mesh.
\*---------------------------------------------------------------------------*/
#include "polyMeshToFeMesh.H"
#include "shellSet.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "HashTable.H"
#include "edge.H"
#include "quadShape.H"
#include "cellLattice.H"

Foam::Vector2D<Foam::scalar>
Foam::polyMeshToFeMesh::project(const point& p) const
{
    if (projection_ == projection::planar)
    {
        return Vector2D<scalar>(p.x(), p.y());
    }
    const scalar z = (p & axis_);
    const scalar r = mag(p - z*axis_);
    return Vector2D<scalar>(r, z);
}


Eigen::Vector2d Foam::polyMeshToFeMesh::toPlane(const point& p) const
{
    const Vector2D<scalar> q = project(p);
    return Eigen::Vector2d(q.x(), q.y());
}


form::vecX Foam::polyMeshToFeMesh::toFe(const point& p) const
{
    if (projection_ == projection::space)
    {
        return Eigen::Vector3d(p.x(), p.y(), p.z());
    }
    return toPlane(p);
}


Foam::vector Foam::polyMeshToFeMesh::toSpace
(
    const point& p,
    const form::vecX& v
) const
{
    if (projection_ == projection::space)
    {
        return vector(v(0), v(1), v(2));
    }
    if (projection_ == projection::planar)
    {
        return vector(v(0), v(1), 0);
    }
    const vector radial = p - (p & axis_)*axis_;
    const scalar r = mag(radial);
    const vector er = r > SMALL ? radial/r : Zero;
    return v(0)*er + v(1)*axis_;
}


void Foam::polyMeshToFeMesh::addBoundaryFace
(
    const form::elementBlock& block,
    label celli,
    label localFace,
    const std::vector<int>& localNodes,
    std::vector<form::feFace>& faceSet,
    std::vector<int>& nodeSet
)
{
    form::feFace fef;
    fef.block = 0;
    fef.element = celli;
    fef.localFace = localFace;
    const int* en = block.nodes(celli);
    for (const int a : localNodes) fef.nodes.push_back(en[a]);
    for (const int n : fef.nodes) nodeSet.push_back(n);
    faceSet.push_back(fef);
}


void Foam::polyMeshToFeMesh::uniqueNodes(std::vector<int>& nodeSet)
{
    std::sort(nodeSet.begin(), nodeSet.end());
    nodeSet.erase(std::unique(nodeSet.begin(), nodeSet.end()), nodeSet.end());
}


bool Foam::polyMeshToFeMesh::latticePoint
(
    const label celli,
    std::initializer_list<label> corners,
    point& p
) const
{
    if (lattice_.empty()) return false;
    const FixedList<point, 27>& L = lattice_[celli];
    const pointField& pts = mesh_.points();
    label a = 0, b = 0, c = 0;
    for (const label pointi : corners)
    {
        // the nearest corner of the lattice (0 or 2 in each index)
        label best = 0;
        scalar dmin = GREAT;
        for (const label k : {0, 2, 6, 8, 18, 20, 24, 26})
        {
            const scalar d = magSqr(L[k] - pts[pointi]);
            if (d < dmin)
            {
                dmin = d;
                best = k;
            }
        }
        a += best % 3;
        b += (best/3) % 3;
        c += best/9;
    }
    const label n = corners.size();
    p = L[a/n + 3*(b/n) + 9*(c/n)];
    return true;
}


Foam::polyMeshToFeMesh::polyMeshToFeMesh
(
    const polyMesh& mesh,
    label nDim,
    const fileName& properties,
    label nodesPerElement,
    const word& elementType,
    const word& materialName,
    const form::shellSection& shell
)
:
    mesh_(mesh),
    projection_(projection::planar),
    axis_(0, 0, 1),
    pointToNode_(mesh.nPoints(), -1),
    frontFace_(mesh.nCells(), -1)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const word region = mesh.name();

    // Front/back patches decide the projection
    boolList isFrontBack(patches.size(), false);
    bool anyEmpty = false, anyWedge = false;
    forAll(patches, patchi)
    {
        if (isA<emptyPolyPatch>(patches[patchi]))
        {
            isFrontBack[patchi] = true;
            anyEmpty = true;
        }
        else if (isA<wedgePolyPatch>(patches[patchi]))
        {
            isFrontBack[patchi] = true;
            anyWedge = true;
            axis_ = refCast<const wedgePolyPatch>(patches[patchi]).axis();
            axis_ /= mag(axis_);
        }
    }
    // The two wedge patches report opposite axis directions: orient the
    // axis so that its largest component is positive, so that the axial
    // FE coordinate grows with the global coordinate it follows (y for an
    // axis along y), whatever the patch order
    if (anyWedge)
    {
        direction d = 0;
        for (direction i = 1; i < 3; ++i)
        {
            if (mag(axis_[i]) > mag(axis_[d])) d = i;
        }
        if (axis_[d] < 0) axis_ = -axis_;
    }
    // Mid-side nodes where blockMesh puts them (curved edges, projected
    // faces), else on the chords
    if (nodesPerElement == 9 || nodesPerElement == 27)
    {
        string why;
        lattice_ = cellLattice(mesh, why);
        if (lattice_.empty())
        {
            Info<< "Solid region '" << region << "': mid-side nodes on the"
                << " cells' chords (" << why.c_str() << ")" << endl;
        }
    }

    if (nDim == 3)
    {
        if (anyEmpty || anyWedge)
        {
            FatalErrorInFunction
                << "The mesh of solid region '" << region << "' has 'empty'"
                << " or 'wedge' patches (a 2D mesh), but " << properties
                << " gives analysisType solid3D." << nl
                << "    Use planeStrain or axisymmetric, or a 3D mesh whose"
                << " patches are all of type patch or wall."
                << exit(FatalError);
        }
        projection_ = projection::space;
        if (form::shellSet::isShellType(elementType))
        {
            buildShell(elementType, materialName, shell, properties);
            return;
        }
        build3D(nodesPerElement, elementType, materialName);
        return;
    }
    if (!anyEmpty && !anyWedge)
    {
        FatalErrorInFunction
            << "The mesh of solid region '" << region << "' has no 'empty' or"
            << " 'wedge' patches (a 3D mesh), but " << properties
            << " gives a 2D analysisType." << nl
            << "    2D solid meshes must be one cell thick with empty (plane"
            << " strain) or wedge (axisymmetric) front and back patches;"
            << " a 3D mesh needs analysisType solid3D."
            << exit(FatalError);
    }
    if (anyWedge) projection_ = projection::wedge;
    build2D(isFrontBack, nodesPerElement, elementType, materialName);
}


void Foam::polyMeshToFeMesh::build2D
(
    const boolList& isFrontBack,
    label nodesPerElement,
    const word& elementType,
    const word& materialName
)
{
    const polyMesh& mesh = mesh_;
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const word region = mesh.name();

    // The front face of every cell: the one of its two front/back faces
    // that lies on the positive side (largest z for planar meshes; for
    // wedges, the side of the wedge normal's positive component).
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    labelList nFrontBack(mesh.nCells(), 0);
    forAll(patches, patchi)
    {
        if (!isFrontBack[patchi]) continue;
        const polyPatch& pp = patches[patchi];
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const label celli = mesh.faceOwner()[facei];
            ++nFrontBack[celli];
            const label other = frontFace_[celli];
            const bool better =
                other < 0
             || (
                    projection_ == projection::planar
                  ? Cf[facei].z() > Cf[other].z()
                  : (Sf[facei] & vector(0, 0, 1)) > (Sf[other] & vector(0, 0, 1))
                );
            if (better) frontFace_[celli] = facei;
        }
    }

    fe_.nDim = 2;
    DynamicList<Eigen::Vector2d> X;
    form::elementBlock block;
    block.name = region;
    block.elementType = elementType;
    block.materialName = materialName;
    block.nodesPerElement = nodesPerElement;
    block.connectivity.reserve(mesh.nCells()*nodesPerElement);

    HashTable<label, edge, Hash<edge>> midNode;
    const faceList& faces = mesh.faces();
    const pointField& pts = mesh.points();

    // corner nodes of each cell in counter-clockwise order
    List<FixedList<label, 4>> cellCorners(mesh.nCells());

    forAll(frontFace_, celli)
    {
        if (nFrontBack[celli] != 2 || faces[frontFace_[celli]].size() != 4)
        {
            FatalErrorInFunction
                << "Cell " << celli << " of solid region '" << region
                << "' cannot be upgraded to a quad element: it has "
                << nFrontBack[celli] << " faces on empty/wedge patches and a"
                << " front face with "
                << (frontFace_[celli] >= 0 ? faces[frontFace_[celli]].size() : 0)
                << " points." << nl
                << "    2D solid meshes must be one cell thick, made of"
                << " hexahedra (blockMesh with 1 cell in the third direction)."
                << exit(FatalError);
        }
        const face& f = faces[frontFace_[celli]];
        FixedList<label, 4> c;
        Eigen::Matrix<double, 4, 2> P;
        for (label k = 0; k < 4; ++k)
        {
            c[k] = f[k];
            P.row(k) = toPlane(pts[f[k]]).transpose();
        }
        // signed area (shoelace); reverse to counter-clockwise if needed
        scalar area = 0;
        for (label k = 0; k < 4; ++k)
        {
            const label l = (k + 1) % 4;
            area += P(k, 0)*P(l, 1) - P(l, 0)*P(k, 1);
        }
        if (area < 0)
        {
            std::swap(c[1], c[3]);
            P.row(1).swap(P.row(3));
        }
        // convexity: every corner's cross product positive
        for (label k = 0; k < 4; ++k)
        {
            const Eigen::Vector2d a = P.row((k + 1) % 4) - P.row(k);
            const Eigen::Vector2d b = P.row((k + 3) % 4) - P.row(k);
            if (a(0)*b(1) - a(1)*b(0) <= 0)
            {
                FatalErrorInFunction
                    << "Cell " << celli << " of solid region '" << region
                    << "' is degenerate or not convex in the solid plane"
                    << " (corner " << k << " at " << pts[c[k]] << ")." << nl
                    << "    Check the blockMesh vertices and their order."
                    << exit(FatalError);
            }
        }
        cellCorners[celli] = c;
        for (label k = 0; k < 4; ++k)
        {
            if (pointToNode_[c[k]] < 0)
            {
                pointToNode_[c[k]] = X.size();
                X.append(toPlane(pts[c[k]]));
            }
        }
    }

    forAll(cellCorners, celli)
    {
        const FixedList<label, 4>& c = cellCorners[celli];
        for (label k = 0; k < 4; ++k)
        {
            block.connectivity.push_back(pointToNode_[c[k]]);
        }
        if (nodesPerElement == 9)
        {
            for (label k = 0; k < 4; ++k)
            {
                const edge e(c[k], c[(k + 1) % 4]);
                auto iter = midNode.find(e);
                if (iter.found())
                {
                    block.connectivity.push_back(*iter);
                }
                else
                {
                    const label n = X.size();
                    point m;
                    X.append
                    (
                        latticePoint(celli, {e[0], e[1]}, m)
                      ? toPlane(m)
                      : Eigen::Vector2d
                        (
                            0.5*(X[pointToNode_[e[0]]] + X[pointToNode_[e[1]]])
                        )
                    );
                    midNode.insert(e, n);
                    block.connectivity.push_back(n);
                }
            }
            Eigen::Vector2d centre = Eigen::Vector2d::Zero();
            for (label k = 0; k < 4; ++k) centre += 0.25*X[pointToNode_[c[k]]];
            point m;
            if (latticePoint(celli, {c[0], c[1], c[2], c[3]}, m))
            {
                centre = toPlane(m);
            }
            block.connectivity.push_back(X.size());
            X.append(centre);
        }
    }

    // Back points: same FE node as the front point of the same cell that
    // projects onto the same FE-plane position
    forAll(cellCorners, celli)
    {
        for (const label facei : mesh.cells()[celli])
        {
            for (const label pointi : faces[facei])
            {
                if (pointToNode_[pointi] >= 0) continue;
                const Eigen::Vector2d q = toPlane(pts[pointi]);
                scalar best = GREAT;
                for (const label c : cellCorners[celli])
                {
                    const scalar d = (toPlane(pts[c]) - q).norm();
                    if (d < best)
                    {
                        best = d;
                        pointToNode_[pointi] = pointToNode_[c];
                    }
                }
            }
        }
    }

    fe_.X.resize(X.size(), 2);
    forAll(X, i) fe_.X.row(i) = X[i].transpose();

    // Boundary patches -> face sets (element edges) and node sets
    forAll(patches, patchi)
    {
        if (isFrontBack[patchi]) continue;
        const polyPatch& pp = patches[patchi];
        std::vector<form::feFace>& faceSet = fe_.faceSets[pp.name()];
        std::vector<int>& nodeSet = fe_.nodeSets[pp.name()];
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const label celli = mesh.faceOwner()[facei];
            const FixedList<label, 4>& c = cellCorners[celli];
            // the cell edge whose two corners both belong to this face
            label localEdge = -1;
            for (label k = 0; k < 4; ++k)
            {
                if (faces[facei].found(c[k]) && faces[facei].found(c[(k + 1) % 4]))
                {
                    localEdge = k;
                }
            }
            if (localEdge < 0) continue;    // face on the axis of a wedge
            addBoundaryFace
            (
                block, celli, localEdge,
                form::quadEdgeNodes(nodesPerElement, localEdge),
                faceSet, nodeSet
            );
        }
        uniqueNodes(nodeSet);
    }

    fe_.blocks.push_back(std::move(block));
}
