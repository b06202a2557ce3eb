/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Contact by constraint functions (contactModel.H) in 3D, rigid tools:
    contactor nodes against a rigidSurface (rigidSurface.H). Per node the
    normal multiplier lambda and, with friction, two tangential ones
    tau = (tau_1, tau_2) in the node's tangent frame (t1, t2)
    (tangentFrame: built from a fixed reference direction, so that it
    turns only with the normal). With y = x - d(t) the node in the tool's
    frame, the projection (g, n, dn/dy) and c = y - g n the closest point:
        node:       f_ext += k (lambda n + tau_a t_a)
        lambda:     r = k w(g, lambda)
        tau:        r = k v(s, tau, lambda)     (alartCurnierFrictionVector)
        s_a = t_a . (A (c - c_n) + B (c_n - c_n-1))/deltaT
    the motion of the closest point over the step in the tangent frame
    (the 3D form of the 2D arc-length rate; A, B: setSlipRateLaw), with
        dc/dy = I - n n^T - g dn/dy,
        ds_a/dy = (A t_a^T dc/dy + D^T dt_a/dy)/deltaT,
        D = A (c - c_n) + B (c_n - c_n-1)
    and the tangent blocks of the 2D code with 3-vectors:
        K_uu = -k (lambda dn/dy + tau_a dt_a/dy),  K_u,lambda = -k n,
        K_u,tau_a = -k t_a, K_lambda,u = -k w_g n^T,
        K_tau,u = -k v_s ds/dy, K_tau,tau = -k v_tau, K_tau,lambda = -k v_lambda
    and the force-controlled tool's column and row (y = x - z e).
    The reference direction of a node is the coordinate axis least
    aligned with its first normal; at a commit where the normal has
    turned within 25 deg of it, it is chosen again and the committed
    friction multipliers are re-expressed in the new frame (the tangential
    force vector is unchanged).
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "constraintFunctions.H"
#include "formError.H"
#include <cmath>

