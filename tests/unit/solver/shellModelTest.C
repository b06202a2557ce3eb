// MITC4 shells in the solid model (issue 22; shellSet.H): 5 dofs per
// shell node in the dof map, director frames folded at every commit, the
// 3D materials through the plane-stress adapter, the static solver
// unchanged.
//   - Sze's cantilever under end shear (Sze, Liu & Lo 2004, SHELLS.md)
//     through solidModel and staticSolver: within 1 % of the published
//     tip displacements at half and full load;
//   - the strip rolled up into a full circle by an end moment: the tip
//     returns to the clamp (exact: pure bending, inextensible);
//   - the stresses at the bottom, middle and top points through the
//     thickness of a strip under a small end moment: M z/I, 0, -M z/I;
//   - save / restore of a converged state (frames included) reproduces
//     it; a revert gives back the committed directors;
//   - an elasto-plastic plate strip in cylindrical bending (plane strain)
//     by a prescribed end rotation: the end moment follows the
//     moment-curvature relation of the section integrated by the 5 Gauss
//     points through the thickness, up to 2/sqrt(3) x 0.9448 of the
//     plastic moment;
//   - mass: the translational mass of a strip is rho t A (consistent and
//     lumped), its rotary inertia rho t^3/12 A; a cantilever plate under
//     its own weight deflects q L^4/(8 EI) at the tip (within 0.1 %,
//     observed +0.008 %); the cantilever released from a tip load
//     vibrates with the first Euler-Bernoulli period
//     2 pi/(1.875^2 sqrt(EI/(rho A L^4))) (within 1 %, observed +0.36 %;
//     trapezoidal rule, 100 steps per period);
//   - input errors: a fold (two elements at 90 deg), a zero thickness, 11
//     points through it, a 2D mesh, a rotation constraint on a solid
//     node, a shell node without 5 dofs, an element with a repeated
//     node, an edge shared by three elements (non-manifold).
#include "staticSolver.H"
#include "shellTestTools.H"
#include "timeIntegrator.H"
#include "shellSet.H"
#include "planeStressMaterial.H"
#include "gaussLegendre.H"
#include "materialInput.H"
#include "formError.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace form;

namespace
{

using test::strip;

std::map<std::string, std::shared_ptr<material>> elastic(double E, double nu)
{
    return {{"sheet", material::New("stVenantKirchhoff", {{"E", E}, {"nu", nu}})}};
}

void clamp(solidModel& model)
{
    for (int c = 0; c < 5; ++c) model.addConstraint(model.mesh().nodeSets.at("clamp"), c);
}

using test::tight;

} // anonymous namespace


