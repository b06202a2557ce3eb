/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    form::checkTangentAlong: the Newton matrix against central differences
    of the residual along a Newton update (newtonTangentCheck.H)
\*---------------------------------------------------------------------------*/
#include "newtonTangentCheck.H"
#include "formError.H"
#include <algorithm>
#include <cstdio>

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
    // The central difference dr = (r(U + d) - r(U - d))/2 along the step
    // d, back at U afterwards; false if a perturbed state is inadmissible
    const auto centralDifference = [&](const vecX& d, vecX& dr) -> bool
    {
        bool ok = true;
        try
        {
            model.addToFree(d);
            ok = model.evaluate(t, rp, false);
            model.addToFree(-2*d);
            ok = model.evaluate(t, rm, false) && ok;
        }
        catch (const numericalError&)
        {
            ok = false;
        }
        model.addToFree(d);
        dr = 0.5*(rp - rm);
        return ok;
    };
    // The error of the central difference with step H along u
    const auto errorAt = [&](double H, vecX& err) -> bool
    {
        const bool ok = centralDifference(H*u, err);
        err = err/H + Ku;
        return ok;
    };
    vecX err1, err2;
    bool ok = errorAt(h, err1) && errorAt(0.1*h, err2);
    res.scale = Ku.norm();
    const double s = res.scale > 0 ? res.scale : 1.0;
    res.relativeH = ok ? err1.norm()/s : 0;
    res.relativeH10 = ok ? err2.norm()/s : 0;
    if (ok && std::min(res.relativeH, res.relativeH10) >= detailThreshold)
    {
        // The row of the largest error: its entries K_ij against central
        // differences over the columns where K's row has entries (a
        // missing term inside the pattern shows; one outside it shows as
        // a row error without a column)
        int i;
        (res.relativeH <= res.relativeH10 ? err1 : err2).cwiseAbs().maxCoeff(&i);
        const sparseMatrix Kt = model.K().transpose();
        struct column { int j; double k, fd; };
        std::vector<column> cols;
        bool columnsOk = true;
        for (sparseMatrix::InnerIterator it(Kt, i); it && columnsOk; ++it)
        {
            const int j = int(it.row());
            const double H = h*0.1;
            vecX e = vecX::Zero(dU.size());
            e(j) = H;
            vecX dr;
            columnsOk = centralDifference(e, dr);
            if (columnsOk) cols.push_back({j, it.value(), -dr(i)/H});
        }
        std::sort
        (
            cols.begin(), cols.end(),
            [](const column& a, const column& b)
            {
                return std::abs(a.k - a.fd) > std::abs(b.k - b.fd);
            }
        );
        res.detail = "row" + model.iterationNote(vecX::Unit(dU.size(), i));
        for (std::size_t c = 0; c < std::min<std::size_t>(4, cols.size()); ++c)
        {
            char buf[96];
            std::snprintf
            (
                buf, sizeof(buf), "\n          K %.6e  central difference %.6e  column",
                cols[c].k, cols[c].fd
            );
            res.detail += buf + model.iterationNote(vecX::Unit(dU.size(), cols[c].j));
        }
    }
    // Back to U, with the tangent the caller had
    model.evaluate(t, r, true);
    if (!ok)
    {
        res.evaluated = false;
        return res;
    }
    res.relative = std::min(res.relativeH, res.relativeH10);
    res.where = model.iterationNote(res.relativeH <= res.relativeH10 ? err1 : err2);
    return res;
}

} // namespace form
