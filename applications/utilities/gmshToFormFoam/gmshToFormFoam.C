/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Application
    gmshToFormFoam

Description
    Converts a Gmsh mesh of hexahedra (MSH 2.2 or 4.1, ASCII) into the
    polyMesh of a formFoam solid region, keeping the geometry of its
    second-order elements:
      - every hexahedron (8 or 27 nodes) becomes a hex cell of
        constant/<region>/polyMesh (its corner nodes are the points);
      - every physical surface group of quadrilaterals (4 or 9 nodes)
        becomes a patch of that name (type patch); boundary faces in no
        group go to the patch 'defaultFaces';
      - the nodes of 27-node hexahedra are written to
        constant/<region>/polyMesh/cellLattice (27 points per cell), from
        which formFoam places the mid-side, mid-face and centre nodes of
        its 27-node elements (cellLattice.H): curved CAD surfaces stay
        curved. 8-node hexahedra give straight edges (chords).

    From a CAD file to a case: in Gmsh, import the STEP file (Merge
    "part.step"), define a physical volume and a physical surface per
    boundary condition ("Physical Surface("clamped") = {...}"), mesh with
    hexahedra (transfinite volumes with Recombine, or Mesh.SubdivisionAlgorithm
    = 2), set Mesh.ElementOrder = 2, Mesh.SecondOrderIncomplete = 0 (27-node
    hexahedra), Mesh.Binary = 0, and save part.msh. Then
        gmshToFormFoam -region solid part.msh
    and use the physical surface names as patches in 0/solid/D, with
    analysisType solid3D and elementType Hex27P4 in
    constant/solid/solidProperties.

    Gmsh's node order (gmsh.info, "Node ordering"): corners 0-7 as VTK's;
    mid-edge nodes 8-19 on the edges (0,1) (0,3) (0,4) (1,2) (1,5) (2,3)
    (2,6) (3,7) (4,5) (4,7) (5,6) (6,7); face nodes 20-25 on the faces
    (0,1,2,3) (0,1,5,4) (0,3,7,4) (1,2,6,5) (2,3,7,6) (4,5,6,7); 26 the
    centre. Every mid node is checked to lie near its edge, face or cell.

    With -shell <thickness>, a surface mesh of first-order quadrangles or
    triangles becomes the mid-surface of a shell region (MITC4, MITC4+ or
    MITC3+): a sheet one cell thick, patches bottom, top, one per physical
    curve (named edges for boundary conditions) and sides
    (gmshShellSheet.H). With -shell the file may also be any surface
    format of OpenFOAM's surface readers (STL, OBJ, VTK, ...: every
    boundary edge in the patch sides, which topoSet and createPatch
    split, e.g. tests/cases/shellPlateTriangles/makeMesh -surface).

    Not converted (a message names the element): other cell shapes
    (tetrahedra, prisms, pyramids), 20-node hexahedra (set
    Mesh.SecondOrderIncomplete = 0), triangles in a physical surface,
    binary files.

Usage
    gmshToFormFoam [-case dir] [-region name] [-shell thickness] <file.msh>
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "cellModel.H"
#include "IFstream.H"
#include "pointIOField.H"
#include "OSspecific.H"
#include "unitConversion.H"
#include "MeshedSurfaces.H"
#include <map>
#include <set>
#include <unordered_map>
#include <sstream>

using namespace Foam;

