/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    formScene: the summary (formScene.H, "summary"): its entries evaluated
    per converged step, recorded in postProcessing/history.dat (replayed on
    a restart) and written to postProcessing/summary. Read and checked:
    formSceneSummaryRead.C.
\*---------------------------------------------------------------------------*/
#include "formScene.H"
#include "dictionaryChecks.H"
#include "formError.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "springbackMeasure.H"
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

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
        const label comp = solidComponent(ed.get<word>("component"), ed, solids_[0].analysis());
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
            P.col(solidComponent(ed.get<word>("component"), ed, solids_[0].analysis()));
        value =
            ed.getOrDefault<word>("extreme", "max") == "max"
          ? c.maxCoeff() : c.minCoeff();
    }
    else if (type == "directorRotation")
    {
        value = s.directorRotation(ed.get<point>("point"), ed);
    }
    else if (type == "shellThickness")
    {
        value = s.shellThickness
        (
            ed.getOrDefault<word>("extreme", "min") == "max", ed
        );
    }
    else if (type == "surfaceStrain")
    {
        value = s.surfaceStrain
        (
            ed.get<word>("quantity") == "major",
            ed.getOrDefault<word>("extreme", "max") == "max", ed
        );
    }
    else if (type == "formingLimitMargin")
    {
        value = s.formingLimitMargin(ed);
    }
    else if (type == "maxDisplacement")
    {
        // before 'since' (or not yet reached when the summary is read): 0
        if (e.hasSince && !e.reference) return 0;
        value = s.maxDisplacement
        (
            ed.getOrDefault<word>("patch", word::null),
            ed.getOrDefault<vector>("normalTo", Zero),
            e.reference.get(),
            ed
        );
    }
    else if (type == "angle")
    {
        value = s.lineAngle(ed.get<List<point>>("points"), ed)
            *180/constant::mathematical::pi;
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
        // plane); a profile that is not (yet) a channel gives NaN. In 3D
        // the profile lies in the plane x-y (or x-z: 'plane'), and the
        // nodes with the same reference position in it (a strip in plane
        // strain: one node on each line across the width, e.g. the shell
        // nodes at both faces of a one-element-wide strip) are one point
        // of the profile, their mean current position
        const word patch = ed.get<word>("patch");
        const label c = ed.getOrDefault<word>("plane", "xy") == "xz" ? 2 : 1;
        const Eigen::MatrixXd X = s.patchPoints(patch, ed, false);
        const Eigen::MatrixXd x = s.patchPoints(patch, ed, true);
        std::vector<label> order(X.rows());
        std::iota(order.begin(), order.end(), 0);
        std::sort
        (
            order.begin(), order.end(),
            [&](label a, label b)
            {
                return X(a, 0) < X(b, 0)
                    || (X(a, 0) == X(b, 0) && X(a, c) < X(b, c));
            }
        );
        const scalar tol =
            1e-9*max
            (
                (X.colwise().maxCoeff() - X.colwise().minCoeff()).norm(),
                VSMALL
            );
        std::vector<Eigen::Vector2d> profile;
        std::vector<Eigen::Vector2d> reference;
        std::vector<label> count;
        for (const label i : order)
        {
            const Eigen::Vector2d R(X(i, 0), X(i, c));
            const Eigen::Vector2d p(x(i, 0), x(i, c));
            if (!reference.empty() && (R - reference.back()).norm() <= tol)
            {
                profile.back() += p;
                ++count.back();
            }
            else
            {
                reference.push_back(R);
                profile.push_back(p);
                count.push_back(1);
            }
        }
        for (std::size_t k = 0; k < profile.size(); ++k)
        {
            profile[k] /= count[k];
        }
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
    else if (type == "displacement" && ed.found("direction"))
    {
        // The displacement along a direction (3D), e.g. a draw-in along a
        // diagonal
        // (the direction checked when the summary was read)
        const vector d = ed.get<vector>("direction");
        const point p = ed.get<point>("point");
        value = 0;
        for (label c = 0; c < 3; ++c)
        {
            value += s.displacementAt(p, c, ed)*d[c]/mag(d);
        }
    }
    else
    {
        const label comp = solidComponent(ed.get<word>("component"), ed, solids_[0].analysis());
        if (type == "displacement")
        {
            value = s.displacementAt(ed.get<point>("point"), comp, ed);
        }
        else if (type == "position")
        {
            const point p = ed.get<point>("point");
            value = s.feMesh().toFe(p)(comp) + s.displacementAt(p, comp, ed);
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
    if (e.window)
    {
        e.window->add(time, v);
        e.set = e.window->hasSamples();
        e.value =
            e.statistic == "mean" ? e.window->mean()
          : e.statistic == "amplitude" ? e.window->amplitude()
          : e.window->frequency();
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


void Foam::formScene::recordSummary(scalar time, bool first)
{
    summaryTime_ = time;
    const fileName dir = runTime_.path()/"postProcessing";
    mkDir(dir);
    const bool append = !first && isFile(dir/"history.dat");
    std::ofstream os
    (
        dir/"history.dat", append ? std::ios::app : std::ios::trunc
    );
    os.precision(15);
    if (!append)
    {
        os << "# time";
        for (const summaryEntry& e : summary_) os << ' ' << e.name;
        os << '\n';
    }
    os << time;
    // one state for all entries: the shells' results computed once
    for (const solidRegion& s : solids_) s.holdShellResults(true);
    for (summaryEntry& e : summary_)
    {
        sinceReference(e, time);
        const scalar v = evaluate(e);
        os << ' ' << v;
        updateEntry(e, time, v, first);
    }
    for (const solidRegion& s : solids_) s.holdShellResults(false);
    os << '\n';
    os.flush();
    if (!os)
    {
        FatalErrorInFunction
            << "Cannot append to " << dir/"history.dat" << " (disk full?)"
            << exit(FatalError);
    }
}


void Foam::formScene::sinceReference(summaryEntry& e, scalar time)
{
    if (!e.hasSince || e.reference) return;
    const scalar tol = 1e-9*max(mag(e.since), 1.0);
    if (time < e.since - tol) return;
    const solidRegion& s = solids_[0];
    if (time <= e.since + tol)
    {
        e.reference =
            std::make_shared<const form::matX>(s.model().displacement());
        return;
    }
    // After 'since' without its state (a restart): from its time directory
    e.reference = std::make_shared<const form::matX>
    (
        s.displacementState(runTime_.timeName(e.since), e.dict)
    );
}


bool Foam::formScene::replayHistory(scalar restartTime)
{
    const fileName file = runTime_.path()/"postProcessing"/"history.dat";
    if (!isFile(file)) return false;
    std::ifstream is(file);
    std::string header;
    if (!std::getline(is, header) || header.rfind("# time", 0) != 0)
    {
        return false;
    }
    // Columns by name; entries without a column start afresh
    std::istringstream hs(header.substr(1));
    std::vector<std::string> names;
    for (std::string w; hs >> w;) names.push_back(w);
    std::vector<label> column(summary_.size(), -1);
    forAll(summary_, k)
    {
        const auto it =
            std::find(names.begin(), names.end(), summary_[k].name);
        if (it != names.end()) column[k] = label(it - names.begin());
    }
    // The rows before the restart time (later ones belong to the
    // abandoned continuation and are dropped)
    std::vector<std::string> kept;
    bool first = true;
    const scalar tol = 1e-9*max(mag(restartTime), 1.0);
    for (std::string line; std::getline(is, line);)
    {
        // strtod, not >>: an entry not yet evaluated is recorded as nan
        std::istringstream ls(line);
        std::vector<scalar> v;
        for (std::string w; ls >> w;)
        {
            char* end = nullptr;
            const scalar x = std::strtod(w.c_str(), &end);
            if (end == w.c_str() || *end != '\0') break;
            v.push_back(x);
        }
        if (v.size() != names.size() || v[0] >= restartTime - tol) continue;
        forAll(summary_, k)
        {
            if (column[k] > 0) updateEntry(summary_[k], v[0], v[column[k]], first);
        }
        first = false;
        kept.push_back(line);
    }
    is.close();
    // Rewritten under a temporary name and renamed: a kill leaves either
    // the old or the new history
    std::ostringstream os;
    os << header << '\n';
    for (const std::string& line : kept) os << line << '\n';
    try
    {
        form::writeFileAtomic(file, os.str());
    }
    catch (const form::numericalError& err)
    {
        FatalErrorInFunction << err.what() << exit(FatalError);
    }
    return !kept.empty();
}


void Foam::formScene::writeSummary
(
    label newtonIterations,
    label nSteps,
    label cutbacks,
    scalar wallTime
) const
{
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
        os.precision(15);

        for (const summaryEntry& e : summary_)
        {
            if (!e.set && e.atEntry >= 0)
            {
                FatalIOErrorInFunction(e.dict)
                    << "summary entry '" << e.name << "' in " << e.dict.name()
                    << " was never evaluated: '" << summary_[e.atEntry].name
                    << "' never reached " << e.atValue << " (it ended at "
                    << summary_[e.atEntry].curValue << ")"
                    << exit(FatalIOError);
            }
            if (!e.set && e.window)
            {
                FatalIOErrorInFunction(e.dict)
                    << "summary entry '" << e.name << "' in " << e.dict.name()
                    << " was never evaluated: no converged step in its window ("
                    << e.window->windowStart() << ' ' << e.window->windowEnd()
                    << ")" << exit(FatalIOError);
            }
            if (!e.set)
            {
                FatalIOErrorInFunction(e.dict)
                    << "summary entry '" << e.name << "' in " << e.dict.name()
                    << " was never evaluated: no converged step ended at its"
                    << " time " << e.time << exit(FatalIOError);
            }
            os.writeEntry(e.name, e.value);
            Info<< "    " << e.name << " = " << e.value;
            if (e.window)
            {
                Info<< " (" << e.statistic << " over t = "
                    << e.window->windowStart() << " to "
                    << e.window->windowEnd() << ": " << e.window->samples()
                    << " steps, " << e.window->periods() << " whole periods)";
            }
            Info<< nl;
            if (e.window && e.statistic == "frequency" && !e.window->hasFrequency())
            {
                WarningInFunction
                    << "summary entry '" << e.name << "': no whole period in"
                    << " its window (" << e.window->windowStart() << ' '
                    << e.window->windowEnd() << "): fewer than two upward"
                    << " crossings of the mean; frequency 0 reported" << nl;
            }
        }
        const bool solid = solids_.size();
        os.writeEntry
        (
            "elementType", solid ? solids_[0].elementType() : word("none")
        );
        os.writeEntry
        (
            "fluidModel", fluid_ ? fluid_->fluidModel() : word("none")
        );
        os.writeEntry
        (
            "nElements", solid ? solids_[0].feMesh().feMesh().nElements() : 0
        );
        os.writeEntry("nDofs", model().nFreeDofs());
        if (fluid_ && fluid_->ALE())
        {
            os.writeEntry("nFluidUnknowns", model().nUnknowns() - model().nFreeDofs());
        }
        os.writeEntry("steps", nSteps);
        os.writeEntry("newtonIterations", newtonIterations);
        os.writeEntry
        (
            "newtonIterationsPerStep",
            scalar(newtonIterations)/max(label(1), nSteps)
        );
        os.writeEntry("maxIterationsInAStep", maxStepIterations_);
        os.writeEntry("cutbacks", cutbacks);
        if (checkTangent_)
        {
            os.writeEntry("tangentChecks", tangentChecks_);
            os.writeEntry("tangentCheckMax", worstTangent_.relative);
        }
        for (const auto& sw : stepWallTimes_)
        {
            os.writeEntry(word(sw.first + "WallTime"), sw.second);
        }
        os.writeEntry("wallTime", wallTime);
        os.flush();
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << " (disk full?)" << exit(FatalError);
        }
    }
    if (!Foam::mv(tmp, dir/"summary"))
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << dir/"summary"
            << exit(FatalError);
    }
}


// ************************************************************************* //
