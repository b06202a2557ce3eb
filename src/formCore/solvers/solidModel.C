/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidModel: evaluate (element loop, assembly into the fixed pattern),
    coupled blocks and the increment (see solidModel.H). Set-up, dof
    numbering and the pattern: solidModelSetup.C; constraints and loads:
    solidModelLoads.C; inertia: solidModelDynamics.C; state, commit and
    the pressure linearisations: solidModelState.C; log note, forces,
    reactions and results: solidModelOutput.C; private state:
    solidModelImpl.H.
\*---------------------------------------------------------------------------*/
#include "solidModelImpl.H"
#include "contactModel.H"
#include "coupledBlock.H"
#include "formError.H"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

namespace form
{

bool solidModel::impl::computeElement
(
    int e,
    matX& X,
    matX& u,
    vecX& fe,
    matX* Ke,
    vecX* feTracked,
    bool* tracked
)
{
    const int b = elemBlock[e];
    if (tracked) *tracked = false;
    if (!blocks[b].kernel)
    {
        return shells->compute
        (
            b, elemLocal[e], dofs, U, committed[e], trial[e], fe, Ke
        );
    }
    gather(e, X, u);
    if (trackPressure && blocks[b].kernel->nPressure() > 0)
    {
        const bool active = linActive[e].valid();
        if (tracked) *tracked = active && feTracked;
        return blocks[b].kernel->compute
        (
            X, u, *blocks[b].mat, committed[e], trial[e], fe, Ke, e,
            &linActive[e], Ke ? &linPending[e] : nullptr,
            active ? feTracked : nullptr
        );
    }
    return blocks[b].kernel->compute
    (
        X, u, *blocks[b].mat, committed[e], trial[e], fe, Ke, e
    );
}


const feMesh& solidModel::mesh() const { return impl_->mesh; }
analysisType solidModel::analysis() const { return impl_->analysis; }
int solidModel::nDim() const { return impl_->nDim; }
const dofMap& solidModel::dofs() const { return impl_->dofs; }
int solidModel::nDofs() const { return impl_->nDofs(); }

int solidModel::nFreeDofs() const
{
    impl_->requireFinalised("nFreeDofs");
    return impl_->numbering.nFree();
}

int solidModel::nPrescribedDofs() const
{
    impl_->requireFinalised("nPrescribedDofs");
    return impl_->numbering.nPrescribed();
}

bool solidModel::unsymmetric() const
{
    if (!impl_->pressures.empty() || !impl_->coupled.empty()) return true;
    for (const auto& b : impl_->blocks)
    {
        if (!b.mat->symmetricTangent()) return true;
    }
    return false;
}

int solidModel::patternRevision() const { return impl_->revision; }

const std::vector<int>& solidModel::freeDofs() const
{
    impl_->requireFinalised("freeDofs");
    return impl_->numbering.freeDofs;
}

const std::vector<int>& solidModel::prescribedDofs() const
{
    impl_->requireFinalised("prescribedDofs");
    return impl_->numbering.prescribedDofs;
}


matX solidModel::displacement() const
{
    const impl& m = *impl_;
    matX u(m.mesh.nNodes(), m.nDim);
    for (int node = 0; node < m.mesh.nNodes(); ++node)
    {
        for (int i = 0; i < m.nDim; ++i) u(node, i) = m.U(m.dofs.dof(node, i));
    }
    return u;
}


const vecX& solidModel::U() const { return impl_->U; }


bool solidModel::evaluate(double t, vecX& residual, bool wantTangent)
{
    impl& m = *impl_;
    m.requireFinalised("evaluate");
    const auto start = std::chrono::steady_clock::now();

    m.fint.setZero(m.nDofs());
    m.fext.setZero(m.nDofs());
    m.anyTracked = false;
    for (const auto& l : m.linActive) m.anyTracked = m.anyTracked || l.valid();
    if (m.anyTracked) m.fintTrackedShift.setZero(m.nDofs());
    if (wantTangent)
    {
        std::fill_n(m.Kff.valuePtr(), m.Kff.nonZeros(), 0.0);
        std::fill_n(m.Kfp.valuePtr(), m.Kfp.nonZeros(), 0.0);
    }

    double* fint = m.fint.data();
    double* ff = m.Kff.valuePtr();
    double* fp = m.Kfp.valuePtr();
    int materialFailures = 0;
    bool failed = false;
    std::exception_ptr error;

    // Independent element evaluations with thread-local buffers. The
    // elements of one colour share no dof, so their scatter needs no
    // atomics and the sums do not depend on the thread count. Exceptions
    // cannot leave a parallel region: the first one is kept and rethrown
    // after the loop.
    const auto& colours = m.pattern.colours();
    #pragma omp parallel
    {
        matX X, u, Ke;
        vecX fe, feTracked;
        for (const std::vector<int>& elements : colours)
        {
            const int nc = int(elements.size());
            #pragma omp for schedule(static) reduction(+:materialFailures)
            for (int k = 0; k < nc; ++k)
            {
                bool skip;
                #pragma omp atomic read
                skip = failed;
                if (skip) continue;
                const int e = elements[k];
                try
                {
                    bool tracked = false;
                    const bool ok = m.computeElement
                    (
                        e, X, u, fe, wantTangent ? &Ke : nullptr,
                        m.anyTracked ? &feTracked : nullptr, &tracked
                    );
                    if (!ok)
                    {
                        ++materialFailures;
                        continue;
                    }

                    const elementBlock& blk = m.mesh.blocks[m.elemBlock[e]];
                    const int* nodes = blk.nodes(m.elemLocal[e]);
                    const int nd = m.blocks[m.elemBlock[e]].nodeDofs;
                    for (int a = 0; a < blk.nodesPerElement; ++a)
                    {
                        for (int i = 0; i < nd; ++i)
                        {
                            fint[m.dofs.dof(nodes[a], i)] += fe(a*nd + i);
                        }
                    }
                    if (tracked)
                    {
                        for (int a = 0; a < blk.nodesPerElement; ++a)
                        {
                            for (int i = 0; i < nd; ++i)
                            {
                                m.fintTrackedShift(m.dofs.dof(nodes[a], i)) +=
                                    feTracked(a*nd + i) - fe(a*nd + i);
                            }
                        }
                    }
                    if (wantTangent && m.inertia && m.alpha != 0)
                    {
                        Ke.noalias() += m.alpha*m.Me[e];
                    }
                    if (wantTangent)
                    {
                        const int n = m.pattern.nElementDofs(e);
                        const int* code = m.pattern.scatter(e);
                        const double* ke = Ke.data();
                        for (int ab = 0; ab < n*n; ++ab)
                        {
                            const int c = code[ab];
                            if (c >= 0) ff[c] += ke[ab];
                            else if (c <= -2) fp[-2 - c] += ke[ab];
                        }
                    }
                }
                catch (...)
                {
                    #pragma omp critical(formSolidModelError)
                    {
                        if (!error) error = std::current_exception();
                    }
                    #pragma omp atomic write
                    failed = true;
                }
            }
        }
    }

    if (error)
    {
        m.times.assembly += secondsSince(start);
        std::rethrow_exception(error);
    }
    if (materialFailures)
    {
        m.times.assembly += secondsSince(start);
        return false;
    }

    m.assembleExternal(t, wantTangent);

    // Reactions of gradually released dofs, decaying linearly to zero
    for (const auto& r : m.released)
    {
        const double w =
            std::min(1.0, std::max(0.0, 1 - (t - r.t0)/(r.t1 - r.t0)));
        m.fext(r.dof) += w*r.force;
    }

    // Inertia forces M a(U) (dynamic analysis)
    if (m.inertia)
    {
        m.finertia = m.M*(m.alpha*m.U + m.accelerationOffset);
    }
    else
    {
        m.finertia.setZero(m.nDofs());
    }

    const int nFree = m.numbering.nFree();
    m.times.assembly += secondsSince(start);
    if (m.coupled.empty())
    {
        residual.resize(nFree);
        for (int k = 0; k < nFree; ++k)
        {
            const int d = m.numbering.freeDofs[k];
            residual(k) = m.fext(d) - m.fint(d) - m.finertia(d);
        }
        return residual.allFinite();
    }

    // Coupled blocks (contact, fluid cavity): their forces into f_ext,
    // their equations after the free dofs, and the Newton matrix K_ff
    // bordered by their triplets (block unknowns shifted by the block's
    // offset)
    const int nC = m.nCoupled();
    m.triplets.clear();
    residual.resize(nFree + nC);
    std::vector<Eigen::Triplet<double>> local;
    int offset = 0;
    const int N = m.nDofs();
    for (const auto& b : m.coupled)
    {
        const auto blockStart = std::chrono::steady_clock::now();
        const bool isContact = b.get() == m.contact.get();
        vecX rb;
        local.clear();
        if (isContact) m.fcontact = -m.fext;
        b->evaluate(t, m.U, m.fext, rb, wantTangent ? &local : nullptr);
        if (isContact) m.fcontact += m.fext;
        residual.segment(nFree + offset, b->nUnknowns()) = rb;
        for (const auto& tr : local)
        {
            m.triplets.emplace_back
            (
                tr.row() < N ? tr.row() : tr.row() + offset,
                tr.col() < N ? tr.col() : tr.col() + offset,
                tr.value()
            );
        }
        offset += b->nUnknowns();
        (isContact ? m.times.contact : m.times.fluid) +=
            secondsSince(blockStart);
    }
    for (int k = 0; k < nFree; ++k)
    {
        const int d = m.numbering.freeDofs[k];
        residual(k) = m.fext(d) - m.fint(d) - m.finertia(d);
    }
    if (wantTangent)
    {
        const auto start = std::chrono::steady_clock::now();
        m.buildSystemMatrix();
        m.times.assembly += secondsSince(start);
    }
    return residual.allFinite();
}


const sparseMatrix& solidModel::Kff() const { return impl_->Kff; }

const sparseMatrix& solidModel::K() const
{
    return impl_->coupled.empty() ? impl_->Kff : impl_->Ksys;
}


int solidModel::nUnknowns() const
{
    return nFreeDofs() + impl_->nCoupled();
}


contactModel* solidModel::contact() const
{
    return impl_->contact.get();
}


void solidModel::setContact(std::shared_ptr<contactModel> contact)
{
    impl& m = *impl_;
    if (m.contact)
    {
        m.coupled.erase
        (
            std::find(m.coupled.begin(), m.coupled.end(), m.contact)
        );
    }
    m.contact = std::move(contact);
    if (m.contact)
    {
        m.contact->setShells(m.shells.get());
        m.coupled.insert(m.coupled.begin(), m.contact);
    }
    ++m.revision;
}


void solidModel::addCoupledBlock(std::shared_ptr<coupledBlock> block)
{
    if (!block)
    {
        throw numericalError("solidModel::addCoupledBlock: no block");
    }
    impl_->coupled.push_back(std::move(block));
    ++impl_->revision;
}


int solidModel::coupledOffset(const coupledBlock* block) const
{
    int offset = 0;
    for (const auto& b : impl_->coupled)
    {
        if (b.get() == block) return offset;
        offset += b->nUnknowns();
    }
    return -1;
}


void solidModel::releaseTool(const std::string& tool, double t0, double t1)
{
    impl& m = *impl_;
    if (!m.contact)
    {
        throw inputError(tool, "releaseTool: the model has no contact");
    }
    if (!(t1 > t0))
    {
        throw inputError("endTime", "release ramp needs t1 > t0");
    }
    for (const auto& f : m.contact->releaseTool(tool, m.Ucommitted))
    {
        m.released.push_back({f.first, f.second, t0, t1});
    }
    ++m.revision;
}


std::vector<double> solidModel::releaseLoads() const
{
    std::vector<double> s;
    for (const auto& r : impl_->released)
    {
        s.insert(s.end(), {double(r.dof), r.force, r.t0, r.t1});
    }
    return s;
}


void solidModel::setReleaseLoads(const std::vector<double>& s)
{
    impl& m = *impl_;
    if (s.size() % 4)
    {
        throw numericalError
        (
            "solidModel::setReleaseLoads: " + std::to_string(s.size())
          + " values, not a multiple of 4 (dof force t0 t1)"
        );
    }
    m.released.clear();
    for (std::size_t i = 0; i < s.size(); i += 4)
    {
        const int dof = int(std::lround(s[i]));
        if (dof < 0 || dof >= m.nDofs())
        {
            throw numericalError
            (
                "solidModel::setReleaseLoads: dof " + std::to_string(dof)
              + " out of range"
            );
        }
        m.released.push_back({dof, s[i + 1], s[i + 2], s[i + 3]});
    }
}


void solidModel::beginIncrement(double t0, double t1)
{
    impl& m = *impl_;
    for (const auto& b : m.coupled) b->beginIncrement(t0, t1, m.Ucommitted);
}


vecX solidModel::state() const
{
    const impl& m = *impl_;
    vecX s(m.nDofs() + m.nCoupled());
    s.head(m.nDofs()) = m.U;
    int offset = m.nDofs();
    for (const auto& b : m.coupled)
    {
        s.segment(offset, b->nUnknowns()) = b->unknowns();
        offset += b->nUnknowns();
    }
    return s;
}


void solidModel::addToState(const vecX& d)
{
    impl& m = *impl_;
    m.requireFinalised("addToState");
    for (int dof : m.numbering.freeDofs) m.U(dof) += d(dof);
    int offset = m.nDofs();
    for (const auto& b : m.coupled)
    {
        b->addToUnknowns(d.segment(offset, b->nUnknowns()));
        offset += b->nUnknowns();
    }
}


void solidModel::keepCommitted(vecX& d, const vecX& previous) const
{
    const impl& m = *impl_;
    int offset = m.nDofs();
    for (const auto& b : m.coupled)
    {
        vecX s = d.segment(offset, b->nUnknowns());
        const vecX p =
            previous.size() == d.size()
          ? vecX(previous.segment(offset, b->nUnknowns())) : vecX();
        b->keepCommitted(s, p);
        d.segment(offset, b->nUnknowns()) = s;
        offset += b->nUnknowns();
    }
}


const sparseMatrix& solidModel::Kfp() const { return impl_->Kfp; }


vecX solidModel::prescribedIncrement(double t) const
{
    const impl& m = *impl_;
    m.requireFinalised("prescribedIncrement");
    const int nP = m.numbering.nPrescribed();
    vecX dUp(nP);
    for (int j = 0; j < nP; ++j)
    {
        const int d = m.numbering.prescribedDofs[j];
        auto it = m.constraints.find(d);
        const double target =
            (it != m.constraints.end() && it->second) ? it->second(t) : 0.0;
        dUp(j) = target - m.U(d);
    }
    return dUp;
}


void solidModel::applyPrescribed(double t)
{
    impl& m = *impl_;
    const vecX dUp = prescribedIncrement(t);
    for (int j = 0; j < dUp.size(); ++j)
    {
        m.U(m.numbering.prescribedDofs[j]) += dUp(j);
    }
}


void solidModel::addToFree(const vecX& dUf)
{
    impl& m = *impl_;
    m.requireFinalised("addToFree");
    const int nFree = m.numbering.nFree();
    if (!m.coupled.empty() && dUf.size() == nFree + m.nCoupled())
    {
        for (int k = 0; k < nFree; ++k)
        {
            m.U(m.numbering.freeDofs[k]) += dUf(k);
        }
        int offset = nFree;
        for (const auto& b : m.coupled)
        {
            b->addToUnknowns(dUf.segment(offset, b->nUnknowns()));
            offset += b->nUnknowns();
        }
        return;
    }
    if (dUf.size() != nFree)
    {
        throw numericalError
        (
            "solidModel::addToFree: update has " + std::to_string(dUf.size())
          + " entries for " + std::to_string(m.numbering.nFree())
          + " free dofs"
        );
    }
    for (int k = 0; k < dUf.size(); ++k)
    {
        m.U(m.numbering.freeDofs[k]) += dUf(k);
    }
}


phaseTimes& solidModel::times() { return impl_->times; }


const shellSet* solidModel::shells() const { return impl_->shells.get(); }


void solidModel::alignShellFrames
(
    const std::vector<int>& nodes,
    const vec3& axis
)
{
    if (!impl_->shells) return;
    for (const int n : nodes)
    {
        if (impl_->shells->shellNode(n) >= 0) impl_->shells->alignFrame(n, axis);
    }
}


std::vector<double> solidModel::shellState() const
{
    return impl_->shells ? impl_->shells->state() : std::vector<double>();
}


void solidModel::setShellState(const std::vector<double>& s)
{
    impl& m = *impl_;
    if (m.shells)
    {
        m.shells->setState(s);
        m.shells->foldedRotations(m.dofs, m.U);
        m.shells->foldedRotations(m.dofs, m.Ucommitted);
    }
    else if (!s.empty())
    {
        throw numericalError
        (
            "solidModel::setShellState: the model has no shells"
        );
    }
}

} // namespace form
