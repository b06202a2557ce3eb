// Membrane locking of shell elements (issue 22): the hemispherical shell
// with an 18 deg hole (MacNeal & Harder 1985; Ko, Lee, Lee & Bathe,
// Comput. Struct. 193 (2017) 187-206, sec. 3.7, "[K17p]"; SHELLS.md):
// R = 10, E = 6.825e7, nu = 0.3, two pairs of opposite radial point
// loads on the equator, a quarter modelled with symmetry conditions,
// u_z = 0 at the loaded point A. Reference u_A = 0.093 for t = 0.04 with
// P = 2 and for t = 0.004 with P = 2e-3 (the load scales with t^3).
// Through solidModel and staticSolver at a thousandth of the load (a
// linear response; u_A scaled back).
//   - regular 16 x 16 mesh, t/R = 4/1000: MITC4 and MITC4+ within 2 % of
//     0.093 ([K17p] Table 15: 1.001 and 1.003; observed 1.0012 for both:
//     the elements of this mesh are isosceles trapezoids, flat, where
//     the two elements have the same linear stiffness);
//   - distorted 16 x 16 mesh: MITC4 locks, as published to 1 % ([K17p]
//     Table 16: 0.5815 of the reference at t/R = 4/1000, 0.0280 at
//     4/10000); MITC4+ does not: within 2 % and 5 % of the reference (the
//     membrane-locking test of the issue) and within 1 % of [K17p]'s
//     0.9736 at 4/10000.
// The distorted pattern of [K17p] Fig. 3(c): the bottom and left edges
// of the parameter square divided in the ratios 1 : 2 : ... : N from
// their common corner, the top and right edges likewise from the
// opposite corner, the interior nodes where the straight lines joining
// opposite edge nodes cross; azimuth and latitude linear in the
// parameters. The load per point on the quarter model is P/2
// (each loaded point is shared by two quarters; with it the regular
// mesh gives the published 0.093).
#include "staticSolver.H"
#include "shellSet.H"
#include "materialInput.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace form;

namespace
{

//- Node positions k = 0..N along an edge divided 1 : 2 : ... : N
std::vector<double> graded(int N)
{
    std::vector<double> p(N + 1, 0.0);
    for (int k = 1; k <= N; ++k) p[k] = p[k - 1] + k;
    for (double& v : p) v /= p[N];
    return p;
}

//- The quarter hemisphere (azimuth phi in [0, 90] deg, latitude in
//  [0, 72] deg) of N x N MITC4 or MITC4+ elements, exact radial
//  directors; node sets "y0" (phi = 0), "x0" (phi = 90 deg), "A" (the
//  equator on the x axis), "B" (on the y axis)
feMesh hemisphere(int N, double t, bool distorted, const std::string& type)
{
    const double R = 10;
    const std::vector<double> p = graded(N);
    feMesh mesh;
    mesh.nDim = 3;
    mesh.X.resize((N + 1)*(N + 1), 3);
    mesh.directors.resize((N + 1)*(N + 1), 3);
    const auto id = [N](int i, int j) { return j*(N + 1) + i; };
    for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i)
    {
        double xi = double(i)/N, eta = double(j)/N;
        if (distorted)
        {
            // bottom edge p[i], top 1 - p[N - i]; left edge p[j], right
            // 1 - p[N - j]; the crossing of the two joining lines
            const double xb = p[i], xt = 1 - p[N - i];
            const double yl = p[j], yr = 1 - p[N - j];
            // xi = xb + eta (xt - xb), eta = yl + xi (yr - yl)
            const double a = xt - xb, b = yr - yl;
            xi = (xb + a*yl)/(1 - a*b);
            eta = yl + xi*b;
        }
        const double phi = 0.5*M_PI*xi, psi = 0.4*M_PI*eta;
        const vec3 n(std::cos(psi)*std::cos(phi), std::cos(psi)*std::sin(phi), std::sin(psi));
        mesh.X.row(id(i, j)) = R*n.transpose();
        mesh.directors.row(id(i, j)) = n.transpose();
    }
    elementBlock blk;
    blk.name = "shell";
    blk.elementType = type;
    blk.materialName = "shell";
    blk.nodesPerElement = 4;
    blk.shell.thickness = t;
    blk.shell.points = 2;
    for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i)
    {
        blk.connectivity.insert
        (
            blk.connectivity.end(),
            {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}
        );
    }
    mesh.blocks.push_back(blk);
    for (int j = 0; j <= N; ++j)
    {
        mesh.nodeSets["y0"].push_back(id(0, j));
        mesh.nodeSets["x0"].push_back(id(N, j));
    }
    mesh.nodeSets["A"] = {id(0, 0)};
    mesh.nodeSets["B"] = {id(N, 0)};
    shellSet::assignNodeDofs(mesh);
    return mesh;
}

