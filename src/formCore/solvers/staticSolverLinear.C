/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    staticSolver (see staticSolver.H): the evaluations and linear solves of
    the Newton iteration, and which tangent an update takes: the
    tangent of the iterate (full Newton), or kept factors of an earlier
    one while they still contract the residual (staticSolver.H, "Kept
    tangent"); one increment's attempts (the full-Newton retry of a step
    that failed with kept factors). The iteration itself:
    staticSolver.C.
\*---------------------------------------------------------------------------*/
#include "staticSolver.H"
#include "autoSolver.H"
#include "formError.H"
#include "wallClock.H"
#include <chrono>
#include <cmath>
#include <limits>
#include <ostream>

namespace form
{

bool staticSolver::evaluate(double t, vecX& r, bool wantTangent)
{
    const bool tangent = wantTangent && !tangentKept();
    try
    {
        const bool ok = model_.evaluate(t, r, tangent);
        tangentAtIterate_ = tangent && ok;
        return ok;
    }
    catch (const inversionError& e)
    {
        tangentAtIterate_ = false;
        lastFailure_ = e.what();
        return false;
    }
}


linearSolver& staticSolver::slotSolver()
{
    if (slot_ == 0) return solver_;
    factorSlot& s = slots_[slot_];
    if (!s.owned)
    {
        // (an automatic choice makes its own: "auto (cholmod)")
        const std::string type = solver_.type();
        s.owned =
            type.rfind("auto", 0) == 0
          ? std::make_unique<autoSolver>(&log_)
          : linearSolver::New(type);
    }
    return *s.owned;
}


bool staticSolver::tangentKept() const
{
    const factorSlot& f = slots_[slot_];
    if
    (
        !newton_.keepTangent || newton_.checkTangent || fullNewtonAttempt_
     || refreshTangent_ || !f.valid || f.revision != model_.patternRevision()
    )
    {
        return false;
    }
    const auto same = [](double a, double b)
    {
        return std::abs(a - b) <= 1e-9*std::max(std::abs(a), std::abs(b));
    };
    return
        same(f.alpha, model_.accelerationCoefficient())
     && same(f.deltaT, stageDeltaT_);
}


vecX staticSolver::newtonUpdate(double t, const vecX& rhs, bool& kept)
{
    kept = !tangentAtIterate_ && tangentKept();
    if (kept)
    {
        usedKeptTangent_ = true;
        return solveAgain(rhs);
    }
    if (!tangentAtIterate_)
    {
        // The kept factors no longer serve: the tangent of this iterate
        // (the state of the last evaluation, whose residual is rhs)
        refreshTangent_ = true;
        vecX r;
        if (!evaluate(t, r, true))
        {
            throw numericalError
            (
                lastFailure_.empty() ? "material update failed" : lastFailure_
            );
        }
    }
    return solveLinear(rhs);
}


vecX staticSolver::solveLinear(const vecX& rhs)
{
    phaseTimes& times = model_.times();
    auto start = std::chrono::steady_clock::now();
    factorSlot& slot = slots_[slot_];
    linearSolver& solver = slotSolver();
    if (slot.analysedRevision != model_.patternRevision())
    {
        solver.analyzePattern(model_.K());
        slot.analysedRevision = model_.patternRevision();
    }
    ++times.factorisations;
    ++newTangents_;
    model_.tangentFactorised();
    slot.valid = false;
    try
    {
        solver.factorize(model_.K());
    }
    catch (...)
    {
        times.factorisation += secondsSince(start);
        throw;
    }
    times.factorisation += secondsSince(start);
    slot.valid = true;
    slot.revision = model_.patternRevision();
    slot.alpha = model_.accelerationCoefficient();
    slot.deltaT = stageDeltaT_;
    refreshTangent_ = false;
    const linearSolver::factorStats st = solver.stats();
    times.factorFlops += st.flops;
    times.factorNonzeros = st.nonzeros;

    start = std::chrono::steady_clock::now();
    vecX dU = solver.solve(rhs);
    times.solve += secondsSince(start);
    if (!dU.allFinite())
    {
        throw numericalError("linear solve returned non-finite values");
    }
    return dU;
}


vecX staticSolver::solveAgain(const vecX& rhs)
{
    const auto start = std::chrono::steady_clock::now();
    vecX dU = slotSolver().solve(rhs);
    model_.times().solve += secondsSince(start);
    if (!dU.allFinite())
    {
        throw numericalError("linear solve returned non-finite values");
    }
    return dU;
}


bool staticSolver::attempt(double t0, double t1, stepReport& report)
{
    report.time = t1;
    report.deltaT = t1 - t0;
    report.iterations = 0;
    report.residualNorms.clear();
    report.updateNorms.clear();
    report.energyNorms.clear();
    lastFailure_.clear();
    lastResidual_ = std::numeric_limits<double>::quiet_NaN();
    newTangents_ = 0;
    usedKeptTangent_ = false;
    bool ok = false;
    try
    {
        ok = newton(t0, t1, report);
    }
    catch (const inputError&)
    {
        throw;
    }
    catch (const numericalError& e)
    {
        lastFailure_ = e.what();
        log_<< "    failed: " << lastFailure_ << '\n';
    }
    report.newTangents = newTangents_;
    return ok;
}


bool staticSolver::solveIncrement(double t0, double t1, stepReport& report)
{
    checkSolver();
    stageDeltaT_ = t1 - t0;
    if (attempt(t0, t1, report)) return true;
    if (!usedKeptTangent_) return false;

    // The kept factors may have led the iteration astray: once more from
    // the committed state with a new tangent at every iteration, before
    // the step is cut back
    log_<< "    retrying the increment with full Newton (a new tangent at"
           " every iteration)\n";
    model_.revert();
    const int tangents = report.newTangents;
    fullNewtonAttempt_ = true;
    bool ok = false;
    try
    {
        ok = attempt(t0, t1, report);
    }
    catch (...)
    {
        fullNewtonAttempt_ = false;
        throw;
    }
    fullNewtonAttempt_ = false;
    report.newTangents += tangents;
    return ok;
}

} // namespace form
