#include "formScene.H"
#include "dictionaryChecks.H"
#include "regionProperties.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "clockTime.H"
#include <iostream>

// * * * * * * * * * * * * * * * Private Functions  * * * * * * * * * * * * //

void Foam::formScene::readSolution()
{
    const dictionary& d = solution_;
    checkKeywords
    (
        d,
        {
            "analysis", "linearSolver", "minDeltaT", "maxDeltaT",
            "maxCutbacks", "maxIterations", "forceTolerance",
            "energyTolerance", "lineSearch", "summary"
        }
    );
    const word analysis = d.getOrDefault<word>("analysis", "static");
    if (analysis != "static")
    {
        FatalIOErrorInFunction(d)
            << "analysis '" << analysis << "' in " << d.name()
            << " is not available yet" << nl << "    Valid: static"
            << exit(FatalIOError);
    }

    steps_.startTime = runTime_.startTime().value();
    steps_.endTime = runTime_.endTime().value();
    steps_.deltaT = runTime_.deltaTValue();
    steps_.minDeltaT = d.getOrDefault<scalar>("minDeltaT", 1e-4*steps_.deltaT);
    steps_.maxDeltaT = d.getOrDefault<scalar>("maxDeltaT", steps_.deltaT);
    steps_.maxCutbacks = d.getOrDefault<label>("maxCutbacks", 10);
    newton_.maxIterations = d.getOrDefault<label>("maxIterations", 20);
    newton_.forceTolerance = d.getOrDefault<scalar>("forceTolerance", 1e-8);
    newton_.energyTolerance = d.getOrDefault<scalar>("energyTolerance", 1e-14);
    newton_.lineSearch = d.getOrDefault<bool>("lineSearch", true);

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
    if (steps_.endTime <= steps_.startTime)
    {
        FatalErrorInFunction
            << "endTime " << steps_.endTime << " in system/controlDict is not"
            << " after startTime " << steps_.startTime << exit(FatalError);
    }

    linearSolverName_ = d.getOrDefault<word>("linearSolver", "auto");
}


void Foam::formScene::printScene() const
{
    Info<< nl << "Scene" << nl;
    for (const solidRegion& s : solids_)
    {
        Info<< "    " << s.describe().c_str() << nl;
    }
    Info<< "    analysis: static (no inertia)" << nl
        << "    contact: none declared (not built)" << nl
        << "    fluid: none declared (not built)" << nl
        << "    linear solver: " << linearSolver_->type().c_str() << nl
        << "    steps: t = " << steps_.startTime << " -> " << steps_.endTime
        << ", deltaT " << steps_.deltaT << " (min " << steps_.minDeltaT
        << ", max " << steps_.maxDeltaT << ")" << nl << endl;
}