//- u_A / 0.093 under the reference load for thickness t
double hemisphereU(int N, double t, bool distorted, const std::string& type)
{
    const std::map<std::string, std::shared_ptr<material>> mat =
    {
        {"shell", material::New("stVenantKirchhoff", {{"E", 6.825e7}, {"nu", 0.3}})}
    };
    solidModel model(hemisphere(N, t, distorted, type), analysisType::solid3D, mat);
    const feMesh& mesh = model.mesh();
    // symmetry: u . n = 0, the director turns only about n (frame V1
    // along n, beta held)
    for (const auto& [set, c] : {std::pair<std::string, int>{"y0", 1}, {"x0", 0}})
    {
        const std::vector<int>& nodes = mesh.nodeSets.at(set);
        model.addConstraint(nodes, c);
        model.alignShellFrames(nodes, vec3::Unit(c));
        model.addConstraint(nodes, 4);
    }
    model.addConstraint(mesh.nodeSets.at("A"), 2);
    // P/2 per loaded point of the quarter (P = 2 at t = 0.04, scaling
    // with t^3), a thousandth of it: outward at A, inward at B
    const double P = 2*std::pow(t/0.04, 3), scale = 1e-3;
    model.addNodalLoad(mesh.nodeSets.at("A"), 0, [=](double s) { return 0.5*P*scale*s; });
    model.addNodalLoad(mesh.nodeSets.at("B"), 1, [=](double s) { return -0.5*P*scale*s; });
    model.finalise();
    auto solver = linearSolver::New("cholmod");
    // The residual of the thin shell stalls at about 1e-4 of the load
    // (round-off of the membrane forces) while the update falls to 1e-8
    // of the displacement: converged by the energy norm
    newtonControls newton;
    newton.forceTolerance = 1e-3;
    newton.energyTolerance = 1e-10;
    newton.lineSearch = false;
    stepControls steps;
    steps.deltaT = 1;
    std::ostringstream log;
    try
    {
        staticSolver(model, *solver, newton, steps, log).run(nullptr);
    }
    catch (...)
    {
        std::printf("%s\n", log.str().c_str());
        throw;
    }
    const double uA = model.displacement()(mesh.nodeSets.at("A")[0], 0)/scale;
    const double uB = -model.displacement()(mesh.nodeSets.at("B")[0], 1)/scale;
    std::printf
    (
        "    hemisphere %s N = %d t/R = %g %s: u_A/0.093 = %.4f (u_B %.4f)\n",
        type.c_str(), N, t/10, distorted ? "distorted" : "regular",
        uA/0.093, uB/0.093
    );
    return uA/0.093;
}

} // anonymous namespace


TEST(shellLocking, hemisphereRegularMesh)
{
    EXPECT_NEAR(hemisphereU(16, 0.04, false, "MITC4"), 1, 0.02);
    EXPECT_NEAR(hemisphereU(16, 0.04, false, "MITC4+"), 1, 0.02);
}


TEST(shellLocking, hemisphereDistortedMeshMitc4LocksMitc4PlusDoesNot)
{
    // [K17p] Table 16, N = 16: MITC4 0.5815 and 0.0280, MITC4+ 0.9958 and
    // 0.9736 at t/R = 4/1000 and 4/10000 (observed 0.5823, 0.0280,
    // 0.9936, 0.9723)
    EXPECT_NEAR(hemisphereU(16, 0.04, true, "MITC4")/0.5815, 1, 0.01);
    EXPECT_NEAR(hemisphereU(16, 0.004, true, "MITC4")/0.0280, 1, 0.01);
    EXPECT_NEAR(hemisphereU(16, 0.04, true, "MITC4+"), 1, 0.02);
    const double thin = hemisphereU(16, 0.004, true, "MITC4+");
    EXPECT_NEAR(thin, 1, 0.05);
    EXPECT_NEAR(thin/0.9736, 1, 0.01);
}
