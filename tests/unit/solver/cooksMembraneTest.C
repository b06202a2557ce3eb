// Cook's membrane with the real elements and materials through solidModel
// and staticSolver (references: BENCHMARKS.md).
#include "cooksMembrane.H"
#include "staticSolver.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

using namespace form;
using namespace form::test;

namespace
{

// Linear Cook's: lambda = 7500, G = 0.375, total shear F = 1 on the right
// edge of length 16. One step: the linear solution, with what it cost
struct linearRun
{
    double v = 0;
    int iterations = 0;
    int factorisations = 0;
    std::string log;
};

linearRun linearCookRun(const std::string& element, int N, double nu = -1)
{
    double E, nuL;
    lameToEnu(7500, 0.375, E, nuL);
    if (nu > 0)
    {
        E = 2*0.375*(1 + nu);
        nuL = nu;
    }
    cooksMembrane c(element, N, "linearElastic", E, nuL, 1.0/16);
    auto solver = linearSolver::New("cholmod");
    stepControls sc;
    sc.deltaT = 1;
    std::ostringstream log;
    staticSolver s(*c.model, *solver, {}, sc, log);
    s.run(nullptr);
    return {c.v(), s.totalIterations(), c.model->times().factorisations, log.str()};
}

double linearCook(const std::string& element, int N, double nu = -1)
{
    return linearCookRun(element, N, nu).v;
}

std::vector<double> rates(const std::vector<double>& r)
{
    std::vector<double> out;
    for (std::size_t k = 1; k + 1 < r.size(); ++k)
    {
        const double a = r[k]/r[0], b = r[k + 1]/r[0];
        if (a < 1e-2 && b > 1e-13) out.push_back(std::log(b)/std::log(a));
    }
    return out;
}

} // namespace


TEST(cooksMembrane, LameConversionIsExact)
{
    double E, nu;
    lameToEnu(7500, 0.375, E, nu);
    EXPECT_NEAR(E/(2*(1 + nu)), 0.375, 1e-15);
    EXPECT_NEAR(E*nu/((1 + nu)*(1 - 2*nu)), 7500, 1e-8);
}


TEST(cooksMembrane, Q9P3LinearWithinFiveHundredthsOfAPercent)
{
    // observed error 0.011 %; 0.05 % fails Q9P3 on 4 x 4 and the
    // displacement Q9 on 64 x 64 (a looser 1 % passed both)
    const double v = linearCook("Q9P3", 16);
    std::cout << "Cook's linear, Q9P3 16x16: v(48,52) = " << v
              << "  (reference 16.4326)\n";
    EXPECT_NEAR(v, 16.4326, 5e-4*16.4326);
}


TEST(cooksMembrane, LinearProblemTakesOneFactorisation)
{
    // staticSolver.H: the first iteration meets the force criterion and
    // the energy of the next update, from the factors at hand, decides
    const linearRun r = linearCookRun("Q9P3", 16);
    EXPECT_EQ(r.iterations, 1) << r.log;
    EXPECT_EQ(r.factorisations, 1);
    EXPECT_NE(r.log.find("energy of the next update"), std::string::npos) << r.log;
    EXPECT_NEAR(r.v, 16.4326, 5e-4*16.4326);
}


TEST(cooksMembrane, Q4LinearLocks)
{
    const double v = linearCook("Q4", 16);
    std::cout << "Cook's linear, Q4 16x16: v(48,52) = " << v << '\n';
    EXPECT_GT(v, 0);
    EXPECT_LT(v, 0.5*16.4326);
}