namespace form
{

void contactModel::impl::initialise3D
(
    pairData& p,
    const vecX& U,
    double t
)
{
    if (p.surface)
    {
        initialiseDeformable3D(p, U);
        return;
    }
    const vec3 d = translation(p.tool, t);
    for (std::size_t a = 0; a < p.nodes.size(); ++a)
    {
        const vec3 y = position3(p.nodes[a], U) - d;
        const surfaceProjection P = tools[p.tool].surface->project(y);
        p.cCommitted[a] = y - P.gap*P.normal;
        p.slip3[a] = vec3::Zero();
        p.ref[a] = leastAligned(P.normal);
    }
}


void contactModel::impl::commit3D(pairData& p, const vecX& U)
{
    const vec3 d = p.surface ? vec3::Zero() : translation(p.tool, tCommitted);
    for (std::size_t a = 0; a < p.nodes.size(); ++a)
    {
        surfaceProjection P;
        if (p.surface)
        {
            // Deformable target: the node's motion relative to the target
            // point under it over the step
            const faceProjection Pf = p.surface->project
            (
                position3(p.nodes[a], U), p.nodes[a], U, p.edge[a]
            );
            p.slip3[a] = Pf.onTarget
              ? relativeMotion(p.nodes[a], Pf, U) : vec3::Zero();
            p.lastSlip[a] = p.slip3[a].norm();
            if (!Pf.onTarget) continue;
            P.normal = Pf.normal;
        }
        else
        {
            const vec3 y = position3(p.nodes[a], U) - d;
            P = tools[p.tool].surface->project(y);
            const vec3 c = y - P.gap*P.normal;
            p.slip3[a] = c - p.cCommitted[a];
            p.cCommitted[a] = c;
            p.lastSlip[a] = p.slip3[a].norm();
        }
        if (std::abs(P.normal.dot(p.ref[a])) < std::cos(25*M_PI/180)) continue;
        // The normal turned towards the reference: a new frame, the same
        // tangential force
        const tangentFrame F0 = tangentFrame::of(P, p.ref[a]);
        p.ref[a] = leastAligned(P.normal);
        const tangentFrame F1 = tangentFrame::of(P, p.ref[a]);
        if (p.perNode != 3) continue;
        const int it = p.first + 3*int(a) + 1;
        for (vecX* v : {&x, &xCommitted})
        {
            const vec3 ft = (*v)(it)*F0.t1 + (*v)(it + 1)*F0.t2;
            (*v)(it) = F1.t1.dot(ft);
            (*v)(it + 1) = F1.t2.dot(ft);
        }
    }
}


void contactModel::impl::evaluateRigid3D
(
    pairData& p,
    double t,
    double dt,
    const vecX& U,
    vecX& fext,
    vecX& r,
    std::vector<triplet>* K
)
{
    const int N = nDofs;
    const auto add = [K](int i, int j, double v)
    {
        K->emplace_back(i, j, v);
    };
    const int T = p.tool;
    const rigidToolSpec& tool = tools[T];
    const vec3 d = translation(T, t);
    const int iz = toolUnknown[T];
    const vec3 e = tool.direction;
    const bool withFriction = p.perNode == 3;

    for (int a = 0; a < int(p.nodes.size()); ++a)
    {
        const int node = p.nodes[a];
        const vec3 y = position3(node, U) - d;
        checkPosition(p, node, y);
        const surfaceProjection P = tool.surface->project(y);
        const vec3& n = P.normal;
        const int il = p.first + p.perNode*a;
        const double lambda = x(il);
        const normalConstraint c = normalConstraintFunction(P.gap, lambda, epsN);

        vec3 f = k*lambda*n;
        tangentFrame F;
        Eigen::Vector2d tau = Eigen::Vector2d::Zero();
        frictionVector fc;
        Eigen::Matrix<double, 2, 3> dsdy = Eigen::Matrix<double, 2, 3>::Zero();
        if (withFriction)
        {
            F = tangentFrame::of(P, p.ref[a]);
            tau << x(il + 1), x(il + 2);
            const vec3 ft = k*(tau(0)*F.t1 + tau(1)*F.t2);
            f += ft;
            for (int i = 0; i < 3; ++i) friction(dofs.dof(node, i)) += ft(i);
            const vec3 cpt = y - P.gap*n;
            const vec3 D = rateA*(cpt - p.cCommitted[a]) + rateB*p.slip3[a];
            const Eigen::Vector2d s(F.t1.dot(D)/dt, F.t2.dot(D)/dt);
            p.rate[a] = s.norm();
            fc = frictionLawVector(s, tau, lambda, p.mu, dt);
            r(il + 1) = k*fc.v(0);
            r(il + 2) = k*fc.v(1);
            if (K)
            {
                const mat3 dc =
                    mat3::Identity() - n*n.transpose() - P.gap*P.dNormalDY;
                dsdy.row(0) = (rateA*F.t1.transpose()*dc + D.transpose()*F.dT1DY)/dt;
                dsdy.row(1) = (rateA*F.t2.transpose()*dc + D.transpose()*F.dT2DY)/dt;
            }
        }
        for (int i = 0; i < 3; ++i) fext(dofs.dof(node, i)) += f(i);
        toolForce[T] += f;
        r(il) = k*c.w;

        updateStatus(p, a, lambda, P.gap, U, K != nullptr);
        if (!K) continue;

        mat3 Kuu = -k*lambda*P.dNormalDY;
        if (withFriction) Kuu -= k*(tau(0)*F.dT1DY + tau(1)*F.dT2DY);
        const Eigen::RowVector3d Klu = -k*c.dwdg*n.transpose();
        Eigen::Matrix<double, 2, 3> Ktu = Eigen::Matrix<double, 2, 3>::Zero();
        if (withFriction) Ktu = -k*fc.dvds*dsdy;

        for (int i = 0; i < 3; ++i)
        {
            const int di = dofs.dof(node, i);
            for (int j = 0; j < 3; ++j) add(di, dofs.dof(node, j), Kuu(i, j));
            add(di, N + il, -k*n(i));
            add(N + il, di, Klu(i));
            if (!withFriction) continue;
            add(di, N + il + 1, -k*F.t1(i));
            add(di, N + il + 2, -k*F.t2(i));
            add(N + il + 1, di, Ktu(0, i));
            add(N + il + 2, di, Ktu(1, i));
        }
        add(N + il, N + il, -k*c.dwdl);
        if (withFriction)
        {
            for (int al = 0; al < 2; ++al)
            {
                for (int be = 0; be < 2; ++be)
                {
                    add(N + il + 1 + al, N + il + 1 + be, -k*fc.dvdtau(al, be));
                }
                add(N + il + 1 + al, N + il, -k*fc.dvdl(al));
            }
        }

        if (iz < 0) continue;
        // Force-controlled tool: y = x - z e
        const vec3 Kuz = -Kuu*e;
        const Eigen::RowVector3d Kzu = -e.transpose()*Kuu;
        for (int i = 0; i < 3; ++i)
        {
            add(dofs.dof(node, i), N + iz, Kuz(i));
            add(N + iz, dofs.dof(node, i), Kzu(i));
        }
        add(N + il, N + iz, -Klu.dot(e));
        add(N + iz, N + il, k*e.dot(n));
        if (withFriction)
        {
            const Eigen::Vector2d Ktz = -Ktu*e;
            add(N + il + 1, N + iz, Ktz(0));
            add(N + il + 2, N + iz, Ktz(1));
            add(N + iz, N + il + 1, k*e.dot(F.t1));
            add(N + iz, N + il + 2, k*e.dot(F.t2));
        }
        add(N + iz, N + iz, e.dot(Kuu*e));
    }
}

} // namespace form
