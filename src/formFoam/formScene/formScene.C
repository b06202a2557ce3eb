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
            "energyTolerance", "lineSearch", "lineSearchType", "predictor",
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


void Foam::formScene::checkSupport(const word& stepName) const
{
    if (solids_.empty()) return;
    const solidRegion& s = solids_[0];
    const form::feMesh& fe = s.feMesh().feMesh();
    const form::solidModel& m = s.model();
    // Contact and fluid pressure support a piece only once loaded: a
    // piece they touch counts as supported
    std::vector<int> supported;
    wordList patches;
    if (contact_)
    {
        for (const auto& ps : contact_->model().pairs())
        {
            patches.append(word(ps.faceSet));
            if (!ps.targetFaceSet.empty()) patches.append(word(ps.targetFaceSet));
        }
    }
    if (fluid_) patches.append(fluid_->interfacePatches());
    for (const word& p : patches)
    {
        const auto it = fe.faceSets.find(p);
        if (it == fe.faceSets.end()) continue;
        for (const form::feFace& f : it->second)
        {
            supported.insert(supported.end(), f.nodes.begin(), f.nodes.end());
        }
    }
    const std::vector<form::freePiece> free = form::unsupportedPieces
    (
        fe, s.analysis(), [&m](int dof) { return m.constrained(dof); },
        supported
    );
    if (free.empty()) return;
    const form::freePiece& f = free[0];
    std::ostringstream what;
    if (schedule_.size() > 1) what << " in process step '" << stepName << "'";
    what << ": ";
    if (f.nPieces > 1)
    {
        what<< "its piece " << f.piece + 1 << " of " << f.nPieces << " ("
            << f.nElements << " elements around (" << f.centre(0) << " "
            << f.centre(1) << "); pieces share no node)";
    }
    else
    {
        what<< "the body";
    }
    FatalErrorInFunction
        << "Solid region '" << s.name() << "' is not supported"
        << what.str().c_str()
        << " can move as a rigid body: " << f.description.c_str()
        << "." << nl
        << "    A static analysis needs enough constraints to hold it:"
        << " fixedDisplacement (or symmetry) conditions in 0/" << s.name()
        << "/D, a pin in constant/processSchedule, or contact."
        << (f.nPieces > 1
            ? " Bodies meant to be one need merged points (mergePatchPairs"
              " in blockMeshDict)" : "")
        << exit(FatalError);
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
        energyFile_.reset(new OFstream(path));
        if (kept.empty())
        {
            (*energyFile_)
                << "# time kinetic internalWork externalWork dissipated"
                << " contactWork frictionWork" << nl;
        }
        for (const std::string& line : kept)
        {
            (*energyFile_) << line.c_str() << nl;
        }
    }
    (*energyFile_)
        << time << ' ' << e.kinetic << ' ' << e.internalWork << ' '
        << e.externalWork << ' ' << e.dissipated() << ' ' << e.contactWork
        << ' ' << e.frictionWork << endl;
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
           ) << nl
        << "    predictor: "
        << (
               newton_.quadratic ? "quadratic extrapolation"
             : newton_.extrapolate ? "extrapolated last increment"
             : "last state"
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


void Foam::formScene::readSchedule()
{
    const fileName path = runTime_.path()/"constant"/"processSchedule";
    if (!isFile(path))
    {
        schedule_.push_back
        (
            {"run", steps_.startTime, steps_.endTime, steps_.deltaT,
             steps_.maxDeltaT, dictionary()}
        );
        return;
    }
    IOdictionary sd
    (
        IOobject
        (
            "processSchedule", runTime_.constant(), runTime_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    checkInput(sd, sd.objectPath());
    checkKeywords(sd, {"steps"});
    const dictionary& steps =
        subDictOf(sd, "steps", "{ <step> { endTime ...; } }");
    // The first step starts with the case (before any restart time)
    scalar t0 = -GREAT;
    for (const entry& e : steps)
    {
        const dictionary& d = dictOf(e, steps, "{ endTime ...; deltaT ...; }");
        checkKeywords
        (
            d,
            {
                "endTime", "deltaT", "maxDeltaT", "release", "hold", "pin",
                "prescribe", "releaseTools", "analysis"
            }
        );
        if (d.found("analysis"))
        {
            const word a = d.get<word>("analysis");
            if (!wordList{"static", "dynamic"}.found(a))
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'analysis' of process step '" << e.keyword()
                    << "' in " << d.name() << ": unknown '" << a
                    << "'; valid: static dynamic" << exit(FatalIOError);
            }
            if (a == "dynamic" && !dynamic_)
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'analysis' of process step '" << e.keyword()
                    << "' in " << d.name() << ": a dynamic step needs"
                    << " analysis dynamic in system/solidSolution (the"
                    << " scene's inertia)" << exit(FatalIOError);
            }
        }
        processStep ps;
        ps.name = e.keyword();
        ps.startTime = t0;
        ps.endTime = d.get<scalar>("endTime");
        ps.deltaT = d.getOrDefault<scalar>("deltaT", steps_.deltaT);
        ps.maxDeltaT = d.getOrDefault<scalar>("maxDeltaT", ps.deltaT);
        if (!(ps.endTime > t0) || !(ps.deltaT > 0) || !(ps.maxDeltaT > 0))
        {
            FatalIOErrorInFunction(d)
                << "Process step '" << ps.name << "' in " << d.name()
                << ": endTime must be after the previous step's end (" << t0
                << ") and deltaT, maxDeltaT positive" << exit(FatalIOError);
        }
        ps.actions = d;
        for (const word key : {"release", "hold"})
        {
            if (!d.found(key)) continue;
            const entry& a = d.lookupEntry(key, keyType::LITERAL);
            if (a.isDict()) continue;
            d.get<wordList>(key);   // a list of patch names
        }
        t0 = ps.endTime;
        schedule_.push_back(ps);
    }
    if (schedule_.empty())
    {
        FatalIOErrorInFunction(steps)
            << "No process steps in " << steps.name() << ": give at least"
            << " one, e.g. steps { load { endTime "
            << steps_.endTime << "; } } (or remove the file: one step to"
            << " endTime)" << exit(FatalIOError);
    }
    if (mag(t0 - steps_.endTime) > 1e-9*mag(t0) + 1e-12)
    {
        FatalIOErrorInFunction(steps)
            << "The last process step in " << steps.name() << " ends at "
            << t0 << " but endTime in system/controlDict is "
            << steps_.endTime << "; they must agree" << exit(FatalIOError);
    }
}


void Foam::formScene::applyActions(const processStep& step, bool apply)
{
    const dictionary& d = step.actions;
    if (solids_.empty())
    {
        for (const word key : {"release", "hold", "pin", "prescribe", "releaseTools"})
        {
            if (d.found(key))
            {
                FatalIOErrorInFunction(d)
                    << "Entry '" << key << "' in " << d.name() << ": the"
                    << " scene has no solid region" << exit(FatalIOError);
            }
        }
        return;
    }
    solidRegion& s = solids_[0];
    const auto components = [&](const word& key, const entry& a, word& patch)
    {
        patch = a.keyword();
        labelList comps;
        wordList names;
        a.stream() >> names;
        for (const word& c : names)
        {
            comps.append(planeComponent(c, d, s.analysis()));
        }
        (void)key;
        return comps;
    };
    for (const word key : {"release", "hold"})
    {
        if (!d.found(key)) continue;
        const entry& a = d.lookupEntry(key, keyType::LITERAL);
        std::vector<std::pair<word, labelList>> targets;
        if (a.isDict())
        {
            for (const entry& pe : a.dict())
            {
                word patch;
                labelList comps = components(key, pe, patch);
                targets.push_back({patch, comps});
            }
        }
        else
        {
            for (const word& patch : d.get<wordList>(key))
            {
                targets.push_back({patch, labelList({0, 1})});
            }
        }
        for (const auto& t : targets)
        {
            if (!apply)
            {
                s.patchNodes(t.first, d);
                continue;
            }
            Info<< "    " << key.c_str() << " " << t.first << " components "
                << t.second << nl;
            if (key == "release")
            {
                // A step begun before the restart time: its release loads
                // were read with the state (t1 = t0: release only)
                const bool restored = step.startTime < steps_.startTime - 1e-12;
                s.release
                (
                    t.first, t.second, d,
                    restored ? step.endTime : step.startTime, step.endTime
                );
            }
            else
            {
                s.hold(t.first, t.second, d);
            }
        }
    }
    if (d.found("releaseTools"))
    {
        if (!contact_)
        {
            FatalIOErrorInFunction(d)
                << "Entry 'releaseTools' in " << d.name() << ": the case"
                << " declares no contact (constant/contactProperties)"
                << exit(FatalIOError);
        }
        const wordList tools = d.get<wordList>("releaseTools");
        if (!apply)
        {
            for (const word& t : tools) contact_->toolIndex(t, d);
        }
        else
        {
            Info<< "    release tools " << tools << nl;
            // (after a restart the tools' released flags and loads come
            // with the state, and releaseTools skips released tools)
            contact_->releaseTools(tools, d, step.startTime, step.endTime);
        }
    }
    if (d.found("pin"))
    {
        const dictionary& pd =
            subDictOf(d, "pin", "{ <name> { point (x y z); components (x y); } }");
        for (const entry& pe : pd)
        {
            const dictionary& p =
                dictOf(pe, pd, "{ point (x y z); components (x y); }");
            checkKeywords(p, {"point", "components"});
            labelList comps;
            for (const word& c : p.get<wordList>("components"))
            {
                comps.append(planeComponent(c, p, s.analysis()));
            }
            const point x = p.get<point>("point");
            if (!apply) continue;
            Info<< "    pin " << pe.keyword() << " at " << x
                << " components " << comps << nl;
            s.pin(x, comps, p);
        }
    }
    if (d.found("prescribe"))
    {
        const dictionary& pd =
            subDictOf(d, "prescribe", "{ <patch> { type ...; } }");
        for (const entry& pe : pd)
        {
            const dictionary& bc =
                dictOf(pe, pd, "{ type fixedDisplacement; ... }");
            const word type = bc.get<word>("type");
            if (!solidRegion::conditionTypes().found(type))
            {
                FatalIOErrorInFunction(bc)
                    << "Unknown boundary condition type '" << type << "' in "
                    << bc.name() << nl << "    Valid types: "
                    << solidRegion::conditionTypes() << exit(FatalIOError);
            }
            if (!apply)
            {
                s.patchNodes(pe.keyword(), pd);
                continue;
            }
            Info<< "    prescribe " << pe.keyword() << " " << type << nl;
            s.applyCondition(pe.keyword(), bc);
        }
    }
}


void Foam::formScene::readSummary()
{
    if (!solution_.found("summary")) return;
    const dictionary& sd =
        subDictOf(solution_, "summary", "{ <name> { type ...; } }");
    for (const entry& e : sd)
    {
        summaryEntry se;
        se.name = e.keyword();
        se.dict = dictOf(e, sd, "{ type ...; }");
        const dictionary& ed = se.dict;
        const word type = ed.get<word>("type");
        const wordList common{"type", "scale", "statistic", "time", "at"};
        wordList keys(common);
        if (type == "displacement" || type == "position")
        {
            keys.append(wordList{"point", "component"});
        }
        else if (type == "reaction")
        {
            keys.append(wordList{"patch", "component"});
        }
        else if (type == "circleRadius")
        {
            keys.append(word("patches"));
        }
        else if (type == "rotation")
        {
            keys.append(wordList{"patch", "positive"});
        }
        else if (type == "bendingRadius")
        {
            keys.append(wordList{"patch", "length"});
        }
        else if
        (
            contact_ && (type == "toolForce" || type == "toolPosition")
        )
        {
            keys.append(wordList{"tool", "component"});
        }
        else if (fluid_ && !fluid_->ALE() && type == "fluidPressure")
        {
            // The uniform cavity pressure: a point (for the ALE model of
            // the same case) is accepted and not needed
            keys.append(word("point"));
        }
        else if (fluid_ && fluid_->ALE() && type == "fluidPressure")
        {
            keys.append(word("point"));
        }
        else if (fluid_ && fluid_->ALE() && type == "fluidVelocity")
        {
            keys.append(wordList{"point", "component"});
        }
        else if (fluid_ && fluid_->ALE() && type == "fluidFlowRate")
        {
            keys.append(word("patch"));
            const word patch = ed.get<word>("patch");
            if (!fluid_->hasPatch(patch))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'patch' in " << ed.name() << ": '" << patch
                    << "' is not a patch of fluid region '" << fluid_->name()
                    << "'" << exit(FatalIOError);
            }
        }
        else if (fluid_ && fluid_->ALE() && type == "fluidForce")
        {
            keys.append(wordList{"patches", "component"});
            for (const word& patch : ed.get<wordList>("patches"))
            {
                if (!fluid_->hasPatch(patch))
                {
                    FatalIOErrorInFunction(ed)
                        << "Entry 'patches' in " << ed.name() << ": '"
                        << patch << "' is not a patch of fluid region '"
                        << fluid_->name() << "'" << exit(FatalIOError);
                }
            }
            vectorComponent(ed.get<word>("component"), ed);
        }
        else if (fluid_ && type == "fluidVolume")
        {}
        else if (fluid_ && type == "injectedVolume")
        {}
        else if (type == "extent")
        {
            keys.append(wordList{"patch", "component", "extreme"});
            const word x = ed.getOrDefault<word>("extreme", "max");
            if (!wordList{"max", "min"}.found(x))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'extreme' in " << ed.name() << ": unknown '"
                    << x << "'; valid: max min" << exit(FatalIOError);
            }
        }
        else if (type == "difference")
        {
            keys.append(word("of"));
            const wordList of = ed.get<wordList>("of");
            for (const word& n : of)
            {
                const bool earlier = std::any_of
                (
                    summary_.begin(), summary_.end(),
                    [&](const summaryEntry& o) { return o.name == n; }
                );
                if (!earlier || of.size() != 2)
                {
                    FatalIOErrorInFunction(ed)
                        << "Entry 'of' in " << ed.name() << ": needs two"
                        << " summary entries listed before '" << e.keyword()
                        << "' (got " << of << ")" << exit(FatalIOError);
                }
            }
        }
        else if (type == "uChannelSpringback")
        {
            keys.append(wordList{"patch", "quantity"});
            const word q = ed.get<word>("quantity");
            if (!wordList{"theta1", "theta2", "rho"}.found(q))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'quantity' in " << ed.name() << ": unknown '"
                    << q << "'; valid: theta1 theta2 rho"
                    << exit(FatalIOError);
            }
        }
        else
        {
            FatalIOErrorInFunction(ed)
                << "Unknown summary type '" << type << "' in " << ed.name()
                << nl << "    Valid types: displacement position reaction"
                << " circleRadius rotation bendingRadius extent difference"
                << " uChannelSpringback"
                << (contact_ ? " toolForce toolPosition" : "")
                << (
                       !fluid_ ? ""
                     : fluid_->ALE()
                     ? " fluidPressure fluidVelocity fluidFlowRate fluidForce"
                       " fluidVolume injectedVolume"
                     : " fluidPressure fluidVolume injectedVolume"
                   )
                << exit(FatalIOError);
        }
        checkKeywords(ed, keys);
        se.statistic = ed.getOrDefault<word>("statistic", "final");
        if (!wordList{"final", "max", "min"}.found(se.statistic))
        {
            FatalIOErrorInFunction(ed)
                << "Entry 'statistic' in " << ed.name() << ": unknown '"
                << se.statistic << "'; valid: final max min"
                << exit(FatalIOError);
        }
        se.scale = ed.getOrDefault<scalar>("scale", 1);
        se.atTime = ed.found("time");
        if (se.atTime)
        {
            se.time = ed.get<scalar>("time");
            if (!(se.time >= 0 && se.time <= steps_.endTime))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'time' of summary entry '" << se.name << "' in "
                    << ed.name() << " is out of range: " << se.time
                    << " (valid: a time of the run, 0 to endTime "
                    << steps_.endTime << ")" << exit(FatalIOError);
            }
        }
        if (ed.found("at"))
        {
            // at (entry value): the value where an entry listed before
            // this one first reaches value
            ITstream& is = ed.lookup("at");
            const Tuple2<word, scalar> at(is);
            forAll(summary_, k)
            {
                if (summary_[k].name == at.first()) se.atEntry = k;
            }
            if (se.atEntry < 0 || se.atTime || se.statistic != "final")
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'at' in " << ed.name() << ": needs a summary"
                    << " entry listed before '" << e.keyword() << "' and a"
                    << " value, e.g. at (poleHeight 30); (got " << at.first()
                    << "), and neither 'time' nor a statistic"
                    << exit(FatalIOError);
            }
            se.atValue = at.second();
        }
        const wordList solidTypes
        {
            "displacement", "position", "reaction", "circleRadius",
            "rotation", "bendingRadius", "extent", "uChannelSpringback"
        };
        if (solids_.empty() && solidTypes.found(type))
        {
            FatalIOErrorInFunction(ed)
                << "summary entry '" << se.name << "' in " << ed.name()
                << ": type '" << type << "' needs a solid region, and the"
                << " scene has none" << exit(FatalIOError);
        }
        summary_.push_back(se);
        // Validate points and patches now, not at the end of the run (a
        // springback measure needs a formed channel: patch only)
        if (type == "uChannelSpringback")
        {
            solids_[0].patchPoints(ed.get<word>("patch"), ed, false);
        }
        else
        {
            evaluate(summary_.back());
        }
    }
}


