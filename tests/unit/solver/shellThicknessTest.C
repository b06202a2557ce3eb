// The current thickness of shells (issue 22): a plate strip (L = 1, b =
// 0.2, t = 0.02, 4 MITC4 elements, 5 Gauss points through the
// thickness) of an elasto-plastic steel (E = 2e5, nu = 0.3, sigma_y =
// 250 + 2000 eps_p) pulled in plane to a stretch of 1.2 along its length,
// its width free: in uniaxial stress the plastic flow keeps the volume,
// so the width and thickness stretches are 1/sqrt(1.2) = 0.9129 up to the
// elastic volume change (1 - 2 nu) sigma/E ~ 1e-3 (sigma ~ 600).
// solidModel::shellNodeThickness (the thickness the contact offsets
// follow at every commit) gives t0 times that at every node, within 2e-3.
#include "staticSolver.H"
#include "shellTestTools.H"
#include "materialInput.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace form;
using test::strip;

TEST(shellThickness, followsThePlasticStretch)
{
    const auto mats = test::linearHardeningSheet(2e5, 0.3, 250, 2000);
    const double t0 = 0.02;
    solidModel model(strip(4, 1, 0.2, t0), analysisType::solid3D, mats);
    const std::vector<int>& clamp = model.mesh().nodeSets.at("clamp");
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    std::vector<int> all(model.mesh().nNodes());
    for (int n = 0; n < int(all.size()); ++n) all[n] = n;
    model.addConstraint(clamp, 0);
    model.addConstraint({clamp[0]}, 1);
    model.addConstraint(all, 2);
    model.addConstraint(all, 3);
    model.addConstraint(all, 4);
    model.addConstraint(tip, 0, [](double t) { return 0.2*t; });
    model.finalise();
    auto solver = linearSolver::New("umfpack");
    stepControls steps;
    steps.deltaT = 0.1;
    steps.maxDeltaT = 0.1;
    std::ostringstream log;
    staticSolver(model, *solver, newtonControls(), steps, log)
        .run([](const stepReport&) {});
    const std::vector<double> t = model.shellNodeThickness();
    const double expected = t0/std::sqrt(1.2);
    double worst = 0;
    for (const double tn : t) worst = std::max(worst, std::abs(tn/expected - 1));
    std::printf
    (
        "    stretched to 1.2: thickness %.6f at node 0 (t0/sqrt(1.2) = %.6f);"
        " largest deviation %.2e\n", t[0], expected, worst
    );
    EXPECT_LT(worst, 2e-3) << log.str();
    EXPECT_GT(worst, 0);    // the elastic volume change is there
}
