/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    contactModel: contact with the edges of a deformable body
    (contactModel.H, "Deformable targets").
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include <limits>

namespace form
{

// Node-to-segment contact with the edges of a deformable body: the
// projection of deformableTarget.H as a nodeTarget over q = (y, x_b)
// (contactModelAssembly.C): the weights 1 and -N_b, dw_b = -N'_b dzeta,
// dn = -t h/L, dt = n h/L, and the slip of the node relative to the
// target material point under it, slip = t . (du(y) - sum_b N_b du(x_b)).
void contactModel::impl::evaluateDeformable
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
        const Eigen::Vector2d y = position(node, U);
        checkPosition(p, node, vec3(y(0), y(1), 0));
        const segmentProjection P =
            p.target->project(y, node, U, p.edge[a]);
        if (K) p.edge[a] = P.onTarget ? P.edge : -1;
        if (!P.onTarget)
        {
            offTarget(p, a, U, r, K);
            continue;
        }

        const int m = int(P.nodes.size());
        const int nq = 2 + 2*m;
        nodeTarget q;
        q.dofs = {dofs.dof(node, 0), dofs.dof(node, 1)};
        q.weight = {1};
        q.dWeight.resize(m, nq);
        for (int b = 0; b < m; ++b)
        {
            q.dofs.push_back(dofs.dof(P.nodes[b], 0));
            q.dofs.push_back(dofs.dof(P.nodes[b], 1));
            q.weight.push_back(-P.N(b));
            q.dWeight.row(b) = -P.dN(b)*P.dZeta.transpose();
        }
        q.gap = P.gap;
        q.dGap = P.dGap;
        q.n = P.normal;
        q.dn = -P.tangent*P.h.transpose()/P.length;
        if (p.perNode == 2)
        {
            q.t = P.tangent;
            q.dt = {matX(P.normal*P.h.transpose()/P.length)};
            // Slip rate: relative tangential velocity of the node and the
            // target material point under it
            Eigen::Vector2d delta = dofs.vector2(U - Un, node);
            Eigen::Vector2d dTarget = Eigen::Vector2d::Zero();
            for (int b = 0; b < m; ++b)
            {
                const Eigen::Vector2d dxb = dofs.vector2(U - Un, P.nodes[b]);
                delta -= P.N(b)*dxb;
                dTarget += P.dN(b)*dxb;
            }
            const Eigen::Vector2d& tv = P.tangent;
            const double slip = tv.dot(delta);
            p.rate[a] = (rateA*slip + rateB*p.lastSlip[a])/dt;
            q.s = vecX::Constant(1, p.rate[a]);
            if (K)
            {
                Eigen::VectorXd dSlip = P.normal.dot(delta)/P.length*P.h
                  - tv.dot(dTarget)*P.dZeta;
                dSlip.head<2>() += tv;
                for (int b = 0; b < m; ++b)
                {
                    dSlip.segment<2>(2 + 2*b) -= P.N(b)*tv;
                }
                q.ds = rateA/dt*dSlip.transpose();
            }
        }
        assembleNode(p, a, q, dt, U, fext, r, K);
    }
}


} // namespace form