TEST(cooksMembrane, Q9P3NearlyIncompressibleConverges)
{
    // nu = 0.49999: the Q9P3 answer stays at the incompressible reference
    const double v = linearCook("Q9P3", 16, 0.49999);
    std::cout << "Cook's linear, Q9P3 16x16, nu = 0.49999: v = " << v << '\n';
    EXPECT_NEAR(v, 16.4326, 5e-4*16.4326);      // observed 0.013 %

    // neo-Hookean with the same small-strain moduli (kappa/G = 5e4) at a
    // tenth of the load (rotations ~ 0.03): converges, and agrees with
    // the linear solution on the same mesh to the order of the rotation
    const double nu = 0.49999, E = 2*0.375*(1 + nu);
    const double vLinear = 0.1*linearCook("Q9P3", 8, nu);
    cooksMembrane c("Q9P3", 8, "neoHookean", E, nu, 0.1/16);
    auto solver = linearSolver::New("cholmod");
    stepControls sc;
    sc.deltaT = 0.5;
    std::ostringstream log;
    staticSolver s(*c.model, *solver, {}, sc, log);
    std::vector<stepReport> reports;
    ASSERT_NO_THROW(s.run([&](const stepReport& r) { reports.push_back(r); }))
        << log.str();
    ASSERT_FALSE(reports.empty());
    EXPECT_EQ(reports.back().time, 1.0);
    std::cout << "Cook's neo-Hookean, Q9P3 8x8, nu = 0.49999, F = 0.1: v = "
              << c.v() << " (linear " << vLinear << ") in " << reports.size()
              << " steps, " << s.totalIterations() << " Newton iterations\n";
    EXPECT_NEAR(c.v(), vLinear, 0.03*vLinear);
}


namespace
{
// Cook's neo-Hookean run with or without the tracked pressure of the
// mixed elements (solidElement.H); returns the Newton iterations and the
// tip deflection
std::pair<int, double> neoHookeanCook(bool tracked)
{
    // E = 240.565, nu = 0.4999 (kappa/G = 5000), shear traction 6.25 per
    // unit length (total 100), 10 load steps. umfpack: intermediate Newton
    // iterates of such steps can have an indefinite tangent (large
    // compressive pressures in the geometric stiffness), which CHOLMOD
    // rejects (the step would then be cut back).
    cooksMembrane c("Q9P3", 16, "neoHookean", 240.565, 0.4999, 6.25);
    auto solver = linearSolver::New("umfpack");
    stepControls sc;
    sc.deltaT = 0.1;
    sc.growthFactor = 1;
    std::ostringstream log;
    staticSolver s(*c.model, *solver, {}, sc, log);
    c.model->setPressureTracking(tracked);
    std::vector<stepReport> reports;
    EXPECT_NO_THROW(s.run([&](const stepReport& r) { reports.push_back(r); }))
        << log.str();
    std::cout << log.str();
    EXPECT_EQ(reports.size(), 10u);
    EXPECT_EQ(reports.back().time, 1.0);
    for (const stepReport& r : reports)
    {
        EXPECT_EQ(r.cutbacks, 0);
        EXPECT_LE(r.iterations, 12);

        // The residual norm drops by > 8 orders from its peak (the force
        // tolerance 1e-8 of a load level below the peak; the look-ahead
        // of staticSolver.H accepts an iterate once the force criterion
        // holds and the next update's energy is negligible, so the last
        // residual is not the round-off floor ~ eps kappa)
        const double peak = *std::max_element
        (
            r.residualNorms.begin(), r.residualNorms.end()
        );
        EXPECT_LT(r.residualNorms.back(), 1e-8*peak) << "step " << r.step;

        // Asymptotic rate in the energy norm |dU.r| (relative to the first
        // update): the last two rates of the quadratic range lie near 2.
        // (||r|| itself is dominated by the stiff volumetric modes and
        // reaches its round-off floor ~1e-9 after one quadratic step.)
        // With the tracked pressure the end is faster than quadratic (the
        // pressure error of the iterate is gone with the update before).
        std::vector<double> e;
        for (std::size_t k = 1; k < r.energyNorms.size(); ++k)
        {
            e.push_back(r.energyNorms[k]/r.energyNorms[1]);
        }
        std::vector<double> q;
        for (std::size_t k = 0; k + 1 < e.size(); ++k)
        {
            if (e[k] < 1e-2 && e[k + 1] > 1e-30)
            {
                q.push_back(std::log(e[k + 1])/std::log(e[k]));
            }
        }
        if (!tracked)
        {
            EXPECT_GE(q.size(), 2u) << "step " << r.step;
            for (std::size_t k = q.size() < 2 ? 0 : q.size() - 2; k < q.size(); ++k)
            {
                EXPECT_GT(q[k], 1.6) << "step " << r.step;
                EXPECT_LT(q[k], 2.4) << "step " << r.step;
            }
        }
        else
        {
            // Too fast for two rates (energy 4e-2 -> 1e-11 in one
            // update): the last update is at least quadratic in the one
            // before, d_last <= 10 d_prev^2 (d: |dU| relative to the first)
            const std::vector<double>& d = r.updateNorms;
            EXPECT_GE(d.size(), 3u) << "step " << r.step;
            if (d.size() < 3) continue;
            const double d1 = d[d.size() - 2]/d[1];
            const double d2 = d.back()/d[1];
            EXPECT_LT(d2, 10*d1*d1) << "step " << r.step;
        }
    }
    std::cout << "Cook's neo-Hookean (E 240.565, nu 0.4999, 6.25), Q9P3 16x16:"
              << " v(48,52) = " << c.v() << ", "
              << s.totalIterations() << " Newton iterations\n";
    // Large deformation stiffens the cantilever-like panel: v lies below
    // the small-strain value for these moduli and load, 16.4326 * (100/1)
    // * (0.375/G) with G = E/(2(1 + nu)) = 80.19 (about 7.68), by less
    // than 20%
    const double vSmall = 16.4326*100*0.375/(240.565/(2*1.4999));
    EXPECT_LT(c.v(), vSmall);
    EXPECT_GT(c.v(), 0.8*vSmall);
    const phaseTimes& t = c.model->times();
    std::cout << "  assembly " << t.assembly << " s, factorisation "
              << t.factorisation << " s, solve " << t.solve << " s\n";
    return {s.totalIterations(), c.v()};
}
}


