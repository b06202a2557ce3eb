/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    contactModel: results per pair and tool, names of the unknowns, the
    description for the log and the restart state (contactModel.H).
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "solidElement.H"
#include <algorithm>
#include <cstdio>

namespace form
{


std::map<int, double> contactModel::impl::faceWeights
(
    const pairData& p,
    const vecX& U
) const
{
    std::map<int, double> weight;
    for (const std::vector<int>& face : p.faces)
    {
        const int n = int(face.size());
        if (nDim == 3)
        {
            matX X(n, 3);
            for (int a = 0; a < n; ++a)
            {
                X.row(a) = position3(face[a], U).transpose();
            }
            const vecX f = faceLoad::deadTraction(X, vec3(1, 0, 0));
            for (int a = 0; a < n; ++a) weight[face[a]] += f(3*a);
            continue;
        }
        matX X(n, 2);
        for (int a = 0; a < n; ++a) X.row(a) = position(face[a], U);
        const vecX f =
            edgeLoad::deadTraction(X, Eigen::Vector2d(1, 0), analysis);
        for (int a = 0; a < n; ++a) weight[face[a]] += f(2*a);
    }
    return weight;
}


void contactModel::impl::addToolCompliance(pairData& p) const
{
    if (p.tool < 0 || !(tools[p.tool].compliance > 0)) return;
    const double c = tools[p.tool].compliance;
    const std::map<int, double> area = faceWeights(p, vecX::Zero(nDofs));
    p.compliance.resize(p.nodes.size(), 0.0);
    for (std::size_t a = 0; a < p.nodes.size(); ++a)
    {
        const auto it = area.find(p.nodes[a]);
        // (a node on the axis of an axisymmetric model has no ring area:
        // its force is zero, so is its give)
        if (it != area.end() && it->second > 0) p.compliance[a] += c/it->second;
    }
}


std::vector<contactNodeResult> contactModel::pairResults
(
    const std::string& pair,
    const vecX& U,
    double t
) const
{
    const impl& m = *impl_;
    int ip = -1;
    for (std::size_t i = 0; i < m.pairSpecs.size(); ++i)
    {
        if (m.pairSpecs[i].name == pair) ip = int(i);
    }
    if (ip < 0)
    {
        throw inputError(pair, "unknown contact pair '" + pair + "'");
    }
    const impl::pairData& p = m.pairs[ip];

    // Consistent weights on the current configuration
    std::map<int, double> weight = m.faceWeights(p, U);

    std::vector<contactNodeResult> results;
    const Eigen::Vector2d d =
        p.tool < 0 ? Eigen::Vector2d::Zero() : m.translation2(p.tool, t);
    for (std::size_t a = 0; a < p.nodes.size(); ++a)
    {
        contactNodeResult res;
        res.node = p.nodes[a];
        res.x = m.nDim == 3 ? m.contactPoint(p, int(a), U) : m.position3(res.node, U);
        const int il = p.first + p.perNode*int(a);
        const double lambda = p.active ? m.x(il) : 0.0;
        double tau = p.active && p.perNode == 2 ? m.x(il + 1) : 0.0;
        if (p.active && p.perNode == 3)
        {
            tau = std::hypot(m.x(il + 1), m.x(il + 2));
        }
        res.normalForce = m.k*lambda;
        res.tangentialForce = m.k*tau;
        res.weight = weight[res.node];
        res.pressure = res.weight > 0 ? res.normalForce/res.weight : 0;
        res.shear = res.weight > 0 ? res.tangentialForce/res.weight : 0;
        if (p.target || p.surface)
        {
            // Deformable target: the gap of the node's projection
            // (infinite beyond the target)
            bool on = false;
            double gap = 0;
            if (p.target)
            {
                const segmentProjection P = p.target->project
                (
                    res.x.head<2>(), res.node, U, p.edge[a]
                );
                on = P.onTarget;
                gap = P.gap;
            }
            else
            {
                const faceProjection P =
                    p.surface->project(res.x, res.node, U, p.edge[a]);
                on = P.onTarget;
                gap = P.gap;
            }
            res.gap = on ? gap : std::numeric_limits<double>::infinity();
            res.slip = p.lastSlip[a];
            res.slipRate = p.rate[a];
            res.closed = on && lambda > gap;
            results.push_back(res);
            continue;
        }
        if (m.nDim == 3)
        {
            const surfaceProjection P = m.tools[p.tool].surface->project
            (
                res.x - m.translation(p.tool, t)
            );
            res.gap = P.gap;
            res.slip = p.lastSlip[a];
            res.slipRate = p.rate[a];
            res.closed = lambda > P.gap;
            results.push_back(res);
            continue;
        }
        const profileProjection P =
            m.tools[p.tool].profile->project(res.x.head<2>() - d);
        res.gap = P.gap;
        // Slip over the last step: after a commit (output time) that is
        // the committed step's; during a step, the slip so far
        res.slip =
            std::abs(P.xi - p.xiCommitted[a]) > 0
          ? P.xi - p.xiCommitted[a] : p.lastSlip[a];
        res.slipRate = p.rate[a];
        res.closed = lambda > P.gap;
        results.push_back(res);
    }
    return results;
}


int contactModel::nClosed() const { return impl_->nClosed; }


std::string contactModel::unknownName(int j) const
{
    const impl& m = *impl_;
    for (std::size_t T = 0; T < m.tools.size(); ++T)
    {
        if (m.toolUnknown[T] == j) return m.tools[T].name + " position";
    }
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        const auto& p = m.pairs[i];
        const int n = p.perNode*int(p.nodes.size());
        if (j >= p.first && j < p.first + n)
        {
            const int a = (j - p.first)/p.perNode;
            return m.pairSpecs[i].name + " node " + std::to_string(p.nodes[a])
              + ((j - p.first) % p.perNode ? " friction" : " normal");
        }
    }
    return "unknown " + std::to_string(j);
}

