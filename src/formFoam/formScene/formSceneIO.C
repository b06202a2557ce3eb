/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    formScene: output and restart (formScene.H, "Output and restarts");
    the report of formFoam -checkTangent's checks along the Newton updates

    A time directory appears complete or not at all: every region writes
    under .<time>.writing, every file is checked (not empty, ending with
    OpenFOAM's end divider: a full disk truncates it), the run state
    uniform/formFoamState is written last, and one rename puts the
    directory in place. A restart reads only a time with that run state,
    and rewrites postProcessing files only once the state has been read.
\*---------------------------------------------------------------------------*/
#include "formScene.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "vtkWriter.H"
#include "formError.H"
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <dirent.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Every regular file under dir (recursively)
void filesUnder(const fileName& dir, fileNameList& files)
{
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        files.append(dir/f);
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY))
    {
        filesUnder(dir/d, files);
    }
}

//- A file OpenFOAM wrote completely: not empty and ending with its end
//  divider ("// ***...*** //"), which is written last
bool completeFile(const fileName& file)
{
    std::ifstream is(file, std::ios::binary | std::ios::ate);
    const std::streamoff size = is.tellg();
    if (!is || size <= 0) return false;
    const std::streamoff n = std::min<std::streamoff>(size, 200);
    is.seekg(size - n);
    std::string tail(n, '\0');
    is.read(&tail[0], n);
    return tail.find("// ****") != std::string::npos;
}

//- The hidden directories (.name) of dir: formFoam's temporaries
//  (OpenFOAM's readDir skips hidden names)
wordList hiddenDirs(const fileName& dir)
{
    wordList names;
    if (DIR* d = ::opendir(dir.c_str()))
    {
        while (const dirent* e = ::readdir(d))
        {
            const std::string n = e->d_name;
            if (n.size() > 1 && n[0] == '.' && n != ".." && isDir(dir/n))
            {
                names.append(n);
            }
        }
        ::closedir(d);
    }
    return names;
}

//- The run state file of a time directory
fileName runStateFile(const fileName& timeDir)
{
    return timeDir/"uniform"/"formFoamState";
}

} // namespace


// * * * * * * * * * * * * * * Member Functions * * * * * * * * * * * * * * //

void Foam::formScene::faultPoint(const char* point)
{
    // Test hook (tests/cases/faults.sh): FORMFOAM_FAULT=<point>:<n> kills
    // the run with SIGKILL at that point of its n-th time write; points:
    // region (after the first region's files), rename (every file
    // written, before the directory is renamed), swap (an earlier version
    // of the time moved aside, the new one not yet in place), written
    // (after the rename, before the VTK frame)
    static const char* fault = std::getenv("FORMFOAM_FAULT");
    if (!fault) return;
    const std::string f(fault);
    const auto colon = f.find(':');
    if
    (
        colon != std::string::npos && f.substr(0, colon) == point
     && std::atol(f.c_str() + colon + 1) == nWrites_
    )
    {
        Info<< "FORMFOAM_FAULT: killed at " << point << " of write "
            << nWrites_ << endl;
        ::kill(::getpid(), SIGKILL);
    }
}