namespace
{

struct mshElement
{
    label tag;
    label type;
    label physical;     //!< physical group tag (-1: none)
    std::vector<label> nodes;
};

struct mshFile
{
    fileName name;
    std::unordered_map<label, point> nodes;
    std::map<std::pair<label, label>, word> physicalNames;  //!< (dim, tag) -> name
    std::vector<mshElement> elements;
};

[[noreturn]] void bad(const fileName& f, const std::string& msg)
{
    FatalErrorInFunction
        << (f.ext() == "msh" ? "Gmsh file " : "Surface file ") << f << ": "
        << msg.c_str() << exit(FatalError);
    std::exit(1);
}

label nodesOf(label type)
{
    switch (type)
    {
        case 1: return 2;       // line
        case 2: return 3;       // triangle
        case 3: return 4;       // quadrangle
        case 4: return 4;       // tetrahedron
        case 5: return 8;       // hexahedron
        case 6: return 6;       // prism
        case 7: return 5;       // pyramid
        case 8: return 3;       // line3
        case 9: return 6;       // triangle6
        case 10: return 9;      // quadrangle9
        case 11: return 10;     // tetrahedron10
        case 12: return 27;     // hexahedron27
        case 13: return 18;     // prism18
        case 14: return 14;     // pyramid14
        case 15: return 1;      // point
        case 16: return 8;      // quadrangle8
        case 17: return 20;     // hexahedron20
        case 18: return 15;     // prism15
        case 19: return 13;     // pyramid13
        default: return -1;
    }
}

// $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements of MSH 2.2 and
// 4.1 (ASCII); other sections are skipped
mshFile readMsh(const fileName& file)
{
    std::ifstream is(file);
    if (!is.good()) bad(file, "cannot be opened");
    mshFile m;
    m.name = file;
    double version = 0;
    // MSH 4: physical tags of the entities, per dimension
    std::map<std::pair<label, label>, label> entityPhysical;
    std::string line;
    while (std::getline(is, line))
    {
        if (line.rfind("$MeshFormat", 0) == 0)
        {
            int fileType = 0, dataSize = 0;
            is >> version >> fileType >> dataSize;
            if (fileType != 0)
            {
                bad(file, "is binary; save it as ASCII (Mesh.Binary = 0)");
            }
            if (!(version >= 2 && version < 3) && !(version >= 4 && version < 5))
            {
                bad(file, "has MSH version " + std::to_string(version)
                    + "; versions 2.2 and 4.1 are read");
            }
        }
        else if (line.rfind("$PhysicalNames", 0) == 0)
        {
            label n;
            is >> n;
            for (label i = 0; i < n; ++i)
            {
                label dim, tag;
                std::string name;
                is >> dim >> tag;
                std::getline(is, name);
                const auto a = name.find('"'), b = name.rfind('"');
                if (a == std::string::npos || b <= a) bad(file, "a physical name without quotes");
                m.physicalNames[{dim, tag}] = word::validate(name.substr(a + 1, b - a - 1));
            }
        }
        else if (line.rfind("$Entities", 0) == 0 && version >= 4)
        {
            label np, nc, ns, nv;
            is >> np >> nc >> ns >> nv;
            const label counts[4] = {np, nc, ns, nv};
            for (label dim = 0; dim < 4; ++dim)
            {
                for (label i = 0; i < counts[dim]; ++i)
                {
                    label tag;
                    double x;
                    is >> tag;
                    for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) is >> x;
                    label nPhys;
                    is >> nPhys;
                    for (label k = 0; k < nPhys; ++k)
                    {
                        label p;
                        is >> p;
                        if (k == 0) entityPhysical[{dim, tag}] = std::abs(p);
                    }
                    if (dim > 0)
                    {
                        label nb;
                        is >> nb;
                        for (label k = 0; k < nb; ++k) is >> x;
                    }
                }
            }
        }
        else if (line.rfind("$Nodes", 0) == 0)
        {
            if (version < 4)
            {
                label n;
                is >> n;
                for (label i = 0; i < n; ++i)
                {
                    label id;
                    point p;
                    is >> id >> p.x() >> p.y() >> p.z();
                    m.nodes[id] = p;
                }
            }
            else
            {
                label nBlocks, n, lo, hi;
                is >> nBlocks >> n >> lo >> hi;
                for (label b = 0; b < nBlocks; ++b)
                {
                    label dim, tag, parametric, nb;
                    is >> dim >> tag >> parametric >> nb;
                    if (parametric) bad(file, "has parametric node coordinates; save without them (Mesh.SaveParametric = 0)");
                    std::vector<label> ids(nb);
                    for (label& id : ids) is >> id;
                    for (const label id : ids)
                    {
                        point p;
                        is >> p.x() >> p.y() >> p.z();
                        m.nodes[id] = p;
                    }
                }
            }
        }
        else if (line.rfind("$Elements", 0) == 0)
        {
            if (version < 4)
            {
                label n;
                is >> n;
                for (label i = 0; i < n; ++i)
                {
                    mshElement e;
                    label nTags;
                    is >> e.tag >> e.type >> nTags;
                    e.physical = -1;
                    for (label k = 0; k < nTags; ++k)
                    {
                        label t;
                        is >> t;
                        if (k == 0) e.physical = t;
                    }
                    const label nn = nodesOf(e.type);
                    if (nn < 0) bad(file, "element " + std::to_string(e.tag) + " has the unknown type " + std::to_string(e.type));
                    e.nodes.resize(nn);
                    for (label& v : e.nodes) is >> v;
                    m.elements.push_back(std::move(e));
                }
            }
            else
            {
                label nBlocks, n, lo, hi;
                is >> nBlocks >> n >> lo >> hi;
                for (label b = 0; b < nBlocks; ++b)
                {
                    label dim, tag, type, nb;
                    is >> dim >> tag >> type >> nb;
                    const label nn = nodesOf(type);
                    if (nn < 0) bad(file, "an element block has the unknown type " + std::to_string(type));
                    const auto ph = entityPhysical.find({dim, tag});
                    for (label i = 0; i < nb; ++i)
                    {
                        mshElement e;
                        e.type = type;
                        e.physical = ph == entityPhysical.end() ? -1 : ph->second;
                        is >> e.tag;
                        e.nodes.resize(nn);
                        for (label& v : e.nodes) is >> v;
                        m.elements.push_back(std::move(e));
                    }
                }
            }
        }
        if (is.fail()) bad(file, "cannot be read (a truncated or malformed section before '" + line + "')");
    }
    if (version == 0) bad(file, "has no $MeshFormat: not a Gmsh mesh");
    return m;
}