TEST(cooksMembrane, NeoHookeanLargeDeformationConvergesQuadratically)
{
    // The tracked pressure changes the Newton path, not the solution, and
    // saves iterations (observed 87 -> 31 with these zero-increment starts)
    const auto plain = neoHookeanCook(false);
    const auto tracked = neoHookeanCook(true);
    EXPECT_NEAR(tracked.second, plain.second, 1e-9*plain.second);
    EXPECT_LT(tracked.first, plain.first);
}


namespace
{
// Cook's neo-Hookean with the extrapolating predictor (quadratic), 10
// equal steps from t0 to 1 (t0 > 0: a restart at t0 from the given
// state and run state); the element pressures at the predicted state
// extrapolated or p_e of the predicted displacements (staticSolver.H,
// pressurePredictor)
struct predictedRun
{
    std::vector<int> iterations;    //!< per step
    double v = 0;
    solidModel::savedState state;   //!< at t = 0.5
    resumeState run;                //!< at t = 0.5
    std::string log;
};

using pressurePrediction = newtonControls::pressurePrediction;

predictedRun predictedCook
(
    pressurePrediction mode,
    const predictedRun* from = nullptr,
    bool withHistory = true
)
{
    cooksMembrane c("Q9P3", 16, "neoHookean", 240.565, 0.4999, 6.25);
    auto solver = linearSolver::New("umfpack");
    newtonControls nc;
    nc.extrapolate = true;
    nc.quadratic = true;
    nc.pressurePredictor = mode;
    predictedRun out;
    std::ostringstream log;
    const auto steps = [&](double t0, double t1, resumeState* rs)
    {
        stepControls sc;
        sc.startTime = t0;
        sc.endTime = t1;
        sc.deltaT = 0.1;
        sc.growthFactor = 1;
        staticSolver s(*c.model, *solver, nc, sc, log);
        if (rs) s.resume(*rs);
        s.run
        (
            [&](const stepReport& r) { out.iterations.push_back(r.iterations); }
        );
        return s.resume();
    };
    if (from)
    {
        c.model->restore(from->state);
        resumeState rs = from->run;
        if (!withHistory) rs.pressureHistory.clear();
        steps(0.5, 1, &rs);
    }
    else
    {
        out.run = steps(0, 0.5, nullptr);
        out.state = c.model->save();
        steps(0.5, 1, &out.run);
    }
    out.v = c.v();
    out.log = log.str();
    return out;
}
}


