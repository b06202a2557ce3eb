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
}


void solidModel::commit()
{
    impl& m = *impl_;
    if (m.shells) m.shells->commit(m.dofs, m.U);
    m.Ucommitted = m.U;
    m.committed = m.trial;
    m.linCommitted = m.linPending;
    m.linActive = m.linCommitted;
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
}


void solidModel::tangentFactorised()
{
    impl& m = *impl_;
    if (m.trackPressure) m.linActive = m.linPending;
}


void solidModel::forgetPressureLinearisation()
{
    impl& m = *impl_;
    m.linActive.assign(m.linActive.size(), pressureLinearisation());
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
