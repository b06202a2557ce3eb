/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidModel: inertia for implicit dynamics (mass matrix, acceleration
    and velocity laws of the time integrator; see solidModel.H and
    timeIntegrator.H).
\*---------------------------------------------------------------------------*/
#include "solidModelImpl.H"
#include "contactModel.H"
#include "coupledBlock.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace form
{

void solidModel::setInertia
(
    const std::map<std::string, double>& density,
    bool lumped
)
{
    impl& m = *impl_;
    m.requireFinalised("setInertia");
    const int nElements = int(m.elemBlock.size());
    m.Me.assign(nElements, matX());
    std::vector<Eigen::Triplet<double>> entries;
    matX X, u;
    for (int e = 0; e < nElements; ++e)
    {
        const impl::blockData& b = m.blocks[m.elemBlock[e]];
        const elementBlock& blk = m.mesh.blocks[m.elemBlock[e]];
        auto it = density.find(blk.materialName);
        if (it == density.end())
        {
            throw inputError
            (
                "rho",
                "dynamic analysis: no density for material '"
              + blk.materialName + "' (block '" + blk.name + "')"
            );
        }
        if (!(it->second > 0) || !std::isfinite(it->second))
        {
            throw inputError
            (
                "rho",
                "material '" + blk.materialName + "': density must be"
                " positive, got " + std::to_string(it->second)
            );
        }
        matX Me;
        if (b.kernel)
        {
            m.gather(e, X, u);
            Me = it->second*b.kernel->massMatrix(X);
            if (lumped)
            {
                const vecX rowSum = Me.rowwise().sum();
                Me = rowSum.asDiagonal();
            }
        }
        else
        {
            Me = m.shells->massMatrix
            (
                m.elemBlock[e], m.elemLocal[e], it->second, lumped
            );
        }
        const int* nodes = blk.nodes(m.elemLocal[e]);
        const int nd = b.nodeDofs;
        const int n = blk.nodesPerElement*nd;
        for (int p = 0; p < n; ++p)
        {
            const int gp = m.dofs.dof(nodes[p/nd], p%nd);
            for (int q = 0; q < n; ++q)
            {
                if (Me(p, q) == 0) continue;
                const int gq = m.dofs.dof(nodes[q/nd], q%nd);
                entries.emplace_back(gp, gq, Me(p, q));
            }
        }
        m.Me[e] = std::move(Me);
    }
    m.M.resize(m.nDofs(), m.nDofs());
    m.M.setFromTriplets(entries.begin(), entries.end());
    m.M.makeCompressed();
    m.inertia = true;
    m.alpha = 0;
    m.accelerationOffset = vecX::Zero(m.nDofs());
    m.finertia = vecX::Zero(m.nDofs());
}


bool solidModel::hasInertia() const { return impl_->inertia; }

const sparseMatrix& solidModel::massMatrix() const
{
    impl_->requireFinalised("massMatrix");
    if (!impl_->inertia)
    {
        throw numericalError
        (
            "solidModel::massMatrix: the model has no inertia (static"
            " analysis)"
        );
    }
    return impl_->M;
}


void solidModel::setAccelerationLaw(double alpha, const vecX& b)
{
    impl& m = *impl_;
    if (!m.inertia)
    {
        throw numericalError
        (
            "solidModel::setAccelerationLaw: the model has no inertia"
        );
    }
    if (b.size() != m.nDofs())
    {
        throw numericalError
        (
            "solidModel::setAccelerationLaw: b has "
          + std::to_string(b.size()) + " entries for "
          + std::to_string(m.nDofs()) + " dofs"
        );
    }
    m.alpha = alpha;
    m.accelerationOffset = b;
}


void solidModel::setVelocityLaw(double beta, const vecX& c)
{
    impl& m = *impl_;
    if (c.size() && c.size() != m.nDofs())
    {
        throw numericalError
        (
            "solidModel::setVelocityLaw: c has " + std::to_string(c.size())
          + " entries for " + std::to_string(m.nDofs()) + " dofs"
        );
    }
    m.velocityBeta = beta;
    m.velocityOffset = c;
}


bool solidModel::velocityLaw(double& beta, const vecX*& c) const
{
    const impl& m = *impl_;
    if (!m.velocityOffset.size()) return false;
    beta = m.velocityBeta;
    c = &m.velocityOffset;
    return true;
}


double solidModel::accelerationCoefficient() const
{
    return impl_->inertia ? impl_->alpha : 0;
}


vecX solidModel::acceleration() const
{
    const impl& m = *impl_;
    if (!m.inertia) return vecX::Zero(m.nDofs());
    return m.alpha*m.U + m.accelerationOffset;
}

} // namespace form
