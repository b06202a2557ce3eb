/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The ALE Navier-Stokes fluid block (ALENavierStokes.H has the equations).
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

//- A sparse linear form: sum of coefficients times cell values
struct stencilEntry
{
    label cell;
    vector coeff;
};

using stencil = std::vector<stencilEntry>;

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

//- The representation of a boundary face value and normal gradient of the
//  velocity as affine maps of the cell velocity:
//      u_b = T u_P + c,   snGrad_b = Ts u_P + cs
struct faceMap
{
    tensor T = Zero;
    vector c = Zero;
    tensor Ts = Zero;
    vector cs = Zero;
};

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
        else
        {
            FatalIOErrorInFunction(mesh_.schemesDict())
                << "ddtSchemes in system/" << mesh_.name() << "/fvSchemes: '"
                << ddt << "' is not available for the ALE fluid; use Euler"
                << " (transient) or steadyState" << exit(FatalIOError);
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
        Fm_[f] = faces[f].sweptVol(points0_, pts)/dt_;
    }
}


void Foam::ALENavierStokes::updateBoundaryValues()
{
    U_.correctBoundaryConditions();
    p_.correctBoundaryConditions();
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
        if (!steady_) a[c] += rho*V[c]/dt_;
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

Foam::scalar Foam::ALENavierStokes::volume() const
{
    return depth_*gSum(mesh_.V());
}


Foam::scalar Foam::ALENavierStokes::meanPressure() const
{
    scalar sum = 0, w = 0;
    if (interface_)
    {
        for (const label f : interface_->faces())
        {
            const scalar a = mag(mesh_.faceAreas()[f]);
            sum += a*x_(ip(mesh_.faceOwner()[f]));
            w += a;
        }
    }
    else
    {
        forAll(mesh_.V(), c)
        {
            sum += mesh_.V()[c]*x_(ip(c));
            w += mesh_.V()[c];
        }
    }
    return w > 0 ? sum/w : 0;
}


Foam::label Foam::ALENavierStokes::findCell(const point& pt) const
{
    return mesh_.findCell(pt);
}


Foam::scalar Foam::ALENavierStokes::patchFlux(const word& patch) const
{
    const label patchi = mesh_.boundary().findPatchID(patch);
    if (patchi < 0 || Fb_.empty()) return 0;
    const fvPatch& fp = mesh_.boundary()[patchi];
    scalar q = 0;
    forAll(fp, i)
    {
        q += Fb_[fp.start() + i - mesh_.nInternalFaces()];
    }
    return depth_*q;
}


Foam::vector Foam::ALENavierStokes::patchForce(const word& patch) const
{
    const label patchi = mesh_.boundary().findPatchID(patch);
    if (patchi < 0 || Fw_.empty()) return Zero;
    const fvPatch& fp = mesh_.boundary()[patchi];
    vector F = Zero;
    forAll(fp, i)
    {
        F += Fw_[fp.start() + i - mesh_.nInternalFaces()];
    }
    return depth_*F;
}


std::string Foam::ALENavierStokes::describe() const
{
    std::ostringstream os;
    os  << mesh_.nCells() << " cells, " << x_.size() << " unknowns ("
        << D_ << " velocity components and the pressure per cell), rho "
        << set_.rho << ", mu " << set_.mu << ", ";
    if (set_.incompressible) os << "incompressible";
    else os << "bulk modulus " << set_.bulkModulus;
    os  << '\n' << (steady_ ? "steady" : "transient (Euler)")
        << ", convection " << (upwind_ ? "upwind" : "linear")
        << ", viscous flux " << (corrected_ ? "corrected" : "uncorrected")
        << ", Rhie-Chow pressure-velocity coupling, mesh motion "
        << set_.meshMotion;
    if (interface_)
    {
        label n = 0;
        for (const auto& c : colours_) n += label(c.size());
        os  << "\nmesh derivative: central differences over " << n
            << " moving points in " << colours_.size() << " colours ("
            << 4*colours_.size() << " fluid evaluations per Newton iteration)";
    }
    return os.str();
}


std::string Foam::ALENavierStokes::report() const
{
    scalar uMax = 0, pMin = GREAT, pMax = -GREAT;
    for (label c = 0; c < mesh_.nCells(); ++c)
    {
        uMax = max(uMax, mag(cellU(x_, c)));
        pMin = min(pMin, x_(ip(c)));
        pMax = max(pMax, x_(ip(c)));
    }
    std::ostringstream os;
    os.precision(6);
    os  << "max |U| = " << uMax << ", p in [" << pMin << ", " << pMax
        << "], V = " << volume();
    if (set_.meshMotion != "none")
    {
        os  << "; mesh: min V/V_start " << minVolumeRatio_
            << ", max non-orthogonality " << maxNonOrth_ << " deg";
    }
    return os.str();
}


void Foam::ALENavierStokes::updateFields()
{
    forAll(U_, c)
    {
        U_[c] = cellU(x_, c);
        p_[c] = x_(ip(c));
    }
    U_.correctBoundaryConditions();
    p_.correctBoundaryConditions();
}


bool Foam::ALENavierStokes::write(const word& timeName)
{
    // Full precision: the fields and points are the restart state (the
    // mass of a slightly compressible fluid is exp(p/K) V: six digits of
    // p and of the points would change it on a restart)
    const unsigned precision = IOstream::defaultPrecision(17);
    updateFields();
    const word Uinstance = U_.instance(), pinstance = p_.instance();
    U_.instance() = timeName;
    p_.instance() = timeName;
    bool ok = U_.write();
    ok = p_.write() && ok;
    U_.instance() = Uinstance;
    p_.instance() = pinstance;
    if (set_.meshMotion != "none")
    {
        pointIOField pts
        (
            IOobject
            (
                "points", timeName, polyMesh::meshSubDir, mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh_.points()
        );
        ok = pts.write() && ok;
    }
    IOstream::defaultPrecision(precision);
    return ok;
}


void Foam::ALENavierStokes::beginIncrement
(
    double t0,
    double t1,
    const form::vecX& U
)
{
    t0_ = t0;
    t1_ = t1;
    // The fluid's time step in seconds (timeScale: seconds per unit of
    // the case's time in a quasi-static run)
    dt_ = (t1 - t0)*set_.timeScale;
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


void Foam::ALENavierStokes::assemble
(
    label off,
    form::vecX& r,
    std::vector<triplet>* K,
    std::vector<interfaceEntry>* KI
)
{
    const label nC = mesh_.nCells();
    const scalar s = depth_;
    const scalar rho = set_.rho, mu = set_.mu;
    const scalar rK = set_.incompressible ? 0 : 1/set_.bulkModulus;
    const auto m = [&](scalar p) { return rK > 0 ? Foam::exp(p*rK) : 1.0; };
    r.setZero(x_.size());
    Fb_.setSize(mesh_.nFaces() - mesh_.nInternalFaces());
    Fb_ = 0;
    Fw_.setSize(Fb_.size());
    Fw_ = Zero;

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();
    const surfaceVectorField& kv = mesh_.nonOrthCorrectionVectors();
    const volVectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();

    // Magnitudes of the terms per cell (the residual scale)
    scalarField aM(nC, 0), aC(nC, 0);

    // Current cell values
    vectorField u(nC);
    scalarField p(nC);
    forAll(u, c)
    {
        u[c] = cellU(x_, c);
        p[c] = x_(ip(c));
    }

    // Residual and Jacobian helpers (momentum residual -M, mass +C;
    // K = -dr/dq = [dM/dq; -dC/dq])
    const auto addM = [&](label P, const vector& v)
    {
        for (label k = 0; k < D_; ++k) r(iu(P, k)) -= s*v[cmp_[k]];
    };
    const auto addC = [&](label P, scalar c) { r(ip(P)) += s*c; };
    const auto jMu = [&](label P, label Q, const tensor& A)
    {
        if (!K) return;
        for (label k = 0; k < D_; ++k)
        {
            for (label l = 0; l < D_; ++l)
            {
                const scalar v = A(cmp_[k], cmp_[l]);
                if (v != 0)
                {
                    K->emplace_back(off + iu(P, k), off + iu(Q, l), s*v);
                }
            }
        }
    };
    const auto jMp = [&](label P, label Q, const vector& g)
    {
        if (!K) return;
        for (label k = 0; k < D_; ++k)
        {
            const scalar v = g[cmp_[k]];
            if (v != 0) K->emplace_back(off + iu(P, k), off + ip(Q), s*v);
        }
    };
    const auto jCu = [&](label P, label Q, const vector& b)
    {
        if (!K) return;
        for (label l = 0; l < D_; ++l)
        {
            const scalar v = b[cmp_[l]];
            if (v != 0) K->emplace_back(off + ip(P), off + iu(Q, l), -s*v);
        }
    };
    const auto jCp = [&](label P, label Q, scalar e)
    {
        if (K && e != 0) K->emplace_back(off + ip(P), off + ip(Q), -s*e);
    };

    // Boundary face maps of the velocity and pressure values
    List<List<faceMap>> bmap(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        List<faceMap>& fm = bmap[patchi];
        fm.setSize(fp.size());
        const velocityBC bc = uBC_[patchi];
        if (bc == velocityBC::empty) continue;
        const scalarField& dcb = fp.deltaCoeffs();
        const vectorField nf(fp.nf());
        forAll(fp, i)
        {
            faceMap& f = fm[i];
            switch (bc)
            {
                case velocityBC::fixedValue:
                    f.c = uFixed_[patchi][i];
                    f.Ts = -dcb[i]*tensor(I);
                    f.cs = dcb[i]*uFixed_[patchi][i];
                    break;
                case velocityBC::interface:
                {
                    const vector& ub = uInterface_
                    [
                        interfaceFace_[fp.start() + i - mesh_.nInternalFaces()]
                    ];
                    f.c = ub;
                    f.Ts = -dcb[i]*tensor(I);
                    f.cs = dcb[i]*ub;
                    break;
                }
                case velocityBC::zeroGradient:
                    f.T = I;
                    break;
                case velocityBC::slip:
                    f.T = I - sqr(nf[i]);
                    f.Ts = -dcb[i]*sqr(nf[i]);
                    break;
                case velocityBC::wedge:
                {
                    const wedgeFvPatch& wp = refCast<const wedgeFvPatch>(fp);
                    f.T = wp.faceT();
                    f.Ts = 0.5*dcb[i]*(wp.cellT() - tensor(I));
                    break;
                }
                default:
                    break;
            }
        }
    }
    const auto pFace = [&](label patchi, label i, label P)
    {
        return pFixed_[patchi] ? pFixedValue_[patchi][i] : p[P];
    };

    // Gauss gradient stencils (internal faces) and the boundary parts:
    // grad(phi)_P = sum_Q G_PQ phi_Q + boundary terms
    std::vector<stencil> G(nC);
    forAll(own, f)
    {
        const label P = own[f], N = nei[f];
        G[P].push_back({P, w[f]*Sf[f]/V[P]});
        G[P].push_back({N, (1 - w[f])*Sf[f]/V[P]});
        G[N].push_back({P, -w[f]*Sf[f]/V[N]});
        G[N].push_back({N, -(1 - w[f])*Sf[f]/V[N]});
    }
    // Pressure gradient: stencil with the boundary faces of unfixed p,
    // and the constant part from fixed pressures
    std::vector<stencil> Gp(G);
    vectorField gp0(nC, Zero);
    // Velocity gradient: boundary parts sum_b S_b (T u_P + c)/V per cell
    List<DynamicList<label>> cellBFaces(nC);   // (patch, face) pairs packed
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        if (uBC_[patchi] == velocityBC::empty) continue;
        const labelUList& fc = fp.faceCells();
        forAll(fp, i)
        {
            const label P = fc[i];
            const vector& Sb = Sf.boundaryField()[patchi][i];
            if (pFixed_[patchi]) gp0[P] += pFixedValue_[patchi][i]*Sb/V[P];
            else Gp[P].push_back({P, Sb/V[P]});
            cellBFaces[P].append(patchi);
            cellBFaces[P].append(i);
        }
    }
    vectorField gradP(gp0);
    tensorField gradU(nC, Zero);
    for (label P = 0; P < nC; ++P)
    {
        for (const stencilEntry& e : Gp[P]) gradP[P] += e.coeff*p[e.cell];
        for (const stencilEntry& e : G[P]) gradU[P] += e.coeff*u[e.cell];
        const DynamicList<label>& bf = cellBFaces[P];
        for (label j = 0; j < bf.size(); j += 2)
        {
            const faceMap& f = bmap[bf[j]][bf[j + 1]];
            const vector& Sb = Sf.boundaryField()[bf[j]][bf[j + 1]];
            gradU[P] += Sb*((f.T & u[P]) + f.c)/V[P];
        }
    }
    // d(k . gradU_P)/du_P from the boundary faces of P
    const auto boundaryGradT = [&](label P, const vector& k)
    {
        tensor A = Zero;
        const DynamicList<label>& bf = cellBFaces[P];
        for (label j = 0; j < bf.size(); j += 2)
        {
            const faceMap& f = bmap[bf[j]][bf[j + 1]];
            const vector& Sb = Sf.boundaryField()[bf[j]][bf[j + 1]];
            A += (k & Sb)/V[P]*f.T;
        }
        return A;
    };

    // d(visc)/du_b of an internal face (owner P, neighbour N, correction
    // vector k, coefficient c) through the gradient of cell X: the
    // interface faces b of X give visc = -c (k . S_b)/V_X u_b
    const auto interfaceGrad = [&]
    (
        label P, label N, const vector& k, scalar c, label X
    )
    {
        const DynamicList<label>& bf = cellBFaces[X];
        for (label j = 0; j < bf.size(); j += 2)
        {
            if (uBC_[bf[j]] != velocityBC::interface) continue;
            const fvPatch& fp = mesh_.boundary()[bf[j]];
            const label b =
                interfaceFace_[fp.start() + bf[j + 1] - mesh_.nInternalFaces()];
            const vector& Sb = Sf.boundaryField()[bf[j]][bf[j + 1]];
            const tensor A = c*(k & Sb)/V[X]*tensor(I);
            KI->push_back({P, b, -A});
            KI->push_back({N, b, A});
        }
    };

    // dF/dp of a flux with a Rhie-Chow term coef (p_N - p_P - d . gbar):
    // the entries of -d(c)/dp
    std::vector<std::pair<label, scalar>> dFdp;
    dFdp.reserve(64);

    // Internal faces
    forAll(own, f)
    {
        const label P = own[f], N = nei[f];
        const vector& S = Sf[f];
        const scalar wf = w[f];
        const vector d = C[N] - C[P];
        const scalar pbar = wf*p[P] + (1 - wf)*p[N];
        const vector ubar = wf*u[P] + (1 - wf)*u[N];
        const scalar Df = wf*rAV_[P] + (1 - wf)*rAV_[N];
        const scalar coef = Df*magSf[f]/mag(d);
        const vector gbar = wf*gradP[P] + (1 - wf)*gradP[N];
        const scalar cRC = coef*(p[N] - p[P] - (gbar & d));
        const scalar F = (ubar & S) - cRC - Fm_[f];
        const scalar lam = upwind_ ? (F >= 0 ? 1.0 : 0.0) : wf;
        const vector uc = lam*u[P] + (1 - lam)*u[N];

        // Momentum: convection, pressure, viscous
        const vector snGrad =
            dc[f]*(u[N] - u[P])
          + (corrected_ ? (kv[f] & (wf*gradU[P] + (1 - wf)*gradU[N])) : vector::zero);
        const vector visc = -mu*magSf[f]*snGrad;
        const vector pres = pbar*S;
        if (steady_)
        {
            addM(P, rho*F*(uc - u[P]) + pres + visc);
            addM(N, -rho*F*(uc - u[N]) - pres - visc);
        }
        else
        {
            addM(P, rho*F*uc + pres + visc);
            addM(N, -rho*F*uc - pres - visc);
        }
        // Mass
        const scalar mf = m(pbar);
        addC(P, mf*F);
        addC(N, -mf*F);
        {
            const scalar a = mag(rho*F*uc) + mag(pres) + mag(visc);
            aM[P] += a;
            aM[N] += a;
            aC[P] += mag(mf*F) + mag(ubar & S);
            aC[N] += mag(mf*F) + mag(ubar & S);
        }

        if (!K) continue;

        // dF/du and dF/dp
        const vector dFduP = wf*S, dFduN = (1 - wf)*S;
        dFdp.clear();
        dFdp.push_back({P, coef});
        dFdp.push_back({N, -coef});
        for (const stencilEntry& e : Gp[P])
        {
            dFdp.push_back({e.cell, coef*wf*(d & e.coeff)});
        }
        for (const stencilEntry& e : Gp[N])
        {
            dFdp.push_back({e.cell, coef*(1 - wf)*(d & e.coeff)});
        }

        // Convection
        if (steady_)
        {
            const vector aP = uc - u[P], aN = uc - u[N];
            jMu(P, P, rho*(aP*dFduP + F*(lam - 1)*tensor(I)));
            jMu(P, N, rho*(aP*dFduN + F*(1 - lam)*tensor(I)));
            jMu(N, P, -rho*(aN*dFduP + F*lam*tensor(I)));
            jMu(N, N, -rho*(aN*dFduN - F*lam*tensor(I)));
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*aP*e.second);
                jMp(N, e.first, -rho*aN*e.second);
            }
        }
        else
        {
            const tensor AP = rho*(uc*dFduP + F*lam*tensor(I));
            const tensor AN = rho*(uc*dFduN + F*(1 - lam)*tensor(I));
            jMu(P, P, AP);
            jMu(P, N, AN);
            jMu(N, P, -AP);
            jMu(N, N, -AN);
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*uc*e.second);
                jMp(N, e.first, -rho*uc*e.second);
            }
        }
        // Pressure
        jMp(P, P, wf*S);
        jMp(P, N, (1 - wf)*S);
        jMp(N, P, -wf*S);
        jMp(N, N, -(1 - wf)*S);
        // Viscous
        const scalar cv = mu*magSf[f];
        jMu(P, P, cv*dc[f]*tensor(I));
        jMu(P, N, -cv*dc[f]*tensor(I));
        jMu(N, P, -cv*dc[f]*tensor(I));
        jMu(N, N, cv*dc[f]*tensor(I));
        if (corrected_)
        {
            const vector& k = kv[f];
            for (const stencilEntry& e : G[P])
            {
                const scalar a = cv*wf*(k & e.coeff);
                jMu(P, e.cell, -a*tensor(I));
                jMu(N, e.cell, a*tensor(I));
            }
            for (const stencilEntry& e : G[N])
            {
                const scalar a = cv*(1 - wf)*(k & e.coeff);
                jMu(P, e.cell, -a*tensor(I));
                jMu(N, e.cell, a*tensor(I));
            }
            const tensor BP = cv*wf*boundaryGradT(P, k);
            const tensor BN = cv*(1 - wf)*boundaryGradT(N, k);
            jMu(P, P, -BP);
            jMu(N, P, BP);
            jMu(P, N, -BN);
            jMu(N, N, BN);
            if (KI)
            {
                // The interface velocities in the cells' gradients
                interfaceGrad(P, N, k, cv*wf, P);
                interfaceGrad(P, N, k, cv*(1 - wf), N);
            }
        }
        // Mass
        jCu(P, P, mf*dFduP);
        jCu(P, N, mf*dFduN);
        jCu(N, P, -mf*dFduP);
        jCu(N, N, -mf*dFduN);
        for (const auto& e : dFdp)
        {
            jCp(P, e.first, mf*e.second);
            jCp(N, e.first, -mf*e.second);
        }
        const scalar dm = mf*rK*F;
        jCp(P, P, dm*wf);
        jCp(P, N, dm*(1 - wf));
        jCp(N, P, -dm*wf);
        jCp(N, N, -dm*(1 - wf));
    }

    // Boundary faces
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        const velocityBC bc = uBC_[patchi];
        if (bc == velocityBC::empty) continue;
        const labelUList& fc = fp.faceCells();
        const scalarField& dcb = fp.deltaCoeffs();
        const vectorField delta(fp.delta());
        const bool pfix = pFixed_[patchi];
        forAll(fp, i)
        {
            const label P = fc[i];
            const faceMap& fm = bmap[patchi][i];
            const vector& S = Sf.boundaryField()[patchi][i];
            const scalar magS = magSf.boundaryField()[patchi][i];
            const scalar pb = pFace(patchi, i, P);
            const vector ub = (fm.T & u[P]) + fm.c;

            // Pressure and viscous forces
            const vector wallForce = pb*S - mu*magS*((fm.Ts & u[P]) + fm.cs);
            addM(P, wallForce);
            Fw_[fp.start() + i - mesh_.nInternalFaces()] = wallForce;
            aM[P] += mag(pb*S) + mag(mu*magS*((fm.Ts & u[P]) + fm.cs));
            if (K)
            {
                if (!pfix) jMp(P, P, S);
                jMu(P, P, -mu*magS*fm.Ts);
            }
            // No flux through wedge faces (the rotated cell velocity lies
            // in the wedge plane, which moves within itself), nor through
            // the interface (the fluid moves with the solid's wall: the
            // flux relative to the face is zero)
            if (bc == velocityBC::wedge) continue;
            if (bc == velocityBC::interface)
            {
                if (KI)
                {
                    const label b =
                        interfaceFace_[fp.start() + i - mesh_.nInternalFaces()];
                    KI->push_back({P, b, -mu*magS*dcb[i]*tensor(I)});
                }
                continue;
            }

            // Flux relative to the face; Rhie-Chow against a fixed
            // pressure at an outlet
            const bool rc = bc == velocityBC::zeroGradient && pfix;
            scalar cRC = 0, coef = 0;
            if (rc)
            {
                coef = rAV_[P]*magS*dcb[i];
                cRC = coef*(pb - p[P] - (gradP[P] & delta[i]));
            }
            const scalar F = (ub & S) - cRC - Fm_[fp.start() + i];
            Fb_[fp.start() + i - mesh_.nInternalFaces()] = F;
            const vector uconv = steady_ ? ub - u[P] : ub;
            addM(P, rho*F*uconv);
            // The injection prescribes mass: its volume is at the
            // reference density (as the hydrostatic model's)
            const bool injection =
                set_.injectedVolume && set_.inletPatches.found(fp.name());
            const scalar mb = injection ? 1.0 : m(pb);
            addC(P, mb*F);
            aM[P] += mag(rho*F*ub);
            aC[P] += mag(mb*F) + mag(ub & S);

            if (!K) continue;
            const vector dFdu = S & fm.T;
            dFdp.clear();
            if (rc)
            {
                dFdp.push_back({P, coef});
                for (const stencilEntry& e : Gp[P])
                {
                    dFdp.push_back({e.cell, coef*(delta[i] & e.coeff)});
                }
            }
            const tensor Tc = steady_ ? fm.T - tensor(I) : fm.T;
            jMu(P, P, rho*(uconv*dFdu + F*Tc));
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*uconv*e.second);
                jCp(P, e.first, mb*e.second);
            }
            jCu(P, P, mb*dFdu);
            if (!pfix && !injection) jCp(P, P, mb*rK*F);
        }
    }

    // Cell terms: time derivative, mass storage
    const scalar rdt = 1/dt_;
    for (label P = 0; P < nC; ++P)
    {
        if (!steady_)
        {
            addM(P, rho*(V[P]*u[P] - V0_[P]*cellU(x0_, P))*rdt);
            jMu(P, P, rho*V[P]*rdt*tensor(I));
        }
        const scalar p0 = x0_(ip(P));
        addC(P, (m(p[P])*V[P] - m(p0)*V0_[P])*rdt);
        jCp(P, P, m(p[P])*rK*V[P]*rdt);
        aC[P] += mag(m(p[P])*V[P] - m(p0)*V0_[P])*rdt;
    }
    scale_ = s*Foam::sqrt(sumSqr(aM) + sumSqr(aC));
}


