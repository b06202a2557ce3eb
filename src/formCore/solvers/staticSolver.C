/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    One load step by full Newton-Raphson with line search (see
    staticSolver.H; Bathe, Finite Element Procedures, 2nd ed., sec. 8.4):
    the predictor, the start-state tests, the iteration and its
    convergence criteria. The time loop and cutback: staticSolverRun.C;
    the line searches: staticSolverLineSearch.C; the evaluations, linear
    solves and kept tangents: staticSolverLinear.C.
\*---------------------------------------------------------------------------*/
#include "staticSolver.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace form
{

namespace
{

std::string fmt(const char* format, double a)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), format, a);
    return buf;
}

// Step failure inside the Newton loop: turned into "return false"
struct stepFailure : public numericalError
{
    using numericalError::numericalError;
};

// Loads held in a step: the start state's residuals with the loads of t0
// and of t1 differ by round-off only (relative to the force level)
constexpr double heldLoadTolerance = 1e-12;

// The round-off floors of the two acceptance rules below (a residual or
// an energy that stagnates at round-off), relative to the force level and
// to the first energy: the square roots of the tolerance, but never wider
// than those of the default tolerances (1e-8, 1e-14). A looser tolerance
// does not make a larger residual round-off: at forceTolerance 1e-3 the
// square root would accept 3e-2 of the force level.
constexpr double roundOffForceFloor = 1e-4;
constexpr double roundOffEnergyFloor = 1e-7;
// An update this small against the state (|dU| <= floor |U|: ~5000 eps)
// changes nothing a double can hold
constexpr double roundOffUpdateFloor = 1e-12;

} // namespace


