/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The ALE Navier-Stokes fluid block (ALENavierStokes.H has the equations):
    construction, boundary classification, mesh motion and quality, the
    step. The assembly of its equations: ALENavierStokesAssemble.C; the
    interface and the mesh unknowns: ALENavierStokesInterface.C; the shape
    derivative: ALENavierStokesShape.C; output and state:
    ALENavierStokesIO.C.
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "wallClock.H"
#include "fluidSolidInterface.H"
#include "solidModel.H"
#include "wedgeFvPatch.H"
#include "pointIOField.H"
#include "formError.H"
#include "mathematicalConstants.H"
#include <map>
#include <sstream>

namespace
{

using namespace Foam;

//- The leading words of a scheme entry ("Gauss linear corrected")
wordList schemeWords(ITstream& is)
{
    wordList w;
    while (!is.eof())
    {
        token t(is);
        if (!t.isWord()) break;
        w.append(t.wordToken());
    }
    return w;
}

} // anonymous namespace



// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::ALENavierStokes::ALENavierStokes
(
    Time& runTime,
    fvMesh& mesh,
    const ALEFluidSettings& settings
)
:
    runTime_(runTime),
    mesh_(mesh),
    set_(settings),
    fieldDir_(fileName(runTime.timeName())/mesh.name()),
    U_
    (
        IOobject
        (
            "U", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        ),
        mesh
    ),
    p_
    (
        IOobject
        (
            "p", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        ),
        mesh
    )
{
    // Solved components: the geometric directions
    const Vector<label>& gD = mesh_.geometricD();
    for (direction d = 0; d < 3; ++d)
    {
        if (gD[d] == 1) cmp_.append(label(d));
    }
    D_ = cmp_.size();

    // Depth factor: per unit depth (plane) or full ring (wedge)
    depth_ = 1;
    bool wedge = false;
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        if (isA<wedgeFvPatch>(fp) && fp.size())
        {
            const wedgePolyPatch& wp =
                refCast<const wedgePolyPatch>(fp.patch());
            // Each wedge plane is turned by half the wedge angle a from
            // the centre plane: cos(a/2) = n . centreNormal. A face at
            // radius r spans the chord 2 r sin(a/2): the full ring is
            // pi/sin(a/2) wedges (exact for fluxes and volumes of the
            // planar wedge cells)
            const scalar half =
                Foam::acos(min(1.0, mag(wp.n() & wp.centreNormal())));
            depth_ = constant::mathematical::pi/Foam::sin(half);
            wedge = true;
            break;
        }
    }
    if (!wedge && D_ == 2)
    {
        // Plane mesh: thickness in the empty direction
        label e = 0;
        for (direction d = 0; d < 3; ++d)
        {
            if (gD[d] != 1) e = d;
        }
        const boundBox& bb = mesh_.bounds();
        depth_ = 1/(bb.max()[e] - bb.min()[e]);
    }

    // Schemes: ddt, convection, Laplacian correction
    {
        const word ddt(mesh_.ddtScheme("ddt(U)"));
        if (ddt == "steadyState") steady_ = true;
        else if (ddt == "Euler") steady_ = false;
        else if (ddt == "backward") steady_ = false, backward_ = true;
        else
        {
            FatalIOErrorInFunction(mesh_.schemesDict())
                << "ddtSchemes in system/" << mesh_.name() << "/fvSchemes: '"
                << ddt << "' is not available for the ALE fluid; use Euler"
                << " or backward (transient) or steadyState"
                << exit(FatalIOError);
        }
        const wordList w = schemeWords(mesh_.divScheme("div(phi,U)"));
        if (w.size() != 2 || w[0] != "Gauss" || (w[1] != "linear" && w[1] != "upwind"))
        {
            FatalIOErrorInFunction(mesh_.schemesDict())
                << "divSchemes div(phi,U) in system/" << mesh_.name()
                << "/fvSchemes: the ALE fluid's Newton matrix is exact for"
                << " 'Gauss linear' and 'Gauss upwind'; got " << w
                << exit(FatalIOError);
        }
        upwind_ = w[1] == "upwind";
        const wordList lw =
            schemeWords(mesh_.laplacianScheme("laplacian(mu,U)"));
        if
        (
            lw.size() != 3 || lw[0] != "Gauss" || lw[1] != "linear"
         || (lw[2] != "corrected" && lw[2] != "uncorrected")
        )
        {
            FatalIOErrorInFunction(mesh_.schemesDict())
                << "laplacianSchemes laplacian(mu,U) in system/"
                << mesh_.name() << "/fvSchemes: use 'Gauss linear corrected'"
                << " or 'Gauss linear uncorrected'; got " << lw
                << exit(FatalIOError);
        }
        corrected_ = lw[2] == "corrected";
    }

    restoreInitialConditions();
    classifyPatches();

    // Unknowns from the fields
    const label nC = mesh_.nCells();
    x_.setZero(nC*(D_ + 1));
    forAll(U_, c)
    {
        for (label k = 0; k < D_; ++k) x_(iu(c, k)) = U_[c][cmp_[k]];
        x_(ip(c)) = p_[c];
    }
    x0_ = x_;

    points0_ = mesh_.points();
    V0_ = mesh_.V();
    Vstart_ = mesh_.V();
    swept0_.setSize(mesh_.nFaces(), 0);
    points00_ = pointIOField
    (
        IOobject
        (
            "points", runTime.constant(), polyMesh::meshSubDir, mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    bbMin_ = boundBox(points00_).min();
    bbMax_ = boundBox(points00_).max();

    uFixed_.setSize(mesh_.boundary().size());
    pFixedValue_.setSize(mesh_.boundary().size());
    rAV_.setSize(nC, 0);
    Fm_.setSize(mesh_.nFaces(), 0);
    updateBoundaryValues();
    readBackwardHistory();
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::ALENavierStokes::fixedVelocityTypes()
{
    return
    {
        "fixedValue", "noSlip", "uniformFixedValue", "flowRateInletVelocity",
        "surfaceNormalFixedValue", "fixedProfile"
    };
}


Foam::wordList Foam::ALENavierStokes::fixedPressureTypes()
{
    return {"fixedValue", "uniformFixedValue"};
}


// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

Foam::vector Foam::ALENavierStokes::cellU(const form::vecX& x, label c) const
{
    vector u = Zero;
    for (label k = 0; k < D_; ++k) u[cmp_[k]] = x(iu(c, k));
    return u;
}


void Foam::ALENavierStokes::classifyPatches()
{
    const label nP = mesh_.boundary().size();
    uBC_.setSize(nP);
    pFixed_.setSize(nP, false);
    bool anyPressureFixed = false;
    // The files as the user sees them (unquoted in messages)
    const std::string uFile = "0/" + mesh_.name() + "/U";
    const std::string pFile = "0/" + mesh_.name() + "/p";
    const auto names = [](const wordList& w)
    {
        std::string s;
        for (const word& n : w) s += (s.empty() ? "" : " ") + n;
        return s;
    };
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchVectorField& up = U_.boundaryField()[patchi];
        const fvPatchScalarField& pp = p_.boundaryField()[patchi];
        const word& name = mesh_.boundary()[patchi].name();
        const word ut = up.type();
        const word pt = pp.type();
        const bool isInterface = set_.interfacePatches.found(name);
        if (isInterface != (ut == "movingWallVelocity"))
        {
            FatalErrorInFunction
                << "Patch '" << name << "' in " << uFile.c_str() << ": "
                << (isInterface
                    ? "an interface patch (constant/" + mesh_.name()
                    + "/fluidProperties, fluidInterface) moves with the solid:"
                      " its velocity condition must be movingWallVelocity,"
                      " not " + ut
                    : "movingWallVelocity is the condition of the interface"
                      " with a solid; list the patch in fluidInterface of"
                      " constant/" + mesh_.name() + "/fluidProperties").c_str()
                << exit(FatalError);
        }
        if (isInterface && fixedPressureTypes().found(pt))
        {
            FatalErrorInFunction
                << "Patch '" << name << "' in " << pFile.c_str() << ": the"
                << " pressure on the interface with the solid is the fluid's"
                << " own; use zeroGradient, not " << pt << exit(FatalError);
        }
        if (isInterface) uBC_[patchi] = velocityBC::interface;
        else if (ut == "empty") uBC_[patchi] = velocityBC::empty;
        else if (ut == "wedge") uBC_[patchi] = velocityBC::wedge;
        else if (ut == "slip" || ut == "symmetryPlane" || ut == "symmetry")
        {
            uBC_[patchi] = velocityBC::slip;
        }
        else if (ut == "zeroGradient") uBC_[patchi] = velocityBC::zeroGradient;
        else if (fixedVelocityTypes().found(ut))
        {
            uBC_[patchi] = velocityBC::fixedValue;
        }
        else
        {
            FatalErrorInFunction
                << "Patch '" << name << "' in " << uFile.c_str() << ": velocity"
                << " condition type '" << ut << "' is not available for the"
                << " ALE fluid; use a fixed value (" << names(fixedVelocityTypes())
                << "), zeroGradient (an outlet with a fixed pressure), slip,"
                << " symmetryPlane, wedge or empty" << exit(FatalError);
        }
        if (fixedPressureTypes().found(pt))
        {
            pFixed_[patchi] = true;
            anyPressureFixed = true;
        }
        else if
        (
            pt != "zeroGradient" && pt != "fixedFluxPressure"
         && pt != "empty" && pt != "wedge" && pt != "symmetryPlane"
         && pt != "symmetry" && pt != "slip"
        )
        {
            FatalErrorInFunction
                << "Patch '" << name << "' in " << pFile.c_str() << ": pressure"
                << " condition type '" << pt << "' is not available for the"
                << " ALE fluid; use a fixed value (" << names(fixedPressureTypes())
                << ") or zeroGradient" << exit(FatalError);
        }
        if
        (
            set_.inletPatches.found(name)
         && uBC_[patchi] != velocityBC::fixedValue
        )
        {
            FatalErrorInFunction
                << "Patch '" << name << "' in " << uFile.c_str() << ": the"
                << " injection inlet (constant/" << mesh_.name()
                << "/fluidProperties, inlet) needs a fixed-value velocity"
                << " condition (e.g. fixedValue uniform (0 0 0): the"
                << " injection sets it), not " << ut << exit(FatalError);
        }
        if (uBC_[patchi] == velocityBC::zeroGradient && !pFixed_[patchi])
        {
            FatalErrorInFunction
                << "Patch '" << name << "': U is zeroGradient in " << uFile.c_str()
                << " but p in " << pFile.c_str() << " does not fix its value; an"
                << " outlet needs a fixed pressure (fixedValue)"
                << exit(FatalError);
        }
    }
    for (const word& n : set_.inletPatches)
    {
        if (mesh_.boundary().findPatchID(n) < 0)
        {
            FatalErrorInFunction
                << "Entry 'inlet' in constant/" << mesh_.name()
                << "/fluidProperties: '" << n << "' is not a patch of fluid"
                << " region '" << mesh_.name() << "'" << nl << "    Patches: "
                << mesh_.boundaryMesh().names() << exit(FatalError);
        }
    }
    // (A cavity closed by a solid's interface gets its pressure level
    // from the solid's compliance)
    if (set_.incompressible && !anyPressureFixed && set_.interfacePatches.empty())
    {
        FatalErrorInFunction
            << "Fluid region '" << mesh_.name() << "': incompressible with"
            << " no patch of fixed pressure in " << pFile.c_str() << ": the pressure"
            << " level is undetermined; fix the pressure on an outlet or"
            << " give a bulkModulus in constant/" << mesh_.name()
            << "/fluidProperties" << exit(FatalError);
    }
}


Foam::tmp<Foam::pointField>
Foam::ALENavierStokes::motionPoints(scalar t) const
{
    tmp<pointField> tpts(new pointField(points00_));
    if (set_.meshMotion != "oscillating") return tpts;
    pointField& pts = tpts.ref();
    const scalar a = Foam::sin(constant::mathematical::twoPi*t/set_.period);
    const Vector<label>& gD = mesh_.geometricD();
    forAll(pts, i)
    {
        scalar shape = a;
        for (direction d = 0; d < 3; ++d)
        {
            if (gD[d] != 1) continue;
            const scalar xi =
                (points00_[i][d] - bbMin_[d])/(bbMax_[d] - bbMin_[d]);
            shape *= Foam::sin(constant::mathematical::pi*xi);
        }
        pts[i] += shape*set_.amplitude;
    }
    return tpts;
}


void Foam::ALENavierStokes::computeMeshFluxes()
{
    const faceList& faces = mesh_.faces();
    const pointField& pts = mesh_.points();
    forAll(faces, f)
    {
        Fm_[f] = meshFlux(f, faces[f].sweptVol(points0_, pts));
    }
}


void Foam::ALENavierStokes::updateBoundaryValues()
{
    correctBoundaries();
    forAll(mesh_.boundary(), patchi)
    {
        uFixed_[patchi] = U_.boundaryField()[patchi];
        pFixedValue_[patchi] = p_.boundaryField()[patchi];
    }
    // Injection: the volume of the step through the inlets, uniformly
    if (set_.injectedVolume && set_.inletPatches.size())
    {
        const scalar Q =
            t1_ > t0_
          ? (set_.injectedVolume(t1_) - set_.injectedVolume(t0_))/dt_
          : 0;
        scalar A = 0;
        for (const word& n : set_.inletPatches)
        {
            A += gSum(mesh_.boundary()[n].magSf());
        }
        for (const word& n : set_.inletPatches)
        {
            const label patchi = mesh_.boundary().findPatchID(n);
            uFixed_[patchi] = -Q/(depth_*A)*mesh_.boundary()[patchi].nf();
        }
    }
}


void Foam::ALENavierStokes::computeRhieChowCoefficients()
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();
    const scalarField& V = mesh_.V();
    scalarField a(mesh_.nCells(), 0);
    const scalar rho = set_.rho, mu = set_.mu;
    forAll(own, f)
    {
        const label P = own[f], N = nei[f];
        const scalar w = mesh_.weights()[f];
        const vector ubar = w*cellU(x_, P) + (1 - w)*cellU(x_, N);
        const scalar F = (ubar & Sf[f]) - Fm_[f];
        a[P] += mu*magSf[f]*dc[f] + rho*max(F, 0.0);
        a[N] += mu*magSf[f]*dc[f] + rho*max(-F, 0.0);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        const velocityBC bc = uBC_[patchi];
        if (bc == velocityBC::empty || bc == velocityBC::wedge) continue;
        const labelUList& fc = fp.faceCells();
        const scalarField& dcb = fp.deltaCoeffs();
        forAll(fp, i)
        {
            if (bc == velocityBC::fixedValue || bc == velocityBC::interface)
            {
                a[fc[i]] += mu*magSf.boundaryField()[patchi][i]*dcb[i];
            }
            // No flux through the interface (it moves with the fluid)
            if (bc == velocityBC::interface) continue;
            const scalar F =
                (cellU(x_, fc[i]) & Sf.boundaryField()[patchi][i])
              - Fm_[fp.start() + i];
            a[fc[i]] += rho*max(F, 0.0);
        }
    }
    forAll(a, c)
    {
        if (!steady_) a[c] += a0_*rho*V[c]/dt_;
        rAV_[c] = V[c]/max(a[c], VSMALL);
    }
}


