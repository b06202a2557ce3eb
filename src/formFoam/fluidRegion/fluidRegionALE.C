/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    fluidRegion: the ALENavierStokes model's settings (fluidProperties:
    rho, mu, bulkModulus, timeScale, meshMotion, the injection and the
    interface), its mesh and fluid block, and its interface with a solid
    (see fluidRegion.H).
\*---------------------------------------------------------------------------*/
#include "fluidRegion.H"
#include "dictionaryChecks.H"
#include "formError.H"
#include "OSspecific.H"
#include "pointIOField.H"
#include "wedgePolyPatch.H"
#include "emptyPolyPatch.H"
#include "fluidSolidInterface.H"
#include <limits>
#include <sstream>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fluidRegion::buildALE
(
    PtrList<solidRegion>& solids,
    form::solidModel& model
)
{
    const fileName file = fileName("constant")/name_/"fluidProperties";
    checkKeywords
    (
        dict_,
        {"fluidModel", "solidRegion", "interface", "fluidInterface",
         "bulkModulus", "rho", "mu", "meshMotion", "inlet",
         "injectedVolume", "initialVolume", "pressure", "timeScale"}
    );
    // With a solid region in the scene the fluid is coupled to it (an
    // uncoupled solid and fluid side by side is never what a case means)
    if (solids.size())
    {
        solid_ = &findSolid(dict_, solids);
        for (const word& key : {"interface", "fluidInterface"})
        {
            if (!dict_.found(key) || dict_.get<wordList>(key).empty())
            {
                FatalIOErrorInFunction(dict_)
                    << "Entry '" << key << "' missing or empty in " << file.c_str()
                    << ": the ALENavierStokes fluid region '" << name_
                    << "' needs an interface with solid region '"
                    << solid_->name() << "': interface (its wetted patches)"
                    << " and fluidInterface (the fluid's patches on them)"
                    << exit(FatalIOError);
            }
        }
    }
    else if (dict_.found("interface") || dict_.found("fluidInterface"))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'interface' in " << file.c_str() << ": constant/"
            << "regionProperties lists no solid region for fluid region '"
            << name_ << "' to wet" << exit(FatalIOError);
    }
    if (dict_.found("pressure"))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'pressure' in " << file.c_str() << ": pressure control is"
            << " the hydrostatic model's; the ALENavierStokes fluid takes"
            << " a prescribed pressure from a fixedValue or uniformFixedValue"
            << " condition of an inlet in 0/" << name_ << "/p"
            << exit(FatalIOError);
    }
    ALEFluidSettings set;
    const auto positive = [&](const word& key)
    {
        const scalar v = dict_.get<scalar>(key);
        if (!(v > 0))
        {
            FatalIOErrorInFunction(dict_)
                << "Entry '" << key << "' in " << file.c_str() << " must be"
                << " positive, got " << v << exit(FatalIOError);
        }
        return v;
    };
    set.rho = positive("rho");
    if (dict_.found("timeScale"))
    {
        set.timeScale = positive("timeScale");
    }
    if (dict_.found("fluidInterface"))
    {
        set.interfacePatches = dict_.get<wordList>("fluidInterface");
    }
    // Injection through inlet patches
    if (dict_.found("injectedVolume") != dict_.found("inlet"))
    {
        FatalIOErrorInFunction(dict_)
            << "Fluid region '" << name_ << "' in " << file.c_str() << ": "
            << "injectedVolume and inlet go together (the injected volume"
            << " enters through the inlet patches)" << exit(FatalIOError);
    }
    if (dict_.found("injectedVolume"))
    {
        set.inletPatches = dict_.get<wordList>("inlet");
        load_.reset(Function1<scalar>::New("injectedVolume", dict_).ptr());
        const std::shared_ptr<Function1<scalar>> f = load_;
        set.injectedVolume = [f](double t) { return f->value(t); };
    }
    set.mu = positive("mu");
    set.bulkModulus = readBulkModulus(dict_, file);
    set.incompressible = !std::isfinite(set.bulkModulus);
    if (set.incompressible) set.bulkModulus = GREAT;
    meshDiffusivity diffusivity;
    if (dict_.found("meshMotion"))
    {
        const dictionary& md =
            subDictOf(dict_, "meshMotion", "{ type ...; }");
        checkKeywords
        (
            md,
            {"type", "amplitude", "period", "maxNonOrthogonality",
             "diffusivity", "exponent"}
        );
        set.meshMotion = md.getOrDefault<word>("type", "none");
        if (solid_ && set.meshMotion != "none")
        {
            FatalIOErrorInFunction(md)
                << "Entry 'meshMotion/type' in " << file.c_str() << ": the mesh of a"
                << " fluid coupled to a solid follows the solid; remove the"
                << " type (or set none)" << exit(FatalIOError);
        }
        set.maxNonOrthogonality =
            md.getOrDefault<scalar>("maxNonOrthogonality", 80);
        if (!(set.maxNonOrthogonality > 0 && set.maxNonOrthogonality < 90))
        {
            FatalIOErrorInFunction(md)
                << "Entry 'meshMotion/maxNonOrthogonality' in "
                << file.c_str() << " is out of range: "
                << set.maxNonOrthogonality << " (valid: an angle in degrees"
                << " in (0, 90))" << exit(FatalIOError);
        }
        if (set.meshMotion == "oscillating")
        {
            set.amplitude = md.get<vector>("amplitude");
            set.period = md.get<scalar>("period");
            if (!(set.period > 0))
            {
                FatalIOErrorInFunction(md)
                    << "Entry 'meshMotion/period' in " << file.c_str() << " must be"
                    << " positive" << exit(FatalIOError);
            }
        }
        else if (set.meshMotion != "none")
        {
            FatalIOErrorInFunction(md)
                << "Entry 'meshMotion/type' in " << file.c_str() << ": unknown '"
                << set.meshMotion << "'; valid: none oscillating"
                << exit(FatalIOError);
        }
        if (md.found("diffusivity") || md.found("exponent"))
        {
            if (!solid_)
            {
                FatalIOErrorInFunction(md)
                    << "Entry 'meshMotion/diffusivity' in " << file.c_str()
                    << ": the diffusivity belongs to the motion of a mesh"
                    << " that follows a solid; fluid region '" << name_
                    << "' has none" << exit(FatalIOError);
            }
            diffusivity = meshDiffusivity::read(md, file);
        }
    }

    // The region's mesh: constant/<fluid>/polyMesh
    const fileName meshDir =
        runTime_.path()/runTime_.constant()/name_/polyMesh::meshSubDir;
    if (!isFile(meshDir/"faces") && !isFile(meshDir/"faces.gz"))
    {
        FatalErrorInFunction
            << "Fluid region '" << name_ << "' (" << file.c_str() << ", fluidModel"
            << " ALENavierStokes) has no mesh: " << "constant"/name_
            /polyMesh::meshSubDir << " is missing; run blockMesh -region "
            << name_ << exit(FatalError);
    }
    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                name_, runTime_.timeName(), runTime_, IOobject::MUST_READ
            )
        )
    );
    // The kinds of the two meshes must agree
    if (solid_)
    {
        const bool wedge = mesh_->nGeometricD() == 2
            && [&]()
            {
                for (const polyPatch& pp : mesh_->boundaryMesh())
                {
                    if (isA<wedgePolyPatch>(pp) && pp.size()) return true;
                }
                return false;
            }();
        const form::analysisType a = solid_->analysis();
        const bool axi = a == form::analysisType::axisymmetric;
        std::string why;
        if (a == form::analysisType::solid3D)
        {
            why = "the interface with a 3D solid is not implemented";
        }
        else if (mesh_->nGeometricD() != 2)
        {
            why = "the fluid mesh is 3D; it must be one cell thick";
        }
        else if (axi != wedge)
        {
            why = axi
                ? "the solid is axisymmetric but the fluid mesh has no wedge"
                  " patches"
                : "the fluid mesh is a wedge (axisymmetric) but the solid is"
                  " plane strain";
        }
        else if (!wedge && mesh_->geometricD()[2] != -1)
        {
            why = "a plane fluid mesh must be thin in z (the solid's FE plane"
                  " is x-y)";
        }
        else if (wedge)
        {
            // The solid's axis against the fluid wedge's
            const vector solidAxis =
                solid_->feMesh().toSpace(point(1, 1, 1), Eigen::Vector2d(0, 1));
            for (const polyPatch& pp : mesh_->boundaryMesh())
            {
                if (!isA<wedgePolyPatch>(pp) || !pp.size()) continue;
                const vector ax = refCast<const wedgePolyPatch>(pp).axis();
                if (mag(ax & solidAxis) < 0.9999*mag(ax))
                {
                    why = "the fluid wedge's axis is not the solid's";
                }
                break;
            }
        }
        if (!why.empty())
        {
            FatalIOErrorInFunction(dict_)
                << "Fluid region '" << name_ << "' (" << file.c_str() << ") and solid"
                << " region '" << solid_->name() << "' (constant/"
                << solid_->name() << "/solidProperties, analysisType): "
                << why.c_str() << exit(FatalIOError);
        }
    }
    if (solid_) checkInterface(dict_.get<wordList>("interface"), file);
    for (const word& n : set.interfacePatches)
    {
        const label patchi = mesh_->boundaryMesh().findPatchID(n);
        if
        (
            patchi >= 0
         && (
                isA<emptyPolyPatch>(mesh_->boundaryMesh()[patchi])
             || isA<wedgePolyPatch>(mesh_->boundaryMesh()[patchi])
            )
        )
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'fluidInterface' in " << file.c_str() << ": '" << n
                << "' is an empty or wedge patch of fluid region '" << name_
                << "' (the front and back of the 2D mesh): it cannot carry"
                << " an interface" << exit(FatalIOError);
        }
        if (patchi < 0)
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'fluidInterface' in " << file.c_str() << ": '" << n
                << "' is not a patch of fluid region '" << name_ << "'" << nl
                << "    Patches: " << mesh_->boundaryMesh().names()
                << exit(FatalIOError);
        }
    }
    ale_ = std::make_shared<ALENavierStokes>(runTime_, mesh_(), set);
    if (solid_)
    {
        wordList slip;
        for (const fvPatchVectorField& up : ale_->U().boundaryField())
        {
            const word t = up.type();
            if (t == "slip" || t == "symmetryPlane" || t == "symmetry")
            {
                slip.append(up.patch().name());
            }
        }
        auto itf = std::make_shared<fluidSolidInterface>
        (
            mesh_(), ale_->referencePoints(), set.interfacePatches,
            solid_->feMesh(), dict_.get<wordList>("interface"), slip, file,
            diffusivity
        );
        ale_->setInterface(itf, solid_->model());
        if (dict_.found("initialVolume"))
        {
            const scalar V0 = dict_.get<scalar>("initialVolume");
            if (mag(ale_->volume() - V0) > 0.01*V0)
            {
                WarningInFunction
                    << "initialVolume " << V0 << " in " << file.c_str() << " (the"
                    << " hydrostatic model's) differs from the fluid mesh's"
                    << " volume " << ale_->volume() << " by more than 1 %"
                    << endl;
            }
        }
    }
    model.addCoupledBlock(ale_);
}


// ************************************************************************* //