bool staticSolver::newton(double t0, double t1, stepReport& report)
{
    const int nFree = model_.nUnknowns();
    vecX r;
    model_.beginIncrement(t0, t1);

    // Force level of the equilibrium tests: loads, reactions and the
    // reference under which the committed state was accepted
    const auto level = [&]()
    {
        return std::max
        (
            {
                model_.externalForceNorm(), model_.reactionNorm(),
                model_.forceLevel()
            }
        );
    };

    // Extrapolating predictor: the last increment scaled to this step
    bool predicted = false;
    vecX predictedIncrement;
    bool predict =
        newton_.extrapolate && lastIncrement_.size() == model_.state().size()
     && lastDeltaT_ > 0;
    // A step with nothing to do (a held load, a dwell) must not be
    // pushed off its equilibrium by the last increment: when no
    // prescribed dof moves, the start state is checked first (one
    // residual, no tangent) and accepted if it is in equilibrium and the
    // loads did not change: its residual with the loads of t0 is the same
    // (to round-off). Under a slowly ramped load (the bulge's pressure
    // control at forceTolerance 1e-3) a small increment would otherwise
    // pass the force test step after step with no iteration, and the
    // energy criterion, which needs an update, would never be checked.
    // (r1: the residual of the state with the loads of t1)
    const auto loadsHeld = [&](const vecX& r1)
    {
        vecX rt0;
        return
            evaluate(t0, rt0, false)
         && (r1 - rt0).norm() <= heldLoadTolerance*level();
    };
    if (predict && nFree > 0 && model_.prescribedIncrement(t1).norm() == 0)
    {
        if
        (
            evaluate(t1, r, false) && r.norm() <= newton_.forceTolerance*level()
         && loadsHeld(r)
        )
        {
            report.residualNorms.push_back(r.norm());
            report.updateNorms.push_back(0);
            report.energyNorms.push_back(0);
            lastResidual_ = r.norm();
            char note[160];
            std::snprintf
            (
                note, sizeof(note),
                "    equilibrium at the start state: |r| %.3e <= forceTolerance"
                " * %.3e\n", r.norm(), level()
            );
            log_<< note;
            model_.setForceLevel(level());
            report.iterations = 0;
            return true;
        }
        model_.revert();
        model_.beginIncrement(t0, t1);
    }
    if (predict)
    {
        const double h = t1 - t0;
        // predicted increment = c1 dU1 + c2 dU2 (last, previous): the
        // element pressures are extrapolated with the same weights
        double c1 = h/lastDeltaT_, c2 = 0;
        if
        (
            newton_.quadratic && previousDeltaT_ > 0
         && previousIncrement_.size() == lastIncrement_.size()
        )
        {
            // Newton form through (t0 - h1 - h2, t0 - h1, t0): with the
            // slopes d1 = dU1/h1, d0 = dU2/h2 (last, previous) the
            // quadratic gives U(t0 + h) = U0 + h d1 + h (h + h1)
            // (d1 - d0)/(h1 + h2)
            const double h1 = lastDeltaT_, h2 = previousDeltaT_;
            const vecX d1 = lastIncrement_/h1;
            const vecX d0 = previousIncrement_/h2;
            predictedIncrement = h*d1 + (h*(h + h1)/(h1 + h2))*(d1 - d0);
            const double q = h*(h + h1)/(h1 + h2);
            c1 = (h + q)/h1;
            c2 = -q/h2;
        }
        else
        {
            predictedIncrement = (h/lastDeltaT_)*lastIncrement_;
        }
        // Unknowns whose increments do not carry over (contact forces)
        // stay at their committed values
        model_.keepCommitted(predictedIncrement, previousIncrement_);
        model_.addToState(predictedIncrement);
        // The prescribed dofs at their values of t1: the predicted free
        // dofs moved with them, and a state with the free dofs moved but
        // the prescribed ones left behind would strain the elements at a
        // prescribed boundary by a whole increment (bending under a
        // prescribed end rotation turned the tangent indefinite)
        model_.applyPrescribed(t1);
        // (linearised: the committed linearisations stay active)
        using pp = newtonControls::pressurePrediction;
        if (newton_.pressurePredictor == pp::extrapolated)
        {
            model_.predictPressure(c1, c2);
        }
        else if (newton_.pressurePredictor == pp::projected)
        {
            model_.forgetPressureLinearisation();
        }
        predicted = true;
    }

    // Residual at the committed (or predicted) state with the loads of t1
    const vecX dUp = model_.prescribedIncrement(t1);
    bool ok0 = evaluate(t1, r, nFree > 0);
    if (!ok0 && predicted)
    {
        log_<< "    extrapolated state not admissible: predictor dropped\n";
        model_.revert();
        model_.beginIncrement(t0, t1);
        predicted = false;
        ok0 = evaluate(t1, r, nFree > 0);
    }
    if (!ok0)
    {
        throw stepFailure
        (
            lastFailure_.empty()
          ? "material update failed at the start of the step"
          : lastFailure_
        );
    }

    // Consistent predictor (FEP sec. 8.4): the prescribed increment enters
    // the first right-hand side as -K_fp dU_p, so the first update already
    // carries the elastic response to the imposed motion
    vecX rhs = r;
    if (nFree > 0 && dUp.size() > 0)
    {
        // Contact unknowns (after the free dofs) get no predictor term
        rhs.head(model_.nFreeDofs()).noalias() -= model_.Kfp()*dUp;
    }
    model_.applyPrescribed(t1);

    const double r0 = rhs.norm();
    // Force level at the start of the step: divergence is measured against
    // it (the reactions of a diverging iterate grow with its residual)
    const double startRef = std::max
    (
        {r0, model_.externalForceNorm(), model_.reactionNorm()}
    );
    report.residualNorms.push_back(r0);
    report.updateNorms.push_back(0);
    report.energyNorms.push_back(0);
    lastResidual_ = r0;

    char line[160];
    std::snprintf
    (
        line, sizeof(line), "    iter %2d  |r| %.3e  |dU_p| %.3e%s",
        0, r0, dUp.norm(), predicted ? "  predicted" : ""
    );
    // Where the start state is out of balance (per block, largest entry)
    log_<< line << model_.iterationNote(r) << '\n';

    // Energy reference of a predicted step: the work of the predicted
    // increment on the tangent, dU_pred . K_ff dU_pred (for a step
    // without prediction the reference dU^(1) . r^(0) is the same form,
    // dU^(1) = K^-1 r^(0)); the first update of a good prediction is small
    // and no reference for the step
    const auto predictedWork = [&]()
    {
        const std::vector<int>& free = model_.freeDofs();
        vecX v(free.size());
        for (std::size_t i = 0; i < free.size(); ++i)
        {
            v(i) = predictedIncrement(free[i]);
        }
        return std::abs(v.dot(model_.Kff()*v));
    };
    double predictedEnergy = 0;

    // A step may start in equilibrium: a linear response reached by the
    // predictor, a steady stretch of a forming process, or a step with
    // nothing to do (loads held, a dwell). The force criterion: ||r0|| <=
    // forceTol * L with L = max(||f_ext||, ||R||, F_c), F_c the force
    // reference under which the committed state was accepted (L does not
    // vanish when the increment does). The energy criterion needs an
    // update, so the state is accepted with no iteration only where it
    // can be judged without one:
    // - a predicted state: the energy of the update from it (its
    //   factorisation is iteration 1's if the state is not accepted)
    //   against the predicted increment's work;
    // - an unmoved state (no prediction, no prescribed increment) whose
    //   loads did not change: the committed state, already accepted.
    // Otherwise a small load increment would pass the force test with no
    // iteration (the bulge's pressure control at forceTolerance 1e-3 fell
    // behind its load step after step).
    vecX firstUpdate;
    bool firstKept = false;
    if (nFree > 0 && r0 <= newton_.forceTolerance*level())
    {
        // r0 is linearised in the prescribed increment: evaluate at the
        // state with it applied, which also gives the reactions of this
        // state (they were those before the increment)
        if (!evaluate(t1, r, true))
        {
            throw stepFailure("material update failed");
        }
        const double r1 = r.norm();
        const double level1 = level();
        bool accept = false;
        double energyRatio = -1;
        if (r1 <= newton_.forceTolerance*level1)
        {
            if (predicted)
            {
                predictedEnergy = predictedWork();
                firstUpdate = newtonUpdate(t1, r, firstKept);
                const double e = std::abs(firstUpdate.dot(r));
                energyRatio = predictedEnergy > 0 ? e/predictedEnergy : 1;
                accept =
                    e == 0 || energyRatio <= newton_.energyTolerance;
            }
            else if (dUp.norm() == 0)
            {
                accept = loadsHeld(r);
            }
        }
        if (accept)
        {
            char note[200];
            std::snprintf
            (
                note, sizeof(note),
                "    equilibrium at the %s state: |r| %.3e <= forceTolerance"
                " * %.3e%s\n",
                predicted ? "predicted" : "start", r1, level1,
                predicted
              ? fmt(", energy of the update %.3e <= energyTolerance", energyRatio).c_str()
              : ", loads unchanged"
            );
            log_<< note;
            model_.setForceLevel(level1);
            report.iterations = 0;
            return true;
        }
        rhs = r;
    }
    // A step that starts close to equilibrium (||r0|| <= sqrt(forceTol)
    // times the load and reaction level, e.g. a small change of load): its
    // first update is small, so the energy ratio has no reference and the
    // force criterion alone decides, as long as the premise holds: an
    // update carrying more work than the reference (the predicted
    // increment's, or the first step's) is not small. A coupled block's
    // scale raises the load level (a fluid's: the magnitudes of its
    // terms), and the ALE oil at fast injection was accepted in one
    // iteration with an update of 9 times the predicted work and the oil
    // at 124 m/s (2026-11-29)
    const double loadLevel =
        std::max(model_.externalForceNorm(), model_.reactionNorm());
    const bool nearEquilibrium =
        r0 <= std::sqrt(newton_.forceTolerance)*loadLevel;
    if (predicted && nFree > 0 && firstUpdate.size() == 0)
    {
        predictedEnergy = predictedWork();
    }

    if (nFree == 0)
    {
        if (!evaluate(t1, r, false))
        {
            throw stepFailure("material update failed");
        }
        report.iterations = 0;
        return true;
    }

    // The step's own scale in the force reference: the first right-hand
    // side, unless it belongs to a predicted state. A prediction that is
    // off in a stiff direction (nearly incompressible material: the
    // extrapolated displacements violate the constraint at second order
    // in the step, times the bulk modulus) has a residual far above the
    // load level; it must not loosen the tolerance. It is then capped by
    // the level under which the last step was accepted.
    const double stepRef = predicted ? std::min(r0, model_.forceLevel()) : r0;

    double energy1 = 0;
    double rPrevNorm = r0;
    // residual norms of the step's iterates, for a non-monotone search
    std::vector<double> recent{rhs.norm()};
    // The iteration limit; a step caught by it inside Newton's quadratic
    // basin gets a few more iterations (below)
    int limit = newton_.maxIterations;
    for (int i = 1; i <= limit; ++i)
    {
        // (the first update may be computed already: the start state's
        // energy test above)
        bool kept = firstKept;
        const vecX dU =
            i == 1 && firstUpdate.size() > 0
          ? firstUpdate : newtonUpdate(t1, rhs, kept);
        if (newton_.checkTangent)
        {
            const tangentCheckResult c = checkTangentAlong(model_, t1, dU);
            char buf[128];
            std::snprintf
            (
                buf, sizeof(buf),
                "      tangent check: |dr/dh + K u|/|K u| %.3e (h %.2e, h/10 %.2e)",
                c.relative, c.relativeH, c.relativeH10
            );
            log_<< buf
                << (c.evaluated ? c.where : "  (perturbed state not admissible)")
                << '\n';
            if (!c.detail.empty()) log_<< "        " << c.detail << '\n';
            ++nChecks_;
            if (c.evaluated && c.relative >= worstCheck_.relative)
            {
                worstCheck_ = c;
                worstCheckTime_ = t1;
                worstCheckIteration_ = i;
            }
        }

        model_.addToFree(dU);
        bool ok = evaluate(t1, r, true);
        double beta = 1;
        // No line search once an update carries negligible energy (the
        // energy criterion already holds): its residual is round-off
        const bool negligible =
            i > 1
         && std::abs(dU.dot(rhs)) <= newton_.energyTolerance*energy1;
        bool search = newton_.lineSearch && !negligible;
        // The residual norm the backtracking must go below (non-monotone:
        // the largest of the last lineSearchMemory + 1)
        const double rRef = *std::max_element
        (
            recent.end()
          - std::min<std::ptrdiff_t>
            (
                recent.size(), newton_.lineSearchMemory + 1
            ),
            recent.end()
        );
        // The tracked pressure (solidElement.H): a full step that the
        // energy line search would damp is taken if the residual with the
        // mixed system's own pressure update accepts it, where the residual
        // is mostly kappa times the step's second-order volume error (the
        // difference of the two is more than half of it)
        if (search && ok && !newton_.residualLineSearch && model_.tracksPressure())
        {
            const vecX rt = model_.trackedResidual(r);
            if
            (
                (r - rt).norm() > 0.5*r.norm()
             && !fullStepAccepted(dU, rhs, r, rRef)
             && fullStepAccepted(dU, rhs, rt, rRef)
            )
            {
                search = false;
            }
        }
        if (search)
        {
            ok =
                newton_.residualLineSearch
              ? residualLineSearch(t1, dU, rRef, ok, r, beta)
              : lineSearch(t1, dU, rhs, ok, r, beta);
        }
        if (!ok)
        {
            throw stepFailure
            (
                "iteration " + std::to_string(i) + ": "
              + (
                    lastFailure_.empty()
                  ? std::string("material update failed")
                  : lastFailure_
                )
            );
        }

        // Convergence (FEP eqs. 8.xx): out-of-balance force relative to
        // the force level, and the energy of this update relative to the
        // first one
        // (header: the step taken or, if the line search cut it, the
        // energy still to go, whichever is larger)
        const double energyFull = std::abs(dU.dot(rhs));
        const double energy =
            std::max(beta, (1 - beta)*(1 - beta))*energyFull;
        // The reference: the work of the first step taken (or of the
        // predicted increment)
        if (i == 1)
        {
            energy1 = predictedEnergy > 0 ? predictedEnergy : beta*energyFull;
        }
        const double energyRatio = energy1 > 0 ? energy/energy1 : 0;
        // The work of the step taken, beta |dU.r| (the measure of the
        // round-off rule below: a stagnating iterate's line search takes
        // random beta)
        const double takenRatio = energy1 > 0 ? beta*energyFull/energy1 : 0;
        const double rNorm = r.norm();
        const double ref = std::max
        (
            {model_.externalForceNorm(), model_.reactionNorm(), stepRef}
        );
        const double rRel = ref > 0 ? rNorm/ref : rNorm;
        const double dUNorm = beta*dU.norm();

        report.residualNorms.push_back(rNorm);
        recent.push_back(rNorm);
        report.updateNorms.push_back(dUNorm);
        report.energyNorms.push_back(beta*energyFull);   // the work taken
        report.iterations = i;
        lastResidual_ = rNorm;

        std::snprintf
        (
            line, sizeof(line),
            "    iter %2d  |r| %.3e  |r|/ref %.3e  |dU| %.3e  energy %.3e"
            "  beta %.3g",
            i, rNorm, rRel, dUNorm, energyRatio, beta
        );
        log_<< line << (kept ? "  kept" : "") << model_.iterationNote(r)
            << '\n';

        if (!std::isfinite(rNorm))
        {
            throw stepFailure("non-finite residual");
        }
        const bool converged =
            rNorm <= newton_.absoluteForceTolerance
         || (
                rNorm <= newton_.forceTolerance*ref
             && (
                    (nearEquilibrium && energyRatio <= 1)
                 || energyRatio <= newton_.energyTolerance
                )
            );
        // The force criterion holds, the energy criterion not yet: the
        // energy of the next update, from the factors at hand, decides
        // (header). At the first iteration of an unpredicted step (its
        // energy ratio is 1 by definition) and after a full Newton step
        // (beta = 1: inside the quadratic basin, where the factors of the
        // last iterate are those of a close tangent)
        if
        (
            !converged && !nearEquilibrium && energy1 > 0
         && rNorm <= newton_.forceTolerance*ref
         && (i == 1 ? !predicted : beta == 1)
        )
        {
            const double next = std::abs(solveAgain(r).dot(r))/energy1;
            if (next <= newton_.energyTolerance)
            {
                std::snprintf
                (
                    line, sizeof(line),
                    "    energy of the next update (factors of iteration %d)"
                    " %.3e <= energyTolerance: converged\n", i, next
                );
                log_<< line;
                model_.setForceLevel(ref);
                return true;
            }
        }
        // Round-off floor: the energy criterion holds, the residual no
        // longer decreases and is small. Nearly incompressible materials
        // put this floor (~ eps kappa |Omega|, independent of the load)
        // above forceTolerance*ref at low load levels; the state cannot be
        // improved in double precision, so the step is accepted and the
        // log says why.
        const bool roundOff =
            !converged
         && i > 1
         && energyRatio <= newton_.energyTolerance
         && rNorm > 0.5*rPrevNorm
         && rNorm
         <= std::min(std::sqrt(newton_.forceTolerance), roundOffForceFloor)*ref;
        // The converse floor: the force criterion holds with a tenfold
        // margin, |r| no longer decreases, and the energy ratio stalls
        // between sqrt(energyTol) and energyTol: the update is round-off
        // (|dU| ~ 1e-16 of the state) against a small energy reference
        // (a short predicted step, whose reference is the predicted
        // increment's work: hemming's flanging at 1e-5 steps)
        const bool energyRoundOff =
            !converged && !roundOff
         && i > 1
         && rNorm <= 0.1*newton_.forceTolerance*ref
         && rNorm > 0.5*rPrevNorm
         && takenRatio
         <= std::min(std::sqrt(newton_.energyTolerance), roundOffEnergyFloor);
        // The same floor seen in the update itself: the force criterion
        // holds tenfold, |r| no longer decreases, and the update is
        // round-off of the state. Free of the energy reference, which a
        // predicted increment that does almost no work makes meaningless
        // (a strip drawn rigidly: its energy ratios of 1e23 at the first
        // iterations, and a floor that depends on the BLAS kernels'
        // rounding)
        const bool updateRoundOff =
            !converged && !roundOff && !energyRoundOff
         && i > 1
         && rNorm <= 0.1*newton_.forceTolerance*ref
         && rNorm > 0.5*rPrevNorm
         && dUNorm <= roundOffUpdateFloor*model_.U().norm();
        if (roundOff)
        {
            log_<< "    force residual at round-off level (energy converged,"
                   " |r| stagnates): accepted\n";
        }
        if (updateRoundOff)
        {
            log_<< "    update at round-off level of the state (force"
                   " converged tenfold, |r| stagnates): accepted\n";
        }
        if (energyRoundOff)
        {
            log_<< "    energy at round-off level (force converged tenfold,"
                   " |r| stagnates): accepted\n";
        }
        // Stalled at the force tolerance: the force criterion holds and
        // the line search found no step along Newton's direction that
        // reduces the residual (beta cut to its floor). The energy of the
        // update then sits in a direction the residual does not see (the
        // non-unique multipliers of two-pass contact, where both sides
        // press the same points): the state cannot be improved.
        // Only where the update carries no more work than the reference
        // (energy ratio at most 1): a stalled line search with an update
        // larger than the step's first is a Newton method that has lost
        // its way, not a converged state (the ALE bulge at fast injection
        // was accepted with the oil at 130 m/s and updates of hundreds of
        // times the reference work: its residual, 1e-4 of the fluid's
        // scale, passed the force criterion of 1e-2, 2026-11-29). Not
        // sqrt(energyTol): a reference near zero (a strip drawn rigidly,
        // whose predicted increment does no work) makes round-off
        // updates look large against it
        const bool forceStalled =
            !converged && !roundOff && !energyRoundOff && !updateRoundOff
         && i > 1
         && newton_.lineSearch
         && beta <= std::pow(0.5, newton_.maxLineSearchIterations)
         && rNorm >= 0.99*rPrevNorm
         && rNorm <= newton_.forceTolerance*ref;
        const bool stalled = forceStalled && energyRatio <= 1;
        if (stalled)
        {
            log_<< "    force criterion holds and no line-search step reduces"
                   " |r|: accepted\n";
        }
        else if (forceStalled)
        {
            std::snprintf
            (
                line, sizeof(line),
                "    force criterion holds and no line-search step reduces"
                " |r|, but the update's energy ratio %.3e > 1: not"
                " converged\n", energyRatio
            );
            log_<< line;
        }
        if (converged || roundOff || energyRoundOff || updateRoundOff || stalled)
        {
            model_.setForceLevel(ref);
            return true;
        }
        // At the limit inside the quadratic basin (a full step that cut
        // ||r|| a hundredfold, ||r|| within sqrt(forceTol) of the
        // reference): one more iteration, up to 5 beyond maxIterations,
        // instead of a cutback that would throw the step's work away
        if
        (
            i == limit && limit < newton_.maxIterations + 5
         && beta == 1 && rNorm <= 0.01*rPrevNorm
         && rNorm <= std::sqrt(newton_.forceTolerance)*ref
        )
        {
            ++limit;
            log_<< "    converging quadratically at the iteration limit:"
                   " one more iteration\n";
        }
        // Kept factors that no longer contract the residual fast enough,
        // or whose step the line search shortened: a new tangent for the
        // next update (header)
        if
        (
            kept
         && (beta < 1 || rNorm > newton_.keptTangentContraction*rPrevNorm)
        )
        {
            refreshTangent_ = true;
        }
        rPrevNorm = rNorm;
        if (rNorm > newton_.divergenceFactor*startRef)
        {
            throw stepFailure
            (
                "residual diverged (|r| = " + fmt("%.3e", rNorm)
              + " > divergenceFactor * " + fmt("%.3e", startRef)
              + ")"
            );
        }
        rhs = r;
    }
    throw stepFailure
    (
        "not converged in maxIterations = "
      + std::to_string(newton_.maxIterations)
      + (limit > newton_.maxIterations
          ? " (+" + std::to_string(limit - newton_.maxIterations)
          + " in the quadratic basin)" : std::string())
    );
}

} // namespace form
