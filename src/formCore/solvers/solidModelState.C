/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The state of solidModel (see solidModel.H): displacements and material
    states set from outside, save and restore, commit and revert, and the
    pressure linearisations of the mixed elements that go with them (the
    tracked pressure, solidElement.H).
\*---------------------------------------------------------------------------*/
#include "solidModelImpl.H"
#include "formError.H"
#include "upElementTools.H"
#include <string>

namespace form
{

void solidModel::setDisplacement(const vecX& U)
{
    impl& m = *impl_;
    if (U.size() != m.nDofs())
    {
        throw numericalError
        (
            "solidModel::setDisplacement: vector has " + std::to_string(U.size())
          + " entries for " + std::to_string(m.nDofs()) + " dofs"
        );
    }
    m.U = U;
}


const std::vector<std::vector<materialState>>&
solidModel::materialStates() const
{
    return impl_->committed;
}


void solidModel::setMaterialStates
(
    const std::vector<std::vector<materialState>>& states
)
{
    impl& m = *impl_;
    bool ok = states.size() == m.committed.size();
    for (std::size_t e = 0; ok && e < states.size(); ++e)
    {
        ok = states[e].size() == m.committed[e].size();
        for (std::size_t q = 0; ok && q < states[e].size(); ++q)
        {
            ok = states[e][q].history.size()
              == m.committed[e][q].history.size();
        }
    }
    if (!ok)
    {
        throw numericalError
        (
            "solidModel::setMaterialStates: the states do not match the"
            " model's elements, quadrature points or material history"
        );
    }
    m.committed = states;
    m.trial = states;
    m.resetPressureLinearisations();
}


solidModel::savedState solidModel::save() const
{
    const impl& m = *impl_;
    savedState s;
    s.U = m.Ucommitted;
    s.materialStates = m.committed;
    for (const auto& b : m.coupled) s.coupled.push_back(b->state());
    s.releaseLoads = releaseLoads();
    if (m.shells) s.shells = m.shells->state();
    s.pressures = pressureHistory();
    return s;
}


void solidModel::restore(const savedState& s)
{
    impl& m = *impl_;
    setDisplacement(s.U);
    m.Ucommitted = s.U;
    setMaterialStates(s.materialStates);
    for (std::size_t i = 0; i < m.coupled.size() && i < s.coupled.size(); ++i)
    {
        m.coupled[i]->setState(s.coupled[i]);
    }
    setReleaseLoads(s.releaseLoads);
    if (m.shells) m.shells->setState(s.shells);
    updateShellContactThickness();
    setPressureHistory(s.pressures);
    lineariseCommittedPressures();
}


void solidModel::commit()
{
    impl& m = *impl_;
    if (m.shells) m.shells->commit(m.dofs, m.U);
    m.Ucommitted = m.U;
    m.committed = m.trial;
    m.linCommitted = m.linPending;
    m.linActive = m.linCommitted;
    m.commitPressureHistory();
    for (const auto& b : m.coupled) b->commit(m.U);
    updateShellContactThickness();
}


void solidModel::revert()
{
    impl& m = *impl_;
    m.U = m.Ucommitted;
    m.trial = m.committed;
    m.linActive = m.linCommitted;
    for (const auto& b : m.coupled) b->revert();
}


void solidModel::impl::resetPressureLinearisations()
{
    linPending.assign(trial.size(), pressureLinearisation());
    linActive = linPending;
    linCommitted = linPending;
    clearPressureHistory();
}


void solidModel::impl::clearPressureHistory()
{
    for (auto& h : pressureHistory) h.clear();
    nPressureHistory = 0;
}


void solidModel::impl::commitPressureHistory()
{
    // p_e at the committed state: the linearisation of its last tangent,
    // if that was evaluated there (a state reached by a line search's
    // residual-only evaluations breaks the history)
    std::vector<vecX> p(linPending.size());
    bool any = false, atState = true;
    matX X, u;
    for (std::size_t e = 0; e < linPending.size() && atState; ++e)
    {
        const pressureLinearisation& l = linPending[e];
        if (!l.valid()) continue;
        gather(int(e), X, u);
        const vecX ue = elementDofVector(u);
        atState = (ue - l.u).norm() <= 1e-12*(1 + ue.norm());
        p[e] = l.p;
        any = true;
    }
    if (!trackPressure || !any || !atState)
    {
        clearPressureHistory();
        return;
    }
    pressureHistory[2] = std::move(pressureHistory[1]);
    pressureHistory[1] = std::move(pressureHistory[0]);
    pressureHistory[0] = std::move(p);
    nPressureHistory = std::min(nPressureHistory + 1, 3);
}


void solidModel::tangentFactorised()
{
    impl& m = *impl_;
    if (!m.trackPressure) return;
    m.linActive = m.linPending;
    // A tangent at the committed state (a step that starts unpredicted,
    // the first one) gives the pressure history its first entry
    if (m.nPressureHistory == 0 && m.U == m.Ucommitted)
    {
        m.commitPressureHistory();
    }
}


void solidModel::forgetPressureLinearisation()
{
    impl& m = *impl_;
    m.linActive.assign(m.linActive.size(), pressureLinearisation());
}


void solidModel::predictPressure(double c1, double c2)
{
    impl& m = *impl_;
    forgetPressureLinearisation();
    if (!m.trackPressure || m.nPressureHistory < (c2 != 0 ? 3 : 2)) return;
    const std::vector<vecX>* h = m.pressureHistory;
    matX X, u;
    for (std::size_t e = 0; e < m.linActive.size(); ++e)
    {
        if
        (
            h[0][e].size() == 0 || h[1][e].size() != h[0][e].size()
         || (c2 != 0 && h[2][e].size() != h[0][e].size())
        )
        {
            continue;
        }
        pressureLinearisation& l = m.linActive[e];
        m.gather(int(e), X, u);
        l.u = elementDofVector(u);
        l.p = h[0][e] + c1*(h[0][e] - h[1][e]);
        if (c2 != 0) l.p += c2*(h[1][e] - h[2][e]);
        // (the tangent is evaluated at l.u itself: the slope is not used)
        l.dpdu = matX::Zero(l.p.size(), l.u.size());
    }
}


std::vector<double> solidModel::pressureHistory() const
{
    // [n, then per entry and element: size, values]
    const impl& m = *impl_;
    std::vector<double> h(1, m.nPressureHistory);
    for (int k = 0; k < m.nPressureHistory; ++k)
    {
        for (const vecX& p : m.pressureHistory[k])
        {
            h.push_back(p.size());
            h.insert(h.end(), p.data(), p.data() + p.size());
        }
    }
    return h;
}


void solidModel::setPressureHistory(const std::vector<double>& h)
{
    impl& m = *impl_;
    m.clearPressureHistory();
    if (h.empty()) return;
    const std::size_t nElements = m.linActive.size();
    const auto bad = []()
    {
        return numericalError
        (
            "solidModel::setPressureHistory: the list does not fit the"
            " model's elements"
        );
    };
    const double n = h[0];
    if (!(n >= 0 && n <= 3 && n == int(n))) throw bad();
    std::size_t i = 1;
    for (int k = 0; k < int(n); ++k)
    {
        std::vector<vecX>& entry = m.pressureHistory[k];
        entry.resize(nElements);
        for (std::size_t e = 0; e < nElements; ++e)
        {
            if (i >= h.size()) throw bad();
            const double size = h[i++];
            if (!(size >= 0 && size == int(size)) || i + size > h.size())
            {
                throw bad();
            }
            entry[e] = Eigen::Map<const vecX>(h.data() + i, int(size));
            i += std::size_t(size);
        }
    }
    if (i != h.size()) throw bad();
    m.nPressureHistory = int(n);
}


void solidModel::lineariseCommittedPressures()
{
    impl& m = *impl_;
    if (!m.trackPressure) return;
    const vecX U = m.U;
    m.U = m.Ucommitted;
    matX X, u, Ke;
    vecX fe;
    for (std::size_t e = 0; e < m.linActive.size(); ++e)
    {
        const auto& kernel = m.blocks[m.elemBlock[e]].kernel;
        if (!kernel || kernel->nPressure() == 0) continue;
        // with no active linearisation the element takes p_e(u)
        m.linActive[e] = pressureLinearisation();
        m.computeElement(int(e), X, u, fe, &Ke);
    }
    m.linCommitted = m.linPending;
    m.linActive = m.linCommitted;
    m.trial = m.committed;
    m.U = U;
}


void solidModel::setPressureTracking(bool on)
{
    impl_->trackPressure = on;
}


bool solidModel::tracksPressure() const
{
    return impl_->anyTracked;
}


vecX solidModel::trackedResidual(const vecX& r) const
{
    const impl& m = *impl_;
    vecX rt = r;
    if (!m.anyTracked) return rt;
    const int nFree = m.numbering.nFree();
    for (int k = 0; k < nFree && k < rt.size(); ++k)
    {
        rt(k) -= m.fintTrackedShift(m.numbering.freeDofs[k]);
    }
    return rt;
}

} // namespace form
