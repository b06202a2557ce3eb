/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of formScene.H: a case as a scene, its set-up. Reading
    system/solidSolution (analysis, steps, Newton's controls, the linear
    solver), building the regions and the coupled blocks the case declares,
    the dynamic integrator's start, and the scene printed at the start of
    the log. The run: formScene.C.
\*---------------------------------------------------------------------------*/
#include "formScene.H"
#include "blockTangentCheck.H"
#include "dictionaryChecks.H"
#include "regionProperties.H"
#include "OFstream.H"
#include "IOField.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "clockTime.H"
#include "autoSolver.H"
#include "springbackMeasure.H"
#include "supportCheck.H"
#include "vtkWriter.H"
#include "formError.H"
#include <algorithm>
#include <iostream>
#include <limits>
#include <numeric>
#include <sstream>

// * * * * * * * * * * * * * * * Private Functions  * * * * * * * * * * * * //

void Foam::formScene::readSolution()
{
    const dictionary& d = solution_;
    checkInput
    (
        runTime_.controlDict(), runTime_.path()/"system"/"controlDict"
    );
    checkInput(solution_, solution_.objectPath());
    checkKeywords
    (
        d,
        {
            "analysis", "linearSolver", "minDeltaT", "maxDeltaT",
            "maxCutbacks", "maxIterations", "forceTolerance",
            "energyTolerance", "lineSearch", "lineSearchType",
            "lineSearchMemory", "predictor",
            "growthFactor",
            "growthIterations", "summary", "integrator", "gamma", "mass",
            "initialVelocity", "effectThreshold", "newton",
            "keptTangentContraction"
        }
    );
    const word analysis = d.getOrDefault<word>("analysis", "static");
    if (!wordList{"static", "dynamic", "trapezoidal", "bathe"}.found(analysis))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'analysis' in " << d.name() << ": unknown '"
            << analysis << "'; valid: static dynamic trapezoidal bathe"
            << exit(FatalIOError);
    }
    // analysis trapezoidal | bathe: short for analysis dynamic with that
    // integrator
    const bool shorthand = analysis == "trapezoidal" || analysis == "bathe";
    if (shorthand && d.found("integrator"))
    {
        FatalIOErrorInFunction(d)
            << "Entries 'analysis " << analysis << "' and 'integrator' in "
            << d.name() << ": give either analysis dynamic with an"
            << " integrator, or analysis " << analysis << " alone"
            << exit(FatalIOError);
    }
    dynamic_ = analysis == "dynamic" || shorthand;
    if (!dynamic_)
    {
        for (const word key : {"integrator", "gamma", "mass", "initialVelocity"})
        {
            if (d.found(key))
            {
                FatalIOErrorInFunction(d)
                    << "Entry '" << key << "' in " << d.name() << " needs"
                    << " analysis dynamic (the analysis is static)"
                    << exit(FatalIOError);
            }
        }
    }
    integratorName_ =
        shorthand ? analysis : d.getOrDefault<word>("integrator", "bathe");
    gamma_ = d.getOrDefault<scalar>("gamma", 0.5);
    const word mass = d.getOrDefault<word>("mass", "consistent");
    if (!wordList{"consistent", "lumped"}.found(mass))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'mass' in " << d.name() << ": unknown '" << mass
            << "'; valid: consistent lumped" << exit(FatalIOError);
    }
    lumpedMass_ = mass == "lumped";
    initialVelocity_ = d.getOrDefault<vector>("initialVelocity", Zero);
    if (dynamic_)
    {
        try
        {
            integrator_.reset(new form::timeIntegrator(integratorName_, gamma_));
        }
        catch (const form::inputError& err)
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << err.entry().c_str() << "' in " << d.name()
                << ": " << err.what() << exit(FatalIOError);
        }
    }

    steps_.startTime = runTime_.startTime().value();
    steps_.endTime = runTime_.endTime().value();
    steps_.deltaT = runTime_.deltaTValue();
    steps_.minDeltaT = d.getOrDefault<scalar>("minDeltaT", 1e-4*steps_.deltaT);
    steps_.maxDeltaT = d.getOrDefault<scalar>("maxDeltaT", steps_.deltaT);
    steps_.maxCutbacks = d.getOrDefault<label>("maxCutbacks", 10);
    steps_.growthFactor = d.getOrDefault<scalar>("growthFactor", 1.5);
    steps_.easyIterations = d.getOrDefault<label>("growthIterations", 4);
    if (!(steps_.growthFactor >= 1))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'growthFactor' in " << d.name() << " must be >= 1, got "
            << steps_.growthFactor << exit(FatalIOError);
    }
    newton_.maxIterations = d.getOrDefault<label>("maxIterations", 20);
    newton_.forceTolerance = d.getOrDefault<scalar>("forceTolerance", 1e-8);
    newton_.energyTolerance = d.getOrDefault<scalar>("energyTolerance", 1e-14);
    newton_.lineSearch = d.getOrDefault<bool>("lineSearch", true);
    predictor_ = d.getOrDefault<word>("predictor", "auto");
    if (!wordList{"auto", "none", "extrapolate", "quadratic"}.found(predictor_))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'predictor' in " << d.name() << ": unknown '"
            << predictor_ << "'; valid: auto none extrapolate quadratic"
            << exit(FatalIOError);
    }
    // Newton's matrix: the tangent of every iterate, or kept factors while
    // they contract the residual (staticSolver.H, "Kept tangent")
    const word method = d.getOrDefault<word>("newton", "full");
    if (!wordList{"full", "modified"}.found(method))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'newton' in " << d.name() << ": unknown '" << method
            << "'; valid: full modified" << exit(FatalIOError);
    }
    newton_.keepTangent = method == "modified";
    if (!newton_.keepTangent && d.found("keptTangentContraction"))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'keptTangentContraction' in " << d.name() << " needs"
            << " newton modified (the method is full Newton)"
            << exit(FatalIOError);
    }
    newton_.keptTangentContraction =
        d.getOrDefault<scalar>("keptTangentContraction", 0.25);
    if
    (
        !(newton_.keptTangentContraction > 0)
     || !(newton_.keptTangentContraction < 1)
    )
    {
        FatalIOErrorInFunction(d)
            << "Entry 'keptTangentContraction' in " << d.name() << " must be"
            << " in (0, 1) (the residual reduction per iteration below which"
            << " kept factors are refreshed), got "
            << newton_.keptTangentContraction << exit(FatalIOError);
    }
    lineSearchType_ = d.getOrDefault<word>("lineSearchType", "auto");
    newton_.lineSearchMemory = d.getOrDefault<label>("lineSearchMemory", 0);
    if (newton_.lineSearchMemory < 0 || newton_.lineSearchMemory > 20)
    {
        FatalIOErrorInFunction(d)
            << "Entry 'lineSearchMemory' in " << d.name() << " must be"
            << " between 0 (monotone) and 20, got "
            << newton_.lineSearchMemory << exit(FatalIOError);
    }
    if (!wordList{"auto", "energy", "residual"}.found(lineSearchType_))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'lineSearchType' in " << d.name() << ": unknown '"
            << lineSearchType_ << "'; valid: auto energy residual"
            << exit(FatalIOError);
    }

    const auto positive = [&](const char* key, scalar v)
    {
        if (!(v > 0))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "' in " << d.name()
                << " must be positive, got " << v << exit(FatalIOError);
        }
    };
    positive("deltaT (controlDict)", steps_.deltaT);
    positive("minDeltaT", steps_.minDeltaT);
    positive("maxDeltaT", steps_.maxDeltaT);
    positive("maxIterations", newton_.maxIterations);
    positive("forceTolerance", newton_.forceTolerance);
    positive("energyTolerance", newton_.energyTolerance);
    const auto below = [&](const char* key, scalar v, scalar max, const char* why)
    {
        if (!(v <= max))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "' in " << d.name() << " is out of"
                << " range: " << v << " > " << max << " (" << why << ")"
                << exit(FatalIOError);
        }
    };
    below
    (
        "minDeltaT", steps_.minDeltaT, steps_.deltaT,
        "the smallest step after cutbacks cannot exceed deltaT of"
        " system/controlDict"
    );
    below
    (
        "forceTolerance", newton_.forceTolerance, 0.1,
        "a relative tolerance; 1e-8 is the default"
    );
    below
    (
        "energyTolerance", newton_.energyTolerance, 0.1,
        "a relative tolerance; 1e-14 is the default"
    );
    below("maxIterations", newton_.maxIterations, 1000, "Newton iterations");
    const scalar effectThreshold =
        d.getOrDefault<scalar>("effectThreshold", 0.01);
    positive("effectThreshold", effectThreshold);
    below
    (
        "effectThreshold", effectThreshold, 1,
        "the relative influence below which the effect report calls a"
        " declared effect negligible; 0.01 is the default"
    );
    effects_ = effectReport(effectThreshold);
    if (!(steps_.maxCutbacks >= 0 && steps_.easyIterations >= 0))
    {
        FatalIOErrorInFunction(d)
            << "Entries 'maxCutbacks' and 'growthIterations' in " << d.name()
            << " must be >= 0" << exit(FatalIOError);
    }
    if (steps_.endTime <= steps_.startTime)
    {
        FatalErrorInFunction
            << "endTime " << steps_.endTime << " in system/controlDict is not"
            << " after startTime " << steps_.startTime << exit(FatalError);
    }

    linearSolverName_ = d.getOrDefault<word>("linearSolver", "auto");
}


