/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    staticSolver (see staticSolver.H): construction and checks, the time
    loop (steps, automatic cutback and growth of the step, the callbacks
    of converged steps), the dynamic integrator, and the state a restart
    resumes from. One step's Newton iteration: staticSolver.C; the line
    searches: staticSolverLineSearch.C.
\*---------------------------------------------------------------------------*/
#include "staticSolver.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace form
{

namespace
{

// A residual norm for messages, as printf's %.3e writes it
std::string scientific(double v)
{
    std::ostringstream os;
    os << std::scientific << std::setprecision(3) << v;
    return os.str();
}

} // namespace
staticSolver::staticSolver
(
    solidModel& model,
    linearSolver& solver,
    newtonControls newton,
    stepControls steps,
    std::ostream& log
)
:
    model_(model),
    solver_(solver),
    newton_(newton),
    steps_(steps),
    log_(log)
{
    checkSolver();
    // The tangent check compares the tangent with differences of the
    // residual: the tracked pressure (solidElement.H) is off there
    model_.setPressureTracking(!newton_.checkTangent);
    if (newton_.maxIterations < 1)
    {
        throw inputError("maxIterations", "maxIterations must be >= 1");
    }
    if (!(steps_.deltaT > 0) || !(steps_.minDeltaT > 0)
     || !(steps_.maxDeltaT > 0))
    {
        throw inputError
        (
            "deltaT",
            "deltaT, minDeltaT and maxDeltaT must be positive"
        );
    }
    if (!(steps_.cutbackFactor > 0 && steps_.cutbackFactor < 1))
    {
        throw inputError("cutbackFactor", "cutbackFactor must be in (0, 1)");
    }
    if (!(steps_.growthFactor >= 1))
    {
        throw inputError("growthFactor", "growthFactor must be >= 1");
    }
}


void staticSolver::checkSolver() const
{
    if (solver_.requiresSPD() && model_.unsymmetric())
    {
        throw inputError
        (
            "linearSolver",
            "linearSolver " + solver_.type() + " needs a symmetric positive"
            " definite matrix, but follower loads or contact make the"
            " Newton matrix unsymmetric; use umfpack"
        );
    }
}


void staticSolver::run
(
    const std::function<void(const stepReport&)>& onConverged
)
{
    const double tEnd = steps_.endTime;
    double t = steps_.startTime;
    double dt =
        nextDeltaT_ > 0
      ? nextDeltaT_ : std::min(steps_.deltaT, steps_.maxDeltaT);
    // Times closer than this to endTime count as endTime
    const double tiny = 1e-12*std::max(1.0, std::abs(tEnd));
    int step = 0;

    while (t < tEnd - tiny)
    {
        ++step;
        int cutbacks = 0;
        for (;;)
        {
            double t1 = t + dt;
            // Land exactly on endTime (no sliver of a last step)
            if (t1 >= tEnd - 1e-6*dt) t1 = tEnd;

            char line[160];
            std::snprintf
            (
                line, sizeof(line), "Step %d  t = %.6g  deltaT = %.6g%s\n",
                step, t1, t1 - t,
                cutbacks ? ("  (cutback " + std::to_string(cutbacks) + ")")
                    .c_str() : ""
            );
            log_<< line;

            stepReport report;
            report.step = step;
            report.cutbacks = cutbacks;
            const int nStages = integrator_ ? integrator_->nStages() : 1;
            solidModel::savedState start;
            if (nStages > 1) start = model_.save();
            bool ok = true;
            int stagesDone = 0;
            for (int stage = 0; stage < nStages && ok; ++stage)
            {
                const double ts0 =
                    stage == 0 ? t : integrator_->stageEnd(0, t, t1);
                const double ts1 =
                    integrator_ ? integrator_->stageEnd(stage, t, t1) : t1;
                if (nStages > 1)
                {
                    std::snprintf
                    (
                        line, sizeof(line), "  stage %d  t = %.6g\n",
                        stage + 1, ts1
                    );
                    log_<< line;
                }
                if (integrator_) integrator_->beginStage(stage, t, t1, model_);
                const vecX before =
                    newton_.extrapolate ? model_.state() : vecX();
                stepReport stageReport;
                // (kept tangents: the factors of this stage)
                slot_ = newton_.keepTangent ? stage : 0;
                if (slot_ >= int(slots_.size())) slots_.resize(slot_ + 1);
                ok = solveIncrement(ts0, ts1, stageReport);
                slot_ = 0;
                report.iterations += stageReport.iterations;
                report.newTangents += stageReport.newTangents;
                for (std::size_t k = 0; k < stageReport.residualNorms.size(); ++k)
                {
                    report.residualNorms.push_back
                    (
                        stageReport.residualNorms[k]
                    );
                    report.updateNorms.push_back(stageReport.updateNorms[k]);
                    report.energyNorms.push_back(stageReport.energyNorms[k]);
                }
                if (!ok) break;
                model_.commit();
                ++stagesDone;
                if (integrator_) integrator_->endStage(stage, t, t1, model_);
                if (newton_.extrapolate)
                {
                    previousIncrement_ = lastIncrement_;
                    previousDeltaT_ = lastDeltaT_;
                    lastIncrement_ = model_.state() - before;
                    lastDeltaT_ = ts1 - ts0;
                }
            }
            report.time = t1;
            report.deltaT = t1 - t;
            if (ok)
            {
                if (integrator_) integrator_->commitStep();
                totalIterations_ += report.iterations;
                std::snprintf
                (
                    line, sizeof(line),
                    "  converged in %d iterations, |r| = %.3e%s\n",
                    report.iterations, report.residualNorms.back(),
                    newton_.keepTangent
                  ? (", new tangents " + std::to_string(report.newTangents))
                    .c_str()
                  : ""
                );
                log_<< line;
                t = t1;
                if
                (
                    cutbacks == 0
                 && report.iterations <= nStages*steps_.easyIterations
                )
                {
                    dt = std::min(dt*steps_.growthFactor, steps_.maxDeltaT);
                }
                nextDeltaT_ = dt;
                if (onConverged) onConverged(report);
                break;
            }

            if (integrator_) integrator_->revertStep();
            if (stagesDone > 0)
            {
                model_.restore(start);
            }
            model_.revert();
            ++cutbacks;
            const double tried = t1 - t;
            const double next = tried*steps_.cutbackFactor;
            if (cutbacks > steps_.maxCutbacks || next < steps_.minDeltaT)
            {
                std::string msg =
                    "staticSolver: no convergence for the step from t = "
                  + formatNumber(t) + " to t = " + formatNumber(t1)
                  + " (deltaT = " + formatNumber(tried) + ") after "
                  + std::to_string(cutbacks - 1) + " cutbacks";
                msg +=
                    cutbacks > steps_.maxCutbacks
                  ? "; maxCutbacks = " + std::to_string(steps_.maxCutbacks)
                      + " reached"
                  : "; deltaT would fall below minDeltaT = "
                      + formatNumber(steps_.minDeltaT);
                msg += "; last residual |r| = " + scientific(lastResidual_);
                if (!lastFailure_.empty())
                {
                    msg += "; last failure: " + lastFailure_;
                }
                log_<< msg << '\n';
                throw convergenceError(msg);
            }
            log_<< "  step failed"
                << (lastFailure_.empty() ? "" : ": " + lastFailure_)
                << "; cutting back deltaT to " << formatNumber(next) << '\n';
            dt = next;
        }
    }
}


void staticSolver::setIntegrator(timeIntegrator* integrator)
{
    if (integrator && !model_.hasInertia())
    {
        throw numericalError
        (
            "staticSolver::setIntegrator: the model has no inertia"
            " (solidModel::setInertia)"
        );
    }
    integrator_ = integrator;
}


int staticSolver::totalIterations() const
{
    return totalIterations_;
}


resumeState staticSolver::resume() const
{
    return
    {
        nextDeltaT_, lastIncrement_, lastDeltaT_, previousIncrement_,
        previousDeltaT_, model_.pressureHistory()
    };
}


void staticSolver::resume(const resumeState& s)
{
    nextDeltaT_ = s.deltaT;
    lastIncrement_ = s.lastIncrement;
    lastDeltaT_ = s.lastDeltaT;
    previousIncrement_ = s.previousIncrement;
    previousDeltaT_ = s.previousDeltaT;
    model_.setPressureHistory(s.pressureHistory);
    model_.lineariseCommittedPressures();
}

} // namespace form
