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
    frame, the projection (g, n, dn/dy) and c = y - g n the closest point,
    the node's nodeTarget (contactModelAssembly.C: the equations and
    their tangent) has q = y, the weight 1, dg/dy (= n, except on a
    triangulated surface with smoothed normals), and the slip rate
        s_a = t_a . (A (c - c_n) + B (c_n - c_n-1))/deltaT
    the motion of the closest point over the step in the tangent frame
    (the 3D form of the 2D arc-length rate; A, B: setSlipRateLaw), with
        dc/dy = I - n (dg/dy)^T - g dn/dy,
        ds_a/dy = (A t_a^T dc/dy + D^T dt_a/dy)/deltaT,
        D = A (c - c_n) + B (c_n - c_n-1).
    The reference direction of a node is the coordinate axis least
    aligned with its first normal; at a commit where the normal has
    turned within 25 deg of it, it is chosen again and the committed
    friction multipliers are re-expressed in the new frame (the tangential
    force vector is unchanged). Deformable targets share the commit
    (contactModelDeformable3D.C).
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
        const vec3 y = contactPoint(p, int(a), U) - d;
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
            const vec3 y = contactPoint(p, int(a), U) - d;
            P = tools[p.tool].surface->project(y);
            const vec3 c = y - P.gap*P.normal;
            p.slip3[a] = c - p.cCommitted[a];
            p.cCommitted[a] = c;
            p.lastSlip[a] = p.slip3[a].norm();
        }
        if (std::abs(P.normal.dot(p.ref[a])) < std::cos(25*M_PI/180)) continue;
        // The normal turned towards the reference: a new frame, the same
        // tangential force. (The old frame as the assembly built it: with
        // the normal within 10 deg of the reference, on the least aligned
        // axis; tangentFrame::of would throw on a normal parallel to it)
        const tangentFrame F0 = frameOf(p, int(a), P);
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


tangentFrame contactModel::impl::frameOf
(
    const pairData& p,
    int a,
    const surfaceProjection& P
) const
{
    // The node's reference direction stays fixed over a step (commit3D
    // renews it when the normal has turned by 65 deg), so that the
    // friction multipliers keep their frame. Only the closest point of a
    // node far from the tool can jump that far within a step (a point on
    // the core of a swept profile has a ring of closest points): its
    // friction multipliers vanish, and the least aligned axis serves
    if (std::abs(P.normal.dot(p.ref[a])) > std::cos(10*M_PI/180))
    {
        return tangentFrame::of(P, leastAligned(P.normal));
    }
    return tangentFrame::of(P, p.ref[a]);
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
    const int T = p.tool;
    const rigidToolSpec& tool = tools[T];
    const vec3 d = translation(T, t);
    if (p.offset.empty() && !p.nodes.empty() && dofs.count(p.nodes[0]) == 5)
    {
        throw numericalError
        (
            "contact: pair '" + pairSpecs[&p - pairs.data()].name
          + "' has shell nodes, but the contact model was not given the"
            " model's shells (contactModel::setShells)"
        );
    }

    for (int a = 0; a < int(p.nodes.size()); ++a)
    {
        const int node = p.nodes[a];
        const vec3 y = contactPoint(p, a, U) - d;
        checkPosition(p, node, y);
        const surfaceProjection P = tool.surface->project(y);
        const vec3& n = P.normal;
        nodeTarget q;
        q.dofs = {dofs.dof(node, 0), dofs.dof(node, 1), dofs.dof(node, 2)};
        q.weight = {1};
        q.gap = P.gap;
        q.dGap = P.dGapDY();
        q.n = n;
        q.dn = P.dNormalDY;
        q.tool = T;
        if (p.perNode == 3)
        {
            const tangentFrame F = frameOf(p, a, P);
            q.t.resize(3, 2);
            q.t << F.t1, F.t2;
            q.dt = {F.dT1DY, F.dT2DY};
            const vec3 cpt = y - P.gap*n;
            const vec3 D = rateA*(cpt - p.cCommitted[a]) + rateB*p.slip3[a];
            q.s = Eigen::Vector2d(F.t1.dot(D)/dt, F.t2.dot(D)/dt);
            p.rate[a] = q.s.norm();
            if (K)
            {
                const mat3 dc = mat3::Identity()
                  - n*P.dGapDY().transpose() - P.gap*P.dNormalDY;
                q.ds.resize(2, 3);
                q.ds.row(0) = (rateA*F.t1.transpose()*dc + D.transpose()*F.dT1DY)/dt;
                q.ds.row(1) = (rateA*F.t2.transpose()*dc + D.transpose()*F.dT2DY)/dt;
            }
        }
        if (!p.offset.empty())
        {
            // A shell node: the derivatives in y chained to its 5 dofs
            shellContactor(p, a, U, q);
            q.dGap = q.J.transpose()*q.dGap;
            q.dn = q.dn*q.J;
            for (matX& m : q.dt) m = m*q.J;
            if (q.ds.size()) q.ds = q.ds*q.J;
        }
        assembleNode(p, a, q, dt, U, fext, r, K);
    }
}

} // namespace form
