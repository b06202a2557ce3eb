/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    contactModel: contact with the edges of a deformable body
    (contactModel.H, "Deformable targets").
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "solidElement.H"
#include <algorithm>

namespace form
{

// Node-to-segment contact with the edges of a deformable body: the
// equations of evaluate(), with the projection derivatives of
// deformableTarget.H over q = (y, x_b): f = k (lambda n + tau t) on the
// node, -N_b f on the edge nodes; dn = -t h/L, dt = n h/L, dN_b = N'_b
// dzeta.
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
    const int N = nDofs;
    const bool friction = p.perNode == 2;
    const vecX& Un = Ucommitted.size() == U.size() ? Ucommitted : U;
    const auto add = [K](int i, int j, double v)
    {
        K->emplace_back(i, j, v);
    };

    for (int a = 0; a < int(p.nodes.size()); ++a)
    {
        const int node = p.nodes[a];
        const Eigen::Vector2d y = position(node, U);
        if (!y.allFinite() || y.cwiseAbs().maxCoeff() > 1e30)
        {
            throw numericalError
            (
                "contact: node " + std::to_string(node) + " of pair '"
              + pairSpecs[&p - pairs.data()].name
              + "' has a non-finite or diverged position"
            );
        }
        const int il = p.first + p.perNode*a;
        const int it = il + 1;
        const double lambda = x(il);
        const double tau = friction ? x(it) : 0.0;
        const segmentProjection P =
            p.target->project(y, node, U, p.edge[a]);
        if (K) p.edge[a] = P.onTarget ? P.edge : -1;
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
        const int nq = 2 + 2*m;
        std::vector<int> dof(nq);
        dof[0] = dofs.dof(node, 0);
        dof[1] = dofs.dof(node, 1);
        for (int b = 0; b < m; ++b)
        {
            dof[2 + 2*b] = dofs.dof(P.nodes[b], 0);
            dof[3 + 2*b] = dofs.dof(P.nodes[b], 1);
        }
        const Eigen::Vector2d& n = P.normal;
        const Eigen::Vector2d& tv = P.tangent;

        const normalConstraint c =
            normalConstraintFunction(P.gap, lambda, epsN);
        const Eigen::Vector2d f = k*(lambda*n + tau*tv);
        // Force on the node and the reaction on the edge, as a vector over q
        Eigen::VectorXd F(nq);
        F.head<2>() = f;
        for (int b = 0; b < m; ++b) F.segment<2>(2 + 2*b) = -P.N(b)*f;
        for (int i = 0; i < nq; ++i) fext(dof[i]) += F(i);
        {
            const Eigen::Vector2d ft = k*tau*tv;
            vecX& fFriction = this->friction;
            fFriction(dof[0]) += ft(0);
            fFriction(dof[1]) += ft(1);
            for (int b = 0; b < m; ++b)
            {
                fFriction(dof[2 + 2*b]) -= P.N(b)*ft(0);
                fFriction(dof[3 + 2*b]) -= P.N(b)*ft(1);
            }
        }
        r(il) = k*c.w;
        updateStatus(p, a, lambda, P.gap, U, K != nullptr);

        // Slip rate: relative tangential velocity of the node and the
        // target material point under it
        frictionConstraint fc;
        Eigen::VectorXd dSlip;
        if (friction)
        {
            Eigen::Vector2d delta = dofs.vector2(U - Un, node);
            Eigen::Vector2d dTarget = Eigen::Vector2d::Zero();
            for (int b = 0; b < m; ++b)
            {
                const Eigen::Vector2d dxb = dofs.vector2(U - Un, P.nodes[b]);
                delta -= P.N(b)*dxb;
                dTarget += P.dN(b)*dxb;
            }
            const double slip = tv.dot(delta);
            p.rate[a] = (rateA*slip + rateB*p.lastSlip[a])/dt;
            fc = frictionLaw(p.rate[a], tau, lambda, p.mu, dt);
            r(it) = k*fc.v;
            if (K)
            {
                dSlip = n.dot(delta)/P.length*P.h
                      - tv.dot(dTarget)*P.dZeta;
                dSlip.head<2>() += tv;
                for (int b = 0; b < m; ++b)
                {
                    dSlip.segment<2>(2 + 2*b) -= P.N(b)*tv;
                }
            }
        }
        if (!K) continue;

        // dF/dq: df/dq = k (-lambda t + tau n) h^T/L on every block,
        // weighted by 1 (node) or -N_b (edge), plus -f dN_b/dq
        const Eigen::Vector2d g = k*(-lambda*tv + tau*n)/P.length;
        Eigen::MatrixXd dF(nq, nq);
        dF.topRows<2>() = g*P.h.transpose();
        for (int b = 0; b < m; ++b)
        {
            dF.middleRows<2>(2 + 2*b) =
                -P.N(b)*g*P.h.transpose()
              - P.dN(b)*f*P.dZeta.transpose();
        }
        // dF/dlambda = k n w, dF/dtau = k t w (w = 1 node, -N_b edge)
        Eigen::VectorXd Fn(nq), Ft(nq);
        Fn.head<2>() = k*n;
        Ft.head<2>() = k*tv;
        for (int b = 0; b < m; ++b)
        {
            Fn.segment<2>(2 + 2*b) = -P.N(b)*k*n;
            Ft.segment<2>(2 + 2*b) = -P.N(b)*k*tv;
        }
        for (int i = 0; i < nq; ++i)
        {
            for (int j = 0; j < nq; ++j) add(dof[i], dof[j], -dF(i, j));
            add(dof[i], N + il, -Fn(i));
            add(N + il, dof[i], -k*c.dwdg*P.dGap(i));
            if (friction)
            {
                add(dof[i], N + it, -Ft(i));
                add(N + it, dof[i], -k*fc.dvds*dSlip(i));
            }
        }
        add(N + il, N + il, -k*c.dwdl);
        if (friction)
        {
            add(N + it, N + it, -k*fc.dvdtau);
            add(N + it, N + il, -k*fc.dvdl);
        }
    }
}


} // namespace form
