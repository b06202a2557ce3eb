/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of cellLattice.H: the 3 x 3 x 3 lattice of every cell
    of a hexahedral mesh, from gmshToFormFoam's file or from the mesh's
    blocks meshed twice as finely.
\*---------------------------------------------------------------------------*/
#include "cellLattice.H"
#include "pointIOField.H"
#include "blockMesh.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "Time.H"

namespace
{

using namespace Foam;

// The lattice from the blocks of system/<region>/blockMeshDict, not yet
// checked against the mesh
List<FixedList<point, 27>> blockMeshLattice
(
    const polyMesh& mesh,
    string& why
)
{
    List<FixedList<point, 27>> lattice;
    const Time& runTime = mesh.time();
    const fileName dictPath =
        runTime.path()/runTime.system()/mesh.name()/"blockMeshDict";
    if (!isFile(dictPath))
    {
        why =
            "no " + ("system"/mesh.name()/"blockMeshDict")
          + " and no cellLattice from gmshToFormFoam";
        return lattice;
    }
    IOdictionary dict
    (
        IOobject
        (
            "blockMeshDict",
            runTime.system(),
            mesh.name(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    dict.set("verbose", false);
    // blockMesh prints its topology checks; quiet while it reads
    const int infoLevel = Info.level;
    Info.level = 0;
    blockMesh blocks(dict, mesh.name());
    Info.level = infoLevel;
    const scalar scale = blocks.scaleFactor();

    lattice.resize(mesh.nCells());
    label celli = 0;
    forAll(blocks, blocki)
    {
        const block& blk = blocks[blocki];
        const labelVector n = blk.density();
        if (celli + n.x()*n.y()*n.z() > mesh.nCells())
        {
            why = "the mesh has fewer cells than " + dictPath.name() + " makes";
            lattice.clear();
            return lattice;
        }
        // Twice the cells per graded section, each section's points kept
        List<gradingDescriptors> fineGrading(blk.grading());
        forAll(fineGrading, edgei)
        {
            const label nDiv = n[edgei/4];   // edges 0-3: i, 4-7: j, 8-11: k
            for (gradingDescriptor& g : fineGrading[edgei])
            {
                const scalar cells = g.nDivFraction()*nDiv;
                const label nc = label(std::round(cells));
                if (mag(cells - nc) > 1e-9 || nc < 1)
                {
                    why =
                        "a graded section of block " + Foam::name(blocki)
                      + " has " + Foam::name(cells) + " cells";
                    lattice.clear();
                    return lattice;
                }
                const scalar R =
                    nc > 1
                  ? std::pow
                    (
                        g.expansionRatio(), (2.0*nc - 1)/(2.0*(nc - 1))
                    )
                  : 1.0;
                g = gradingDescriptor
                (
                    g.blockFraction(), g.nDivFraction(), R
                );
            }
        }
        const block fine
        (
            blk.blockShape(), blk.vertices(), blocks.edges(), blocks.faces(),
            labelVector(2*n.x(), 2*n.y(), 2*n.z()), fineGrading,
            blk.zoneName()
        );
        const pointField& P = fine.points();
        for (label k = 0; k < n.z(); ++k)
        {
            for (label j = 0; j < n.y(); ++j)
            {
                for (label i = 0; i < n.x(); ++i)
                {
                    FixedList<point, 27>& L = lattice[celli++];
                    for (label c = 0; c < 3; ++c)
                    {
                        for (label b = 0; b < 3; ++b)
                        {
                            for (label a = 0; a < 3; ++a)
                            {
                                L[a + 3*b + 9*c] = scale*P
                                [
                                    fine.pointLabel(2*i + a, 2*j + b, 2*k + c)
                                ];
                            }
                        }
                    }
                }
            }
        }
    }
    if (celli != mesh.nCells())
    {
        why = "the mesh has more cells than " + dictPath.name() + " makes";
        lattice.clear();
    }
    return lattice;
}

} // anonymous namespace


Foam::List<Foam::FixedList<Foam::point, 27>> Foam::cellLattice
(
    const polyMesh& mesh,
    string& why
)
{
    List<FixedList<point, 27>> lattice;
    const fileName file =
        mesh.time().path()/mesh.time().constant()/mesh.name()
       /polyMesh::meshSubDir/"cellLattice";
    string source;
    if (isFile(file) || isFile(file + ".gz"))
    {
        source = "constant"/mesh.name()/polyMesh::meshSubDir/"cellLattice";
        const pointIOField P
        (
            IOobject
            (
                "cellLattice",
                mesh.time().constant(),
                mesh.name()/polyMesh::meshSubDir,
                mesh.time(),
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        if (P.size() != 27*mesh.nCells())
        {
            why =
                source + " has " + Foam::name(P.size()) + " points, not 27"
                " per cell of the mesh";
            return lattice;
        }
        lattice.resize(mesh.nCells());
        forAll(lattice, c)
        {
            for (label k = 0; k < 27; ++k) lattice[c][k] = P[27*c + k];
        }
    }
    else
    {
        source = "system"/mesh.name()/"blockMeshDict";
        lattice = blockMeshLattice(mesh, why);
        if (lattice.empty()) return lattice;
    }

    // Every corner of a lattice must be a point of its cell
    const pointField& pts = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(lattice, c)
    {
        const FixedList<point, 27>& L = lattice[c];
        const scalar tol = 1e-7*mag(L[26] - L[0]);
        for (const label corner : {0, 2, 6, 8, 18, 20, 24, 26})
        {
            bool found = false;
            for (const label p : cellPoints[c])
            {
                found = found || mag(pts[p] - L[corner]) <= tol;
            }
            if (!found)
            {
                why =
                    "cell " + Foam::name(c) + " is not where "
                  + source + " puts it (a renumbered or edited mesh?)";
                lattice.clear();
                return lattice;
            }
        }
    }
    return lattice;
}
