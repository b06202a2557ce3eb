/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    formScene: the process schedule (formScene.H, "Process steps"): steps
    read and checked at start, their actions applied at their start, and
    the support of the solid checked for every static step
\*---------------------------------------------------------------------------*/
#include "formScene.H"
#include "dictionaryChecks.H"
#include "supportCheck.H"
#include <sstream>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

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
            comps.append(solidComponent(c, d, s.analysis()));
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
        s.pinPoints
        (
            subDictOf(d, "pin", "{ <name> { point (x y z); components (x y); } }"),
            apply
        );
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


// ************************************************************************* //