void Foam::formScene::checkStart()
{
    const fileName path = runTime_.path();
    // A kill between the two renames of an overwrite leaves the complete
    // earlier version of a time aside: put it back. Other temporaries are
    // incomplete writes: remove them.
    for (const word& d : hiddenDirs(path))
    {
        const std::string n = d;
        const auto ends = [&](const std::string& s)
        {
            return n.size() > s.size() + 1
                && n.compare(n.size() - s.size(), s.size(), s) == 0;
        };
        if (ends(".old"))
        {
            const fileName t = n.substr(1, n.size() - 5);
            if (!isDir(path/t))
            {
                Info<< "Restoring time " << t.c_str() << " from "
                    << (path/d).c_str()
                    << " (a run was killed while rewriting it)" << endl;
                Foam::mv(path/d, path/t);
            }
            else
            {
                rmDir(path/d);
            }
        }
        else if (ends(".writing"))
        {
            Info<< "Removing " << (path/d).c_str() << ": an incomplete write"
                << " of a run that was killed" << endl;
            rmDir(path/d);
        }
    }

    // The start time: a time directory that holds the input (the earliest
    // time) or a complete written state
    const word startName = runTime_.timeName();
    const fileName startDir = path/startName;
    const instantList times = runTime_.times();
    wordList written, all;
    for (const instant& t : times)
    {
        if (t.name() == runTime_.constant()) continue;
        all.append(t.name());
        if (isFile(runStateFile(path/t.name()))) written.append(t.name());
    }
    const auto available = [&]()
    {
        std::ostringstream os;
        os  << "    Times with a complete written state: "
            << (written.empty() ? std::string("none") : std::string())
            << nl;
        for (const word& w : written) os << ' ' << w;
        if (written.size()) os << nl;
        return os.str();
    };
    if (!isDir(startDir))
    {
        FatalErrorInFunction
            << "The start time " << startName << " (system/controlDict:"
            << " startFrom " << runTime_.controlDict().getOrDefault<word>
               ("startFrom", "startTime")
            << ") has no time directory in " << path << nl
            << available().c_str()
            << "    To restart, set startTime to one of them (or startFrom"
            << " latestTime); to start afresh, startTime to the time of the"
            << " case's input (" << (all.size() ? all[0] : word("0"))
            << ")" << exit(FatalError);
    }
    restarted_ = isFile(runStateFile(startDir));
    if (!restarted_ && all.size() && startName != all[0])
    {
        // Not the input time and not a complete state: a time directory
        // left by another program or an older formFoam, or damaged
        FatalErrorInFunction
            << "The start time directory " << startDir << " holds no"
            << " complete formFoam state (" << runStateFile(startDir)
            << " is missing): it was not written completely, or not by"
            << " formFoam, and a run cannot start from it" << nl
            << available().c_str()
            << "    Set startTime to one of them (startFrom startTime in"
            << " system/controlDict)" << exit(FatalError);
    }
}


