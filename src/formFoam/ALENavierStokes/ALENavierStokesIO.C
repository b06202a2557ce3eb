/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    ALENavierStokes: what the fluid reports (volume, pressures, fluxes and
    forces, the set-up and step lines of the log), its output (U, p and the
    moved points) and the names and restart state of its unknowns
    (ALENavierStokes.H).
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "fluidSolidInterface.H"
#include "pointIOField.H"
#include "formError.H"
#include <sstream>

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


Foam::ALENavierStokes::interfaceLoad
Foam::ALENavierStokes::interfaceLoadMeasures() const
{
    interfaceLoad m;
    if (!interface_ || Fw_.empty()) return m;
    const labelList& faces = interface_->faces();
    const label nI = mesh_.nInternalFaces();
    const vectorField& Sf = mesh_.faceAreas();
    scalar pA = 0, A = 0, pMin = GREAT, pMax = -GREAT;
    scalar pressureForce = 0, viscousForce = 0;
    forAll(faces, j)
    {
        const label f = faces[j];
        const scalar p = cellPressure(mesh_.faceOwner()[f]);
        const vector Fp = p*Sf[f];
        pA += p*mag(Sf[f]);
        A += mag(Sf[f]);
        pMin = min(pMin, p);
        pMax = max(pMax, p);
        pressureForce += mag(Fp);
        viscousForce += mag(Fw_[f - nI] - Fp);
    }
    if (A <= 0) return m;
    m.valid = true;
    m.meanPressure = pA/A;
    const scalar spread = pMax - pMin;
    m.pressureSpread =
        mag(m.meanPressure) > VSMALL ? spread/mag(m.meanPressure)
      : spread > 0 ? GREAT : 0;
    m.viscousRatio =
        pressureForce > VSMALL ? viscousForce/pressureForce
      : viscousForce > 0 ? GREAT : 0;
    return m;
}


