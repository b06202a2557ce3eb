/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    form::checkTangentAlong: the Newton matrix against central differences
    of the residual along a Newton update (newtonTangentCheck.H)
\*---------------------------------------------------------------------------*/
#include "newtonTangentCheck.H"
#include "formError.H"
#include <algorithm>

namespace form
{

tangentCheckResult checkTangentAlong
(
    solidModel& model,
    double t,
    const vecX& dU
)
{
    tangentCheckResult res;
    const double dMax = dU.lpNorm<Eigen::Infinity>();
    if (!(dMax > 0)) return res;
    const vecX u = dU/dMax;
    const vecX Ku = model.K()*u;
    const double h =
        1e-5*std::max(1.0, model.U().lpNorm<Eigen::Infinity>());

    vecX rp(dU.size()), rm(dU.size()), r(dU.size());
    bool ok = true;
    try
    {
        model.addToFree(h*u);
        ok = model.evaluate(t, rp, false);
        model.addToFree(-2*h*u);
        ok = model.evaluate(t, rm, false) && ok;
    }
    catch (const numericalError&)
    {
        ok = false;
    }
    model.addToFree(h*u);
    // Back to U, with the tangent the caller had
    model.evaluate(t, r, true);
    if (!ok)
    {
        res.evaluated = false;
        return res;
    }
    const vecX err = (rp - rm)/(2*h) + Ku;
    res.scale = Ku.norm();
    res.relative = res.scale > 0 ? err.norm()/res.scale : err.norm();
    res.where = model.iterationNote(err);
    return res;
}

} // namespace form
