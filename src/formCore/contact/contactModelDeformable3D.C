/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    contactModel: contact with the faces of a deformable body in 3D
    (contactModel.H, "Deformable targets"; the projection and its
    derivatives: deformableSurface.H). The node's nodeTarget
    (contactModelAssembly.C: the equations and their tangent) over
    q = (y, x_b):
        weights      1 (node), -N_b(xi) (face node b): action = reaction,
                     dw_b/dq = -N_b,a dxi_a/dq
        gap, normal  g, n, dg/dq, dn/dq of the projection
        frame        t1, t2 from the node's reference direction
                     (tangentFrame::derivatives: dt_a/dq from dn/dq)
    and the slip rate the motion of the node relative to the target
    material point under it, in the node's tangent frame,
        delta = (u - u_n)(y) - sum_b N_b (u - u_n)(x_b),
        D = A delta + B delta_n-1,   s_a = t_a . D/deltaT,
        ddelta/dq = [I, -N_b I] - (sum_b (u - u_n)(x_b) N_b,a) dxi_a/dq,
        ds_a/dq = (A t_a^T ddelta/dq + D^T dt_a/dq)/deltaT.
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
    const vecX& Un = Ucommitted.size() == U.size() ? Ucommitted : U;

    for (int a = 0; a < int(p.nodes.size()); ++a)
    {
        const int node = p.nodes[a];
        const vec3 y = position3(node, U);
        checkPosition(p, node, y);
        const faceProjection P = p.surface->project(y, node, U, p.edge[a]);
        if (K) p.edge[a] = P.onTarget ? P.face : -1;
        if (!P.onTarget)
        {
            offTarget(p, a, U, r, K);
            continue;
        }

        const int m = int(P.nodes.size());
        const int nq = 3 + 3*m;
        nodeTarget q;
        q.dofs.resize(nq);
        q.weight.assign(1, 1.0);
        for (int i = 0; i < 3; ++i)
        {
            q.dofs[i] = dofs.dof(node, i);
            for (int b = 0; b < m; ++b)
            {
                q.dofs[3 + 3*b + i] = dofs.dof(P.nodes[b], i);
            }
        }
        for (int b = 0; b < m; ++b) q.weight.push_back(-P.N(b));
        // dw_b/dq = -N_b,a dxi_a/dq
        q.dWeight = -P.dN*P.dXi;
        q.gap = P.gap;
        q.dGap = P.dGap;
        q.n = P.normal;
        q.dn = P.dNormal;
        if (p.perNode == 3)
        {
            // Tangent frame from the node's reference direction
            const vec3& n = P.normal;
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
            const vec3 t1 = w/lw;
            const vec3 t2 = n.cross(t1);
            q.t.resize(3, 2);
            q.t << t1, t2;
            // Slip rate: the node's motion relative to the target point
            // under it, in the tangent frame
            const vec3 D = rateA*relativeMotion(node, P, U) + rateB*p.slip3[a];
            q.s = Eigen::Vector2d(t1.dot(D)/dt, t2.dot(D)/dt);
            p.rate[a] = q.s.norm();
            if (K)
            {
                matX dT1, dT2;
                tangentFrame::derivatives(n, ref, t1, lw, P.dNormal, dT1, dT2);
                q.dt = {dT1, dT2};
                // d delta/dq
                matX dDelta = matX::Zero(3, nq);
                dDelta.leftCols<3>() = mat3::Identity();
                Eigen::Matrix<double, 3, 2> G =
                    Eigen::Matrix<double, 3, 2>::Zero();
                for (int b = 0; b < m; ++b)
                {
                    dDelta.middleCols<3>(3 + 3*b) = -P.N(b)*mat3::Identity();
                    G += (dofs.vector3(U, P.nodes[b]) - dofs.vector3(Un, P.nodes[b]))
                        *P.dN.row(b);
                }
                dDelta -= G*P.dXi;
                q.ds.resize(2, nq);
                q.ds.row(0) = (rateA*t1.transpose()*dDelta + D.transpose()*dT1)/dt;
                q.ds.row(1) = (rateA*t2.transpose()*dDelta + D.transpose()*dT2)/dt;
            }
        }
        assembleNode(p, a, q, dt, U, fext, r, K);
    }
}

} // namespace form
