/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidModel: the Newton log's per-block note, nodal force vectors,
    reactions, force norms and averaged element results (see
    solidModel.H).
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

std::string solidModel::iterationNote(const vecX& residual) const
{
    const impl& m = *impl_;
    if (m.coupled.empty()) return "";
    std::string note =
        m.contact ? "  closed " + std::to_string(m.contact->nClosed()) : "";
    if (residual.size() == 0) return note;
    // Per-block residual norms: the solid's dofs, then each block's
    const int nFree = m.numbering.nFree();
    const auto norm = [](const std::string& name, double v)
    {
        char buf[64];
        std::snprintf(buf, sizeof(buf), "  |r_%s| %.2e", name.c_str(), v);
        return std::string(buf);
    };
    note += norm("solid", residual.head(nFree).norm());
    {
        int offset = nFree;
        for (const auto& b : m.coupled)
        {
            note += norm
            (
                b->effect(), residual.segment(offset, b->nUnknowns()).norm()
            );
            offset += b->nUnknowns();
        }
    }
    int i;
    residual.cwiseAbs().maxCoeff(&i);
    if (i < nFree)
    {
        const int d = m.numbering.freeDofs[i];
        const int node = m.dofs.node(d);
        // components: translations x, y (, z), then a shell node's two
        // rotations (shellSet.H)
        static const char* names[] = {" x", " y", " z", " rotation 1", " rotation 2"};
        const int comp = m.dofs.component(d);
        note += "  max at node " + std::to_string(node)
          + (comp >= 0 && comp < 5 ? names[comp] : " dof") + " (";
        for (int c = 0; c < m.nDim; ++c)
        {
            char buf[32];
            std::snprintf
            (
                buf, sizeof(buf), c ? " %.4g" : "%.4g",
                m.mesh.X(node, c) + m.U(m.dofs.dof(node, c))
            );
            note += buf;
        }
        note += ")";
    }
    else
    {
        int j = i - nFree;
        for (const auto& b : m.coupled)
        {
            if (j < b->nUnknowns())
            {
                note += "  max at " + b->unknownName(j);
                break;
            }
            j -= b->nUnknowns();
        }
    }
    return note;
}


const vecX& solidModel::internalForce() const { return impl_->fint; }
const vecX& solidModel::externalForce() const { return impl_->fext; }
const vecX& solidModel::inertiaForce() const { return impl_->finertia; }

const vecX& solidModel::contactForce() const { return impl_->fcontact; }

vecX solidModel::frictionForce() const
{
    const impl& m = *impl_;
    if (m.contact && m.contact->frictionForces().size() == m.nDofs())
    {
        return m.contact->frictionForces();
    }
    return vecX::Zero(m.nDofs());
}


Eigen::Vector3d solidModel::reaction(const std::vector<int>& nodes) const
{
    const impl& m = *impl_;
    Eigen::Vector3d R = Eigen::Vector3d::Zero();
    if (m.fint.size() != m.nDofs()) return R;
    for (int node : nodes)
    {
        for (int i = 0; i < m.nDim; ++i)
        {
            const int d = m.dofs.dof(node, i);
            R(i) += m.fint(d) - m.fext(d)
              + (m.finertia.size() ? m.finertia(d) : 0.0);
        }
    }
    return R;
}


double solidModel::externalForceNorm() const
{
    const impl& m = *impl_;
    if (m.fext.size() != m.nDofs()) return 0;
    double s = 0;
    for (int d : m.numbering.freeDofs) s += m.fext(d)*m.fext(d);
    for (const auto& b : m.coupled)
    {
        s += b->residualScale()*b->residualScale();
    }
    return std::sqrt(s);
}


double solidModel::forceLevel() const { return impl_->forceLevel; }
void solidModel::setForceLevel(double F) { impl_->forceLevel = F; }


double solidModel::reactionNorm() const
{
    const impl& m = *impl_;
    if (m.fint.size() != m.nDofs()) return 0;
    double s = 0;
    for (int d : m.numbering.prescribedDofs)
    {
        const double r =
            m.fint(d) - m.fext(d)
          + (m.finertia.size() ? m.finertia(d) : 0.0);
        s += r*r;
    }
    return std::sqrt(s);
}


std::vector<elementResult> solidModel::elementResults() const
{
    const impl& m = *impl_;
    const auto start = std::chrono::steady_clock::now();
    const int nElements = int(m.elemBlock.size());
    std::vector<elementResult> results(nElements);
    std::exception_ptr error;
    #pragma omp parallel
    {
        matX X, u;
        #pragma omp for schedule(static)
        for (int e = 0; e < nElements; ++e)
        {
            try
            {
                const impl::blockData& b = m.blocks[m.elemBlock[e]];
                if (!b.kernel)
                {
                    results[e] = m.shells->result
                    (
                        m.elemBlock[e], m.elemLocal[e], m.dofs, m.U,
                        m.trial[e]
                    );
                    continue;
                }
                m.gather(e, X, u);
                results[e] = b.kernel->result(X, u, *b.mat, m.trial[e]);
            }
            catch (...)
            {
                #pragma omp critical(formSolidModelError)
                {
                    if (!error) error = std::current_exception();
                }
            }
        }
    }
    impl_->times.output += secondsSince(start);
    if (error) std::rethrow_exception(error);
    return results;
}

double solidModel::plasticDissipation() const
{
    const impl& m = *impl_;
    const int nElements = int(m.elemBlock.size());
    double D = 0;
    matX X, u;
    for (int e = 0; e < nElements; ++e)
    {
        const impl::blockData& b = m.blocks[m.elemBlock[e]];
        if (!b.mat || !b.mat->dissipative()) continue;
        if (!b.kernel)
        {
            D += m.shells->plasticDissipation
            (
                m.elemBlock[e], m.elemLocal[e], m.committed[e]
            );
            continue;
        }
        m.gather(e, X, u);
        const std::vector<double> v = b.kernel->pointVolumes(X);
        for (std::size_t q = 0; q < v.size(); ++q)
        {
            D += v[q]*b.mat->plasticDissipation(m.committed[e][q]);
        }
    }
    return D;
}


bool solidModel::dissipative() const
{
    for (const impl::blockData& b : impl_->blocks)
    {
        if (b.mat && b.mat->dissipative()) return true;
    }
    return false;
}


std::vector<double> solidModel::shellNodeThickness() const
{
    const impl& m = *impl_;
    std::vector<double> t(m.mesh.nNodes(), 0.0);
    if (!m.shells) return t;
    std::vector<double> stretch(m.mesh.nNodes(), 0.0);
    std::vector<int> count(m.mesh.nNodes(), 0);
    for (int e = 0; e < int(m.elemBlock.size()); ++e)
    {
        const int b = m.elemBlock[e];
        if (m.blocks[b].kernel) continue;
        const double s = m.shells->result
        (
            b, m.elemLocal[e], m.dofs, m.U, m.trial[e]
        ).meanThicknessStretch;
        const elementBlock& blk = m.mesh.blocks[b];
        const int* nodes = blk.nodes(m.elemLocal[e]);
        for (int k = 0; k < blk.nodesPerElement; ++k)
        {
            stretch[nodes[k]] += s;
            ++count[nodes[k]];
        }
    }
    for (int n = 0; n < m.mesh.nNodes(); ++n)
    {
        if (count[n]) t[n] = m.shells->thickness(n)*stretch[n]/count[n];
    }
    return t;
}


void solidModel::updateShellContactThickness()
{
    impl& m = *impl_;
    if (m.contact && m.shells) m.contact->setShellThickness(shellNodeThickness());
}

} // namespace form
