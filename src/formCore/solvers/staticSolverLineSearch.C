/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The line searches of staticSolver (see staticSolver.H): the energy line
    search (Bathe, Finite Element Procedures, 2nd ed., sec. 8.4.2), the
    residual-norm backtracking, and the test whether the full step is taken
    at once (the tracked pressure of the mixed elements, solidElement.H).
\*---------------------------------------------------------------------------*/
#include "staticSolver.H"
#include <algorithm>
#include <cmath>
#include <limits>

namespace form
{

bool staticSolver::fullStepAccepted
(
    const vecX& dU,
    const vecX& r0,
    const vecX& r,
    double rRef
) const
{
    if (newton_.residualLineSearch) return r.norm() <= (1 - 1e-4)*rRef;
    const double s0 = dU.dot(r0);
    const double s1 = dU.dot(r);
    return std::abs(s1) <= newton_.lineSearchTolerance*std::abs(s0) || s1*s0 > 0;
}


// FEP sec. 8.4.2: find beta with |dU . r(U0 + beta dU)| <= tol |dU . r(U0)|
// by regula falsi with the Illinois modification on the bracket [0, 1]
// (the full step is tried first). A failed evaluation (inverted element,
// failed material update) is treated as "too far" and bisected.
bool staticSolver::lineSearch
(
    double t,
    const vecX& dU,
    const vecX& r0,
    bool ok,
    vecX& r,
    double& beta
)
{
    beta = 1;
    const double s0 = dU.dot(r0);
    double s1 = ok ? dU.dot(r) : 0;
    if (ok && std::abs(s1) <= newton_.lineSearchTolerance*std::abs(s0))
    {
        return true;
    }
    // Still descending at the full step: maxBeta limits the step (no
    // extrapolation beyond it)
    if (ok && s1*s0 > 0)
    {
        if (newton_.maxBeta <= 1) return true;
    }

    double bLo = 0, sLo = s0;
    double bHi = 1, sHi = s1;
    bool hiValid = ok;
    int lastSide = 0;
    double current = 1;

    if (ok && s1*s0 > 0)
    {
        // Extrapolate towards maxBeta until the sign changes
        bLo = 1; sLo = s1;
        bHi = newton_.maxBeta;
        model_.addToFree((bHi - current)*dU);
        current = bHi;
        hiValid = evaluate(t, r, false);
        if (hiValid) sHi = dU.dot(r);
        if (hiValid && sHi*s0 > 0)
        {
            beta = current;
            return evaluate(t, r, true);
        }
    }

    bool found = false;
    bool currentValid = hiValid;
    for (int k = 0; k < newton_.maxLineSearchIterations; ++k)
    {
        double b;
        if (!hiValid)
        {
            b = 0.5*(bLo + bHi);
        }
        else
        {
            b = bHi - sHi*(bHi - bLo)/(sHi - sLo);
            const double w = bHi - bLo;
            b = std::min(std::max(b, bLo + 0.05*w), bHi - 0.05*w);
        }
        model_.addToFree((b - current)*dU);
        current = b;
        currentValid = evaluate(t, r, false);
        if (!currentValid)
        {
            bHi = b;
            hiValid = false;
            continue;
        }
        const double s = dU.dot(r);
        if (std::abs(s) <= newton_.lineSearchTolerance*std::abs(s0))
        {
            found = true;
            break;
        }
        if (s*s0 > 0)
        {
            bLo = b; sLo = s;
            if (lastSide == -1 && hiValid) sHi *= 0.5;
            lastSide = -1;
        }
        else
        {
            bHi = b; sHi = s; hiValid = true;
            if (lastSide == 1) sLo *= 0.5;
            lastSide = 1;
        }
    }
    if (!found && !currentValid)
    {
        // Fall back to the largest admissible point of the bracket
        if (bLo <= 0) return false;
        model_.addToFree((bLo - current)*dU);
        current = bLo;
    }
    beta = current;
    return evaluate(t, r, true);
}


bool staticSolver::residualLineSearch
(
    double t,
    const vecX& dU,
    double r0,
    bool ok,
    vecX& r,
    double& beta
)
{
    beta = 1;
    double rNorm = ok ? r.norm() : std::numeric_limits<double>::infinity();
    if (ok && rNorm <= (1 - 1e-4)*r0) return true;
    double bestBeta = ok ? 1.0 : 0.0;
    double best = ok ? rNorm : std::numeric_limits<double>::infinity();
    double current = 1;
    for (int k = 0; k < newton_.maxLineSearchIterations; ++k)
    {
        const double b = 0.5*current;
        model_.addToFree((b - current)*dU);
        current = b;
        if (!evaluate(t, r, false)) continue;
        rNorm = r.norm();
        if (rNorm < best)
        {
            best = rNorm;
            bestBeta = b;
        }
        if (rNorm <= (1 - 1e-4*b)*r0) break;
    }
    if (bestBeta <= 0) return false;
    model_.addToFree((bestBeta - current)*dU);
    beta = bestBeta;
    return evaluate(t, r, true);
}

} // namespace form