void Foam::ALENavierStokes::checkMeshQuality()
{
    const scalarField& V = mesh_.V();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.C();
    const vectorField& Sf = mesh_.Sf();
    minVolumeRatio_ = GREAT;
    label worstCell = -1;
    forAll(V, c)
    {
        const scalar ratio = V[c]/Vstart_[c];
        if (ratio < minVolumeRatio_)
        {
            minVolumeRatio_ = ratio;
            worstCell = c;
        }
    }
    maxNonOrth_ = 0;
    label worstFace = -1;
    forAll(own, f)
    {
        const vector d = C[nei[f]] - C[own[f]];
        const scalar cosA = (d & Sf[f])/(mag(d)*mag(Sf[f]) + VSMALL);
        const scalar angle =
            Foam::acos(max(-1.0, min(1.0, cosA)))*180/constant::mathematical::pi;
        if (angle > maxNonOrth_)
        {
            maxNonOrth_ = angle;
            worstFace = f;
        }
    }
    std::ostringstream os;
    if (!(minVolumeRatio_ > 0))
    {
        os  << "fluid mesh of region " << mesh_.name() << ": cell "
            << worstCell << " at " << C[worstCell].x() << ' '
            << C[worstCell].y() << ' ' << C[worstCell].z()
            << " turned inside out (volume " << V[worstCell] << ")";
    }
    else if (maxNonOrth_ > set_.maxNonOrthogonality)
    {
        const point& c = mesh_.Cf()[worstFace];
        os  << "fluid mesh of region " << mesh_.name() << ": face "
            << worstFace << " at " << c.x() << ' ' << c.y() << ' ' << c.z()
            << " is " << maxNonOrth_ << " degrees non-orthogonal, beyond"
            << " maxNonOrthogonality " << set_.maxNonOrthogonality
            << " (constant/" << mesh_.name() << "/fluidProperties): the"
            << " mesh motion is about to invert cells";
    }
    if (!os.str().empty())
    {
        throw form::inversionError(-1, os.str());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::ALENavierStokes::beginIncrement
(
    double t0,
    double t1,
    const form::vecX& U
)
{
    t0_ = t0;
    t1_ = t1;
    stepBegun_ = true;
    scaleStart_ = -1;
    // The fluid's time step in seconds (timeScale: seconds per unit of
    // the case's time in a quasi-static run)
    dt_ = (t1 - t0)*set_.timeScale;
    // The backward difference on the last two levels (Euler at the first
    // step); variable steps: Hairer, Norsett & Wanner, Solving ODEs I,
    // sec. III.5 (BDF2 with step ratio w)
    a0_ = 1;
    a1_ = -1;
    a2_ = 0;
    if (backward_ && history_)
    {
        const scalar w = dt_/dt0_;
        a0_ = (1 + 2*w)/(1 + w);
        a1_ = -(1 + w);
        a2_ = w*w/(1 + w);
    }
    // Boundary values at t1 (time functions of the fields' conditions)
    const label index = runTime_.timeIndex();
    runTime_.setTime(t1, index);
    if (set_.meshMotion == "oscillating")
    {
        const auto start = std::chrono::steady_clock::now();
        mesh_.movePoints(motionPoints(t1));
        meshMotionTime_ += form::secondsSince(start);
        checkMeshQuality();
    }
    if (interface_)
    {
        Un_ = U;
    }
    computeMeshFluxes();
    updateFields();
    updateBoundaryValues();
    computeRhieChowCoefficients();
}


void Foam::ALENavierStokes::evaluate
(
    double,
    const form::vecX& Us,
    form::vecX& fext,
    form::vecX& r,
    std::vector<triplet>* K
)
{
    if (interface_)
    {
        evaluateInterface(Us, fext, r, K);
        return;
    }
    assemble(Us.size(), r, K, nullptr);
}


void Foam::ALENavierStokes::commit(const form::vecX&)
{
    if (backward_ && stepBegun_)
    {
        // The committed level becomes the one before it
        x00_ = x0_.head(nCellUnknowns());
        V00_ = V0_;
        const faceList& faces = mesh_.faces();
        forAll(faces, f)
        {
            swept0_[f] = faces[f].sweptVol(points0_, mesh_.points());
        }
        dt0_ = dt_;
        history_ = true;
    }
    stepBegun_ = false;
    x0_ = x_;
    points0_ = mesh_.points();
    V0_ = mesh_.V();
    pecletSinceCommit_ = peclet_;
}


void Foam::ALENavierStokes::revert()
{
    x_ = x0_;
    if (set_.meshMotion != "none")
    {
        mesh_.movePoints(points0_);
    }
}


// ************************************************************************* //