std::string Foam::ALENavierStokes::describe() const
{
    std::ostringstream os;
    os  << mesh_.nCells() << " cells, " << nCellUnknowns() << " unknowns ("
        << D_ << " velocity components and the pressure per cell";
    if (interface_)
    {
        os  << ", and " << interface_->nMeshUnknowns() << " mesh unknowns";
    }
    os  << "), rho "
        << set_.rho << ", mu " << set_.mu << ", ";
    if (set_.incompressible) os << "incompressible";
    else os << "bulk modulus " << set_.bulkModulus;
    os  << '\n'
        << (
               steady_ ? "steady"
             : backward_ ? "transient (backward: BDF2, Euler at the first step)"
             : "transient (Euler)"
           )
        << ", convection " << (upwind_ ? "upwind" : "linear")
        << ", viscous flux " << (corrected_ ? "corrected" : "uncorrected")
        << ", Rhie-Chow pressure-velocity coupling, mesh motion "
        << set_.meshMotion;
    if (interface_)
    {
        os  << "\nmesh derivative: exact (sparse forward-mode automatic"
            << " differentiation) with respect to the points, one evaluation"
            << " per Newton iteration";
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
    os  << "max |U| = " << uMax << " (face Peclet number up to "
        << maxFacePeclet() << "), p in [" << pMin << ", " << pMax
        << "], V = " << volume();
    if (set_.meshMotion != "none")
    {
        os  << "; mesh: min V/V_start " << minVolumeRatio_
            << ", max non-orthogonality " << maxNonOrth_ << " deg";
    }
    return os.str();
}


Foam::scalar Foam::ALENavierStokes::maxFacePeclet() const
{
    const vectorField& S = mesh_.Sf();
    const vectorField& C = mesh_.C();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    scalar Pe = 0;
    forAll(nei, f)
    {
        const vector u = 0.5*(cellU(x_, own[f]) + cellU(x_, nei[f]));
        Pe = max
        (
            Pe,
            mag(u & S[f])/mag(S[f])*mag(C[nei[f]] - C[own[f]])
        );
    }
    return set_.rho*Pe/set_.mu;
}


std::string Foam::ALENavierStokes::failureNote() const
{
    if (!steady_ || pecletSinceCommit_ <= 2) return std::string();
    std::ostringstream os;
    os.precision(3);
    os  << "The steady momentum equation of " << mesh_.name()
        << " reached face Peclet numbers of " << pecletSinceCommit_
        << " in the failed step's iterates (rho |u.n| |d|/mu; above 2"
        << " the central differencing of convection is unbounded, and a"
        << " steady flow on"
        << " this mesh may not exist or not be reachable by Newton's"
        << " method from the last state). A flow this fast is transient:"
        << " ddtSchemes { default Euler; } in system/" << mesh_.name()
        << "/fvSchemes (or slower loading, timeScale in constant/"
        << mesh_.name() << "/fluidProperties).";
    return os.str();
}


void Foam::ALENavierStokes::updateFields()
{
    forAll(U_, c)
    {
        U_[c] = cellU(x_, c);
        p_[c] = x_(ip(c));
    }
    correctBoundaries();
}


void Foam::ALENavierStokes::correctBoundaries()
{
    // OpenFOAM's own conditions, except on the interface with a solid: its
    // movingWallVelocity evaluates the mesh flux through the case's ddt
    // scheme, whose backward variant needs old-time volumes that the fvMesh
    // does not keep here (the mesh moves within one time index). The
    // interface moves with the solid: its faces' velocities at the last
    // evaluation (zero before the first)
    const label nI = mesh_.nInternalFaces();
    auto& Ub = U_.boundaryFieldRef();
    forAll(Ub, patchi)
    {
        if (uBC_.size() == 0 || uBC_[patchi] != velocityBC::interface)
        {
            Ub[patchi].initEvaluate();
            Ub[patchi].evaluate();
            continue;
        }
        const label start = mesh_.boundary()[patchi].start() - nI;
        vectorField v(Ub[patchi].size(), Zero);
        forAll(v, i)
        {
            const label j =
                interfaceFace_.size() ? interfaceFace_[start + i] : -1;
            if (j >= 0 && j < uInterface_.size()) v[i] = uInterface_[j];
        }
        Ub[patchi] == v;
    }
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
    // The backward scheme's level before this one: a restart continues
    // with the same second-order step as the uninterrupted run
    if (backward_ && history_)
    {
        const label n = nCellUnknowns();
        scalarField h(1 + n + V00_.size() + swept0_.size());
        label k = 0;
        h[k++] = dt0_;
        for (label i = 0; i < n; ++i) h[k++] = x00_(i);
        forAll(V00_, i) h[k++] = V00_[i];
        forAll(swept0_, i) h[k++] = swept0_[i];
        IOField<scalar> f
        (
            IOobject
            (
                "backwardHistory", timeName, mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            h
        );
        ok = f.write() && ok;
    }
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


void Foam::ALENavierStokes::restoreInitialConditions()
{
    // The first time directory that holds the fluid's U
    word first;
    scalar firstValue = GREAT;
    for (const instant& t : runTime_.times())
    {
        if (t.name() == runTime_.constant()) continue;
        IOobject io
        (
            "U", t.name(), mesh_, IOobject::MUST_READ, IOobject::NO_WRITE,
            false
        );
        if (t.value() < firstValue && io.typeHeaderOk<volVectorField>(true))
        {
            first = t.name();
            firstValue = t.value();
        }
    }
    if (first.empty() || first == runTime_.timeName()) return;
    const volVectorField U0
    (
        IOobject
        (
            "U", first, mesh_, IOobject::MUST_READ, IOobject::NO_WRITE,
            false
        ),
        mesh_
    );
    const volScalarField p0
    (
        IOobject
        (
            "p", first, mesh_, IOobject::MUST_READ, IOobject::NO_WRITE,
            false
        ),
        mesh_
    );
    forAll(mesh_.boundary(), patchi)
    {
        U_.boundaryFieldRef().set(patchi, U0.boundaryField()[patchi].clone(U_));
        p_.boundaryFieldRef().set(patchi, p0.boundaryField()[patchi].clone(p_));
    }
    Info<< "    fluid region " << mesh_.name() << ": boundary conditions of U"
        << " and p from " << first << "/" << mesh_.name()
        << " (the case's input)" << endl;
}


void Foam::ALENavierStokes::readBackwardHistory()
{
    if (!backward_) return;
    IOobject io
    (
        "backwardHistory", runTime_.timeName(), mesh_,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (!io.typeHeaderOk<IOField<scalar>>(true)) return;
    const IOField<scalar> h(io);
    const label n = nCellUnknowns();
    const label nC = mesh_.nCells(), nF = mesh_.nFaces();
    if (h.size() != 1 + n + nC + nF || !(h[0] > 0))
    {
        FatalErrorInFunction
            << "Restart: " << h.objectPath() << ": " << h.size() << " values, not the "
            << 1 + n + nC + nF << " of this mesh (step length, "
            << n << " unknowns, " << nC << " cell volumes, " << nF
            << " swept volumes), or a step length that is not positive"
            << exit(FatalError);
    }
    label k = 0;
    dt0_ = h[k++];
    x00_.resize(n);
    for (label i = 0; i < n; ++i) x00_(i) = h[k++];
    V00_.setSize(nC);
    for (label i = 0; i < nC; ++i) V00_[i] = h[k++];
    for (label i = 0; i < nF; ++i) swept0_[i] = h[k++];
    history_ = true;
}


std::string Foam::ALENavierStokes::unknownName(int j) const
{
    const char* names = "xyz";
    std::ostringstream os;
    if (j >= nCellUnknowns())
    {
        // A mesh unknown: its unit's reference point and direction
        const fluidSolidInterface& itf = *interface_;
        const label k = j - nCellUnknowns();
        forAll(itf.motionUnits(), u)
        {
            for (label c = 0; c < 2; ++c)
            {
                if (itf.meshUnknown(u, c) != k) continue;
                const label p = itf.motionUnits()[u][0];
                const point& x = points00_[p];
                os  << mesh_.name() << " mesh point (" << x.x() << ' '
                    << x.y() << ' ' << x.z() << ") displacement "
                    << (c ? "z (y)" : "r (x)");
                return os.str();
            }
        }
    }
    const label c = j/(D_ + 1), k = j % (D_ + 1);
    os  << mesh_.name() << " cell " << c << ' '
        << (k == D_ ? std::string("p") : std::string("U") + names[cmp_[k]]);
    return os.str();
}


std::vector<double> Foam::ALENavierStokes::state() const
{
    // The cells' unknowns (the mesh unknowns follow from the points,
    // written with the fields); with the backward scheme the level before
    // the committed one: its unknowns, volumes, the faces' swept volumes
    // and the step length
    const label n = nCellUnknowns();
    std::vector<double> s(x_.data(), x_.data() + n);
    s.insert(s.end(), x0_.data(), x0_.data() + n);
    if (backward_ && history_)
    {
        s.push_back(dt0_);
        s.insert(s.end(), x00_.data(), x00_.data() + n);
        s.insert(s.end(), V00_.begin(), V00_.end());
        s.insert(s.end(), swept0_.begin(), swept0_.end());
    }
    return s;
}


void Foam::ALENavierStokes::setState(const std::vector<double>& s)
{
    const std::size_t n = nCellUnknowns();
    const std::size_t nC = mesh_.nCells(), nF = mesh_.nFaces();
    const std::size_t withHistory = 3*n + 1 + nC + nF;
    if (s.size() != 2*n && !(backward_ && s.size() == withHistory))
    {
        throw form::numericalError
        (
            "ALENavierStokes::setState: " + std::to_string(s.size())
          + " values, not " + std::to_string(2*n)
          + (backward_ ? " or " + std::to_string(withHistory) : "")
        );
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        x_(i) = s[i];
        x0_(i) = s[n + i];
    }
    // (a state without the level before, e.g. written by a run with the
    // Euler scheme: the next step is an Euler step)
    history_ = s.size() == withHistory;
    if (history_)
    {
        std::size_t k = 2*n;
        dt0_ = s[k++];
        x00_.resize(n);
        for (std::size_t i = 0; i < n; ++i) x00_(i) = s[k++];
        V00_.setSize(nC);
        for (std::size_t i = 0; i < nC; ++i) V00_[i] = s[k++];
        for (std::size_t i = 0; i < nF; ++i) swept0_[i] = s[k++];
    }
}


// ************************************************************************* //
