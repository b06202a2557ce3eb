/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    contactModel: contact with the faces of a deformable body in 3D
    (contactModel.H, "Deformable targets"; the projection and its
    derivatives: deformableSurface.H). The equations of the rigid 3D pairs
    (contactModel3D.C) with the target's face nodes among the unknowns,
    over q = (y, x_b):
        node:        f = k (lambda n + tau_a t_a)
        face node b: -N_b(xi) f                      (action = reaction)
        lambda:      r = k w(g, lambda)
        tau:         r = k v(s, tau, lambda)
    with the slip rate the motion of the node relative to the target
    material point under it, in the node's tangent frame,
        delta = (u - u_n)(y) - sum_b N_b (u - u_n)(x_b),
        D = A delta + B delta_n-1,   s_a = t_a . D/deltaT
    and the linearisation
        df/dq   = k (lambda dn/dq + tau_a dt_a/dq)
        dF_b/dq = -N_b df/dq - f N_b,a dxi_a/dq
        ddelta/dq = [I, -N_b I] - (sum_b (u - u_n)(x_b) N_b,a) dxi_a/dq
        ds_a/dq = (A t_a^T ddelta/dq + D^T dt_a/dq)/deltaT
    (dt_a/dq from dn/dq: rigidSurface.H, tangentFrame::derivatives).
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "constraintFunctions.H"
#include "formError.H"
#include <cmath>
#include <limits>
#include <map>