TEST(shellModel, szeCantileverUnderEndShear)
{
    // L = 10, b = 1, h = 0.1, E = 1.2e6, nu = 0, end shear up to
    // P_max = 4 (Sze, Liu & Lo 2004): tip -u 1.604, w 4.933 at P_max/2 and
    // -u 3.286, w 6.698 at P_max
    solidModel model(strip(16, 10, 1, 0.1), analysisType::solid3D, elastic(1.2e6, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addNodalLoad(tip, 2, [](double t) { return 0.5*4*t; });
    model.finalise();
    EXPECT_EQ(model.nDofs(), 5*34);

    auto solver = linearSolver::New("cholmod");
    stepControls steps;
    steps.deltaT = 0.05;
    steps.maxDeltaT = 0.05;
    std::ostringstream log;
    double uHalf = 0, wHalf = 0;
    int maxIterations = 0;
    staticSolver(model, *solver, tight(), steps, log).run
    (
        [&](const stepReport& r)
        {
            maxIterations = std::max(maxIterations, r.iterations);
            if (std::abs(r.time - 0.5) < 1e-9)
            {
                uHalf = -model.displacement()(tip[0], 0);
                wHalf = model.displacement()(tip[0], 2);
            }
        }
    );
    const double u = -model.displacement()(tip[0], 0);
    const double w = model.displacement()(tip[0], 2);
    std::printf
    (
        "    model: end shear P_max/2 -u %.4f w %.4f (Sze 1.604, 4.933);"
        " P_max -u %.4f w %.4f (Sze 3.286, 6.698); at most %d iterations\n",
        uHalf, wHalf, u, w, maxIterations
    );
    EXPECT_NEAR(uHalf/1.604, 1, 0.01) << log.str();
    EXPECT_NEAR(wHalf/4.933, 1, 0.01);
    EXPECT_NEAR(u/3.286, 1, 0.01);
    EXPECT_NEAR(w/6.698, 1, 0.01);
    // The directors of the two tip nodes agree (a plane problem)
    const vec3 d0 = model.shells()->director(tip[0], model.dofs(), model.U());
    const vec3 d1 = model.shells()->director(tip[1], model.dofs(), model.U());
    EXPECT_LT((d0 - d1).norm(), 1e-8);
    EXPECT_NEAR(d0.norm(), 1, 1e-14);
}


TEST(shellModel, stripRolledUpIntoACircle)
{
    // Sze, Liu & Lo 2004: L = 12, b = 1, h = 0.1, E = 1.2e6, nu = 0, end
    // moment M_max = 2 pi EI/L rolls the strip into a full circle: a line
    // moment -M_max/b y on the tip edge (addLineMoment), which acts on beta
    // (about the frames' V2 = y, which the rotation about y keeps). 32
    // elements: the tip within 0.0074 L (kernel test)
    const double L = 12, E = 1.2e6, h = 0.1;
    const double EI = E*h*h*h/12, Mmax = 2*M_PI*EI/L;
    solidModel model(strip(32, L, 1, h), analysisType::solid3D, elastic(E, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addLineMoment("tip", [=](double t) { return vec3(0, -Mmax*t, 0); });
    model.finalise();
    // The load on beta is conjugate to the rotation increment about V2,
    // a fixed-axis moment only while alpha = 0: past about 290 degrees
    // the tangent has a small negative eigenvalue in a twist mode (-0.04
    // of 6e5), so an LU solver (cholmod refuses it)
    auto solver = linearSolver::New("umfpack");
    stepControls steps;
    steps.deltaT = 0.05;
    steps.maxDeltaT = 0.05;
    std::ostringstream log;
    double worst = 0;
    staticSolver(model, *solver, tight(), steps, log).run
    (
        [&](const stepReport& r)
        {
            const double phi = 2*M_PI*r.time;
            const double ue = L*(std::sin(phi)/phi - 1);
            const double we = L*(1 - std::cos(phi))/phi;
            const matX u = model.displacement();
            worst = std::max
            (
                worst, std::hypot(u(tip[0], 0) - ue, u(tip[0], 2) - we)/L
            );
        }
    );
    const vec3 tipPoint =
        model.mesh().X.row(tip[0]).transpose()
      + model.displacement().row(tip[0]).transpose();
    std::printf
    (
        "    model: roll-up tip at (%.4f, %.4f, %.4f) (exact: the clamp,"
        " origin); largest tip error over the loading %.4f L\n",
        tipPoint(0), tipPoint(1), tipPoint(2), worst
    );
    EXPECT_LT(worst, 0.01) << log.str();
    EXPECT_LT(std::hypot(tipPoint(0), tipPoint(2)), 0.01*L);
    // The tip director points back along -z... after a full turn: +z
    const vec3 d = model.shells()->director(tip[0], model.dofs(), model.U());
    EXPECT_GT(d(2), 0.99);
}


TEST(shellModel, stressesAtTheBottomMiddleAndTopPoints)
{
    // The strip L = 12, b = 1, h = 0.1, E = 1.2e6, nu = 0 (16 elements,
    // 5 Gauss points through the thickness) under a small end moment M
    // (the tip turns by 0.06 rad): uniform curvature M/EI, the bending
    // stress M z/I at the outermost points z = +-0.906 h/2, zero at the
    // middle; -M curls the strip up, compressing its top (the director's
    // side). Within 0.5 % (the geometric nonlinearity of the turn).
    const double L = 12, E = 1.2e6, h = 0.1;
    const double EI = E*h*h*h/12, M = 0.01*2*M_PI*EI/L;
    solidModel model(strip(16, L, 1, h), analysisType::solid3D, elastic(E, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addNodalLoad(tip, 4, [=](double t) { return -0.5*M*t; });
    model.finalise();
    auto solver = linearSolver::New("cholmod");
    stepControls steps;
    steps.deltaT = 1;
    std::ostringstream log;
    staticSolver(model, *solver, tight(), steps, log).run(nullptr);
    std::vector<double> z, w;
    gaussLegendre1D(5, z, w);
    const double sigma = M*(z.back()*h/2)/(h*h*h/12);
    for (const elementResult& r : model.elementResults())
    {
        EXPECT_NEAR(r.shellLayers[2](0, 0)/-sigma, 1, 5e-3);
        EXPECT_NEAR(r.shellLayers[0](0, 0)/sigma, 1, 5e-3);
        EXPECT_LT(std::abs(r.shellLayers[1](0, 0)), 5e-3*sigma);
        EXPECT_LT(std::abs(r.shellLayers[2](1, 1)), 1e-6*sigma);
    }
    const elementResult r = model.elementResults()[8];
    std::printf
    (
        "    end moment: sigma_xx bottom %.3f middle %.3f top %.3f"
        " (M z/I = %.3f)\n",
        r.shellLayers[0](0, 0), r.shellLayers[1](0, 0), r.shellLayers[2](0, 0),
        sigma
    );
}


TEST(shellModel, saveRestoreAndRevertKeepTheDirectors)
{
    solidModel model(strip(4, 4, 1, 0.1), analysisType::solid3D, elastic(1e5, 0.3));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addNodalLoad(tip, 2, [](double t) { return 0.5*t; });
    model.finalise();
    auto solver = linearSolver::New("cholmod");
    std::ostringstream log;
    stepControls steps;
    steps.endTime = 0.5;
    steps.deltaT = 0.25;
    staticSolver(model, *solver, tight(), steps, log).run(nullptr);
    const solidModel::savedState saved = model.save();
    const vec3 d = model.shells()->director(tip[0], model.dofs(), model.U());
    EXPECT_LT(d(2), 0.999);     // turned

    // Further: a trial state, reverted
    vecX r;
    vecX dU = vecX::Zero(model.nFreeDofs());
    dU.setConstant(1e-3);
    model.addToFree(dU);
    model.revert();
    EXPECT_LT
    (
        (model.shells()->director(tip[0], model.dofs(), model.U()) - d).norm(),
        1e-15
    );
    // Further: committed states, then restored
    stepControls more = steps;
    more.startTime = 0.5;
    more.endTime = 1;
    staticSolver(model, *solver, tight(), more, log).run(nullptr);
    EXPECT_GT
    (
        (model.shells()->director(tip[0], model.dofs(), model.U()) - d).norm(),
        1e-3
    );
    model.restore(saved);
    EXPECT_LT
    (
        (model.shells()->director(tip[0], model.dofs(), model.U()) - d).norm(),
        1e-15
    );
    // The restored state is the converged one: no residual at t = 0.5
    ASSERT_TRUE(model.evaluate(0.5, r, false));
    EXPECT_LT(r.norm(), 1e-9);
    // Restart data: frames that are not orthonormal are refused
    std::vector<double> bad = model.shellState();
    bad[0] += 0.1;
    EXPECT_THROW(model.setShellState(bad), numericalError);
    EXPECT_THROW(model.setShellState({1, 2, 3}), numericalError);
}


TEST(shellModel, plasticPlateStripInCylindricalBending)
{
    // An elasto-plastic plate strip (sigma_y = 250 + 2000 eps_p, E = 2e5,
    // nu = 0.3),
    // L = 1, b = 0.2, h = 0.02, bent into a cylinder by a prescribed
    // rotation of its tip about y, in plane strain (u_y = 0 and the
    // rotation alpha about the frames' V1 held at every node): every fibre
    // z of the section stretches by 1 + k z, E11 = k z + (k z)^2/2,
    // E22 = 0. The end moment conjugate to the tip rotation is then
    //     M(k) = b sum_i w_i (h/2) S11(z_i) z_i (1 + k z_i)
    // over the element's 5 Gauss points z_i through the thickness, with
    // S11 from the material at each point along the same path (the
    // membrane strain is zero to second order: the section is symmetric).
    // Hardening keeps M(k) rising, so the curvature stays uniform (with
    // perfect plasticity the 5-point section's M(k) is flat once its
    // outer four points yield, and the curvature may localise anywhere).
    // Without hardening M(k) would tend to 2/sqrt(3) (plane strain) x
    // 0.9448 (the 5-point rule of |z|) x b h^2 sigma_y / 4.
    const double E = 2e5, nu = 0.3, sy = 250, L = 1, b = 0.2, h = 0.02;
    const auto mats = test::linearHardeningSheet(E, nu, sy, 2000);
    const double Mp = b*h*h*sy/4;
    // The largest relative deviation from the section's M(k) over the
    // loading with n elements along the strip; the final M / M_p
    const auto run = [&](int n, double& Mend, bool lobatto = false)
    {
        feMesh mesh = strip(n, L, b, h);
        mesh.blocks[0].shell.lobatto = lobatto;
        solidModel model(mesh, analysisType::solid3D, mats);
        clamp(model);
        std::vector<int> all(model.mesh().nNodes());
        for (int n = 0; n < model.mesh().nNodes(); ++n) all[n] = n;
        model.addConstraint(all, 1);
        model.addConstraint(all, 3);
        const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
        // Tip rotation k L about y: beta = -dw/dx, so -k L bends the strip up
        const double kMax = 20*2*sy/(E*h);      // 20 x the first-yield curvature
        model.addConstraint(tip, 4, [=](double t) { return -kMax*L*t; });
        model.finalise();

        // The reference section: the material at the 5 points
        const planeStressMaterial law(mats.at("sheet"));
        std::vector<double> zq, wq;
        if (lobatto) gaussLobatto1D(5, zq, wq);
        else gaussLegendre1D(5, zq, wq);
        std::vector<materialState> points(5, law.initialState());
        const auto sectionMoment = [&](double k)
        {
            double M = 0;
            for (int i = 0; i < 5; ++i)
            {
                const double z = 0.5*h*zq[i];
                vec5 eps = vec5::Zero(), S;
                eps(0) = k*z + 0.5*k*k*z*z;
                mat5 D;
                materialState trial = points[i];
                EXPECT_TRUE(law.stress(mat3::Identity(), eps, points[i], trial, S, D));
                points[i] = trial;
                M += b*wq[i]*0.5*h*S(0)*z*(1 + k*z);
            }
            return M;
        };

        auto solver = linearSolver::New("cholmod");
        std::ostringstream log;
        stepControls steps;
        steps.deltaT = 0.05;
        steps.maxDeltaT = 0.05;
        double worst = 0, Mref = 0, M = 0;
        staticSolver(model, *solver, tight(), steps, log).run
        (
            [&](const stepReport& r)
            {
                Mref = sectionMoment(kMax*r.time);
                M = 0;
                for (const int n : tip) M -= model.internalForce()(model.dofs().dof(n, 4));
                worst = std::max(worst, std::abs(M/Mref - 1));
            }
        );
        std::printf
        (
            "    plastic plate strip, %d elements%s: end moment %.5f M_p (section"
            " %.5f); largest deviation from the section's M(k) %.2e\n",
            n, lobatto ? " (Lobatto)" : "", M/Mp, Mref/Mp, worst
        );
        Mend = M;
        return worst;
    };
    // The flat facets measure the cylinder's curvature through their
    // chords: the deviation falls at second order in the element size
    // (observed 1.3e-2 with 8 elements, 3.3e-3 with 16)
    double M8, M16;
    const double e8 = run(8, M8);
    const double e16 = run(16, M16);
    EXPECT_LT(e8, 2e-2);
    EXPECT_LT(e16, 5e-3);
    EXPECT_GT(e8/e16, 3.5);
    // The Gauss-Lobatto points through the thickness (the surfaces
    // yield first): the same agreement with their own section
    double M16L;
    EXPECT_LT(run(16, M16L, true), 5e-3);
    // Well into the plastic range: beyond the perfectly plastic limit
    EXPECT_GT(M16/Mp, 2/std::sqrt(3.0)*0.94485);
}


TEST(shellModel, massGravityAndFreeVibration)
{
    // The strip L = 10, b = 1, t = 0.1 (16 x 1), E = 1.2e6, nu = 0,
    // rho = 1: EI = 100, rho A = 0.1
    const double L = 10, b = 1, t = 0.1, E = 1.2e6, rho = 1;
    const double EI = E*b*t*t*t/12, rhoA = rho*b*t;
    for (const bool lumped : {false, true})
    {
        solidModel model(strip(16, L, b, t, 2), analysisType::solid3D, elastic(E, 0));
        model.finalise();
        model.setInertia({{"sheet", rho}}, lumped);
        const sparseMatrix& M = model.massMatrix();
        const dofMap& d = model.dofs();
        vecX ez = vecX::Zero(model.nDofs()), rot = vecX::Zero(model.nDofs());
        for (int n = 0; n < model.mesh().nNodes(); ++n)
        {
            ez(d.dof(n, 2)) = 1;
            rot(d.dof(n, 3)) = 1;
        }
        EXPECT_NEAR(ez.dot(M*ez), rho*t*L*b, 1e-12) << lumped;
        EXPECT_NEAR(rot.dot(M*rot), rho*t*t*t/12*L*b, 1e-14) << lumped;
    }

    // Under its own weight g = -0.01 (q = rho t b g; the tip deflects
    // 1.25e-3 L, a linear response), clamped: q L^4/(8 EI)
    {
        solidModel model(strip(16, L, b, t, 2), analysisType::solid3D, elastic(E, 0));
        clamp(model);
        model.finalise();
        model.setBodyForce(rho, [](double) { return vec3(0, 0, -0.01); });
        auto solver = linearSolver::New("cholmod");
        std::ostringstream log;
        stepControls steps;
        steps.deltaT = 1;
        staticSolver(model, *solver, tight(), steps, log).run(nullptr);
        const double w =
            model.displacement()(model.mesh().nodeSets.at("tip")[0], 2);
        const double exact = -0.01*rhoA*std::pow(L, 4)/(8*EI);
        std::printf("    gravity: tip %.6g (q L^4/8EI %.6g)\n", w, exact);
        EXPECT_NEAR(w/exact, 1, 1e-3) << log.str();
    }

    // Released from a tip load: the first bending period
    solidModel model(strip(16, L, b, t, 2), analysisType::solid3D, elastic(E, 0));
    clamp(model);
    const std::vector<int>& tip = model.mesh().nodeSets.at("tip");
    model.addNodalLoad(tip, 2, [](double time) { return time <= 1 ? 0.005 : 0.0; });
    model.finalise();
    auto solver = linearSolver::New("cholmod");
    std::ostringstream log;
    stepControls steps;
    steps.deltaT = 1;
    staticSolver(model, *solver, tight(), steps, log).run(nullptr);
    const double T1 = 2*M_PI/(1.875104068711961*1.875104068711961
       *std::sqrt(EI/(rhoA*std::pow(L, 4))));
    model.setInertia({{"sheet", rho}}, false);
    timeIntegrator integrator("trapezoidal");
    integrator.initialise(model, 1, vecX());
    stepControls dyn;
    dyn.startTime = 1;
    dyn.endTime = 1 + 3*T1;
    dyn.deltaT = T1/100;
    dyn.maxDeltaT = T1/100;
    dyn.growthFactor = 1;
    staticSolver s(model, *solver, tight(), dyn, log);
    s.setIntegrator(&integrator);
    std::vector<double> crossings;
    double tPrev = 1, wPrev = model.displacement()(tip[0], 2);
    s.run
    (
        [&](const stepReport& r)
        {
            const double w = model.displacement()(tip[0], 2);
            if (wPrev > 0 && w <= 0)
            {
                crossings.push_back(tPrev + (r.time - tPrev)*wPrev/(wPrev - w));
            }
            tPrev = r.time;
            wPrev = w;
        }
    );
    ASSERT_GE(crossings.size(), 2u) << log.str();
    const double T = (crossings.back() - crossings.front())/(crossings.size() - 1);
    std::printf("    free vibration: period %.6g (Euler-Bernoulli %.6g)\n", T, T1);
    EXPECT_NEAR(T/T1, 1, 0.01);
}


TEST(shellModel, inputErrorsNameTheirEntry)
{
    const auto expectInput = [](const std::function<void()>& f, const std::string& entry)
    {
        try
        {
            f();
            ADD_FAILURE() << "no error for " << entry;
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), entry) << e.what();
        }
    };
    // A fold: two elements meeting at more than 90 degrees
    {
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.X(4, 0) = 0.5;
        mesh.X(4, 2) = 1;
        mesh.X(5, 0) = 0.5;
        mesh.X(5, 2) = 1;
        expectInput
        (
            [&] { solidModel(mesh, analysisType::solid3D, elastic(1, 0)); },
            "mesh"
        );
    }
    {
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.blocks[0].shell.thickness = 0;
        expectInput
        (
            [&] { solidModel(mesh, analysisType::solid3D, elastic(1, 0)); },
            "thickness"
        );
        mesh.blocks[0].shell.thickness = 0.1;
        mesh.blocks[0].shell.points = 11;
        expectInput
        (
            [&] { solidModel(mesh, analysisType::solid3D, elastic(1, 0)); },
            "thicknessPoints"
        );
    }
    {
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.nDim = 2;
        mesh.X = mesh.X.leftCols(2).eval();
        mesh.nodeDofs.clear();
        expectInput
        (
            [&] { solidModel(mesh, analysisType::planeStrain, elastic(1, 0)); },
            "elementType"
        );
    }
    {
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.nodeDofs.clear();     // 3 dofs on every node
        expectInput
        (
            [&] { solidModel(mesh, analysisType::solid3D, elastic(1, 0)); },
            "mesh"
        );
    }
    {
        // An element with a repeated node
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.blocks[0].connectivity[3] = 2;     // element 0: 0 2 3 2
        expectInput
        (
            [&] { solidModel(mesh, analysisType::solid3D, elastic(1, 0)); },
            "mesh"
        );
    }
    {
        // A non-manifold edge: a third element on the edge 2-3 (a fin
        // standing up from the strip)
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.X.conservativeResize(8, 3);
        mesh.X.row(6) << 1, 0, 1;
        mesh.X.row(7) << 1, 1, 1;
        mesh.blocks[0].connectivity.insert
        (
            mesh.blocks[0].connectivity.end(), {2, 6, 7, 3}
        );
        mesh.nodeDofs.assign(8, 5);
        try
        {
            solidModel(mesh, analysisType::solid3D, elastic(1, 0));
            ADD_FAILURE() << "no error for a non-manifold edge";
        }
        catch (const inputError& e)
        {
            EXPECT_EQ(e.entry(), "mesh");
            EXPECT_NE(std::string(e.what()).find("non-manifold"), std::string::npos)
                << e.what();
        }
    }
    {
        // A solid node (not in a shell element) with a rotation constraint
        feMesh mesh = strip(2, 2, 1, 0.1);
        mesh.X.conservativeResize(mesh.X.rows() + 1, 3);
        mesh.X.row(mesh.X.rows() - 1) << 5, 5, 5;
        mesh.nodeDofs.push_back(3);
        solidModel model(mesh, analysisType::solid3D, elastic(1, 0));
        expectInput([&] { model.addConstraint({6}, 3); }, "component");
        expectInput([&] { model.addNodalLoad({6}, 4, [](double) { return 1.0; }); }, "component");
        EXPECT_NO_THROW(model.addConstraint({5}, 4));
        expectInput([&] { model.addMoment({6}, [](double) { return vec3(1, 0, 0); }); }, "moment");
        EXPECT_NO_THROW(model.addMoment({5}, [](double) { return vec3(1, 0, 0); }));
    }
}
