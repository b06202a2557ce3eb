/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    formScene: the summary (formScene.H, "summary"), its entries read from
    system/solidSolution and checked (type, tool, patch, point, time,
    statistic; a clear error naming the entry otherwise). Evaluated,
    recorded and written: formSceneSummary.C.
\*---------------------------------------------------------------------------*/
#include "formScene.H"
#include "dictionaryChecks.H"
#include "formError.H"
#include "springbackMeasure.H"

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
        const wordList common
        {
            "type", "scale", "statistic", "time", "at", "window"
        };
        wordList keys(common);
        if (type == "displacement" || type == "position")
        {
            keys.append(wordList{"point", "component"});
            if (type == "displacement") keys.append(word("direction"));
            // a displacement along a direction (3D), e.g. a draw-in along
            // a diagonal, or a component
            if
            (
                ed.found("direction")
             && (
                    type != "displacement" || ed.found("component")
                 || !(mag(ed.get<vector>("direction")) > 0)
                 || solids_[0].analysis() != form::analysisType::solid3D
                )
            )
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'direction' in " << ed.name() << ": a"
                    << " displacement summary takes either 'component' or"
                    << " a non-zero 'direction' (3D solids only)"
                    << exit(FatalIOError);
            }
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
        else if (type == "directorRotation")
        {
            keys.append(word("point"));
        }
        else if (type == "surfaceStrain")
        {
            keys.append(wordList{"quantity", "extreme"});
            const word q = ed.get<word>("quantity");
            const word x = ed.getOrDefault<word>("extreme", "max");
            if (!wordList{"major", "minor"}.found(q))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'quantity' in " << ed.name() << ": unknown '"
                    << q << "'; valid: major minor" << exit(FatalIOError);
            }
            if (!wordList{"max", "min"}.found(x))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'extreme' in " << ed.name() << ": unknown '"
                    << x << "'; valid: max min" << exit(FatalIOError);
            }
        }
        else if (type == "formingLimitMargin")
        {}
        else if (type == "shellThickness")
        {
            keys.append(word("extreme"));
            const word x = ed.getOrDefault<word>("extreme", "min");
            if (!wordList{"max", "min"}.found(x))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'extreme' in " << ed.name() << ": unknown '"
                    << x << "'; valid: min max" << exit(FatalIOError);
            }
        }
        else if (type == "maxDisplacement")
        {
            // The largest displacement over the nodes (of a patch), less
            // its component along normalTo, since a time (maxDisplacement
            // in formScene.H)
            keys.append(wordList{"patch", "normalTo", "since"});
            if
            (
                ed.found("normalTo")
             && !(mag(ed.get<vector>("normalTo")) > 0)
            )
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'normalTo' in " << ed.name() << ": a non-zero"
                    << " direction" << exit(FatalIOError);
            }
            if (ed.found("since"))
            {
                se.hasSince = true;
                se.since = ed.get<scalar>("since");
                if (!(se.since >= 0 && se.since < steps_.endTime))
                {
                    FatalIOErrorInFunction(ed)
                        << "Entry 'since' in " << ed.name() << " is out of"
                        << " range: " << se.since << " (valid: a time of the"
                        << " run before endTime " << steps_.endTime << ")"
                        << exit(FatalIOError);
                }
            }
        }
        else if (type == "angle")
        {
            keys.append(word("points"));
            if (ed.get<List<point>>("points").size() != 4)
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'points' in " << ed.name() << ": four points"
                    << " (A B C D): the angle between the lines AB and CD"
                    << exit(FatalIOError);
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
            // plane (3D only): the plane of the profile, xy (default) or
            // xz (a sheet whose normal is z)
            keys.append(wordList{"patch", "quantity", "plane"});
            const word q = ed.get<word>("quantity");
            if (!wordList{"theta1", "theta2", "rho"}.found(q))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'quantity' in " << ed.name() << ": unknown '"
                    << q << "'; valid: theta1 theta2 rho"
                    << exit(FatalIOError);
            }
            const bool is3D =
                !solids_.empty()
             && solids_[0].analysis() == form::analysisType::solid3D;
            const word plane = ed.getOrDefault<word>("plane", "xy");
            if (!wordList{"xy", "xz"}.found(plane) || (!is3D && plane != "xy"))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'plane' in " << ed.name() << ": unknown '"
                    << plane << "'; valid: "
                    << (is3D ? "xy xz" : "xy (the FE plane of a 2D analysis)")
                    << exit(FatalIOError);
            }
        }
        else
        {
            FatalIOErrorInFunction(ed)
                << "Unknown summary type '" << type << "' in " << ed.name()
                << nl << "    Valid types: displacement position reaction"
                << " circleRadius rotation bendingRadius extent difference"
                << " uChannelSpringback shellThickness directorRotation"
                << " surfaceStrain formingLimitMargin maxDisplacement angle"
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
        // Measures of a curve in the FE plane (uChannelSpringback also in
        // 3D: the profile of a strip in plane strain, evaluate())
        if
        (
            wordList{"circleRadius", "rotation", "bendingRadius"}.found(type)
         && !solids_.empty()
         && solids_[0].analysis() == form::analysisType::solid3D
        )
        {
            FatalIOErrorInFunction(ed)
                << "Summary type '" << type << "' in " << ed.name()
                << " measures a profile in the plane of a 2D analysis;"
                << " solid region '" << solids_[0].name() << "' is 3D" << nl
                << "    Valid in 3D: displacement position reaction extent"
                << " difference uChannelSpringback shellThickness"
                << " directorRotation surfaceStrain formingLimitMargin"
                << " maxDisplacement angle"
                << (contact_ ? " toolForce toolPosition" : "")
                << exit(FatalIOError);
        }
        se.statistic = ed.getOrDefault<word>("statistic", "final");
        const wordList windowed{"mean", "amplitude", "frequency"};
        if
        (
            !wordList{"final", "max", "min"}.found(se.statistic)
         && !windowed.found(se.statistic)
        )
        {
            FatalIOErrorInFunction(ed)
                << "Entry 'statistic' in " << ed.name() << ": unknown '"
                << se.statistic << "'; valid: final max min mean amplitude"
                << " frequency" << exit(FatalIOError);
        }
        if (windowed.found(se.statistic) != ed.found("window"))
        {
            FatalIOErrorInFunction(ed)
                << "Entry 'window' in " << ed.name() << ": the statistics"
                << " mean, amplitude and frequency need a time window, e.g."
                << " window (8 10); (the others take none); statistic '"
                << se.statistic << "'" << exit(FatalIOError);
        }
        if (ed.found("window"))
        {
            const FixedList<scalar, 2> w(ed.get<FixedList<scalar, 2>>("window"));
            if (!(0 <= w[0] && w[0] < w[1] && w[1] <= steps_.endTime))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'window' of summary entry '" << se.name
                    << "' in " << ed.name() << " is out of range: (" << w[0]
                    << ' ' << w[1] << ") (valid: two times of the run,"
                    << " 0 <= start < end <= endTime " << steps_.endTime
                    << ")" << exit(FatalIOError);
            }
            if (ed.found("time") || ed.found("at"))
            {
                FatalIOErrorInFunction(ed)
                    << "Entry 'window' in " << ed.name() << ": a statistic"
                    << " over a window takes neither 'time' nor 'at'"
                    << exit(FatalIOError);
            }
            se.window = std::make_shared<form::oscillation>(w[0], w[1]);
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
            "rotation", "bendingRadius", "extent", "uChannelSpringback",
            "shellThickness", "directorRotation", "surfaceStrain",
            "formingLimitMargin", "maxDisplacement", "angle"
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


// ************************************************************************* //