void Foam::ALENavierStokes::moveMesh(const pointField& points, bool check)
{
    const auto start = std::chrono::steady_clock::now();
    mesh_.movePoints(points);
    computeMeshFluxes();
    meshMotionTime_ += form::secondsSince(start);
    if (check) checkMeshQuality();
}


void Foam::ALENavierStokes::setInterface
(
    const std::shared_ptr<fluidSolidInterface>& interface,
    const form::solidModel& solid
)
{
    interface_ = interface;
    solid_ = &solid;
    set_.meshMotion = "interface";
    interfaceFace_.setSize(mesh_.nFaces() - mesh_.nInternalFaces(), -1);
    forAll(interface_->faces(), j)
    {
        interfaceFace_[interface_->faces()[j] - mesh_.nInternalFaces()] = j;
    }
    uInterface_.setSize(interface_->faces().size(), Zero);
    colourMotionUnits();
}


void Foam::ALENavierStokes::colourMotionUnits()
{
    // The equations of cell P depend on the points of P, of its
    // neighbours N (face weights, delta coefficients, centres) and of
    // theirs (the Gauss gradients of N in the Rhie-Chow and non-orthogonal
    // corrections use N's face weights). So moving a point changes the
    // equations of its cells and two layers around them, and the forces
    // on the interface faces those cells own.
    const fluidSolidInterface& itf = *interface_;
    const List<labelList>& units = itf.motionUnits();
    const labelListList& pointCells = mesh_.pointCells();
    const labelListList& cellCells = mesh_.cellCells();
    const label nC = mesh_.nCells();
    unitCells_.setSize(units.size());
    colours_.clear();
    labelList stamp(nC, -1);
    std::vector<std::vector<char>> used;
    forAll(units, u)
    {
        unitCells_[u].clear();
        if
        (
            itf.unitKind(u, 0) == fluidSolidInterface::fixedUnit
         && itf.unitKind(u, 1) == fluidSolidInterface::fixedUnit
        )
        {
            continue;
        }
        DynamicList<label> cells;
        for (const label p : units[u])
        {
            for (const label c : pointCells[p])
            {
                if (stamp[c] != u) { stamp[c] = u; cells.append(c); }
            }
        }
        for (label layer = 0; layer < 2; ++layer)
        {
            const label n = cells.size();
            for (label k = 0; k < n; ++k)
            {
                for (const label c : cellCells[cells[k]])
                {
                    if (stamp[c] != u) { stamp[c] = u; cells.append(c); }
                }
            }
        }
        unitCells_[u].transfer(cells);
        // Greedy: the first colour none of whose units shares a cell
        std::size_t k = 0;
        for (;; ++k)
        {
            if (k == used.size())
            {
                used.emplace_back(nC, 0);
                colours_.emplace_back();
            }
            bool free = true;
            for (const label c : unitCells_[u])
            {
                if (used[k][c]) { free = false; break; }
            }
            if (free) break;
        }
        for (const label c : unitCells_[u]) used[k][c] = 1;
        colours_[k].push_back(u);
    }
}


