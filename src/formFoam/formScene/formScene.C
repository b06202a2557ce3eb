/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of formScene.H: a case as a scene, its run (the steps of
    the process schedule, output, the energy balance of dynamic runs). The
    set-up: formSceneSetup.C; output and restart: formSceneIO.C; the
    summary: formSceneSummary.C; the process schedule: formSceneSchedule.C.
\*---------------------------------------------------------------------------*/
#include "formScene.H"
#include "blockTangentCheck.H"
#include "OSspecific.H"
#include "clockTime.H"
#include "springbackMeasure.H"
#include "formError.H"
#include <algorithm>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

// * * * * * * * * * * * * * * * Private Functions  * * * * * * * * * * * * //

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
    // The effect report from the start, or continued from the restart
    // state (readRunState); a state written before the report existed
    // starts it at the restart time
    if (!restarted_ || !effectsRestored_)
    {
        effects_.start(model, restarted_ ? steps_.startTime : -1);
    }
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
                    effects_.record
                    (
                        model, stepDynamic ? integrator_.get() : nullptr,
                        fluid_.get()
                    );
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
            const std::string note =
                fluid_ ? fluid_->failureNote() : std::string();
            const std::string noteLine =
                note.empty() ? note : "    " + note + "\n";
            FatalErrorInFunction
                << err.what() << nl
                << noteLine.c_str()
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
    {
        const fileName dir = runTime_.path()/"postProcessing";
        mkDir(dir);
        effects_.write
        (
            effects_.lines
            (
                model, contact_.get(), bool(integrator_), fluid_.get()
            ),
            dir/"effects"
        );
    }
    // The phases are this process's: so are the steps, iterations and
    // wall time they are reported with (the summary's wallTime and
    // iterations count from t = 0 across restarts)
    const form::phaseTimes& t = model.times();
    const label runSteps = totals_.steps - restored_.steps;
    const label runIterations = totals_.iterations - restored_.iterations;
    Info<< nl << "Time per phase (s)";
    if (restored_.steps)
    {
        Info<< " of this run (restarted after step " << restored_.steps
            << "; from t = 0: " << totals_.steps << " steps, "
            << totals_.iterations << " Newton iterations, wall time "
            << wallTime << " s)";
    }
    Info<< nl
        << "    assembly        " << t.assembly << nl
        << "    contact         " << t.contact << nl
        << "    fluid           " << t.fluid << nl
        << "      mesh motion   "
        << (fluid_ ? fluid_->meshMotionTime() : scalar(0))
        << " (part of fluid)" << nl
        << "      mesh derivative "
        << (fluid_ ? fluid_->meshDerivativeTime() : scalar(0))
        << " (part of fluid)" << nl
        << "    factorisation   " << t.factorisation << nl
        << "    solve           " << t.solve << nl
        << "    factorisations  " << t.factorisations << " (count)" << nl
        << "    factor nonzeros " << t.factorNonzeros << " (last)" << nl
        << "    factor flops    " << t.factorFlops << " (total, "
        << (t.factorisation > 0 ? 1e-9*t.factorFlops/t.factorisation : 0)
        << " GFLOP/s)" << nl
        << "    output          " << t.output << nl
        << "    total (wall)    " << elapsed() << nl
        << "    steps " << runSteps << ", Newton iterations "
        << runIterations << nl;
    if (runIterations > 0)
    {
        const scalar n = runIterations;
        Info<< "Time per Newton iteration (ms): assembly "
            << 1e3*t.assembly/n << ", contact " << 1e3*t.contact/n
            << ", fluid " << 1e3*t.fluid/n << ", linear solve " << 1e3*(t.factorisation + t.solve)/n << nl;
    }
    Info<< nl << "End" << nl << endl;
}
