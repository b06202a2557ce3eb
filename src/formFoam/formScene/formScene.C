/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of formScene.H: A case as a scene.
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
#include <fstream>
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
            "initialVelocity"
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


void Foam::formScene::writeEnergy(scalar time)
{
    const form::energyBalance& e = integrator_->energy();
    const scalar level =
        max(e.initialKinetic + e.externalWork, e.kinetic + e.internalWork);
    Info<< "    energy: kinetic " << e.kinetic << ", internal work "
        << e.internalWork << ", external work " << e.externalWork;
    if (contact_)
    {
        Info<< " (contact " << e.contactWork << ", friction "
            << e.frictionWork << ")";
    }
    Info<< ", dissipated by the scheme " << e.dissipated();
    if (level > 0) Info<< " (" << e.dissipated()/level << ")";
    Info<< endl;
    if (!energyFile_)
    {
        const fileName dir = runTime_.path()/"postProcessing";
        mkDir(dir);
        // After a restart the rows up to the restart time stand
        const fileName path = dir/"energy.dat";
        std::vector<std::string> kept;
        if (restarted_ && isFile(path))
        {
            std::ifstream in(path);
            std::string line;
            while (std::getline(in, line))
            {
                std::istringstream is(line);
                double t;
                if (line.empty() || line[0] == '#' || !(is >> t)
                 || t <= steps_.startTime + 1e-12)
                {
                    kept.push_back(line);
                }
            }
        }
        // The kept rows (or the header) are written under a temporary
        // name and renamed, then the file is appended to: a kill never
        // leaves it truncated
        std::ostringstream text;
        if (kept.empty())
        {
            text<< "# time kinetic internalWork externalWork dissipated"
                << " contactWork frictionWork\n";
        }
        for (const std::string& line : kept) text << line << '\n';
        try
        {
            form::writeFileAtomic(path, text.str());
        }
        catch (const form::numericalError& err)
        {
            FatalErrorInFunction << err.what() << exit(FatalError);
        }
        energyFile_.reset(new std::ofstream(path, std::ios::app));
        energyFile_->precision(15);
    }
    std::ofstream& os = *energyFile_;
    os  << time << ' ' << e.kinetic << ' ' << e.internalWork << ' '
        << e.externalWork << ' ' << e.dissipated() << ' ' << e.contactWork
        << ' ' << e.frictionWork << std::endl;
    if (!os)
    {
        FatalErrorInFunction
            << "Cannot append to " << runTime_.path()/"postProcessing"
            << "/energy.dat (disk full?)" << exit(FatalError);
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::formScene::run()
{
    printScene();
    form::solidModel& model = this->model();

    const word writeControl =
        runTime_.controlDict().getOrDefault<word>("writeControl", "timeStep");
    const scalar writeInterval =
        runTime_.controlDict().getOrDefault<scalar>("writeInterval", 1);
    runStart_ = clock_.elapsedTime();
    const auto elapsed = [&]() { return clock_.elapsedTime() - runStart_; };
    scalar nextWrite = steps_.startTime + writeInterval;
    scalar lastTime = steps_.startTime;
    // The process step running, its solver (for the run state written
    // with a time) and the step's name
    const form::staticSolver* current = nullptr;
    word currentStep;

    // After a restart the history before it is kept and replayed, so
    // that statistics (max, min) and values at earlier times stand
    const bool replayed = restarted_ && replayHistory(steps_.startTime);
    if (restarted_ && solids_.size()) solids_[0].resumeVTK(steps_.startTime);
    recordSummary(steps_.startTime, !replayed);

    // The state at the start (or the restart) is dynamic if the step that
    // contains it is (the integrator was initialised or restored)
    bool previousDynamic = bool(integrator_);
    bool first = true;
    for (const processStep& ps : schedule_)
    {
        // Steps that ended before a restart time were run before it
        if (ps.endTime <= steps_.startTime + 1e-12)
        {
            applyActions(ps);
            continue;
        }
        if (first)
        {
            // A restart exactly at the start of a dynamic step that
            // follows a static one: the written velocities are those of an
            // earlier dynamic step, so it starts at rest
            first = false;
            const processStep* before = nullptr;
            for (const processStep& q : schedule_)
            {
                if (&q == &ps) break;
                before = &q;
            }
            if
            (
                restarted_ && before
             && ps.startTime >= steps_.startTime - 1e-12
             && before->actions.getOrDefault<word>("analysis", "dynamic")
             == "static"
            )
            {
                previousDynamic = false;
            }
        }
        if (schedule_.size() > 1)
        {
            Info<< nl << "Process step '" << ps.name << "': t = "
                << max(ps.startTime, steps_.startTime) << " -> " << ps.endTime
                << ", deltaT " << ps.deltaT << nl;
        }
        applyActions(ps);
        if (schedule_.size() > 1) Info<< endl;
        if
        (
            !(
                integrator_
             && ps.actions.getOrDefault<word>("analysis", "dynamic")
             == "dynamic"
            )
        )
        {
            checkSupport(ps.name);
        }

        // A dynamic scene may run single process steps statically (e.g.
        // springback); a dynamic step after a static one starts at rest
        const bool stepDynamic =
            integrator_
         && ps.actions.getOrDefault<word>("analysis", "dynamic") == "dynamic";
        if (stepDynamic && !previousDynamic)
        {
            Info<< "    dynamic analysis from rest at t = "
                << max(ps.startTime, steps_.startTime) << endl;
            initialiseDynamics
            (
                max(ps.startTime, steps_.startTime), form::vecX()
            );
        }
        if (integrator_ && !stepDynamic)
        {
            // Inertia off: a(U) = 0
            model.setAccelerationLaw
            (
                0, form::vecX::Zero(model.nDofs())
            );
            model.setVelocityLaw(0, form::vecX());
            // and backward-Euler slip rates over the (pseudo-)time step
            if (model.contact())
            {
                model.contact()->setSlipRateLaw(1, 0);
            }
            Info<< "    static analysis (no inertia) in this step" << endl;
        }
        previousDynamic = stepDynamic;

        const scalar stepClockStart = elapsed();
        form::stepControls sc = steps_;
        sc.startTime = max(ps.startTime, steps_.startTime);
        sc.endTime = ps.endTime;
        sc.deltaT = ps.deltaT;
        sc.maxDeltaT = ps.maxDeltaT;
        sc.minDeltaT = min(steps_.minDeltaT, ps.deltaT);
        // auto line search: the residual-norm backtracking while contact
        // acts or a fluid is coupled (saddle points, friction); the energy
        // line search once every tool is released (springback: a
        // potential problem, where the residual norm, dominated by the
        // sheet's stiff membrane modes, cuts Newton's steps to 1/8-1/16;
        // README of the U-channel, "Convergence")
        form::newtonControls nc = newton_;
        nc.checkTangent = checkTangent_;
        if (lineSearchType_ == "auto")
        {
            nc.residualLineSearch =
                fluid_ || (model.contact() && model.contact()->active());
            if (nc.residualLineSearch != newton_.residualLineSearch)
            {
                Info<< "    line search: "
                    << (
                           nc.residualLineSearch
                         ? "residual norm (backtracking)"
                         : "energy (no contact acts in this step)"
                       ) << endl;
            }
        }
        form::staticSolver solver
        (
            model, *linearSolver_, nc, sc, std::cout
        );
        solver.setIntegrator(stepDynamic ? integrator_.get() : nullptr);
        // A restart inside this step continues it as the interrupted run
        // would have: same next step size, same predictor. (The written
        // state names the process step that was running; a state written
        // at the end of a step names that step, not the next. The start
        // time is no test: without a processSchedule the one step "run"
        // starts at the restart time itself, and the restarted bulge lost
        // its predictor and step size.)
        if (restarted_ && ps.name == resumeStep_)
        {
            solver.resume(resume_);
        }
        current = &solver;
        currentStep = ps.name;

        try
        {
            solver.run
            (
                [&](const form::stepReport& r)
                {
                    ++totals_.steps;
                    totals_.cutbacks += r.cutbacks;
                    maxStepIterations_ = max(maxStepIterations_, r.iterations);
                    lastTime = r.time;
                    const scalar frac =
                        (r.time - steps_.startTime)
                       /(steps_.endTime - steps_.startTime);
                    const scalar wall = elapsed();
                    const scalar eta = frac > 0 ? wall*(1 - frac)/frac : 0;
                    Info<< "Step " << totals_.steps << "  t = " << r.time
                        << " (" << label(100*frac + 0.5) << "%)"
                        << "  dt = " << r.deltaT
                        << "  Newton " << r.iterations
                        << (r.cutbacks ? "  cutbacks " : "")
                        << (r.cutbacks ? Foam::name(r.cutbacks) : word())
                        << "  elapsed " << wall << " s  ETA " << eta
                        << " s" << endl;
                    if (fluid_) Info<< fluid_->report(r.time).c_str() << endl;
                    if (fluid_ && checkTangent_)
                    {
                        // Dense: a large block (a fine ALE mesh) has
                        // only its coupling with the solid checked
                        const bool couplingOnly =
                            fluid_->block().nUnknowns() > maxDenseCheck;
                        const form::blockTangentError e =
                            form::checkBlockTangent
                            (
                                fluid_->block(), r.time, model.U(), 1e-6,
                                couplingOnly
                            );
                        const auto where = [&](int k)
                        {
                            return k >= 0
                                ? fluid_->block().unknownName(k)
                                : "solid dof " + std::to_string(-1 - k);
                        };
                        std::string what;
                        if (e.couplingOnly)
                        {
                            what = ": only the columns of its coupling with "
                              + std::to_string(e.nodalDofs) + " solid dofs, its "
                              + std::to_string(fluid_->block().nUnknowns())
                              + " unknowns being too many for a dense check";
                        }
                        else if (e.nodalDofs)
                        {
                            what = " and its coupling with "
                              + std::to_string(e.nodalDofs) + " solid dofs";
                        }
                        Info<< "    tangent check (" << fluid_->name()
                            << what.c_str()
                            << "): max |K - K_fd|/max |K| = " << e.relative
                            << " (max |K| " << e.maxEntry << "; worst at "
                            << where(e.row).c_str() << " / "
                            << where(e.col).c_str()
                            << ": " << e.analytic << " vs "
                            << e.finiteDifference << ")" << endl;
                    }
                    recordSummary(r.time, false);
                    if (stepDynamic) writeEnergy(r.time);

                    const bool last = r.time >= ps.endTime - 1e-12;
                    bool doWrite = last;
                    if (writeControl == "timeStep")
                    {
                        doWrite =
                            doWrite
                         || (totals_.steps % label(writeInterval) == 0);
                    }
                    else if (r.time >= nextWrite - 1e-12*writeInterval)
                    {
                        doWrite = true;
                        while (nextWrite <= r.time + 1e-12)
                        {
                            nextWrite += writeInterval;
                        }
                    }
                    if (doWrite) writeTime(r.time, &solver, ps.name);
                }
            );
            totals_.iterations += solver.totalIterations();
            collectTangentChecks(solver);
            current = nullptr;
            if (schedule_.size() > 1)
            {
                stepWallTimes_.push_back
                (
                    {ps.name, elapsed() - stepClockStart}
                );
            }
        }
        catch (const form::inputError& err)
        {
            // Input that only shows as wrong once the run meets it (e.g.
            // a force-controlled tool that can never touch the body, oil
            // withdrawn beyond the cavity's volume); the last converged
            // state is kept
            model.revert();
            if (lastTime > steps_.startTime)
            {
                writeTime(lastTime, current, currentStep);
            }
            const fileName where =
                contact_ && contact_->hasTool(err.entry())
              ? runTime_.path()/"constant"/"contactProperties"
              : fluid_ && err.entry() == "injectedVolume"
              ? runTime_.path()/"constant"/fluid_->name()/"fluidProperties"
              : fileName(runTime_.path()/"system"/"solidSolution");
            FatalErrorInFunction
                << "Entry '" << err.entry().c_str() << "' in " << where
                << ": " << err.what() << exit(FatalError);
        }
        catch (const form::numericalError& err)
        {
            collectTangentChecks(solver);
            reportTangentChecks();
            model.revert();
            // The start time directory holds the case's input: never
            // overwrite it
            if (lastTime > steps_.startTime)
            {
                writeTime(lastTime, current, currentStep);
            }
            FatalErrorInFunction
                << err.what() << nl
                << "    The last converged state (t = " << lastTime
                << ") is in its time directory; restart from it with"
                << " startFrom latestTime after changing the step controls"
                << " in system/solidSolution or constant/processSchedule."
                << exit(FatalError);
        }
    }

    const scalar wallTime = totals_.wallTime + elapsed();
    Info<< nl << "Summary" << nl;
    writeSummary
    (
        totals_.iterations, totals_.steps, totals_.cutbacks, wallTime
    );

    if (contact_) contact_->reportUntouched();
    reportTangentChecks();
    const form::phaseTimes& t = model.times();
    Info<< nl << "Time per phase (s)" << nl
        << "    assembly        " << t.assembly << nl
        << "    contact         " << t.contact << nl
        << "    fluid           " << t.fluid << nl
        << "      mesh motion   "
        << (fluid_ ? fluid_->meshMotionTime() : scalar(0))
        << " (part of fluid)" << nl
        << "    factorisation   " << t.factorisation << nl
        << "    solve           " << t.solve << nl
        << "    factorisations  " << t.factorisations << " (count)" << nl
        << "    factor nonzeros " << t.factorNonzeros << " (last)" << nl
        << "    factor flops    " << t.factorFlops << " (total, "
        << (t.factorisation > 0 ? 1e-9*t.factorFlops/t.factorisation : 0)
        << " GFLOP/s)" << nl
        << "    output          " << t.output << nl
        << "    total (wall)    " << wallTime << nl
        << "    steps " << totals_.steps << ", Newton iterations "
        << totals_.iterations << nl;
    if (totals_.iterations > 0)
    {
        const scalar n = totals_.iterations;
        Info<< "Time per Newton iteration (ms): assembly "
            << 1e3*t.assembly/n << ", contact " << 1e3*t.contact/n
            << ", fluid " << 1e3*t.fluid/n << ", linear solve " << 1e3*(t.factorisation + t.solve)/n << nl;
    }
    Info<< nl << "End" << nl << endl;
}