void Foam::ALENavierStokes::evaluateInterface
(
    const form::vecX& Us,
    form::vecX& fext,
    form::vecX& r,
    std::vector<triplet>* K
)
{
    const fluidSolidInterface& itf = *interface_;
    const label off = Us.size();
    const label nI = mesh_.nInternalFaces();
    if (Un_.size() != Us.size()) Un_ = Us;

    // The mesh follows the solid
    const pointField base(itf.points(Us));
    moveMesh(base);

    // The solid's velocity by its time integrator, or the backward
    // difference over the (pseudo-)time step of a static analysis
    double beta = 0;
    const form::vecX* c = nullptr;
    form::vecX v;
    if (solid_->velocityLaw(beta, c))
    {
        beta /= set_.timeScale;
        v = beta*Us + *c/set_.timeScale;
    }
    else
    {
        beta = 1/dt_;
        v = beta*(Us - Un_);
    }
    uInterface_ = itf.faceVelocities(v);

    std::vector<interfaceEntry> KI;
    assemble(off, r, K, K ? &KI : nullptr);

    // The fluid's forces on the solid
    const labelList& faces = itf.faces();
    vectorField F(faces.size());
    forAll(F, j) F[j] = Fw_[faces[j] - nI];
    itf.addForces(F, depth_, fext);
    if (!K) return;

    const scalar s = depth_;
    const auto& fi = itf.faceInterpolation();

    // Solid rows: f_a = s N_a(xi_f) F_f . e_c with
    // F_f = p_P S - mu |S| dc (u_f - u_P), u_f = sum_b N_b v_b(U)
    forAll(faces, j)
    {
        const label f = faces[j];
        const label P = mesh_.faceOwner()[f];
        const label patchi = mesh_.boundaryMesh().whichPatch(f);
        const label i = f - mesh_.boundary()[patchi].start();
        const vector& S = mesh_.Sf().boundaryField()[patchi][i];
        const scalar cv =
            set_.mu*mesh_.magSf().boundaryField()[patchi][i]
           *mesh_.boundary()[patchi].deltaCoeffs()[i];
        const std::vector<int>& nodes = fi[j].nodes;
        for (label cc = 0; cc < 2; ++cc)
        {
            const vector& e = itf.faceDirection(j, cc);
            for (std::size_t a = 0; a < nodes.size(); ++a)
            {
                const label row = solid_->dofs().dof(nodes[a], cc);
                const scalar w = s*fi[j].N[a];
                K->emplace_back(row, off + ip(P), -w*(S & e));
                for (label k = 0; k < D_; ++k)
                {
                    K->emplace_back(row, off + iu(P, k), -w*cv*e[cmp_[k]]);
                }
                for (label cb = 0; cb < 2; ++cb)
                {
                    const scalar eb = e & itf.faceDirection(j, cb);
                    if (eb == 0) continue;
                    for (std::size_t b = 0; b < nodes.size(); ++b)
                    {
                        K->emplace_back
                        (
                            row, solid_->dofs().dof(nodes[b], cb),
                            w*cv*eb*fi[j].N[b]*beta
                        );
                    }
                }
            }
        }
    }

    // Fluid rows through the interface velocities: K = s dM/du_f du_f/dU
    for (const interfaceEntry& e : KI)
    {
        const std::vector<int>& nodes = fi[e.face].nodes;
        for (label cb = 0; cb < 2; ++cb)
        {
            const vector Ae = e.A & itf.faceDirection(e.face, cb);
            for (std::size_t b = 0; b < nodes.size(); ++b)
            {
                const scalar w = s*fi[e.face].N[b]*beta;
                for (label k = 0; k < D_; ++k)
                {
                    const scalar val = w*Ae[cmp_[k]];
                    if (val != 0)
                    {
                        K->emplace_back
                        (
                            off + iu(e.cell, k),
                            solid_->dofs().dof(nodes[b], cb), val
                        );
                    }
                }
            }
        }
    }

    // Through the mesh. R (the fluid's residuals and its forces on the
    // solid) depends on the mesh points x; the points on the interface
    // point displacements d_i by the harmonic extension, and d_i on U by
    // (1) of fluidSolidInterface.H:
    //     dR/dU = sum_units dR/dx_u (dx_u/dd_i) (dd_i/dU),
    // dx_u/dd_i = 1 for the unit of interface point i, H_c(u, i) for a
    // free unit, 0 for a fixed one. dR/dx_u by central differences,
    // coloured: the units of one colour change disjoint sets of cells, so
    // one pair of evaluations per colour and component gives them all.
    const std::vector<int> dofs = itf.dofs();
    std::map<int, label> local;
    forAll(dofs, k) local[dofs[k]] = k;
    const label nF = x_.size(), nd = dofs.size();
    // Transposed, so that a row's columns are contiguous
    form::matX DgT = form::matX::Zero(nd, nF + nd);
    const scalarField FbSave(Fb_);
    const vectorField FwSave(Fw_);
    const scalar scaleSave = scale_;
    const scalar h = 1e-6*itf.minFaceLength();
    const label nR = D_ + 1;
    const List<labelList>& units = itf.motionUnits();
    const auto& pi = itf.pointInterpolation();
    const cellList& cells = mesh_.cells();
    form::vecX rp, rm, coef(nd), dF(nd);
    vectorField Fp(faces.size()), Fm(faces.size());
    // The mesh fluxes of the base mesh; a perturbation changes those of
    // the faces of the points it moves
    const scalarField FmBase(Fm_);
    const labelListList& pointFaces = mesh_.pointFaces();
    const faceList& meshFaces = mesh_.faces();
    const auto evaluateAt = [&]
    (
        const pointField& pts,
        const std::vector<label>& members,
        form::vecX& rr,
        vectorField& FF
    )
    {
        const auto start = std::chrono::steady_clock::now();
        mesh_.movePoints(pts);
        Fm_ = FmBase;
        for (const label u : members)
        {
            for (const label p : units[u])
            {
                for (const label f : pointFaces[p])
                {
                    Fm_[f] = meshFaces[f].sweptVol(points0_, pts)/dt_;
                }
            }
        }
        meshMotionTime_ += form::secondsSince(start);
        assemble(off, rr, nullptr, nullptr);
        forAll(FF, j) FF[j] = Fw_[faces[j] - nI];
    };
    for (label cc = 0; cc < 2; ++cc)
    {
        for (const std::vector<label>& colour : colours_)
        {
            std::vector<label> members;
            for (const label u : colour)
            {
                if (itf.unitKind(u, cc) != fluidSolidInterface::fixedUnit)
                {
                    members.push_back(u);
                }
            }
            if (members.empty()) continue;
            for (const label sign : {1, -1})
            {
                pointField pts(base);
                for (const label u : members)
                {
                    for (const label p : units[u])
                    {
                        pts[p] += sign*h*itf.direction(p, cc);
                    }
                }
                if (sign > 0) evaluateAt(pts, members, rp, Fp);
                else evaluateAt(pts, members, rm, Fm);
            }
            for (const label u : members)
            {
                // dx_u/dU: the columns of the solid's dofs (component cc)
                coef.setZero();
                const label kind = itf.unitKind(u, cc);
                for (label i = 0; i < itf.nPoints(); ++i)
                {
                    const scalar w =
                        kind == fluidSolidInterface::freeUnit
                      ? itf.unitWeight(u, cc, i)
                      : scalar(kind == i);
                    if (w == 0) continue;
                    for (std::size_t a = 0; a < pi[i].nodes.size(); ++a)
                    {
                        const int d = solid_->dofs().dof(pi[i].nodes[a], cc);
                        coef(local[d]) += w*pi[i].N[a];
                    }
                }
                // Fluid rows of the unit's cells; forces on their faces
                dF.setZero();
                for (const label c : unitCells_[u])
                {
                    for (label k = 0; k < nR; ++k)
                    {
                        const label row = c*nR + k;
                        const scalar d = (rp(row) - rm(row))/(2*h);
                        if (d != 0) DgT.col(row) += d*coef;
                    }
                    for (const label f : cells[c])
                    {
                        if (f < nI) continue;
                        const label j = interfaceFace_[f - nI];
                        if (j < 0) continue;
                        const vector dFj = depth_*(Fp[j] - Fm[j])/(2*h);
                        for (label cb = 0; cb < 2; ++cb)
                        {
                            const scalar v = dFj & itf.faceDirection(j, cb);
                            const auto& fj = fi[j];
                            for (std::size_t a = 0; a < fj.nodes.size(); ++a)
                            {
                                const int d =
                                    solid_->dofs().dof(fj.nodes[a], cb);
                                dF(local[d]) += fj.N[a]*v;
                            }
                        }
                    }
                }
                for (label k = 0; k < nd; ++k)
                {
                    if (dF(k) != 0) DgT.col(nF + k) += dF(k)*coef;
                }
            }
        }
    }
    for (label row = 0; row < nF + nd; ++row)
    {
        for (label col = 0; col < nd; ++col)
        {
            const scalar val = DgT(col, row);
            if (val == 0) continue;
            // K = -dR/dU: R = r for the fluid rows, f_ext for the solid's
            K->emplace_back
            (
                row < nF ? off + row : dofs[row - nF], dofs[col], -val
            );
        }
    }
    const auto start = std::chrono::steady_clock::now();
    mesh_.movePoints(base);
    meshMotionTime_ += form::secondsSince(start);
    Fm_ = FmBase;
    Fb_ = FbSave;
    Fw_ = FwSave;
    scale_ = scaleSave;
}