void Foam::formScene::initialiseDynamics(scalar t0, const form::vecX& V0)
{
    try
    {
        integrator_->initialise(solids_[0].model(), t0, V0);
    }
    catch (const form::numericalError& err)
    {
        FatalErrorInFunction
            << "Dynamic analysis (" << solution_.name() << "): the initial"
            << " state at t = " << t0 << " cannot start the integrator: "
            << err.what() << exit(FatalError);
    }
}


void Foam::formScene::printScene() const
{
    Info<< nl << "Scene" << nl;
    for (const solidRegion& s : solids_)
    {
        Info<< "    " << s.describe().c_str() << nl;
    }
    if (solids_.empty())
    {
        Info<< "    solid: none declared (the Newton system is the fluid's)"
            << nl;
    }
    if (integrator_)
    {
        Info<< "    analysis: dynamic, " << integratorName_;
        if (integrator_->nStages() > 1) Info<< " (gamma " << gamma_ << ")";
        Info<< ", " << (lumpedMass_ ? "lumped" : "consistent")
            << " mass, density " << solids_[0].density() << nl;
    }
    else
    {
        Info<< "    analysis: static (no inertia)" << nl;
    }
    Info
        << "    line search: "
        << (
               !newton_.lineSearch ? "off"
             : newton_.residualLineSearch ? "residual norm (backtracking)"
             : "energy"
           )
        << (
               newton_.lineSearch && newton_.lineSearchMemory > 0
             ? ", non-monotone over the last "
             + std::to_string(newton_.lineSearchMemory + 1) + " iterates"
             : std::string()
           ).c_str() << nl
        << "    Newton: "
        << (
               newton_.keepTangent
             ? "modified (factors kept while each iteration cuts |r| to "
             : "full (a new tangent at every iteration)"
           );
    if (newton_.keepTangent)
    {
        Info<< newton_.keptTangentContraction << " of the last)";
    }
    Info<< nl
        << "    predictor: "
        << (
               newton_.quadratic ? "quadratic extrapolation"
             : newton_.extrapolate ? "extrapolated last increment"
             : "last state"
           )
        << (
               !newton_.extrapolate ? ""
             : newton_.pressurePredictor
            == form::newtonControls::pressurePrediction::extrapolated
             ? " (u/p elements: pressures extrapolated too)"
             : " (u/p elements: committed pressures linearised)"
           )
        << nl;
    if (contact_)
    {
        Info<< "    contact (constraint functions):" << nl;
        std::istringstream is(contact_->describe());
        std::string line;
        while (std::getline(is, line))
        {
            Info<< "        " << line.c_str() << nl;
        }
    }
    else
    {
        Info<< "    contact: none declared (not built)" << nl;
    }
    if (fluid_)
    {
        std::istringstream is(fluid_->describe());
        std::string line;
        std::getline(is, line);
        Info<< "    " << line.c_str() << nl;
        while (std::getline(is, line))
        {
            Info<< "        " << line.c_str() << nl;
        }
    }
    else
    {
        Info<< "    fluid: none declared (not built)" << nl;
    }
    Info
        << "    linear solver: " << linearSolver_->type().c_str() << nl
        << "    steps: t = " << steps_.startTime << " -> " << steps_.endTime
        << ", deltaT " << steps_.deltaT << " (min " << steps_.minDeltaT
        << ", max " << steps_.maxDeltaT << ")" << nl << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::formScene::formScene(Time& runTime)
:
    runTime_(runTime),
    lock_(runTime.path()),
    solution_
    (
        IOobject
        (
            "solidSolution",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    )
{
    checkStart();
    readSolution();

    const regionProperties rp(runTime);
    for (const word& kind : rp.toc())
    {
        if (kind != "solid" && kind != "fluid")
        {
            FatalErrorInFunction
                << "Unknown kind of region '" << kind << "' in"
                << " constant/regionProperties; valid kinds: solid fluid"
                << exit(FatalError);
        }
    }
    const wordList fluidNames(rp.found("fluid") ? rp["fluid"] : wordList());
    const wordList solidNames(rp.found("solid") ? rp["solid"] : wordList());
    if (fluidNames.size() > 1)
    {
        FatalErrorInFunction
            << "constant/regionProperties lists fluid regions " << fluidNames
            << "; one fluid region is supported" << exit(FatalError);
    }
    if (solidNames.size() > 1 || (solidNames.empty() && fluidNames.empty()))
    {
        FatalErrorInFunction
            << "constant/regionProperties must list one solid region, or"
            << " none with a fluid region (found solid " << solidNames
            << ", fluid " << fluidNames << ")" << exit(FatalError);
    }
    for (const word& name : solidNames)
    {
        solids_.append(new solidRegion(runTime, name));
    }
    if (solids_.empty())
    {
        // A fluid on its own: the Newton system of an empty solid model
        // holds the fluid block alone
        if (integrator_)
        {
            FatalIOErrorInFunction(solution_)
                << "Entry 'analysis' in " << solution_.name() << ": dynamic"
                << " analysis integrates a solid's inertia, and the scene"
                << " has no solid region; the fluid's inertia is chosen by"
                << " ddtSchemes in system/" << fluidNames[0] << "/fvSchemes"
                << exit(FatalIOError);
        }
        form::feMesh empty;
        empty.nDim = 2;
        empty.X.resize(0, 2);
        fluidOnlyModel_.reset
        (
            new form::solidModel
            (
                empty, form::analysisType::planeStrain, {}
            )
        );
        fluidOnlyModel_->finalise();
    }
    if (solidContact::declared(runTime))
    {
        if (solids_.empty())
        {
            FatalErrorInFunction
                << "constant/contactProperties declares contact, but"
                << " constant/regionProperties lists no solid region"
                << exit(FatalError);
        }
        contact_.reset(new solidContact(runTime, solids_[0]));
    }
    // A fluid only if regionProperties lists one: a dry case builds none
    if (fluidNames.size())
    {
        fluid_.reset
        (
            new fluidRegion(runTime, fluidNames[0], solids_, model())
        );
    }
    // auto: the energy line search suits potential problems; contact and
    // a fluid cavity (saddle points, friction) need the residual-norm
    // backtracking
    newton_.residualLineSearch =
        lineSearchType_ == "residual"
     || (lineSearchType_ == "auto" && (contact_ || fluid_));
    // auto: extrapolate (staticSolver.H): quadratically through the last
    // three states in a static analysis without contact or fluid (smooth
    // load paths: Cook's membrane, pure bending and the necking bar take
    // 10-40 % fewer iterations than with the linear extrapolation),
    // linearly otherwise (contact: the U-channel's study found the
    // quadratic one no better; dynamics: not studied). Figures:
    // tests/benchmarks/newtonEfficiency, README "What Newton's method
    // costs"
    newton_.extrapolate = predictor_ != "none";
    newton_.quadratic =
        predictor_ == "quadratic"
     || (predictor_ == "auto" && !contact_ && !fluid_ && !dynamic_);
    // The pressures of the mixed elements at a predicted state
    // (staticSolver.H): extrapolated with the displacements, or, with
    // contact, the committed ones carried along their linearisation
    // (element pressures under a tool radius alternate from step to step)
    newton_.pressurePredictor =
        contact_
      ? form::newtonControls::pressurePrediction::linearised
      : form::newtonControls::pressurePrediction::extrapolated;

    // auto: UMFPACK for unsymmetric tangents; otherwise CHOLMOD, switching
    // to UMFPACK if a tangent turns out indefinite (autoSolver.H)
    word solverName = linearSolverName_;
    if (solverName == "auto" && model().unsymmetric())
    {
        solverName = "umfpack";
    }
    try
    {
        if (solverName == "auto")
        {
            linearSolver_.reset(new form::autoSolver(&std::cout));
        }
        else
        {
            linearSolver_ = form::linearSolver::New(solverName);
        }
    }
    catch (const form::inputError& err)
    {
        FatalIOErrorInFunction(solution_)
            << "Entry 'linearSolver' in " << solution_.name() << ": "
            << err.what() << " auto" << exit(FatalIOError);
    }
    if (linearSolver_->requiresSPD() && model().unsymmetric())
    {
        FatalIOErrorInFunction(solution_)
            << "Entry 'linearSolver' in " << solution_.name() << ": "
            << solverName << " needs a symmetric positive definite matrix,"
            << " but follower pressure loads, contact (a saddle point with"
            << " friction terms) or a fluid cavity (a saddle point) make the"
            << " Newton matrix unsymmetric or indefinite; use"
            << " umfpack or auto" << exit(FatalIOError);
    }

    readSchedule();
    // The whole schedule is checked now, not when each step begins
    for (const processStep& ps : schedule_) applyActions(ps, false);
    readSummary();

    // Inertia: only for a dynamic analysis
    if (integrator_)
    {
        const solidRegion& s = solids_[0];
        if (!(s.density() > 0))
        {
            FatalIOErrorInFunction(s.properties())
                << "Entry 'material/rho' (density) missing in "
                << s.properties().name() << ": analysis dynamic in "
                << solution_.name() << " needs it" << exit(FatalIOError);
        }
        solids_[0].model().setInertia
        (
            {{"material", s.density()}}, lumpedMass_
        );
    }

    if (restarted_)
    {
        if (solids_.size() && !solids_[0].readState(runTime.timeName()))
        {
            FatalErrorInFunction
                << "Restart at time " << runTime.timeName() << ": the state"
                << " of solid region '" << solids_[0].name() << "' (feU) is"
                << " missing" << exit(FatalError);
        }
        if (fluid_) fluid_->readState(runTime.timeName());
        readRunState();
        model().commit();
        if (integrator_)
        {
            IOobject io
            (
                "feDynamics", runTime.timeName(), solids_[0].mesh(),
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            );
            if (!io.typeHeaderOk<IOField<scalar>>(true))
            {
                FatalErrorInFunction
                    << "Restart of a dynamic analysis at time "
                    << runTime.timeName() << ": " << io.objectPath()
                    << " (velocities, accelerations) is missing"
                    << exit(FatalError);
            }
            const IOField<scalar> f(io);
            try
            {
                integrator_->setState(std::vector<double>(f.begin(), f.end()));
            }
            catch (const form::numericalError& err)
            {
                FatalErrorInFunction
                    << io.objectPath() << ": " << err.what()
                    << exit(FatalError);
            }
        }
        // Forces of the restored state (reactions, contact and tool
        // forces) for the first summary record
        form::vecX r;
        model().evaluate(steps_.startTime, r, false);
        Info<< "Restarting from the state written at time "
            << runTime.timeName() << endl;
    }
    else if (integrator_)
    {
        // At rest or with the initial velocity on the free dofs; the
        // initial acceleration balances the initial loads
        form::solidModel& m = solids_[0].model();
        form::vecX V0 = form::vecX::Zero(m.nDofs());
        for (const int dof : m.freeDofs())
        {
            V0(dof) = initialVelocity_[m.dofs().component(dof)];
        }
        initialiseDynamics(steps_.startTime, V0);
    }
}