void Foam::formScene::writeSummary
(
    const form::staticSolver& solver,
    label nSteps,
    scalar wallTime
) const
{
    const solidRegion& s = solids_[0];
    const fileName dir = runTime_.path()/"postProcessing";
    mkDir(dir);
    const fileName tmp = dir/"summary.writing";
    {
        OFstream os(tmp);
        os  << "FoamFile" << nl << "{" << nl
            << "    version     2.0;" << nl
            << "    format      ascii;" << nl
            << "    class       dictionary;" << nl
            << "    object      summary;" << nl
            << "}" << nl << nl;
        os.precision(10);

        if (solution_.found("summary"))
        {
            const dictionary& sd = solution_.subDict("summary");
            for (const entry& e : sd)
            {
                if (!e.isDict())
                {
                    FatalIOErrorInFunction(sd)
                        << "summary entry '" << e.keyword()
                        << "' must be a dictionary" << exit(FatalIOError);
                }
                const dictionary& ed = e.dict();
                const word type = ed.get<word>("type");
                const label comp = planeComponent(ed.get<word>("component"), ed);
                scalar value = 0;
                if (type == "displacement")
                {
                    checkKeywords(ed, {"type", "point", "component"});
                    value = s.displacementAt(ed.get<point>("point"), comp, ed);
                }
                else if (type == "reaction")
                {
                    checkKeywords(ed, {"type", "patch", "component"});
                    value = s.reaction(ed.get<word>("patch"), comp, ed);
                }
                else
                {
                    FatalIOErrorInFunction(ed)
                        << "Unknown summary type '" << type << "' in "
                        << ed.name() << nl
                        << "    Valid types: displacement reaction"
                        << exit(FatalIOError);
                }
                os.writeEntry(e.keyword(), value);
                Info<< "    " << e.keyword() << " = " << value << nl;
            }
        }
        os.writeEntry("elementType", s.elementType());
        os.writeEntry("nElements", s.feMesh().feMesh().nElements());
        os.writeEntry("nDofs", s.model().nFreeDofs());
        os.writeEntry("steps", nSteps);
        os.writeEntry("newtonIterations", solver.totalIterations());
        os.writeEntry("wallTime", wallTime);
    }
    Foam::mv(tmp, dir/"summary");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::formScene::formScene(Time& runTime)
:
    runTime_(runTime),
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
    readSolution();

    const regionProperties rp(runTime);
    const wordList fluidNames(rp.found("fluid") ? rp["fluid"] : wordList());
    const wordList solidNames(rp.found("solid") ? rp["solid"] : wordList());
    if (fluidNames.size())
    {
        FatalErrorInFunction
            << "constant/regionProperties lists fluid regions " << fluidNames
            << "; fluid regions are not available yet" << exit(FatalError);
    }
    if (solidNames.size() != 1)
    {
        FatalErrorInFunction
            << "constant/regionProperties must list exactly one solid region"
            << " (found " << solidNames << ")" << exit(FatalError);
    }
    for (const word& name : solidNames)
    {
        solids_.append(new solidRegion(runTime, name));
    }

    word solverName = linearSolverName_;
    if (solverName == "auto")
    {
        solverName = solids_[0].model().unsymmetric() ? "umfpack" : "cholmod";
    }
    try
    {
        linearSolver_ = form::linearSolver::New(solverName);
    }
    catch (const form::inputError& err)
    {
        FatalIOErrorInFunction(solution_)
            << "Entry 'linearSolver' in " << solution_.name() << ": "
            << err.what() << " auto" << exit(FatalIOError);
    }
    if (linearSolver_->requiresSPD() && solids_[0].model().unsymmetric())
    {
        FatalIOErrorInFunction(solution_)
            << "Entry 'linearSolver' in " << solution_.name() << ": "
            << solverName << " needs a symmetric matrix, but follower"
            << " pressure loads make the tangent unsymmetric; use umfpack"
            << " or auto" << exit(FatalIOError);
    }

    if (steps_.startTime > 0 && solids_[0].readState(runTime.timeName()))
    {
        solids_[0].model().commit();
        Info<< "Restarting from the state written at time "
            << runTime.timeName() << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::formScene::run()
{
    printScene();
    solidRegion& solid = solids_[0];
    form::staticSolver solver
    (
        solid.model(), *linearSolver_, newton_, steps_, std::cout
    );

    const word writeControl =
        runTime_.controlDict().getOrDefault<word>("writeControl", "timeStep");
    const scalar writeInterval =
        runTime_.controlDict().getOrDefault<scalar>("writeInterval", 1);
    const clockTime clock;
    scalar nextWrite = steps_.startTime + writeInterval;
    label nSteps = 0;
    scalar lastTime = steps_.startTime;

    const auto writeNow = [&](scalar t, label index)
    {
        const clockTime outClock;
        runTime_.setTime(t, index);
        Info<< "    writing time " << runTime_.timeName() << endl;
        solid.write();
        solid.model().times().output += outClock.elapsedTime();
    };

    try
    {
        solver.run
        (
            [&](const form::stepReport& r)
            {
                ++nSteps;
                lastTime = r.time;
                const scalar frac =
                    (r.time - steps_.startTime)
                   /(steps_.endTime - steps_.startTime);
                const scalar elapsed = clock.elapsedTime();
                const scalar eta = frac > 0 ? elapsed*(1 - frac)/frac : 0;
                Info<< "Step " << r.step << "  t = " << r.time
                    << " (" << label(100*frac + 0.5) << "%)"
                    << "  dt = " << r.deltaT
                    << "  Newton " << r.iterations
                    << (r.cutbacks ? "  cutbacks " : "")
                    << (r.cutbacks ? Foam::name(r.cutbacks) : word())
                    << "  elapsed " << elapsed << " s  ETA " << eta << " s"
                    << endl;

                const bool last = r.time >= steps_.endTime - 1e-12;
                bool doWrite = last;
                if (writeControl == "timeStep")
                {
                    doWrite = doWrite || (nSteps % label(writeInterval) == 0);
                }
                else if (r.time >= nextWrite - 1e-12*writeInterval)
                {
                    doWrite = true;
                    while (nextWrite <= r.time + 1e-12) nextWrite += writeInterval;
                }
                if (doWrite) writeNow(r.time, r.step);
            }
        );
    }
    catch (const form::numericalError& err)
    {
        solid.model().revert();
        // The start time directory holds the case's input: never overwrite it
        if (lastTime > steps_.startTime)
        {
            writeNow(lastTime, nSteps);
        }
        FatalErrorInFunction
            << err.what() << nl
            << "    The last converged state (t = " << lastTime
            << ") is in its time directory; restart from it with startFrom"
            << " latestTime after changing the step controls in"
            << " system/solidSolution." << exit(FatalError);
    }

    const scalar wallTime = clock.elapsedTime();
    Info<< nl << "Summary" << nl;
    writeSummary(solver, nSteps, wallTime);

    const form::phaseTimes& t = solid.model().times();
    Info<< nl << "Time per phase (s)" << nl
        << "    assembly        " << t.assembly << nl
        << "    factorisation   " << t.factorisation << nl
        << "    solve           " << t.solve << nl
        << "    output          " << t.output << nl
        << "    total (wall)    " << wallTime << nl
        << "    steps " << nSteps << ", Newton iterations "
        << solver.totalIterations() << nl << nl << "End" << nl << endl;
}
