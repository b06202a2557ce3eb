/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    ALENavierStokes: the mesh following the solid (moveMesh), the
    interface and the derivatives of the fluid residual with respect to
    the solid's interface dofs (evaluateInterface; ALENavierStokes.H).
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "wallClock.H"
#include "fluidSolidInterface.H"
#include "solidModel.H"
#include "formError.H"
#include <map>

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
    colourMotionUnits();
}


void Foam::ALENavierStokes::colourMotionUnits()
{
    // The equations of cell P depend on the points of P, of its
    // neighbours N (face weights, delta coefficients, centres) and of
    // theirs (the Gauss gradients of N in the Rhie-Chow and non-orthogonal
    // corrections use N's face weights). So moving a point changes the
    // equations of its cells and two layers around them, and the forces
    // on the interface faces those cells own.
    const fluidSolidInterface& itf = *interface_;
    const List<labelList>& units = itf.motionUnits();
    const labelListList& pointCells = mesh_.pointCells();
    const labelListList& cellCells = mesh_.cellCells();
    const label nC = mesh_.nCells();
    unitCells_.setSize(units.size());
    colours_.clear();
    labelList stamp(nC, -1);
    std::vector<std::vector<char>> used;
    forAll(units, u)
    {
        unitCells_[u].clear();
        if
        (
            itf.unitKind(u, 0) == fluidSolidInterface::fixedUnit
         && itf.unitKind(u, 1) == fluidSolidInterface::fixedUnit
        )
        {
            continue;
        }
        DynamicList<label> cells;
        for (const label p : units[u])
        {
            for (const label c : pointCells[p])
            {
                if (stamp[c] != u) { stamp[c] = u; cells.append(c); }
            }
        }
        for (label layer = 0; layer < 2; ++layer)
        {
            const label n = cells.size();
            for (label k = 0; k < n; ++k)
            {
                for (const label c : cellCells[cells[k]])
                {
                    if (stamp[c] != u) { stamp[c] = u; cells.append(c); }
                }
            }
        }
        unitCells_[u].transfer(cells);
        // Greedy: the first colour none of whose units shares a cell
        std::size_t k = 0;
        for (;; ++k)
        {
            if (k == used.size())
            {
                used.emplace_back(nC, 0);
                colours_.emplace_back();
            }
            bool free = true;
            for (const label c : unitCells_[u])
            {
                if (used[k][c]) { free = false; break; }
            }
            if (free) break;
        }
        for (const label c : unitCells_[u]) used[k][c] = 1;
        colours_[k].push_back(u);
    }
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
    if (Un_.size() != Us.size()) Un_ = Us;

    // The mesh follows the solid
    const pointField base(itf.points(Us));
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

    // Through the mesh. R (the fluid's residuals and its forces on the
    // solid) depends on the mesh points x; the points on the interface
    // point displacements d_i by the harmonic extension, and d_i on U by
    // (1) of fluidSolidInterface.H:
    //     dR/dU = sum_units dR/dx_u (dx_u/dd_i) (dd_i/dU),
    // dx_u/dd_i = 1 for the unit of interface point i, H_c(u, i) for a
    // free unit, 0 for a fixed one. dR/dx_u by central differences,
    // coloured: the units of one colour change disjoint sets of cells, so
    // one pair of evaluations per colour and component gives them all.
    const std::vector<int> dofs = itf.dofs();
    std::map<int, label> local;
    forAll(dofs, k) local[dofs[k]] = k;
    const label nF = x_.size(), nd = dofs.size();
    // Transposed, so that a row's columns are contiguous
    form::matX DgT = form::matX::Zero(nd, nF + nd);
    const scalarField FbSave(Fb_);
    const vectorField FwSave(Fw_);
    const scalar scaleSave = scale_;
    const scalar h = 1e-6*itf.minFaceLength();
    const label nR = D_ + 1;
    const List<labelList>& units = itf.motionUnits();
    const auto& pi = itf.pointInterpolation();
    const cellList& cells = mesh_.cells();
    form::vecX rp, rm, coef(nd), dF(nd);
    vectorField Fp(faces.size()), Fm(faces.size());
    // The mesh fluxes of the base mesh; a perturbation changes those of
    // the faces of the points it moves
    const scalarField FmBase(Fm_);
    const labelListList& pointFaces = mesh_.pointFaces();
    const faceList& meshFaces = mesh_.faces();
    const auto evaluateAt = [&]
    (
        const pointField& pts,
        const std::vector<label>& members,
        form::vecX& rr,
        vectorField& FF
    )
    {
        const auto start = std::chrono::steady_clock::now();
        mesh_.movePoints(pts);
        Fm_ = FmBase;
        for (const label u : members)
        {
            for (const label p : units[u])
            {
                for (const label f : pointFaces[p])
                {
                    Fm_[f] = meshFaces[f].sweptVol(points0_, pts)/dt_;
                }
            }
        }
        meshMotionTime_ += form::secondsSince(start);
        assemble(off, rr, nullptr, nullptr);
        forAll(FF, j) FF[j] = Fw_[faces[j] - nI];
    };
    for (label cc = 0; cc < 2; ++cc)
    {
        for (const std::vector<label>& colour : colours_)
        {
            std::vector<label> members;
            for (const label u : colour)
            {
                if (itf.unitKind(u, cc) != fluidSolidInterface::fixedUnit)
                {
                    members.push_back(u);
                }
            }
            if (members.empty()) continue;
            for (const label sign : {1, -1})
            {
                pointField pts(base);
                for (const label u : members)
                {
                    for (const label p : units[u])
                    {
                        pts[p] += sign*h*itf.direction(p, cc);
                    }
                }
                if (sign > 0) evaluateAt(pts, members, rp, Fp);
                else evaluateAt(pts, members, rm, Fm);
            }
            for (const label u : members)
            {
                // dx_u/dU: the columns of the solid's dofs (component cc)
                coef.setZero();
                const label kind = itf.unitKind(u, cc);
                for (label i = 0; i < itf.nPoints(); ++i)
                {
                    const scalar w =
                        kind == fluidSolidInterface::freeUnit
                      ? itf.unitWeight(u, cc, i)
                      : scalar(kind == i);
                    if (w == 0) continue;
                    for (std::size_t a = 0; a < pi[i].nodes.size(); ++a)
                    {
                        const int d = solid_->dofs().dof(pi[i].nodes[a], cc);
                        coef(local[d]) += w*pi[i].N[a];
                    }
                }
                // Fluid rows of the unit's cells; forces on their faces
                dF.setZero();
                for (const label c : unitCells_[u])
                {
                    for (label k = 0; k < nR; ++k)
                    {
                        const label row = c*nR + k;
                        const scalar d = (rp(row) - rm(row))/(2*h);
                        if (d != 0) DgT.col(row) += d*coef;
                    }
                    for (const label f : cells[c])
                    {
                        if (f < nI) continue;
                        const label j = interfaceFace_[f - nI];
                        if (j < 0) continue;
                        const vector dFj = depth_*(Fp[j] - Fm[j])/(2*h);
                        for (label cb = 0; cb < 2; ++cb)
                        {
                            const scalar v = dFj & itf.faceDirection(j, cb);
                            const auto& fj = fi[j];
                            for (std::size_t a = 0; a < fj.nodes.size(); ++a)
                            {
                                const int d =
                                    solid_->dofs().dof(fj.nodes[a], cb);
                                dF(local[d]) += fj.N[a]*v;
                            }
                        }
                    }
                }
                for (label k = 0; k < nd; ++k)
                {
                    if (dF(k) != 0) DgT.col(nF + k) += dF(k)*coef;
                }
            }
        }
    }
    for (label row = 0; row < nF + nd; ++row)
    {
        for (label col = 0; col < nd; ++col)
        {
            const scalar val = DgT(col, row);
            if (val == 0) continue;
            // K = -dR/dU: R = r for the fluid rows, f_ext for the solid's
            K->emplace_back
            (
                row < nF ? off + row : dofs[row - nF], dofs[col], -val
            );
        }
    }
    const auto start = std::chrono::steady_clock::now();
    mesh_.movePoints(base);
    meshMotionTime_ += form::secondsSince(start);
    Fm_ = FmBase;
    Fb_ = FbSave;
    Fw_ = FwSave;
    scale_ = scaleSave;
}


// ************************************************************************* //