Foam::scalar Foam::formScene::evaluate(const summaryEntry& e) const
{
    const dictionary& ed = e.dict;
    const word type = ed.get<word>("type");
    scalar value = 0;
    if (type.starts_with("fluid") || type == "injectedVolume")
    {
        return e.scale*evaluateFluid(ed, type);
    }
    if (type == "difference")
    {
        // The reported values (after their statistic or time) of two
        // entries listed before this one
        const wordList of = ed.get<wordList>("of");
        scalar v[2] = {0, 0};
        for (label i = 0; i < 2; ++i)
        {
            for (const summaryEntry& o : summary_)
            {
                if (o.name == of[i])
                {
                    v[i] = o.set ? o.value : NAN;
                }
            }
        }
        return e.scale*(v[0] - v[1]);
    }
    if (type == "toolForce" || type == "toolPosition")
    {
        const label comp = planeComponent(ed.get<word>("component"), ed, solids_[0].analysis());
        const word tool = ed.get<word>("tool");
        return e.scale*
        (
            type == "toolForce"
          ? contact_->toolForce(tool, comp, ed)
          : contact_->toolPosition(tool, comp, summaryTime_, ed)
        );
    }
    const solidRegion& s = solids_[0];
    if (type == "circleRadius")
    {
        const wordList patches = ed.get<wordList>("patches");
        for (const word& p : patches) value += s.circleRadius(p, ed);
        value /= max(label(1), patches.size());
    }
    else if (type == "rotation")
    {
        value = s.patchRotation(ed.get<word>("patch"), ed);
        // positive: in [0, 2 pi) instead of (-pi, pi] (a hem turns its
        // flange by about pi)
        if (ed.getOrDefault<bool>("positive", false) && value < 0)
        {
            value += constant::mathematical::twoPi;
        }
    }
    else if (type == "extent")
    {
        // Largest (smallest) current coordinate of a patch's nodes
        const Eigen::MatrixXd P =
            s.patchPoints(ed.get<word>("patch"), ed, true);
        const Eigen::VectorXd c =
            P.col(planeComponent(ed.get<word>("component"), ed, solids_[0].analysis()));
        value =
            ed.getOrDefault<word>("extreme", "max") == "max"
          ? c.maxCoeff() : c.minCoeff();
    }
    else if (type == "bendingRadius")
    {
        const scalar theta = s.patchRotation(ed.get<word>("patch"), ed);
        value = mag(theta) > VSMALL ? ed.get<scalar>("length")/mag(theta) : GREAT;
    }
    else if (type == "uChannelSpringback")
    {
        // NUMISHEET'93 measures of the patch's current node line, ordered
        // by the reference position along the strip (from the symmetry
        // plane); a profile that is not (yet) a channel gives NaN
        const word patch = ed.get<word>("patch");
        const Eigen::MatrixXd X = s.patchPoints(patch, ed, false);
        const Eigen::MatrixXd x = s.patchPoints(patch, ed, true);
        std::vector<label> order(X.rows());
        std::iota(order.begin(), order.end(), 0);
        std::sort
        (
            order.begin(), order.end(),
            [&](label a, label b) { return X(a, 0) < X(b, 0); }
        );
        std::vector<Eigen::Vector2d> profile;
        for (const label i : order) profile.emplace_back(x(i, 0), x(i, 1));
        try
        {
            const form::uChannelSpringback m = form::measureUChannel(profile);
            const word q = ed.get<word>("quantity");
            value = q == "theta1" ? m.theta1 : q == "theta2" ? m.theta2 : m.rho;
        }
        catch (const form::numericalError&)
        {
            value = std::numeric_limits<scalar>::quiet_NaN();
        }
    }
    else
    {
        const label comp = planeComponent(ed.get<word>("component"), ed, solids_[0].analysis());
        if (type == "displacement")
        {
            value = s.displacementAt(ed.get<point>("point"), comp, ed);
        }
        else if (type == "position")
        {
            const point p = ed.get<point>("point");
            const Eigen::Vector2d X = s.feMesh().toPlane(p);
            value = X(comp) + s.displacementAt(p, comp, ed);
        }
        else
        {
            value = s.reaction(ed.get<word>("patch"), comp, ed);
        }
    }
    return e.scale*value;
}