// A surface file in any format of OpenFOAM's surface readers (STL, OBJ,
// VTK, ...) as the elements of a Gmsh surface mesh: its triangles and
// quadrangles (no physical groups: the boundary edges become the patch
// sides, which topoSet and createPatch can split)
mshFile readSurface(const fileName& file)
{
    if (!isFile(file)) bad(file, "cannot be opened");
    mshFile m;
    m.name = file;
    meshedSurface surf;
    try
    {
        FatalError.throwExceptions();
        FatalIOError.throwExceptions();
        surf = meshedSurface(file);
    }
    catch (const Foam::error& e)
    {
        bad(file, "cannot be read as a surface (" + e.message() + ")");
    }
    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
    forAll(surf.points(), i) m.nodes[i + 1] = surf.points()[i];
    forAll(surf.surfFaces(), i)
    {
        const face& f = surf.surfFaces()[i];
        if (f.size() != 3 && f.size() != 4)
        {
            bad(file, "face " + std::to_string(i) + " has " + std::to_string(f.size())
                + " corners; shells are quadrangles or triangles");
        }
        mshElement e;
        e.tag = i + 1;
        e.type = f.size() == 4 ? 3 : 2;
        e.physical = -1;
        for (const label v : f) e.nodes.push_back(v + 1);
        m.elements.push_back(std::move(e));
    }
    return m;
}

