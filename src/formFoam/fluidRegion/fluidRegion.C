/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    constant/<fluid>/fluidProperties -> a fluid model joined to the solid's
    Newton system (see fluidRegion.H).
\*---------------------------------------------------------------------------*/
#include "fluidRegion.H"
#include "dictionaryChecks.H"
#include "formError.H"
#include "IOField.H"
#include "OSspecific.H"
#include "pointIOField.H"
#include "wedgePolyPatch.H"
#include "emptyPolyPatch.H"
#include "fluidSolidInterface.H"
#include <limits>
#include <sstream>

// * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::solidRegion& Foam::fluidRegion::findSolid
(
    const IOdictionary& dict,
    PtrList<solidRegion>& solids
)
{
    const fileName file = dict.objectPath().relative(dict.time().path());
    if (!dict.found("solidRegion"))
    {
        if (solids.size() != 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'solidRegion' missing in " << file
                << ": name the solid region the fluid wets" << exit(FatalIOError);
        }
        return solids[0];
    }
    const word name = dict.get<word>("solidRegion");
    wordList names;
    for (solidRegion& s : solids)
    {
        if (s.name() == name) return s;
        names.append(s.name());
    }
    FatalIOErrorInFunction(dict)
        << "Entry 'solidRegion' in " << file << ": unknown solid"
        << " region '" << name << "'" << nl
        << "    Solid regions of constant/regionProperties: " << names
        << exit(FatalIOError);
    return solids[0];
}