Foam::scalar Foam::formScene::evaluateFluid
(
    const dictionary& ed,
    const word& type
) const
{
    if (type == "fluidVolume") return fluid_->volume();
    if (type == "injectedVolume") return fluid_->injectedVolume(summaryTime_);
    if (type == "fluidFlowRate") return fluid_->flowRate(ed.get<word>("patch"));
    if (type == "fluidForce")
    {
        const direction d = vectorComponent(ed.get<word>("component"), ed);
        scalar F = 0;
        for (const word& patch : ed.get<wordList>("patches"))
        {
            F += fluid_->force(patch)[d];
        }
        return F;
    }
    // Without a point: the cavity pressure, or the ALE fluid's mean
    // pressure on its interface with the solid
    if (type == "fluidPressure" && !ed.found("point"))
    {
        return fluid_->pressure();
    }
    if (type == "fluidPressure" && !fluid_->ALE()) return fluid_->pressure();
    // A point of the fluid mesh
    const point pt = ed.get<point>("point");
    const scalar v =
        type == "fluidPressure"
      ? fluid_->pressureAt(pt)
      : fluid_->velocityAt(pt, vectorComponent(ed.get<word>("component"), ed));
    if (std::isnan(v))
    {
        FatalIOErrorInFunction(ed)
            << "Entry 'point' in " << ed.name() << ": " << pt << " is not"
            << " inside the mesh of fluid region '" << fluid_->name() << "'"
            << exit(FatalIOError);
    }
    return v;
}


