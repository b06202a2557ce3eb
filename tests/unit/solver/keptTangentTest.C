/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Unit tests of the kept tangent (modified Newton with automatic
    refresh, staticSolver.H): the converged states are full Newton's, a
    slow contraction refreshes the tangent, a new step size refreshes
    it, a step that fails with kept factors is retried with full Newton.
\*---------------------------------------------------------------------------*/
#include "staticSolver.H"
#include "trussModels.H"
#include <gtest/gtest.h>
#include <cmath>
#include <sstream>
#include <string>

using namespace form;
using namespace form::test;

namespace
{

struct runResult
{
    vecX U;
    int iterations = 0;
    int tangents = 0;
    int steps = 0;
    std::string log;
};

//- The von Mises truss loaded to 70 % of its snap-through load in steps
//  of deltaT (constant unless grow)
runResult loadTruss
(
    const newtonControls& nc,
    double deltaT = 0.1,
    bool grow = false
)
{
    solidModel model = vonMisesTruss(0.5, 3.0, barLaw(true, 100));
    auto solver = linearSolver::New("umfpack");
    stepControls sc;
    sc.deltaT = deltaT;
    sc.maxDeltaT = 1;
    sc.growthFactor = grow ? 1.5 : 1;
    sc.easyIterations = 100;
    std::ostringstream log;
    staticSolver s(model, *solver, nc, sc, log);
    runResult r;
    s.run([&](const stepReport& rep)
    {
        r.iterations += rep.iterations;
        r.tangents += rep.newTangents;
        ++r.steps;
    });
    r.U = model.U();
    r.log = log.str();
    return r;
}

newtonControls tight()
{
    newtonControls nc;
    nc.forceTolerance = 1e-12;
    nc.energyTolerance = 1e-24;
    return nc;
}

//- Iteration lines of a log: (|r|, kept) in order, a step's iteration 0
//  with kept = false; steps separated by an entry with |r| = -1
std::vector<std::pair<double, bool>> iterations(const std::string& log)
{
    std::vector<std::pair<double, bool>> it;
    std::istringstream is(log);
    std::string line;
    while (std::getline(is, line))
    {
        if (line.rfind("Step ", 0) == 0) it.emplace_back(-1, false);
        const auto p = line.find("|r| ");
        if (line.find("    iter ") != 0 || p == std::string::npos) continue;
        it.emplace_back
        (
            std::stod(line.substr(p + 4)),
            line.find("  kept") != std::string::npos
        );
    }
    return it;
}

} // namespace


TEST(keptTangent, ConvergesToTheFullNewtonStateWithFewerFactorisations)
{
    const runResult full = loadTruss(tight());
    newtonControls nc = tight();
    nc.keepTangent = true;
    const runResult kept = loadTruss(nc);

    ASSERT_EQ(kept.steps, 10) << kept.log;
    EXPECT_LE((kept.U - full.U).norm(), 1e-9*full.U.norm()) << kept.log;
    // Full Newton factorises at every iteration; the kept tangent fewer
    // times than it iterates, and fewer times than full Newton
    EXPECT_EQ(full.tangents, full.iterations);
    EXPECT_LT(kept.tangents, kept.iterations) << kept.log;
    EXPECT_LT(kept.tangents, full.tangents) << kept.log;
    EXPECT_NE(kept.log.find("  kept"), std::string::npos);
    EXPECT_NE(kept.log.find("new tangents"), std::string::npos);
    EXPECT_EQ(full.log.find("  kept"), std::string::npos);
    std::cout << "full Newton: " << full.iterations << " iterations, "
        << full.tangents << " factorisations; kept tangent: "
        << kept.iterations << " iterations, " << kept.tangents
        << " factorisations\n";
}


TEST(keptTangent, SlowContractionRefreshesTheTangent)
{
    for (const double c : {0.9, 0.01})
    {
        newtonControls nc = tight();
        nc.keepTangent = true;
        nc.keptTangentContraction = c;
        const runResult r = loadTruss(nc);
        ASSERT_EQ(r.steps, 10) << r.log;
        // After an update from kept factors that cut |r| by less than c,
        // the next update takes a new tangent (beta is 1 throughout: the
        // truss needs no line search)
        const auto it = iterations(r.log);
        int checked = 0;
        for (std::size_t k = 2; k < it.size(); ++k)
        {
            if (it[k].first < 0 || it[k - 1].first < 0 || it[k - 2].first < 0)
            {
                continue;
            }
            if (it[k - 1].second && it[k - 1].first > c*it[k - 2].first)
            {
                EXPECT_FALSE(it[k].second) << "c " << c << '\n' << r.log;
                ++checked;
            }
        }
        std::cout << "contraction " << c << ": " << r.iterations
            << " iterations, " << r.tangents << " factorisations, "
            << checked << " refreshes checked\n";
        if (c < 0.1)
        {
            EXPECT_GT(checked, 0) << r.log;
        }
    }
}


TEST(keptTangent, ANewStepSizeRefreshesTheTangent)
{
    newtonControls nc = tight();
    nc.keepTangent = true;
    // Steps growing by 1.5 after every step: the factors of a step never
    // belong to the next
    const runResult r = loadTruss(nc, 0.05, true);
    ASSERT_GT(r.steps, 3) << r.log;
    const auto it = iterations(r.log);
    int steps = 0;
    for (std::size_t k = 2; k < it.size(); ++k)
    {
        // iteration 1 of every step (after its iteration 0)
        if (it[k - 2].first < 0)
        {
            EXPECT_FALSE(it[k].second) << r.log;
            ++steps;
        }
    }
    EXPECT_EQ(steps, r.steps);
    EXPECT_GE(r.tangents, r.steps);
}


TEST(keptTangent, AFailedKeptAttemptIsRetriedWithFullNewton)
{
    // Kept factors that contract slowly (refreshed only below 0.99) cannot
    // reach the tolerance in 4 iterations; full Newton can
    newtonControls nc = tight();
    nc.maxIterations = 4;
    const runResult full = loadTruss(nc);
    nc.keepTangent = true;
    nc.keptTangentContraction = 0.99;
    const runResult r = loadTruss(nc);
    ASSERT_EQ(r.steps, 10) << r.log;
    EXPECT_NE(r.log.find("retrying the increment with full Newton"),
        std::string::npos) << r.log;
    EXPECT_EQ(r.log.find("cutting back"), std::string::npos) << r.log;
    EXPECT_LE((r.U - full.U).norm(), 1e-9*full.U.norm()) << r.log;
}