void Foam::formScene::readRunState()
{
    IOdictionary d
    (
        IOobject
        (
            "formFoamState", runTime_.timeName(), "uniform", runTime_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    // The exact time of the state: the directory's name holds it only to
    // timePrecision digits
    const scalar t = d.get<scalar>("time");
    if (mag(t - steps_.startTime) > 1e-6*max(mag(t), 1.0))
    {
        FatalIOErrorInFunction(d)
            << "The run state " << d.objectPath() << " is of time " << t
            << ", not of its directory's time " << runTime_.timeName()
            << " (was the directory renamed?)" << exit(FatalIOError);
    }
    steps_.startTime = t;
    runTime_.setTime(t, runTime_.timeIndex());
    // Without a processSchedule the one step "run" was built from
    // controlDict's startTime, the rounded directory name: it starts at
    // the exact time (the restarted bulge stepped from 0.515938 instead of
    // 0.5159375: loads off by 1e-6 of a step, results by 1e-9). (The
    // steps of a processSchedule start where the one before ended.)
    if (!isFile(runTime_.path()/"constant"/"processSchedule"))
    {
        for (processStep& ps : schedule_) ps.startTime = t;
    }
    totals_.steps = d.get<label>("steps");
    totals_.iterations = d.get<label>("newtonIterations");
    totals_.cutbacks = d.get<label>("cutbacks");
    maxStepIterations_ = d.get<label>("maxIterationsInAStep");
    totals_.wallTime = d.get<scalar>("wallTime");
    restored_ = totals_;
    if (solids_.size() || fluidOnlyModel_)
    {
        model().setForceLevel(d.get<scalar>("forceLevel"));
    }
    for (const entry& e : d.subOrEmptyDict("stepWallTimes"))
    {
        stepWallTimes_.push_back({e.keyword(), readScalar(e.stream())});
    }
    // (restart files written before 2026-11-29 have no effect report)
    if (solids_.size() || fluidOnlyModel_)
    {
        effectsRestored_ =
            effects_.setState(d.subOrEmptyDict("effects"), model());
    }
    resumeStep_ = d.get<word>("processStep");
    resume_.deltaT = d.get<scalar>("deltaT");
    resume_.lastDeltaT = d.get<scalar>("lastDeltaT");
    resume_.previousDeltaT = d.get<scalar>("previousDeltaT");
    const auto vec = [&](const word& key)
    {
        const scalarList l(d.get<scalarList>(key));
        form::vecX v(l.size());
        forAll(l, i) v(i) = l[i];
        return v;
    };
    resume_.lastIncrement = vec("lastIncrement");
    resume_.previousIncrement = vec("previousIncrement");
    // (restart files written before 2026-11-28 have no pressure history:
    // the predictor then starts without it)
    if (d.found("pressureHistory"))
    {
        const form::vecX h = vec("pressureHistory");
        resume_.pressureHistory.assign(h.data(), h.data() + h.size());
    }
}


void Foam::formScene::writeTime
(
    scalar t,
    const form::staticSolver* solver,
    const word& stepName
)
{
    const clockTime outClock;
    ++nWrites_;
    runTime_.setTime(t, totals_.steps);
    const word timeName = runTime_.timeName();
    const fileName path = runTime_.path();
    const word tmpName = "." + timeName + ".writing";
    const fileName tmpDir = path/tmpName;
    if (isDir(tmpDir)) rmDir(tmpDir);
    Info<< "    writing time " << timeName << endl;

    // Every region writes to the temporary directory: OpenFOAM writes
    // fields to the time's name, so the time is named after it meanwhile
    runTime_.setTime(instant(t, tmpName), totals_.steps);
    bool ok = true;
    std::string streamError;
    try
    {
    if (solids_.size())
    {
        ok = solids_[0].write() && ok;
        if (integrator_)
        {
            const std::vector<double> ds = integrator_->state();
            IOField<scalar> f
            (
                IOobject
                (
                    "feDynamics", tmpName, solids_[0].mesh(),
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                scalarField(ds.size())
            );
            forAll(f, i) f[i] = ds[i];
            const unsigned precision = IOstream::defaultPrecision(17);
            ok = f.write() && ok;
            IOstream::defaultPrecision(precision);
        }
    }
    faultPoint("region");
    if (fluid_) ok = fluid_->write(tmpName) && ok;

    // The run state, last: totals, the force level of the state, and what
    // the next step of the current process step starts from
    {
        const unsigned precision = IOstream::defaultPrecision(17);
        IOdictionary d
        (
            IOobject
            (
                "formFoamState", tmpName, "uniform", runTime_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            )
        );
        const label iterations =
            totals_.iterations + (solver ? solver->totalIterations() : 0);
        d.add("time", t);
        d.add("steps", totals_.steps);
        d.add("newtonIterations", iterations);
        d.add("cutbacks", totals_.cutbacks);
        d.add("maxIterationsInAStep", maxStepIterations_);
        d.add
        (
            "wallTime", totals_.wallTime + clock_.elapsedTime() - runStart_
        );
        d.add("forceLevel", model().forceLevel());
        d.add("effects", effects_.state());
        dictionary sw;
        for (const auto& w : stepWallTimes_) sw.add(w.first, w.second);
        d.add("stepWallTimes", sw);
        const form::resumeState rs =
            solver ? solver->resume() : form::resumeState();
        const auto list = [](const form::vecX& v)
        {
            scalarList l(v.size());
            forAll(l, i) l[i] = v(i);
            return l;
        };
        d.add("processStep", stepName);
        d.add("deltaT", rs.deltaT);
        d.add("lastDeltaT", rs.lastDeltaT);
        d.add("previousDeltaT", rs.previousDeltaT);
        d.add("lastIncrement", list(rs.lastIncrement));
        d.add("previousIncrement", list(rs.previousIncrement));
        d.add
        (
            "pressureHistory",
            list
            (
                Eigen::Map<const form::vecX>
                (
                    rs.pressureHistory.data(), rs.pressureHistory.size()
                )
            )
        );
        ok = d.regIOobject::write() && ok;
        IOstream::defaultPrecision(precision);
    }
    }
    catch (const Foam::error& err)
    {
        // OpenFOAM's streams report a failed write (a full disk) as a
        // fatal error: the transaction fails like any other write
        ok = false;
        streamError = err.message();
    }
    runTime_.setTime(instant(t, timeName), totals_.steps);

    // Every file complete? (a full disk truncates files, and OpenFOAM's
    // streams do not always report it)
    fileNameList files;
    filesUnder(tmpDir, files);
    for (const fileName& f : files)
    {
        if (!completeFile(f))
        {
            ok = false;
            Info<< "    incomplete file " << f << endl;
        }
    }
    const auto failed = [&](const std::string& what)
    {
        rmDir(tmpDir);
        FatalErrorInFunction
            << "Writing time " << timeName << " failed: " << what.c_str()
            << nl << "    The last complete time is "
            << (lastWritten_.empty() ? word("the start time") : lastWritten_)
            << "; restart from it (startFrom latestTime) once the cause is"
            << " mended" << exit(FatalError);
    };
    if (!ok || !isFile(runStateFile(tmpDir)))
    {
        failed
        (
            "a file could not be written completely (disk full?)"
          + (streamError.empty() ? std::string() : ": " + streamError)
        );
    }
    // Contact results and the VTK frame before the rename: a restart
    // from this time then finds them (a restart from an earlier time
    // drops the frames after it)
    if (contact_ && !contact_->write(timeName, t))
    {
        rmDir(tmpDir);
        FatalErrorInFunction
            << "Writing the contact results of time " << timeName
            << " (postProcessing/contact) failed (disk full?)" << nl
            << "    The last complete time is "
            << (lastWritten_.empty() ? word("the start time") : lastWritten_)
            << exit(FatalError);
    }
    if (solids_.size())
    {
        try
        {
            solids_[0].writeVTK();
        }
        catch (const form::numericalError& err)
        {
            failed(err.what());
        }
    }
    faultPoint("rename");

    // One rename puts the complete time in place; an earlier version of
    // it is moved aside first and removed after
    const fileName timeDir = path/timeName;
    const fileName oldDir = path/("." + timeName + ".old");
    if (isDir(timeDir))
    {
        if (isDir(oldDir)) rmDir(oldDir);
        if (!Foam::mv(timeDir, oldDir))
        {
            failed("cannot move the earlier " + timeDir + " aside");
        }
        faultPoint("swap");
    }
    if (!Foam::mv(tmpDir, timeDir))
    {
        failed("cannot rename " + tmpDir + " to " + timeDir);
    }
    if (isDir(oldDir)) rmDir(oldDir);
    lastWritten_ = timeName;
    faultPoint("written");

    model().times().output += outClock.elapsedTime();
}


void Foam::formScene::collectTangentChecks(const form::staticSolver& solver)
{
    if (!checkTangent_) return;
    tangentChecks_ += solver.tangentChecks();
    const form::tangentCheckResult& w = solver.worstTangentCheck();
    if (solver.tangentChecks() && w.relative >= worstTangent_.relative)
    {
        worstTangent_ = w;
        worstTangentTime_ = solver.worstTangentCheckTime();
        worstTangentIteration_ = solver.worstTangentCheckIteration();
    }
}


void Foam::formScene::reportTangentChecks() const
{
    if (!checkTangent_) return;
    Info<< nl << "Tangent check (-checkTangent): " << tangentChecks_
        << " Newton updates checked";
    if (tangentChecks_)
    {
        Info<< "; largest |dr/dh + K u|/|K u| = " << worstTangent_.relative
            << " at t = " << worstTangentTime_ << ", iteration "
            << worstTangentIteration_ << nl << "    error vector:"
            << worstTangent_.where.c_str();
    }
    Info<< endl;
}
