/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    ALENavierStokes: the assembly of the fluid block's residual and its
    derivatives with respect to the fluid unknowns (ALENavierStokes.H has
    the equations).
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "wallClock.H"
#include "formError.H"
#include "wedgeFvPatch.H"
#include "mathematicalConstants.H"

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

//- The representation of a boundary face value and normal gradient of the
//  velocity as affine maps of the cell velocity:
//      u_b = T u_P + c,   snGrad_b = Ts u_P + cs
struct faceMap
{
    tensor T = Zero;
    vector c = Zero;
    tensor Ts = Zero;
    vector cs = Zero;
};

} // anonymous namespace


void Foam::ALENavierStokes::assemble
(
    label off,
    form::vecX& r,
    std::vector<triplet>* K,
    std::vector<interfaceEntry>* KI
)
{
    const label nC = mesh_.nCells();
    const scalar s = depth_;
    const scalar rho = set_.rho, mu = set_.mu;
    const scalar rK = set_.incompressible ? 0 : 1/set_.bulkModulus;
    const auto m = [&](scalar p) { return rK > 0 ? Foam::exp(p*rK) : 1.0; };
    r.setZero(x_.size());
    Fb_.setSize(mesh_.nFaces() - mesh_.nInternalFaces());
    Fb_ = 0;
    Fw_.setSize(Fb_.size());
    Fw_ = Zero;

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();
    const surfaceVectorField& kv = mesh_.nonOrthCorrectionVectors();
    const volVectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();

    // Magnitudes of the terms per cell (the residual scale)
    scalarField aM(nC, 0), aC(nC, 0);

    // Current cell values
    vectorField u(nC);
    scalarField p(nC);
    forAll(u, c)
    {
        u[c] = cellU(x_, c);
        p[c] = x_(ip(c));
    }

    // Residual and Jacobian helpers (momentum residual -M, mass +C;
    // K = -dr/dq = [dM/dq; -dC/dq])
    const auto addM = [&](label P, const vector& v)
    {
        for (label k = 0; k < D_; ++k) r(iu(P, k)) -= s*v[cmp_[k]];
    };
    const auto addC = [&](label P, scalar c) { r(ip(P)) += s*c; };
    const auto jMu = [&](label P, label Q, const tensor& A)
    {
        if (!K) return;
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
        if (!K) return;
        for (label k = 0; k < D_; ++k)
        {
            const scalar v = g[cmp_[k]];
            if (v != 0) K->emplace_back(off + iu(P, k), off + ip(Q), s*v);
        }
    };
    const auto jCu = [&](label P, label Q, const vector& b)
    {
        if (!K) return;
        for (label l = 0; l < D_; ++l)
        {
            const scalar v = b[cmp_[l]];
            if (v != 0) K->emplace_back(off + ip(P), off + iu(Q, l), -s*v);
        }
    };
    const auto jCp = [&](label P, label Q, scalar e)
    {
        if (K && e != 0) K->emplace_back(off + ip(P), off + ip(Q), -s*e);
    };

    // Boundary face maps of the velocity and pressure values
    List<List<faceMap>> bmap(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        List<faceMap>& fm = bmap[patchi];
        fm.setSize(fp.size());
        const velocityBC bc = uBC_[patchi];
        if (bc == velocityBC::empty) continue;
        const scalarField& dcb = fp.deltaCoeffs();
        const vectorField nf(fp.nf());
        forAll(fp, i)
        {
            faceMap& f = fm[i];
            switch (bc)
            {
                case velocityBC::fixedValue:
                    f.c = uFixed_[patchi][i];
                    f.Ts = -dcb[i]*tensor(I);
                    f.cs = dcb[i]*uFixed_[patchi][i];
                    break;
                case velocityBC::interface:
                {
                    const vector& ub = uInterface_
                    [
                        interfaceFace_[fp.start() + i - mesh_.nInternalFaces()]
                    ];
                    f.c = ub;
                    f.Ts = -dcb[i]*tensor(I);
                    f.cs = dcb[i]*ub;
                    break;
                }
                case velocityBC::zeroGradient:
                    f.T = I;
                    break;
                case velocityBC::slip:
                    f.T = I - sqr(nf[i]);
                    f.Ts = -dcb[i]*sqr(nf[i]);
                    break;
                case velocityBC::wedge:
                {
                    const wedgeFvPatch& wp = refCast<const wedgeFvPatch>(fp);
                    f.T = wp.faceT();
                    f.Ts = 0.5*dcb[i]*(wp.cellT() - tensor(I));
                    break;
                }
                default:
                    break;
            }
        }
    }
    const auto pFace = [&](label patchi, label i, label P)
    {
        return pFixed_[patchi] ? pFixedValue_[patchi][i] : p[P];
    };

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
    // Pressure gradient: stencil with the boundary faces of unfixed p,
    // and the constant part from fixed pressures
    std::vector<stencil> Gp(G);
    vectorField gp0(nC, Zero);
    // Velocity gradient: boundary parts sum_b S_b (T u_P + c)/V per cell
    List<DynamicList<label>> cellBFaces(nC);   // (patch, face) pairs packed
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& fp = mesh_.boundary()[patchi];
        if (uBC_[patchi] == velocityBC::empty) continue;
        const labelUList& fc = fp.faceCells();
        forAll(fp, i)
        {
            const label P = fc[i];
            const vector& Sb = Sf.boundaryField()[patchi][i];
            if (pFixed_[patchi]) gp0[P] += pFixedValue_[patchi][i]*Sb/V[P];
            else Gp[P].push_back({P, Sb/V[P]});
            cellBFaces[P].append(patchi);
            cellBFaces[P].append(i);
        }
    }
    vectorField gradP(gp0);
    tensorField gradU(nC, Zero);
    for (label P = 0; P < nC; ++P)
    {
        for (const stencilEntry& e : Gp[P]) gradP[P] += e.coeff*p[e.cell];
        for (const stencilEntry& e : G[P]) gradU[P] += e.coeff*u[e.cell];
        const DynamicList<label>& bf = cellBFaces[P];
        for (label j = 0; j < bf.size(); j += 2)
        {
            const faceMap& f = bmap[bf[j]][bf[j + 1]];
            const vector& Sb = Sf.boundaryField()[bf[j]][bf[j + 1]];
            gradU[P] += Sb*((f.T & u[P]) + f.c)/V[P];
        }
    }
    // d(k . gradU_P)/du_P from the boundary faces of P
    const auto boundaryGradT = [&](label P, const vector& k)
    {
        tensor A = Zero;
        const DynamicList<label>& bf = cellBFaces[P];
        for (label j = 0; j < bf.size(); j += 2)
        {
            const faceMap& f = bmap[bf[j]][bf[j + 1]];
            const vector& Sb = Sf.boundaryField()[bf[j]][bf[j + 1]];
            A += (k & Sb)/V[P]*f.T;
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
        const DynamicList<label>& bf = cellBFaces[X];
        for (label j = 0; j < bf.size(); j += 2)
        {
            if (uBC_[bf[j]] != velocityBC::interface) continue;
            const fvPatch& fp = mesh_.boundary()[bf[j]];
            const label b =
                interfaceFace_[fp.start() + bf[j + 1] - mesh_.nInternalFaces()];
            const vector& Sb = Sf.boundaryField()[bf[j]][bf[j + 1]];
            const tensor A = c*(k & Sb)/V[X]*tensor(I);
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
        const vector ubar = wf*u[P] + (1 - wf)*u[N];
        const scalar Df = wf*rAV_[P] + (1 - wf)*rAV_[N];
        const scalar coef = Df*magSf[f]/mag(d);
        const vector gbar = wf*gradP[P] + (1 - wf)*gradP[N];
        const scalar cRC = coef*(p[N] - p[P] - (gbar & d));
        const scalar F = (ubar & S) - cRC - Fm_[f];
        const scalar lam = upwind_ ? (F >= 0 ? 1.0 : 0.0) : wf;
        const vector uc = lam*u[P] + (1 - lam)*u[N];

        // Momentum: convection, pressure, viscous
        const vector snGrad =
            dc[f]*(u[N] - u[P])
          + (corrected_ ? (kv[f] & (wf*gradU[P] + (1 - wf)*gradU[N])) : vector::zero);
        const vector visc = -mu*magSf[f]*snGrad;
        const vector pres = pbar*S;
        if (steady_)
        {
            addM(P, rho*F*(uc - u[P]) + pres + visc);
            addM(N, -rho*F*(uc - u[N]) - pres - visc);
        }
        else
        {
            addM(P, rho*F*uc + pres + visc);
            addM(N, -rho*F*uc - pres - visc);
        }
        // Mass
        const scalar mf = m(pbar);
        addC(P, mf*F);
        addC(N, -mf*F);
        {
            const scalar a = mag(rho*F*uc) + mag(pres) + mag(visc);
            aM[P] += a;
            aM[N] += a;
            aC[P] += mag(mf*F) + mag(ubar & S);
            aC[N] += mag(mf*F) + mag(ubar & S);
        }

        if (!K) continue;

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
        const scalarField& dcb = fp.deltaCoeffs();
        const vectorField delta(fp.delta());
        const bool pfix = pFixed_[patchi];
        forAll(fp, i)
        {
            const label P = fc[i];
            const faceMap& fm = bmap[patchi][i];
            const vector& S = Sf.boundaryField()[patchi][i];
            const scalar magS = magSf.boundaryField()[patchi][i];
            const scalar pb = pFace(patchi, i, P);
            const vector ub = (fm.T & u[P]) + fm.c;

            // Pressure and viscous forces
            const vector wallForce = pb*S - mu*magS*((fm.Ts & u[P]) + fm.cs);
            addM(P, wallForce);
            Fw_[fp.start() + i - mesh_.nInternalFaces()] = wallForce;
            aM[P] += mag(pb*S) + mag(mu*magS*((fm.Ts & u[P]) + fm.cs));
            if (K)
            {
                if (!pfix) jMp(P, P, S);
                jMu(P, P, -mu*magS*fm.Ts);
            }
            // No flux through wedge faces (the rotated cell velocity lies
            // in the wedge plane, which moves within itself), nor through
            // the interface (the fluid moves with the solid's wall: the
            // flux relative to the face is zero)
            if (bc == velocityBC::wedge) continue;
            if (bc == velocityBC::interface)
            {
                if (KI)
                {
                    const label b =
                        interfaceFace_[fp.start() + i - mesh_.nInternalFaces()];
                    KI->push_back({P, b, -mu*magS*dcb[i]*tensor(I)});
                }
                continue;
            }

            // Flux relative to the face; Rhie-Chow against a fixed
            // pressure at an outlet
            const bool rc = bc == velocityBC::zeroGradient && pfix;
            scalar cRC = 0, coef = 0;
            if (rc)
            {
                coef = rAV_[P]*magS*dcb[i];
                cRC = coef*(pb - p[P] - (gradP[P] & delta[i]));
            }
            const scalar F = (ub & S) - cRC - Fm_[fp.start() + i];
            Fb_[fp.start() + i - mesh_.nInternalFaces()] = F;
            const vector uconv = steady_ ? ub - u[P] : ub;
            addM(P, rho*F*uconv);
            // The injection prescribes mass: its volume is at the
            // reference density (as the hydrostatic model's)
            const bool injection =
                set_.injectedVolume && set_.inletPatches.found(fp.name());
            const scalar mb = injection ? 1.0 : m(pb);
            addC(P, mb*F);
            aM[P] += mag(rho*F*ub);
            aC[P] += mag(mb*F) + mag(ub & S);

            if (!K) continue;
            const vector dFdu = S & fm.T;
            dFdp.clear();
            if (rc)
            {
                dFdp.push_back({P, coef});
                for (const stencilEntry& e : Gp[P])
                {
                    dFdp.push_back({e.cell, coef*(delta[i] & e.coeff)});
                }
            }
            const tensor Tc = steady_ ? fm.T - tensor(I) : fm.T;
            jMu(P, P, rho*(uconv*dFdu + F*Tc));
            for (const auto& e : dFdp)
            {
                jMp(P, e.first, rho*uconv*e.second);
                jCp(P, e.first, mb*e.second);
            }
            jCu(P, P, mb*dFdu);
            if (!pfix && !injection) jCp(P, P, mb*rK*F);
        }
    }

    // Cell terms: time derivative, mass storage
    const scalar rdt = 1/dt_;
    for (label P = 0; P < nC; ++P)
    {
        if (!steady_)
        {
            addM(P, rho*(V[P]*u[P] - V0_[P]*cellU(x0_, P))*rdt);
            jMu(P, P, rho*V[P]*rdt*tensor(I));
        }
        const scalar p0 = x0_(ip(P));
        addC(P, (m(p[P])*V[P] - m(p0)*V0_[P])*rdt);
        jCp(P, P, m(p[P])*rK*V[P]*rdt);
        aC[P] += mag(m(p[P])*V[P] - m(p0)*V0_[P])*rdt;
    }
    scale_ = s*Foam::sqrt(sumSqr(aM) + sumSqr(aC));
}


// ************************************************************************* //
