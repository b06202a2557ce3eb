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
    // The error of the central difference with step H along u
    const auto errorAt = [&](double H, vecX& err) -> bool
    {
        bool ok = true;
        try
        {
            model.addToFree(H*u);
            ok = model.evaluate(t, rp, false);
            model.addToFree(-2*H*u);
            ok = model.evaluate(t, rm, false) && ok;
        }
        catch (const numericalError&)
        {
            ok = false;
        }
        model.addToFree(H*u);
        err = (rp - rm)/(2*H) + Ku;
        return ok;
    };
    vecX err1, err2;
    const bool ok = errorAt(h, err1) && errorAt(0.1*h, err2);
    // Back to U, with the tangent the caller had
    model.evaluate(t, r, true);
    if (!ok)
    {
        res.evaluated = false;
        return res;
    }
    res.scale = Ku.norm();
    const double s = res.scale > 0 ? res.scale : 1.0;
    res.relativeH = err1.norm()/s;
    res.relativeH10 = err2.norm()/s;
    res.relative = std::min(res.relativeH, res.relativeH10);
    res.where = model.iterationNote(res.relativeH <= res.relativeH10 ? err1 : err2);
    return res;
}

} // namespace form