void Foam::formScene::updateEntry
(
    summaryEntry& e,
    scalar time,
    scalar v,
    bool first
)
{
    const scalar tPrev = e.curTime, vPrev = e.curValue;
    e.prevTime = tPrev;
    e.prevValue = vPrev;
    e.curTime = time;
    e.curValue = v;
    if (e.atEntry >= 0)
    {
        // The value where entry atEntry (updated before this one in the
        // same record) first reaches atValue: linear interpolation
        // between the two records that bracket it
        if (e.set) return;
        const summaryEntry& a = summary_[e.atEntry];
        const scalar target = e.atValue;
        if (a.curValue == target)
        {
            e.value = v;
            e.set = true;
        }
        else if
        (
            !first && a.prevValue != target
         && (a.prevValue - target)*(a.curValue - target) < 0
        )
        {
            const scalar w = (target - a.prevValue)/(a.curValue - a.prevValue);
            e.value = vPrev + w*(v - vPrev);
            e.set = true;
        }
        return;
    }
    if (e.atTime)
    {
        // Value at e.time: linear interpolation between the converged
        // steps that bracket it (exact when a step ends on it)
        const scalar tol = 1e-9*max(mag(e.time), 1.0);
        if (mag(time - e.time) <= tol)
        {
            e.value = v;
            e.set = true;
        }
        else if (!first && tPrev < e.time && e.time < time)
        {
            const scalar w = (e.time - tPrev)/(time - tPrev);
            e.value = vPrev + w*(v - vPrev);
            e.set = true;
        }
        return;
    }
    if
    (
        !e.set || e.statistic == "final"
     || (e.statistic == "max" && v > e.value)
     || (e.statistic == "min" && v < e.value)
    )
    {
        e.value = v;
    }
    e.set = true;
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
    // auto: extrapolate the last increment when tools move over the body
    // or fluid is injected
    newton_.extrapolate =
        predictor_ == "extrapolate" || predictor_ == "quadratic"
     || (predictor_ == "auto" && (contact_ || fluid_));
    newton_.quadratic = predictor_ == "quadratic";

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
            V0(dof) = initialVelocity_[dof % m.nDim()];
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
        form::staticSolver solver
        (
            model, *linearSolver_, newton_, sc, std::cout
        );
        solver.setIntegrator(stepDynamic ? integrator_.get() : nullptr);
        // A restart inside this step continues it as the interrupted run
        // would have: same next step size, same predictor
        if (restarted_ && ps.name == resumeStep_ && sc.startTime > ps.startTime)
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