Foam::scalar Foam::fluidRegion::readBulkModulus
(
    const dictionary& dict,
    const fileName& file
)
{
    ITstream& is = dict.lookup("bulkModulus");
    const token t(is);
    if (t.isWord() && t.wordToken() == "incompressible")
    {
        return std::numeric_limits<scalar>::infinity();
    }
    if (!t.isNumber() || !(t.number() > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'bulkModulus' in " << file << " must be a positive"
            << " number or 'incompressible', got " << t << exit(FatalIOError);
    }
    return t.number();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::wordList Foam::fluidRegion::fluidModels()
{
    return {"hydrostatic", "ALENavierStokes"};
}


Foam::fluidRegion::fluidRegion
(
    Time& runTime,
    const word& name,
    PtrList<solidRegion>& solids,
    form::solidModel& model
)
:
    runTime_(runTime),
    name_(name),
    dict_
    (
        IOobject
        (
            "fluidProperties", runTime.constant(), name, runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    ),
    model_(dict_.get<word>("fluidModel")),
    solid_(nullptr)
{
    checkInput(dict_, dict_.objectPath());
    // The file as the user sees it, for messages
    const fileName file = fileName("constant")/name/"fluidProperties";
    if (!fluidModels().found(model_))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'fluidModel' in " << file << ": unknown model '"
            << model_ << "'" << nl << "    Valid fluid models: "
            << fluidModels() << exit(FatalIOError);
    }
    if (model_ == "ALENavierStokes")
    {
        buildALE(solids, model);
        return;
    }
    if (solids.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'fluidModel' in " << file << ": the hydrostatic fluid"
            << " is a cavity bounded by a solid, but constant/"
            << "regionProperties lists no solid region" << exit(FatalIOError);
    }
    solid_ = &findSolid(dict_, solids);
    checkKeywords
    (
        dict_,
        {"fluidModel", "solidRegion", "interface", "bulkModulus",
         "initialVolume", "injectedVolume", "pressure",
         // the ALENavierStokes model's, so that one case serves both
         "fluidInterface", "rho", "mu", "inlet", "meshMotion",
         "timeScale"}
    );

    form::hydrostaticCavitySpec spec;
    spec.name = name_;

    // The interface: wetted patches of the solid region
    if (!dict_.found("interface"))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'interface' missing in " << file << ": fluid"
            << " region '" << name_ << "' needs an interface with solid"
            << " region '" << solid_->name() << "' (its wetted patches, e.g."
            << " interface (bottom);)" << exit(FatalIOError);
    }
    const wordList patches = dict_.get<wordList>("interface");
    if (patches.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'interface' in " << file << " is empty: fluid"
            << " region '" << name_ << "' has no interface with a solid"
            << exit(FatalIOError);
    }
    checkInterface(patches, file);
    for (const word& p : patches) spec.faceSets.push_back(p);
    if (solid_->analysis() == form::analysisType::solid3D)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'fluidModel' in " << file << ": the hydrostatic"
            << " cavity needs a plane strain or axisymmetric solid region;"
            << " '" << solid_->name() << "' is 3D" << exit(FatalIOError);
    }

    // The fluid: bulk modulus (or incompressible), initial volume
    spec.bulkModulus = readBulkModulus(dict_, file);
    spec.initialVolume = dict_.get<scalar>("initialVolume");
    if (!(spec.initialVolume > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'initialVolume' in " << file << " must be"
            << " positive (the cavity's volume at the start, fixed walls"
            << " included), got " << spec.initialVolume << exit(FatalIOError);
    }

    // The load: injected volume or pressure, one of them
    const bool vol = dict_.found("injectedVolume");
    if (vol == dict_.found("pressure"))
    {
        FatalIOErrorInFunction(dict_)
            << "Fluid region '" << name_ << "' in " << file
            << " needs exactly one of 'injectedVolume' (volume control) and"
            << " 'pressure' (pressure control)" << exit(FatalIOError);
    }
    load_.reset
    (
        Function1<scalar>::New(vol ? "injectedVolume" : "pressure", dict_)
       .ptr()
    );
    const std::shared_ptr<Function1<scalar>> f = load_;
    if (vol)
    {
        spec.injectedVolume = [f](double t) { return f->value(t); };
    }
    else
    {
        spec.pressure = [f](double t) { return f->value(t); };
    }
    // The pressure equation's scale: Young's modulus of the solid
    const form::material& mat = solid_->material();
    const scalar K = mat.bulkModulus(), G = mat.shearModulus();
    spec.referenceModulus = 9*K*G/(3*K + G);

    try
    {
        cavity_ = std::make_shared<form::hydrostaticCavity>
        (
            solid_->feMesh().feMesh(), solid_->analysis(), spec
        );
    }
    catch (const form::inputError& e)
    {
        fatalInput(dict_, e);
    }
    model.addCoupledBlock(cavity_);
}


// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::fluidRegion::checkInterface
(
    const wordList& patches,
    const fileName& file
) const
{
    const auto& faceSets = solid_->feMesh().feMesh().faceSets;
    const polyBoundaryMesh& bm = solid_->mesh().boundaryMesh();
    for (const word& p : patches)
    {
        const label patchi = bm.findPatchID(p);
        if
        (
            patchi >= 0
         && (isA<emptyPolyPatch>(bm[patchi]) || isA<wedgePolyPatch>(bm[patchi]))
        )
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'interface' in " << file.c_str() << ": '" << p
                << "' is an empty or wedge patch of solid region '"
                << solid_->name() << "' (the front and back of the 2D mesh):"
                << " it has no edges in the plane and cannot carry an"
                << " interface. Use a patch on the outline of the region"
                << exit(FatalIOError);
        }
        if (patchi < 0 || !faceSets.count(p) || faceSets.at(p).empty())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'interface' in " << file.c_str() << ": '" << p
                << "' is not a patch of solid region '" << solid_->name()
                << "'" << nl << "    Patches: " << bm.names()
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fluidRegion::pressure() const
{
    return cavity_ ? cavity_->pressure() : ale_->meanPressure();
}


Foam::scalar Foam::fluidRegion::pressureAt(const point& pt) const
{
    if (cavity_) return cavity_->pressure();
    const label c = ale_->findCell(pt);
    return c < 0 ? NAN : ale_->cellPressure(c);
}


Foam::scalar Foam::fluidRegion::velocityAt(const point& pt, direction d) const
{
    if (cavity_) return 0;
    const label c = ale_->findCell(pt);
    return c < 0 ? NAN : ale_->cellVelocity(c)[d];
}


Foam::scalar Foam::fluidRegion::volume() const
{
    return cavity_ ? cavity_->volume(solid_->model().U()) : ale_->volume();
}


Foam::scalar Foam::fluidRegion::flowRate(const word& patch) const
{
    return ale_ ? ale_->patchFlux(patch) : 0;
}


Foam::vector Foam::fluidRegion::force(const word& patch) const
{
    return ale_ ? ale_->patchForce(patch) : vector::zero;
}


bool Foam::fluidRegion::hasPatch(const word& patch) const
{
    return ale_ && mesh_->boundary().findPatchID(patch) >= 0;
}


Foam::scalar Foam::fluidRegion::injectedVolume(scalar t) const
{
    if (cavity_) return cavity_->injected(t);
    return load_ ? load_->value(t) : 0;
}


Foam::string Foam::fluidRegion::describe() const
{
    std::ostringstream os;
    if (ale_)
    {
        os  << "fluid region " << name_ << ": ALENavierStokes on its fvMesh"
            << " (coupled velocity-pressure block)\n" << ale_->describe();
        if (ale_->interface())
        {
            os  << "\ncoupled to solid region " << solid_->name() << " on";
            for (const word& p : dict_.get<wordList>("interface")) os << ' ' << p;
            os  << '\n' << ale_->interface()->describe();
        }
        return os.str();
    }
    os  << "fluid region " << name_ << ": " << model_
        << " (one uniform pressure, no fluid mesh), wets "
        << solid_->name() << " on";
    for (const std::string& p : cavity_->spec().faceSets) os << ' ' << p;
    os  << '\n' << cavity_->describe();
    if (!std::isfinite(cavity_->spec().bulkModulus)) os << " (incompressible)";
    return os.str();
}


Foam::string Foam::fluidRegion::report(scalar t) const
{
    std::ostringstream os;
    os.precision(6);
    if (ale_)
    {
        os  << "    fluid " << name_ << ": " << ale_->report();
        return os.str();
    }
    os  << "    fluid " << name_ << ": p = " << pressure() << ", V = "
        << volume();
    if (cavity_->volumeControlled())
    {
        os << ", injected " << injectedVolume(t);
    }
    return os.str();
}


bool Foam::fluidRegion::write(const word& timeName) const
{
    if (ale_)
    {
        return ale_->write(timeName);
    }
    const std::vector<double> s = cavity_->state();
    IOField<scalar> f
    (
        IOobject
        (
            "fluidState", timeName, name_, runTime_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        scalarField(s.size())
    );
    forAll(f, i) f[i] = s[i];
    const unsigned precision = IOstream::defaultPrecision(17);
    const bool ok = f.write();
    IOstream::defaultPrecision(precision);
    return ok;
}


void Foam::fluidRegion::readState(const word& timeName)
{
    // The ALE fluid read U, p (and the moved points) of the start time
    // when it was built
    if (ale_) return;
    IOobject io
    (
        "fluidState", timeName, name_, runTime_,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (!io.typeHeaderOk<IOField<scalar>>(true))
    {
        FatalErrorInFunction
            << "Restart at time " << timeName << ": the state of fluid region"
            << " '" << name_ << "' (" << io.objectPath() << ") is missing"
            << exit(FatalError);
    }
    const IOField<scalar> f(io);
    try
    {
        cavity_->setState(std::vector<double>(f.begin(), f.end()));
    }
    catch (const form::numericalError& e)
    {
        FatalErrorInFunction
            << f.objectPath() << ": " << e.what() << exit(FatalError);
    }
}


// ************************************************************************* //