namespace form
{

void contactModel::impl::initialiseDeformable3D(pairData& p, const vecX& U)
{
    // The contactor's outward normal at its nodes (sum of the normals of
    // its faces), for nodes that are off target now
    std::map<int, vec3> own;
    for (const std::vector<int>& f : p.faces)
    {
        const vec3 d1 = position3(f[2], U) - position3(f[0], U);
        const vec3 d2 = position3(f[3], U) - position3(f[1], U);
        const vec3 a = d1.cross(d2);
        for (int node : f) own[node] += a;
    }
    for (std::size_t a = 0; a < p.nodes.size(); ++a)
    {
        const int node = p.nodes[a];
        const faceProjection P =
            p.surface->project(position3(node, U), node, U, p.edge[a]);
        p.ref[a] = leastAligned(P.onTarget ? P.normal : own[node]);
        p.slip3[a] = vec3::Zero();
        p.cCommitted[a] = vec3::Zero();
    }
}


void contactModel::impl::evaluateDeformable3D
(
    pairData& p,
    double dt,
    const vecX& U,
    vecX& fext,
    vecX& r,
    std::vector<triplet>* K
)
{
    const int N = nDofs;
    const bool withFriction = p.perNode == 3;
    const vecX& Un = Ucommitted.size() == U.size() ? Ucommitted : U;
    const auto add = [K](int i, int j, double v)
    {
        K->emplace_back(i, j, v);
    };

    for (int a = 0; a < int(p.nodes.size()); ++a)
    {
        const int node = p.nodes[a];
        const vec3 y = position3(node, U);
        checkPosition(p, node, y);
        const int il = p.first + p.perNode*a;
        const double lambda = x(il);
        const faceProjection P = p.surface->project(y, node, U, p.edge[a]);
        if (K) p.edge[a] = P.onTarget ? P.face : -1;
        if (!P.onTarget)
        {
            // Beyond the target: out of contact, multipliers to zero
            updateStatus(p, a, lambda, std::numeric_limits<double>::max(), U,
                K != nullptr);
            for (int j = 0; j < p.perNode; ++j)
            {
                r(il + j) = -k*x(il + j);
                if (K) add(N + il + j, N + il + j, k);
            }
            continue;
        }

        const int m = int(P.nodes.size());
        const int nq = 3 + 3*m;
        std::vector<int> dof(nq);
        for (int i = 0; i < 3; ++i)
        {
            dof[i] = dofs.dof(node, i);
            for (int b = 0; b < m; ++b)
            {
                dof[3 + 3*b + i] = dofs.dof(P.nodes[b], i);
            }
        }
        const vec3& n = P.normal;
        const normalConstraint c =
            normalConstraintFunction(P.gap, lambda, epsN);

        // Tangent frame, friction force and slip rate
        vec3 f = k*lambda*n;
        vec3 t1 = vec3::Zero(), t2 = vec3::Zero();
        matX dT1, dT2;
        Eigen::Vector2d tau = Eigen::Vector2d::Zero();
        frictionVector fc;
        matX dsdq;
        if (withFriction)
        {
            const vec3& ref = p.ref[a];
            const vec3 w = ref - n*n.dot(ref);
            const double lw = w.norm();
            if (!(lw > 1e-8))
            {
                throw numericalError
                (
                    "contact: the tangent frame of node "
                  + std::to_string(node) + " of pair '"
                  + pairSpecs[&p - pairs.data()].name
                  + "' is undefined (its normal turned onto its reference"
                    " direction within a step)"
                );
            }
            t1 = w/lw;
            t2 = n.cross(t1);
            tau << x(il + 1), x(il + 2);
            const vec3 ft = k*(tau(0)*t1 + tau(1)*t2);
            f += ft;
            for (int i = 0; i < 3; ++i)
            {
                friction(dof[i]) += ft(i);
                for (int b = 0; b < m; ++b) friction(dof[3 + 3*b + i]) -= P.N(b)*ft(i);
            }
            const vec3 D = rateA*relativeMotion(node, P, U) + rateB*p.slip3[a];
            const Eigen::Vector2d s(t1.dot(D)/dt, t2.dot(D)/dt);
            p.rate[a] = s.norm();
            fc = frictionLawVector(s, tau, lambda, p.mu, dt);
            r(il + 1) = k*fc.v(0);
            r(il + 2) = k*fc.v(1);
            if (K)
            {
                tangentFrame::derivatives
                (
                    n, ref, t1, lw, P.dNormal, dT1, dT2
                );
                // d delta/dq
                matX dDelta = matX::Zero(3, nq);
                dDelta.leftCols<3>() = mat3::Identity();
                Eigen::Matrix<double, 3, 2> G = Eigen::Matrix<double, 3, 2>::Zero();
                for (int b = 0; b < m; ++b)
                {
                    dDelta.middleCols<3>(3 + 3*b) = -P.N(b)*mat3::Identity();
                    G += (dofs.vector3(U, P.nodes[b]) - dofs.vector3(Un, P.nodes[b]))
                        *P.dN.row(b);
                }
                dDelta -= G*P.dXi;
                dsdq.resize(2, nq);
                dsdq.row(0) = (rateA*t1.transpose()*dDelta + D.transpose()*dT1)/dt;
                dsdq.row(1) = (rateA*t2.transpose()*dDelta + D.transpose()*dT2)/dt;
            }
        }
        for (int i = 0; i < 3; ++i)
        {
            fext(dof[i]) += f(i);
            for (int b = 0; b < m; ++b) fext(dof[3 + 3*b + i]) -= P.N(b)*f(i);
        }
        r(il) = k*c.w;
        updateStatus(p, a, lambda, P.gap, U, K != nullptr);
        if (!K) continue;

        // dF/dq: the node's block df/dq, the face nodes' -N_b df/dq
        // - f dN_b/dq
        matX df = k*lambda*P.dNormal;
        if (withFriction) df += k*(tau(0)*dT1 + tau(1)*dT2);
        const matX dNq = P.dN*P.dXi;     // m x nq: dN_b/dq
        matX dF(nq, nq);
        dF.topRows<3>() = df;
        for (int b = 0; b < m; ++b)
        {
            dF.middleRows<3>(3 + 3*b) = -P.N(b)*df - f*dNq.row(b);
        }
        // dF/dlambda, dF/dtau_a: k n, k t_a weighted by 1 (node), -N_b
        const auto weighted = [&](const vec3& v)
        {
            vecX W(nq);
            W.head<3>() = k*v;
            for (int b = 0; b < m; ++b) W.segment<3>(3 + 3*b) = -P.N(b)*k*v;
            return W;
        };
        const vecX Fn = weighted(n);
        vecX Ft1, Ft2;
        matX Ktu;
        if (withFriction)
        {
            Ft1 = weighted(t1);
            Ft2 = weighted(t2);
            Ktu = -k*fc.dvds*dsdq;
        }
        for (int i = 0; i < nq; ++i)
        {
            for (int j = 0; j < nq; ++j) add(dof[i], dof[j], -dF(i, j));
            add(dof[i], N + il, -Fn(i));
            add(N + il, dof[i], -k*c.dwdg*P.dGap(i));
            if (!withFriction) continue;
            add(dof[i], N + il + 1, -Ft1(i));
            add(dof[i], N + il + 2, -Ft2(i));
            add(N + il + 1, dof[i], Ktu(0, i));
            add(N + il + 2, dof[i], Ktu(1, i));
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
    }
}

} // namespace form
