/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    ALENavierStokes: the assembly of the fluid block's residual
    (ALENavierStokesResidual.H, here instantiated for plain numbers) and
    of its derivatives with respect to the fluid unknowns, the Newton
    matrix, written by hand (ALENavierStokes.H has the equations).
\*---------------------------------------------------------------------------*/
#include "ALENavierStokesResidual.H"
#include "wedgeFvPatch.H"

namespace
{

using namespace Foam;

//- A sparse linear form: sum of coefficients times cell values
struct stencilEntry
{
    label cell;
    vector coeff;
};

using stencil = std::vector<stencilEntry>;

} // anonymous namespace


void Foam::ALENavierStokes::assemble
(
    label off,
    form::vecX& r,
    std::vector<triplet>* K,
    std::vector<interfaceEntry>* KI
)
{
    ALEGeometry<scalar> g;
    g.fromMesh(mesh_);
    ALEResidual<scalar> res;
    residual(g, std::vector<scalar>(Fm_.begin(), Fm_.end()), res);
    r = Eigen::Map<const form::vecX>(res.r.data(), res.r.size());
    const label nI = mesh_.nInternalFaces();
    Fb_.setSize(mesh_.nFaces() - nI);
    Fw_.setSize(Fb_.size());
    forAll(Fb_, b)
    {
        Fb_[b] = res.F[nI + b];
        Fw_[b] = res.Fw[b];
    }
    if (scaleStart_ < 0) scaleStart_ = res.scale;
    scale_ = min(res.scale, maxScaleGrowth*scaleStart_);
    peclet_ = maxFacePeclet();
    pecletSinceCommit_ = max(pecletSinceCommit_, peclet_);
    if (K) assembleMatrix(g, res.F, off, *K, KI);
}


