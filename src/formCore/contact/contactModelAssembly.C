/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    contactModel: the one assembly of the node-to-target equations, for
    every target kind (2D profiles and element edges, 3D surfaces and
    element faces) and both dimensions. Each kind projects its node and
    supplies a nodeTarget (contactModelImpl.H): over q = (the node's dofs,
    the target nodes' dofs), the gap g, the normal n, the tangent basis
    t_a, the slip rate s_a, their derivatives, and the weights w_b of the
    force on each node block (1 for the contactor node, -N_b for target
    node b). Here, with the multipliers lambda, tau_a of the node:
        f      = k (lambda n + tau_a t_a)        force on the node
        F_b    = w_b f                           on each block (w_0 = 1)
        r_lambda = k w(g, lambda)                normal constraint
        r_tau  = k v(s, tau, lambda)             friction constraint
    (constraintFunctions.H) and the Newton matrix K = -dR/dq:
        df/dq  = k (lambda dn/dq + tau_a dt_a/dq)
        dF_b/dq = w_b df/dq + f dw_b/dq
        K_F,lambda = -w_b k n,   K_F,tau_a = -w_b k t_a,
        K_lambda,q = -k w_g dg/dq,  K_lambda,lambda = -k w_lambda,
        K_tau,q = -k v_s ds/dq,  K_tau,tau = -k v_tau,
        K_tau,lambda = -k v_lambda.
    A force-controlled rigid tool moves the node's projection with its
    unknown position z along e (y = x - z e): d/dz = -e . d/dy on every
    row, and its equation r_z = F - e . sum f adds the row e . df.
    A shell contactor node touches with the point y = x + h V of one face
    of the sheet (V its director, h = +-t/2): the kinds then give the
    derivatives over its 5 dofs, with J = dy/dq = [I h dV/d(alpha, beta)],
    and its rows carry the generalised forces J^T f and the tangent
    J^T df/dq + sum_i f_i d2y_i/dq2 (h d2V: the force's moment about the
    director's rotation axes changes as the director turns).
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "constraintFunctions.H"
#include <cmath>

namespace form
{

contactModel::impl::frictionResult contactModel::impl::frictionLaw
(
    const vecX& s,
    const vecX& tau,
    double lambda,
    double mu,
    double dt
) const
{
    const double eT = epsT > 0 ? epsT : std::pow(1e-4*spacing, 2);
    const double rho = controls.frictionAugmentation*dt/rateA;
    const bool ac = controls.frictionLaw == "alartCurnier";
    frictionResult R;
    if (s.size() == 1)
    {
        const frictionConstraint c = ac
          ? alartCurnierFrictionFunction(s(0), tau(0), lambda, mu, eT, rho)
          : frictionConstraintFunction(s(0), tau(0), lambda, mu, eT);
        R.v = vecX::Constant(1, c.v);
        R.dvds = matX::Constant(1, 1, c.dvds);
        R.dvdtau = matX::Constant(1, 1, c.dvdtau);
        R.dvdl = vecX::Constant(1, c.dvdl);
        return R;
    }
    const Eigen::Vector2d s2 = s, tau2 = tau;
    frictionVector c;
    if (ac)
    {
        c = alartCurnierFrictionVector(s2, tau2, lambda, mu, eT, rho);
    }
    else
    {
        // regularised: v = tau + mu lambda s/sqrt(|s|^2 + epsT)
        const double q = std::sqrt(s2.squaredNorm() + eT);
        c.v = tau2 + mu*lambda*s2/q;
        c.dvds = mu*lambda
           *(Eigen::Matrix2d::Identity()/q - s2*s2.transpose()/(q*q*q));
        c.dvdl = mu*s2/q;
    }
    R.v = c.v;
    R.dvds = c.dvds;
    R.dvdtau = c.dvdtau;
    R.dvdl = c.dvdl;
    return R;
}


void contactModel::impl::shellContactor
(
    const pairData& p,
    int a,
    const vecX& U,
    nodeTarget& q
) const
{
    const int node = p.nodes[a];
    const double h = p.offset[a];
    const directorState D = shells->directorAt(node, dofs, U);
    q.dofs.clear();
    for (int i = 0; i < 5; ++i) q.dofs.push_back(dofs.dof(node, i));
    q.J = matX::Zero(3, 5);
    q.J.leftCols(3).setIdentity();
    q.J.rightCols(2) = h*D.dV;
    q.d2y.assign(3, matX::Zero(5, 5));
    for (int i = 0; i < 3; ++i)
    {
        q.d2y[i](3, 3) = h*D.d2V[0](i);
        q.d2y[i](3, 4) = q.d2y[i](4, 3) = h*D.d2V[1](i);
        q.d2y[i](4, 4) = h*D.d2V[2](i);
    }
}


void contactModel::impl::assembleNode
(
    pairData& p,
    int a,
    const nodeTarget& q,
    double dt,
    const vecX& U,
    vecX& fext,
    vecX& r,
    std::vector<triplet>* K
)
{
    const int N = nDofs;
    const int d = nDim;
    const int nt = p.perNode - 1;
    const int nq = int(q.dofs.size());
    // The contactor's dofs (nc) and its map J; then the target nodes
    const bool mapped = q.J.size() > 0;
    const int nc = mapped ? int(q.J.cols()) : d;
    const int nb = 1 + (nq - nc)/d;
    const int il = p.first + p.perNode*a;
    const double lambda = x(il);
    const vecX tau = x.segment(il + 1, nt);
    // A shell's contact point gives way through the half thickness:
    // g~ = g + c k lambda
    const double ck = p.compliance.empty() ? 0.0 : p.compliance[a]*k;
    const double gap = q.gap + ck*lambda;
    const normalConstraint c = normalConstraintFunction(gap, lambda, epsN);
    // Block b's first row in q
    const auto first = [nc, d](int b) { return b == 0 ? 0 : nc + d*(b - 1); };
    // A force on the contact point as generalised forces on the
    // contactor's dofs (J^T v)
    const auto toContactor = [&](const vecX& v) -> vecX
    {
        return mapped ? vecX(q.J.transpose()*v) : v;
    };

    vecX ft = vecX::Zero(d);
    for (int al = 0; al < nt; ++al) ft += k*tau(al)*q.t.col(al);
    const vecX f = k*lambda*q.n + ft;
    {
        const vecX fc = toContactor(f), ftc = toContactor(ft);
        for (int i = 0; i < nc; ++i)
        {
            fext(q.dofs[i]) += fc(i);
            friction(q.dofs[i]) += ftc(i);
        }
    }
    for (int b = 1; b < nb; ++b)
    {
        for (int i = 0; i < d; ++i)
        {
            fext(q.dofs[first(b) + i]) += q.weight[b]*f(i);
            friction(q.dofs[first(b) + i]) += q.weight[b]*ft(i);
        }
    }
    if (q.tool >= 0) toolForce[q.tool].head(d) += f;
    r(il) = k*c.w;
    updateStatus(p, a, lambda, gap, U, K != nullptr);

    frictionResult fc;
    if (nt > 0)
    {
        fc = frictionLaw(q.s, tau, lambda, p.mu, dt);
        r.segment(il + 1, nt) = k*fc.v;
    }
    if (!K) return;
    const auto add = [K](int i, int j, double v)
    {
        K->emplace_back(i, j, v);
    };

    // dF/dq: the contactor's rows J^T df + sum_i f_i d2y_i, the target
    // nodes' w_b df + f dw_b
    matX df = k*lambda*q.dn;
    for (int al = 0; al < nt; ++al) df += k*tau(al)*q.dt[al];
    matX dF(nq, nq);
    dF.topRows(nc) = mapped ? matX(q.J.transpose()*df) : df;
    for (std::size_t i = 0; i < q.d2y.size(); ++i)
    {
        dF.topLeftCorner(nc, nc) += f(i)*q.d2y[i];
    }
    for (int b = 1; b < nb; ++b)
    {
        dF.middleRows(first(b), d) =
            q.weight[b]*df + f*q.dWeight.row(b - 1);
    }
    // The force's directions on the contactor's rows: J^T n, J^T t_a
    matX dirs(d, 1 + nt);
    dirs.col(0) = q.n;
    for (int al = 0; al < nt; ++al) dirs.col(1 + al) = q.t.col(al);
    if (mapped) dirs = q.J.transpose()*dirs;
    const matX Ktq = nt > 0 ? matX(-k*fc.dvds*q.ds) : matX();
    for (int i = 0; i < nq; ++i)
    {
        const int di = q.dofs[i];
        for (int j = 0; j < nq; ++j) add(di, q.dofs[j], -dF(i, j));
        // on the target nodes' rows: w_b n, w_b t_a
        const double w = i < nc ? 1.0 : q.weight[1 + (i - nc)/d];
        const int ii = (i - nc) % d;
        add(di, N + il, i < nc ? -k*dirs(i, 0) : -w*k*q.n(ii));
        add(N + il, di, -k*c.dwdg*q.dGap(i));
        for (int al = 0; al < nt; ++al)
        {
            add
            (
                di, N + il + 1 + al,
                i < nc ? -k*dirs(i, 1 + al) : -w*k*q.t(ii, al)
            );
            add(N + il + 1 + al, di, Ktq(al, i));
        }
    }
    add(N + il, N + il, -k*(c.dwdl + c.dwdg*ck));
    for (int al = 0; al < nt; ++al)
    {
        for (int be = 0; be < nt; ++be)
        {
            add(N + il + 1 + al, N + il + 1 + be, -k*fc.dvdtau(al, be));
        }
        add(N + il + 1 + al, N + il, -k*fc.dvdl(al));
    }

    const int iz = q.tool >= 0 ? toolUnknown[q.tool] : -1;
    if (iz < 0) return;
    // Force-controlled tool: the contact point in the tool's frame is
    // y = x(q) - z e, and the derivatives in y are those in the
    // contactor's translations (the first d columns of q, where dy/dq is
    // the identity): d/dz = -e . d/dy (a rigid tool's q is the contactor
    // alone)
    const vecX e = tools[q.tool].direction.head(d);
    const vecX dfe = df.leftCols(d)*e;
    const vecX dFe = mapped ? vecX(q.J.transpose()*dfe) : dfe;
    for (int i = 0; i < nc; ++i)
    {
        add(q.dofs[i], N + iz, dFe(i));
        add(N + iz, q.dofs[i], e.dot(df.col(i)));
    }
    add(N + il, N + iz, k*c.dwdg*q.dGap.head(d).dot(e));
    add(N + iz, N + il, k*e.dot(q.n));
    for (int al = 0; al < nt; ++al)
    {
        add(N + il + 1 + al, N + iz, -Ktq.row(al).head(d).dot(e));
        add(N + iz, N + il + 1 + al, k*e.dot(q.t.col(al)));
    }
    add(N + iz, N + iz, -e.dot(dfe));
}

} // namespace form