bool contactModel::touched(const std::string& tool) const
{
    const int T = impl_->findTool(tool);
    for (const auto& p : impl_->pairs)
    {
        if (p.tool == T && p.touched) return true;
    }
    return false;
}

bool contactModel::pairTouched(const std::string& pair) const
{
    const impl& m = *impl_;
    for (std::size_t i = 0; i < m.pairSpecs.size(); ++i)
    {
        if (m.pairSpecs[i].name == pair) return m.pairs[i].touched;
    }
    throw numericalError("contactModel::pairTouched: no pair '" + pair + "'");
}

double contactModel::stiffness() const { return impl_->k; }
double contactModel::epsilonN() const { return impl_->epsN; }
double contactModel::epsilonT() const { return impl_->epsT; }


std::string contactModel::describe() const
{
    const impl& m = *impl_;
    std::string s;
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        const auto& p = m.pairs[i];
        const auto& ps = m.pairSpecs[i];
        s += "pair " + ps.name + ": patch " + ps.faceSet + " ("
          + std::to_string(p.nodes.size()) + " nodes) against "
          + (p.target || p.surface
              ? "patch " + ps.targetFaceSet + " ("
              + (p.target
                  ? std::to_string(p.target->nEdges()) + " edges"
                  : std::to_string(p.surface->nFaces()) + " faces")
              + ", deformable)"
              : "tool " + ps.tool + (m.tools[p.tool].forceControlled
              ? " (force-controlled)" : " (motion)"))
          + ", friction " + formatNumber(p.mu) + "\n";
    }
    s += "k " + formatNumber(m.k) + ", sqrt(epsN) "
      + formatNumber(std::sqrt(m.epsN)) + ", sqrt(epsT) "
      + (m.epsT > 0 ? formatNumber(std::sqrt(m.epsT)) : "auto (1 % of tool speed)")
      + ", friction law " + m.controls.frictionLaw
      + (
            m.controls.frictionLaw == "alartCurnier"
          ? " (augmentation " + formatNumber(m.controls.frictionAugmentation)
          + ")"
          : std::string()
        )
      + ", unknowns "
      + std::to_string(m.x.size());
    return s;
}


std::vector<double> contactModel::state() const
{
    const impl& m = *impl_;
    std::vector<double> s(m.xCommitted.data(),
        m.xCommitted.data() + m.xCommitted.size());
    for (const auto& p : m.pairs)
    {
        s.insert(s.end(), p.xiCommitted.begin(), p.xiCommitted.end());
        s.push_back(p.active ? 1 : 0);
        s.push_back(p.touched ? 1 : 0);
        // 3D: closest points, their last slips, reference directions
        for (std::size_t a = 0; m.nDim == 3 && a < p.nodes.size(); ++a)
        {
            for (const vec3* v : {&p.cCommitted[a], &p.slip3[a], &p.ref[a]})
            {
                s.insert(s.end(), v->data(), v->data() + 3);
            }
        }
    }
    for (bool r : m.toolReleased) s.push_back(r ? 1 : 0);
    s.push_back(m.tCommitted);
    s.push_back(m.frictionDissipation);
    return s;
}


void contactModel::setState(const std::vector<double>& s)
{
    impl& m = *impl_;
    std::size_t expected = m.x.size() + m.tools.size() + 1;
    for (const auto& p : m.pairs)
    {
        expected += p.nodes.size()*(m.nDim == 3 ? 10 : 1) + 2;
    }
    // (+1: the friction dissipation, absent from states written before
    // 2026-11-29, which restart with none dissipated)
    if (s.size() != expected && s.size() != expected + 1)
    {
        throw numericalError
        (
            "contactModel::setState: " + std::to_string(s.size())
          + " values for a contact state of " + std::to_string(expected)
        );
    }
    std::size_t i = 0;
    for (int j = 0; j < m.x.size(); ++j) m.x(j) = s[i++];
    m.xCommitted = m.x;
    for (auto& p : m.pairs)
    {
        for (double& xi : p.xiCommitted) xi = s[i++];
        p.active = s[i++] > 0.5;
        p.touched = s[i++] > 0.5;
        for (std::size_t a = 0; m.nDim == 3 && a < p.nodes.size(); ++a)
        {
            for (vec3* v : {&p.cCommitted[a], &p.slip3[a], &p.ref[a]})
            {
                for (int c = 0; c < 3; ++c) (*v)(c) = s[i++];
            }
        }
    }
    for (std::size_t T = 0; T < m.tools.size(); ++T)
    {
        m.toolReleased[T] = s[i++] > 0.5;
    }
    m.tCommitted = s[i++];
    m.frictionDissipation = i < s.size() ? s[i++] : 0.0;
    // A commit() right after a restart (formScene commits the read state)
    // must keep this time: it is the start of the next slip-rate interval
    m.tEvaluated = m.tCommitted;
    m.xiInitialised = true;
    m.restored = true;
}

} // namespace form
