/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    ALENavierStokes: the mesh following the solid and the mesh unknowns
    (moveMesh), the interface, the mesh equations and the derivatives of
    the fluid residual with respect to the solid's interface dofs
    (evaluateInterface; ALENavierStokes.H).
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "wallClock.H"
#include "fluidSolidInterface.H"
#include "solidModel.H"
#include "formError.H"

void Foam::ALENavierStokes::moveMesh(const pointField& points, bool check)
{
    const auto start = std::chrono::steady_clock::now();
    mesh_.movePoints(points);
    computeMeshFluxes();
    meshMotionTime_ += form::secondsSince(start);
    if (check) checkMeshQuality();
}


void Foam::ALENavierStokes::setInterface
(
    const std::shared_ptr<fluidSolidInterface>& interface,
    const form::solidModel& solid
)
{
    interface_ = interface;
    solid_ = &solid;
    set_.meshMotion = "interface";
    interfaceFace_.setSize(mesh_.nFaces() - mesh_.nInternalFaces(), -1);
    forAll(interface_->faces(), j)
    {
        interfaceFace_[interface_->faces()[j] - mesh_.nInternalFaces()] = j;
    }
    uInterface_.setSize(interface_->faces().size(), Zero);
    // The mesh unknowns after the cells' (those of the mesh's points: a
    // restart's written points, or zero)
    const label n = nCellUnknowns(), nM = interface_->nMeshUnknowns();
    x_.conservativeResize(n + nM);
    x_.tail(nM) = interface_->meshUnknowns(mesh_.points());
    x0_.conservativeResize(n + nM);
    x0_.tail(nM) = x_.tail(nM);
}


void Foam::ALENavierStokes::evaluateInterface
(
    const form::vecX& Us,
    form::vecX& fext,
    form::vecX& r,
    std::vector<triplet>* K
)
{
    const fluidSolidInterface& itf = *interface_;
    const label off = Us.size();
    const label nI = mesh_.nInternalFaces();
    const label nCU = nCellUnknowns(), nM = itf.nMeshUnknowns();
    if (Un_.size() != Us.size()) Un_ = Us;

    // The mesh follows the solid and the mesh unknowns
    const form::vecX d = x_.tail(nM);
    const pointField base(itf.points(Us, d));
    moveMesh(base);

    // The solid's velocity by its time integrator, or the backward
    // difference over the (pseudo-)time step of a static analysis
    double beta = 0;
    const form::vecX* c = nullptr;
    form::vecX v;
    if (solid_->velocityLaw(beta, c))
    {
        beta /= set_.timeScale;
        v = beta*Us + *c/set_.timeScale;
    }
    else
    {
        beta = 1/dt_;
        v = beta*(Us - Un_);
    }
    uInterface_ = itf.faceVelocities(v);

    std::vector<interfaceEntry> KI;
    assemble(off, r, K, K ? &KI : nullptr);

    // The mesh equations (fluidSolidInterface.H (4))
    form::vecX rm;
    itf.meshEquations(Us, d, rm, off + nCU, K);
    r.conservativeResize(nCU + nM);
    r.tail(nM) = rm;

    // The fluid's forces on the solid
    const labelList& faces = itf.faces();
    vectorField F(faces.size());
    forAll(F, j) F[j] = Fw_[faces[j] - nI];
    itf.addForces(F, depth_, fext);
    if (!K) return;

    const scalar s = depth_;
    const auto& fi = itf.faceInterpolation();

    // Solid rows: f_a = s N_a(xi_f) F_f . e_c with
    // F_f = p_P S - mu |S| dc (u_f - u_P), u_f = sum_b N_b v_b(U)
    forAll(faces, j)
    {
        const label f = faces[j];
        const label P = mesh_.faceOwner()[f];
        const label patchi = mesh_.boundaryMesh().whichPatch(f);
        const label i = f - mesh_.boundary()[patchi].start();
        const vector& S = mesh_.Sf().boundaryField()[patchi][i];
        const scalar cv =
            set_.mu*mesh_.magSf().boundaryField()[patchi][i]
           *mesh_.boundary()[patchi].deltaCoeffs()[i];
        const std::vector<int>& nodes = fi[j].nodes;
        for (label cc = 0; cc < 2; ++cc)
        {
            const vector& e = itf.faceDirection(j, cc);
            for (std::size_t a = 0; a < nodes.size(); ++a)
            {
                const label row = solid_->dofs().dof(nodes[a], cc);
                const scalar w = s*fi[j].N[a];
                K->emplace_back(row, off + ip(P), -w*(S & e));
                for (label k = 0; k < D_; ++k)
                {
                    K->emplace_back(row, off + iu(P, k), -w*cv*e[cmp_[k]]);
                }
                for (label cb = 0; cb < 2; ++cb)
                {
                    const scalar eb = e & itf.faceDirection(j, cb);
                    if (eb == 0) continue;
                    for (std::size_t b = 0; b < nodes.size(); ++b)
                    {
                        K->emplace_back
                        (
                            row, solid_->dofs().dof(nodes[b], cb),
                            w*cv*eb*fi[j].N[b]*beta
                        );
                    }
                }
            }
        }
    }

    // Fluid rows through the interface velocities: K = s dM/du_f du_f/dU
    for (const interfaceEntry& e : KI)
    {
        const std::vector<int>& nodes = fi[e.face].nodes;
        for (label cb = 0; cb < 2; ++cb)
        {
            const vector Ae = e.A & itf.faceDirection(e.face, cb);
            for (std::size_t b = 0; b < nodes.size(); ++b)
            {
                const scalar w = s*fi[e.face].N[b]*beta;
                for (label k = 0; k < D_; ++k)
                {
                    const scalar val = w*Ae[cmp_[k]];
                    if (val != 0)
                    {
                        K->emplace_back
                        (
                            off + iu(e.cell, k),
                            solid_->dofs().dof(nodes[b], cb), val
                        );
                    }
                }
            }
        }
    }

    // Through the mesh: dR/dx (ALENavierStokesShape.C)
    addMeshDerivative(base, off, *K);
}


// ************************************************************************* //