// Lattice index (a + 3 b + 9 c) of the nodes of a Gmsh Hexahedron27
const FixedList<label, 27>& gmshHex27Lattice()
{
    static const FixedList<label, 27> L = []()
    {
        const label corner[8][3] =
        {
            {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
            {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}
        };
        const std::vector<std::vector<label>> sets =
        {
            {0}, {1}, {2}, {3}, {4}, {5}, {6}, {7},
            {0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
            {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7},
            {0, 1, 2, 3}, {0, 1, 5, 4}, {0, 3, 7, 4}, {1, 2, 6, 5},
            {2, 3, 7, 6}, {4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}
        };
        FixedList<label, 27> idx;
        for (label k = 0; k < 27; ++k)
        {
            label s[3] = {0, 0, 0};
            for (const label c : sets[k])
            {
                for (label d = 0; d < 3; ++d) s[d] += corner[c][d];
            }
            const label n = sets[k].size();
            idx[k] = s[0]/n + 3*(s[1]/n) + 9*(s[2]/n);
        }
        return idx;
    }();
    return L;
}

} // anonymous namespace

#include "gmshShellSheet.H"


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Convert a Gmsh mesh of 8- or 27-node hexahedra into the polyMesh"
        " of a formFoam solid region (with the second-order nodes in"
        " polyMesh/cellLattice)"
    );
    argList::noParallel();
    argList::addArgument("file.msh");
    argList::addOption("region", "name", "The solid region (default: solid)");
    argList::addOption
    (
        "shell", "thickness",
        "A surface mesh of first-order quadrangles or triangles as the"
        " mid-surface of a shell region: written as a sheet one cell thick"
        " (hexahedra or prisms) of this thickness; physical curves become"
        " side patches, the faces the patches bottom and top"
    );
    #include "setRootCase.H"
    #include "createTime.H"

    const fileName mshName = args[1];
    const word region = args.getOrDefault<word>("region", "solid");
    // -shell: any surface format OpenFOAM reads (STL, OBJ, VTK, ...)
    // besides Gmsh's
    const mshFile m = args.found("shell") && mshName.ext() != "msh"
      ? readSurface(mshName) : readMsh(mshName);
    const fileName meshDir = runTime.constant()/region/polyMesh::meshSubDir;

    // Writes the polyMesh of the cells, the named patches and the
    // remaining boundary faces in defaultPatch
    const auto writeMesh = [&]
    (
        pointField&& points,
        const cellShapeList& shapes,
        const faceListList& patchFaces,
        const wordList& patchNames,
        const word& defaultPatch
    )
    {
        if (isDir(runTime.path()/meshDir)) rmDir(runTime.path()/meshDir);
        autoPtr<polyMesh> mesh
        (
            new polyMesh
            (
                IOobject(region, runTime.constant(), runTime),
                std::move(points),
                shapes,
                patchFaces,
                patchNames,
                wordList(patchNames.size(), "patch"),
                defaultPatch,
                "patch",
                wordList(patchNames.size(), word::null)
            )
        );
        mesh->removeFiles();
        if (!mesh->write())
        {
            FatalErrorInFunction << "Cannot write " << meshDir << exit(FatalError);
        }
        return mesh;
    };

    if (args.found("shell"))
    {
        scalar t = 0;
        if (!readScalar(args["shell"], t) || !std::isfinite(t) || !(t > 0))
        {
            FatalErrorInFunction
                << "option -shell: the thickness must be a positive number, not "
                << args["shell"] << exit(FatalError);
        }
        shellSheet S = gmshShellSheet(m, t);
        const autoPtr<polyMesh> mesh = writeMesh
        (
            pointField(std::move(S.points)), S.shapes, S.patchFaces,
            S.patchNames, "sides"
        );
        Info<< "gmshToFormFoam: " << mshName << " -> " << meshDir << ": "
            << S.nElements << (S.triangles ? " triangles" : " quadrangles")
            << " as a shell sheet of thickness " << t << " ("
            << (S.triangles ? "prisms: MITC3+" : "hexahedra: MITC4, MITC4+")
            << "), " << mesh->nPoints()/2 << " shell nodes, the largest angle"
            << " between an element's and a node's normal "
            << S.largestTilt << " deg, patches "
            << mesh->boundaryMesh().names() << endl;
        return 0;
    }

    // Hexahedra -> cells (corner points renumbered), lattices
    std::unordered_map<label, label> pointOf;
    DynamicList<point> points;
    const auto pointLabel = [&](label node)
    {
        const auto it = m.nodes.find(node);
        if (it == m.nodes.end())
        {
            bad(mshName, "node " + std::to_string(node) + " is used but not defined");
        }
        const auto p = pointOf.find(node);
        if (p != pointOf.end()) return p->second;
        pointOf[node] = points.size();
        points.append(it->second);
        return label(points.size() - 1);
    };
    const cellModel& hex = cellModel::ref(cellModel::HEX);
    cellShapeList shapes;
    DynamicList<point> lattice;
    bool anyHex8 = false, anyHex27 = false;
    for (const mshElement& e : m.elements)
    {
        if (e.type == 17)
        {
            bad(mshName, "element " + std::to_string(e.tag) + " is a 20-node"
                " hexahedron; export complete second-order elements"
                " (Mesh.SecondOrderIncomplete = 0: 27 nodes)");
        }
        if (e.type == 4 || e.type == 6 || e.type == 7 || e.type == 11
         || e.type == 13 || e.type == 14 || e.type == 18 || e.type == 19)
        {
            bad(mshName, "element " + std::to_string(e.tag) + " is not a"
                " hexahedron (Gmsh type " + std::to_string(e.type) + "); formFoam's"
                " 3D elements are hexahedra: recombine the mesh into hexahedra");
        }
        if (e.type != 5 && e.type != 12) continue;
        labelList v(8);
        for (label k = 0; k < 8; ++k) v[k] = pointLabel(e.nodes[k]);
        shapes.append(cellShape(hex, v));
        if (e.type == 5)
        {
            anyHex8 = true;
            continue;
        }
        anyHex27 = true;
        FixedList<point, 27> L;
        const FixedList<label, 27>& idx = gmshHex27Lattice();
        for (label k = 0; k < 27; ++k) L[idx[k]] = m.nodes.at(e.nodes[k]);
        // Each mid node near the centre of its corners (a scrambled node
        // order would put it elsewhere)
        const scalar size = mag(L[26] - L[0]) + mag(L[20] - L[6]);
        for (label k = 8; k < 27; ++k)
        {
            const label a = idx[k] % 3, b = (idx[k]/3) % 3, c = idx[k]/9;
            point mean(Zero);
            label n = 0;
            for (const label i : {0, 2}) for (const label j : {0, 2}) for (const label l : {0, 2})
            {
                if ((a == 1 || a == i) && (b == 1 || b == j) && (c == 1 || c == l))
                {
                    mean += L[i + 3*j + 9*l];
                    ++n;
                }
            }
            if (mag(L[idx[k]] - mean/n) > 0.5*size)
            {
                bad(mshName, "node " + std::to_string(e.nodes[k]) + " of hexahedron "
                    + std::to_string(e.tag) + " lies far from its edge, face or"
                    " centre: not Gmsh's Hexahedron27 node order?");
            }
        }
        for (const point& p : L) lattice.append(p);
    }
    if (shapes.empty())
    {
        bad(mshName, "has no hexahedra (Gmsh types 5 or 12); a surface mesh"
            " of a shell region is converted with -shell <thickness>");
    }
    if (anyHex8 && anyHex27)
    {
        bad(mshName, "mixes 8- and 27-node hexahedra; mesh with one element order");
    }

    // Physical surfaces of quadrilaterals -> patches
    std::map<label, faceList> groups;
    for (const mshElement& e : m.elements)
    {
        const label dim =
            (e.type == 2 || e.type == 9 || e.type == 3 || e.type == 10 || e.type == 16) ? 2 : -1;
        if (dim != 2 || e.physical < 0) continue;
        if (e.type == 2 || e.type == 9)
        {
            bad(mshName, "triangle " + std::to_string(e.tag) + " belongs to a"
                " physical surface; the faces of hexahedra are quadrilaterals");
        }
        face f(4);
        for (label k = 0; k < 4; ++k)
        {
            const auto p = pointOf.find(e.nodes[k]);
            if (p == pointOf.end())
            {
                bad(mshName, "quadrangle " + std::to_string(e.tag) + " of a physical"
                    " surface is not a face of the hexahedra");
            }
            f[k] = p->second;
        }
        groups[e.physical].append(f);
    }
    faceListList patchFaces;
    wordList patchNames;
    for (const auto& g : groups)
    {
        const auto n = m.physicalNames.find({2, g.first});
        patchNames.append
        (
            n != m.physicalNames.end() ? n->second
          : word("physical" + Foam::name(g.first))
        );
        patchFaces.append(g.second);
    }
    const autoPtr<polyMesh> meshPtr = writeMesh
    (
        pointField(std::move(points)), shapes, patchFaces, patchNames,
        "defaultFaces"
    );
    const polyMesh& mesh = *meshPtr;
    if (anyHex27)
    {
        pointIOField P
        (
            IOobject
            (
                "cellLattice", runTime.constant(), region/polyMesh::meshSubDir,
                runTime, IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            pointField(std::move(lattice))
        );
        if (!P.write())
        {
            FatalErrorInFunction << "Cannot write " << P.objectPath() << exit(FatalError);
        }
    }

    Info<< "gmshToFormFoam: " << mshName << " -> " << meshDir << ": "
        << mesh.nCells() << " hexahedra (" << (anyHex27 ? 27 : 8)
        << " nodes), " << mesh.nPoints() << " points, patches "
        << mesh.boundaryMesh().names() << endl;
    return 0;
}