TEST(cooksMembrane, PredictedPressureSavesTheSecondIteration)
{
    // At a predicted state p_e of the extrapolated displacements carries
    // kappa (= 5000 G) times their volume error, and the first update's
    // tangent with it left the second iteration of every step without
    // progress; the pressures extrapolated like the displacements do not
    // (observed per step, 10 equal steps: 4 4 3 3 3 3 3 3 3 3 -> 4 3 2 2 2
    // 2 2 2 2 2)
    const predictedRun off = predictedCook(pressurePrediction::projected);
    const predictedRun on = predictedCook(pressurePrediction::extrapolated);
    std::cout << "Cook's neo-Hookean, quadratic predictor, iterations per step"
              << " (pressures extrapolated / p_e of the prediction):";
    for (std::size_t k = 0; k < on.iterations.size(); ++k)
    {
        std::cout << ' ' << on.iterations[k] << '/'
                  << (k < off.iterations.size() ? off.iterations[k] : -1);
    }
    std::cout << '\n';
    ASSERT_EQ(on.iterations.size(), 10u) << on.log;
    ASSERT_EQ(off.iterations.size(), 10u) << off.log;
    EXPECT_NEAR(on.v, off.v, 1e-9*off.v);
    int sumOn = 0, sumOff = 0;
    for (std::size_t k = 0; k < 10; ++k)
    {
        sumOn += on.iterations[k];
        sumOff += off.iterations[k];
        // step 1 starts unpredicted, step 2 from a linear extrapolation,
        // the others from the quadratic one: in 2 iterations each
        if (k > 1) EXPECT_LE(on.iterations[k], 2) << "step " << k + 1;
    }
    EXPECT_LT(sumOn, sumOff);
}


TEST(cooksMembrane, RestartKeepsThePredictedPressures)
{
    // A restart at t = 0.5 (the model's state and the run state of the
    // solver, as formFoam writes them) takes the continuous run's steps:
    // the same iterations and deflection to round-off. Without the
    // pressure history in the run state the first steps fall back to
    // p_e of the prediction: the test sees the difference
    // The restarted run's 5 steps against the continuous run's last 5
    const auto sameSteps = [](const predictedRun& whole, const predictedRun& r)
    {
        ASSERT_EQ(whole.iterations.size(), 10u) << whole.log;
        ASSERT_EQ(r.iterations.size(), 5u) << r.log;
        for (std::size_t k = 0; k < 5; ++k)
        {
            EXPECT_EQ(r.iterations[k], whole.iterations[5 + k])
                << "step " << 6 + k;
        }
        EXPECT_NEAR(r.v, whole.v, 1e-13*whole.v);
    };
    const auto ext = pressurePrediction::extrapolated;
    const predictedRun whole = predictedCook(ext);
    sameSteps(whole, predictedCook(ext, &whole));
    const predictedRun lost = predictedCook(ext, &whole, false);
    ASSERT_EQ(lost.iterations.size(), 5u) << lost.log;
    EXPECT_GT(lost.iterations[0], whole.iterations[5]);

    // The same with the committed pressures carried along their
    // linearisation (the contact cases' rule): the restored model
    // linearises its committed state again, as the converged step left it
    const auto lin = pressurePrediction::linearised;
    const predictedRun wholeLin = predictedCook(lin);
    sameSteps(wholeLin, predictedCook(lin, &wholeLin));

    // A list that does not fit the model's elements is refused
    cooksMembrane c("Q9P3", 4, "neoHookean", 240.565, 0.4999, 6.25);
    EXPECT_THROW
    (
        c.model->setPressureHistory(whole.run.pressureHistory),
        numericalError
    );
    EXPECT_THROW(c.model->setPressureHistory({4}), numericalError);
    EXPECT_NO_THROW(c.model->setPressureHistory({}));
}