void Foam::ALENavierStokes::commit(const form::vecX&)
{
    x0_ = x_;
    points0_ = mesh_.points();
    V0_ = mesh_.V();
}


void Foam::ALENavierStokes::revert()
{
    x_ = x0_;
    if (set_.meshMotion != "none")
    {
        mesh_.movePoints(points0_);
    }
}


std::string Foam::ALENavierStokes::unknownName(int j) const
{
    const label c = j/(D_ + 1), k = j % (D_ + 1);
    const char* names = "xyz";
    std::ostringstream os;
    os  << mesh_.name() << " cell " << c << ' '
        << (k == D_ ? std::string("p") : std::string("U") + names[cmp_[k]]);
    return os.str();
}


std::vector<double> Foam::ALENavierStokes::state() const
{
    std::vector<double> s(x_.data(), x_.data() + x_.size());
    s.insert(s.end(), x0_.data(), x0_.data() + x0_.size());
    return s;
}


void Foam::ALENavierStokes::setState(const std::vector<double>& s)
{
    const std::size_t n = x_.size();
    if (s.size() != 2*n)
    {
        throw form::numericalError
        (
            "ALENavierStokes::setState: " + std::to_string(s.size())
          + " values, not " + std::to_string(2*n)
        );
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        x_(i) = s[i];
        x0_(i) = s[n + i];
    }
}


// ************************************************************************* //