void Foam::ALENavierStokes::assembleMatrix
(
    const ALEGeometry<scalar>& g,
    const std::vector<scalar>& Fface,
    label off,
    std::vector<triplet>& Kt,
    std::vector<interfaceEntry>* KI
) const
{
    std::vector<triplet>* K = &Kt;
    const label nC = mesh_.nCells(), nI = mesh_.nInternalFaces();
    const scalar s = depth_;
    const scalar rho = set_.rho, mu = set_.mu;
    const scalar rK = set_.incompressible ? 0 : 1/set_.bulkModulus;
    const auto m = [&](scalar p) { return rK > 0 ? Foam::exp(p*rK) : 1.0; };

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const std::vector<vector>& Sf = g.Sf;
    const std::vector<scalar>& magSf = g.magSf;
    const std::vector<scalar>& w = g.w;
    const std::vector<scalar>& dc = g.dc;
    const std::vector<vector>& kv = g.kv;
    const std::vector<vector>& C = g.C;
    const std::vector<scalar>& V = g.V;

    // Current cell values
    vectorField u(nC);
    scalarField p(nC);
    forAll(u, c)
    {
        u[c] = cellU(x_, c);
        p[c] = x_(ip(c));
    }

    // Jacobian helpers (momentum residual -M, mass +C;
    // K = -dr/dq = [dM/dq; -dC/dq])
    const auto jMu = [&](label P, label Q, const tensor& A)
    {
        for (label k = 0; k < D_; ++k)
        {
            for (label l = 0; l < D_; ++l)
            {
                const scalar v = A(cmp_[k], cmp_[l]);
                if (v != 0)
                {
                    K->emplace_back(off + iu(P, k), off + iu(Q, l), s*v);
                }
            }
        }
    };
    const auto jMp = [&](label P, label Q, const vector& g)
    {
        for (label k = 0; k < D_; ++k)
        {
            const scalar v = g[cmp_[k]];
            if (v != 0) K->emplace_back(off + iu(P, k), off + ip(Q), s*v);
        }
    };
    const auto jCu = [&](label P, label Q, const vector& b)
    {
        for (label l = 0; l < D_; ++l)
        {
            const scalar v = b[cmp_[l]];
            if (v != 0) K->emplace_back(off + ip(P), off + iu(Q, l), -s*v);
        }
    };
    const auto jCp = [&](label P, label Q, scalar e)
    {
        if (e != 0) K->emplace_back(off + ip(P), off + ip(Q), -s*e);
    };

    // Boundary face maps of the velocity values
    const std::vector<ALEFaceMap<scalar>> bmap = boundaryMaps(g);

    // Gauss gradient stencils (internal faces) and the boundary parts:
    // grad(phi)_P = sum_Q G_PQ phi_Q + boundary terms
    std::vector<stencil> G(nC);
    forAll(own, f)
    {
        const label P = own[f], N = nei[f];
        G[P].push_back({P, w[f]*Sf[f]/V[P]});
        G[P].push_back({N, (1 - w[f])*Sf[f]/V[P]});
        G[N].push_back({P, -w[f]*Sf[f]/V[N]});
        G[N].push_back({N, -(1 - w[f])*Sf[f]/V[N]});
    }
    // Pressure gradient: stencil with the boundary faces of unfixed p
    std::vector<stencil> Gp(G);
    // The boundary faces of each cell
    List<DynamicList<label>> cellBFaces(nC);
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        if (uBC_[patchi] == velocityBC::empty) continue;
        const labelUList& fc = fp.faceCells();
        forAll(fp, i)
        {
            const label P = fc[i];
            if (!pFixed_[patchi]) Gp[P].push_back({P, Sf[fp.start() + i]/V[P]});
            cellBFaces[P].append(fp.start() + i);
        }
    }
    // d(k . gradU_P)/du_P from the boundary faces of P
    const auto boundaryGradT = [&](label P, const vector& k)
    {
        tensor A = Zero;
        for (const label f : cellBFaces[P])
        {
            A += (k & Sf[f])/V[P]*bmap[f - nI].A;
        }
        return A;
    };

    // d(visc)/du_b of an internal face (owner P, neighbour N, correction
    // vector k, coefficient c) through the gradient of cell X: the
    // interface faces b of X give visc = -c (k . S_b)/V_X u_b
    const auto interfaceGrad = [&]
    (
        label P, label N, const vector& k, scalar c, label X
    )
    {
        for (const label f : cellBFaces[X])
        {
            const label b = interfaceFace_[f - nI];
            if (b < 0) continue;
            const tensor A = c*(k & Sf[f])/V[X]*tensor(I);
            KI->push_back({P, b, -A});
            KI->push_back({N, b, A});
        }
    };

    // dF/dp of a flux with a Rhie-Chow term coef (p_N - p_P - d . gbar):
    // the entries of -d(c)/dp
    std::vector<std::pair<label, scalar>> dFdp;
    dFdp.reserve(64);

    // Internal faces
    forAll(own, f)
    {
        const label P = own[f], N = nei[f];
        const vector& S = Sf[f];
        const scalar wf = w[f];
        const vector d = C[N] - C[P];
        const scalar pbar = wf*p[P] + (1 - wf)*p[N];
        const scalar Df = wf*rAV_[P] + (1 - wf)*rAV_[N];
        const scalar coef = Df*magSf[f]/mag(d);
        const scalar F = Fface[f];
        const scalar lam = upwind_ ? (F >= 0 ? 1.0 : 0.0) : wf;
        const vector uc = lam*u[P] + (1 - lam)*u[N];
        const scalar mf = m(pbar);

        // dF/du and dF/dp
        const vector dFduP = wf*S, dFduN = (1 - wf)*S;
        dFdp.clear();
        dFdp.push_back({P, coef});
        dFdp.push_back({N, -coef});
        for (const stencilEntry& e : Gp[P])
        {
            dFdp.push_back({e.cell, coef*wf*(d & e.coeff)});
        }
        for (const stencilEntry& e : Gp[N])
        {
            dFdp.push_back({e.cell, coef*(1 - wf)*(d & e.coeff)});
        }

        // Convection
        if (steady_)
        {
            const vector aP = uc - u[P], aN = uc - u[N];
            jMu(P, P, rho*(aP*dFduP + F*(lam - 1)*tensor(I)));
            jMu(P, N, rho*(aP*dFduN + F*(1 - lam)*tensor(I)));
            jMu(N, P, -rho*(aN*dFduP + F*lam*tensor(I)));
            jMu(N, N, -rho*(aN*dFduN - F*lam*tensor(I)));
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*aP*e.second);
                jMp(N, e.first, -rho*aN*e.second);
            }
        }
        else
        {
            const tensor AP = rho*(uc*dFduP + F*lam*tensor(I));
            const tensor AN = rho*(uc*dFduN + F*(1 - lam)*tensor(I));
            jMu(P, P, AP);
            jMu(P, N, AN);
            jMu(N, P, -AP);
            jMu(N, N, -AN);
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*uc*e.second);
                jMp(N, e.first, -rho*uc*e.second);
            }
        }
        // Pressure
        jMp(P, P, wf*S);
        jMp(P, N, (1 - wf)*S);
        jMp(N, P, -wf*S);
        jMp(N, N, -(1 - wf)*S);
        // Viscous
        const scalar cv = mu*magSf[f];
        jMu(P, P, cv*dc[f]*tensor(I));
        jMu(P, N, -cv*dc[f]*tensor(I));
        jMu(N, P, -cv*dc[f]*tensor(I));
        jMu(N, N, cv*dc[f]*tensor(I));
        if (corrected_)
        {
            const vector& k = kv[f];
            for (const stencilEntry& e : G[P])
            {
                const scalar a = cv*wf*(k & e.coeff);
                jMu(P, e.cell, -a*tensor(I));
                jMu(N, e.cell, a*tensor(I));
            }
            for (const stencilEntry& e : G[N])
            {
                const scalar a = cv*(1 - wf)*(k & e.coeff);
                jMu(P, e.cell, -a*tensor(I));
                jMu(N, e.cell, a*tensor(I));
            }
            const tensor BP = cv*wf*boundaryGradT(P, k);
            const tensor BN = cv*(1 - wf)*boundaryGradT(N, k);
            jMu(P, P, -BP);
            jMu(N, P, BP);
            jMu(P, N, -BN);
            jMu(N, N, BN);
            if (KI)
            {
                // The interface velocities in the cells' gradients
                interfaceGrad(P, N, k, cv*wf, P);
                interfaceGrad(P, N, k, cv*(1 - wf), N);
            }
        }
        // Mass
        jCu(P, P, mf*dFduP);
        jCu(P, N, mf*dFduN);
        jCu(N, P, -mf*dFduP);
        jCu(N, N, -mf*dFduN);
        for (const auto& e : dFdp)
        {
            jCp(P, e.first, mf*e.second);
            jCp(N, e.first, -mf*e.second);
        }
        const scalar dm = mf*rK*F;
        jCp(P, P, dm*wf);
        jCp(P, N, dm*(1 - wf));
        jCp(N, P, -dm*wf);
        jCp(N, N, -dm*(1 - wf));
    }

    // Boundary faces
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        const velocityBC bc = uBC_[patchi];
        if (bc == velocityBC::empty) continue;
        const labelUList& fc = fp.faceCells();
        const bool pfix = pFixed_[patchi];
        forAll(fp, i)
        {
            const label f = fp.start() + i, b = f - nI;
            const label P = fc[i];
            const ALEFaceMap<scalar>& fm = bmap[b];
            const vector& S = Sf[f];
            const scalar magS = magSf[f];
            const scalar pb = pfix ? pFixedValue_[patchi][i] : p[P];
            const vector ub = (fm.A & u[P]) + fm.c;

            // Pressure and viscous forces
            if (!pfix) jMp(P, P, S);
            jMu(P, P, -mu*magS*fm.As);
            // No flux through wedge faces nor the interface
            if (bc == velocityBC::wedge) continue;
            if (bc == velocityBC::interface)
            {
                if (KI)
                {
                    KI->push_back
                    (
                        {P, interfaceFace_[b], -mu*magS*g.dcb[b]*tensor(I)}
                    );
                }
                continue;
            }

            // Flux relative to the face; Rhie-Chow against a fixed
            // pressure at an outlet
            const bool rc = bc == velocityBC::zeroGradient && pfix;
            const scalar coef = rc ? rAV_[P]*magS*g.dcb[b] : 0;
            const scalar F = Fface[f];
            const vector uconv = steady_ ? ub - u[P] : ub;
            const bool inj = injection(fp.name());
            const scalar mb = inj ? 1.0 : m(pb);
            const vector dFdu = S & fm.A;
            dFdp.clear();
            if (rc)
            {
                dFdp.push_back({P, coef});
                for (const stencilEntry& e : Gp[P])
                {
                    dFdp.push_back({e.cell, coef*(g.delta[b] & e.coeff)});
                }
            }
            const tensor Tc = steady_ ? fm.A - tensor(I) : fm.A;
            jMu(P, P, rho*(uconv*dFdu + F*Tc));
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*uconv*e.second);
                jCp(P, e.first, mb*e.second);
            }
            jCu(P, P, mb*dFdu);
            if (!pfix && !inj) jCp(P, P, mb*rK*F);
        }
    }

    // Cell terms: time derivative, mass storage
    const scalar rdt = 1/dt_;
    for (label P = 0; P < nC; ++P)
    {
        if (!steady_) jMu(P, P, a0_*rho*V[P]*rdt*tensor(I));
        jCp(P, P, a0_*m(p[P])*rK*V[P]*rdt);
    }
}


// ************************************************************************* //
