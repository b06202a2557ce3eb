/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Contact by constraint functions (contactModel.H): the step (approach,
    the predictor's rule, status, rigid-tool residual and tangent, commit,
    revert, tool release). Set-up: contactModelSetup.C; deformable
    targets: contactModelDeformable.C; results and restart state:
    contactModelOutput.C.
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "formError.H"
#include <algorithm>
#include <cmath>
#include <limits>

namespace form
{

// Quasi-static approach of a force-controlled tool that touches nothing:
// translate it along e until the first contactor node ahead of it touches.
// For a node with normal n and gap g, a move by dz along e closes the gap
// by dz (n.e) to first order; a few passes make it exact on curved tools.
void contactModel::impl::approach(int T, double t1, const vecX& U)
{
    const rigidToolSpec& tool = tools[T];
    const int iz = toolUnknown[T];
    for (int pass = 0; pass < 20; ++pass)
    {
        const vec3 d = translation(T, t1);
        double best = std::numeric_limits<double>::infinity();
        bool anyAhead = false;
        for (const pairData& p : pairs)
        {
            if (p.tool != T) continue;
            for (int a = 0; a < int(p.nodes.size()); ++a)
            {
                const int node = p.nodes[a];
                double gap, ne;
                if (nDim == 3)
                {
                    const surfaceProjection P =
                        tool.surface->project(contactPoint(p, a, U) - d);
                    gap = P.gap;
                    ne = P.normal.dot(tool.direction);
                }
                else
                {
                    const profileProjection P = tool.profile->project
                    (
                        position(node, U) - d.head<2>()
                    );
                    gap = P.gap;
                    ne = P.normal.dot(tool.direction.head<2>());
                }
                if (ne < 0.1) continue;
                anyAhead = true;
                best = std::min(best, gap/ne);
            }
        }
        if (!anyAhead)
        {
            std::string pairNames;
            for (const auto& ps : pairSpecs)
            {
                if (ps.tool == tool.name) pairNames += " " + ps.name;
            }
            throw inputError
            (
                tool.name,
                "force-controlled tool '" + tool.name + "' moves along ("
              + formatNumber(tool.direction(0)) + " "
              + formatNumber(tool.direction(1))
              + (nDim == 3 ? " " + formatNumber(tool.direction(2)) : "")
              + ") but no contactor node"
                " of its pairs (" + pairNames + " ) lies ahead of it: it"
                " would never touch the body"
            );
        }
        // Touching (within the constraint's corner) or already pressed
        if (best <= std::sqrt(epsN)) return;
        x(iz) += best;
        xCommitted(iz) = x(iz);
    }
}


void contactModel::beginIncrement(double t0, double t1, const vecX& U)
{
    impl& m = *impl_;
    if (!m.xiInitialised)
    {
        m.tCommitted = t0;
        m.initialiseXi(U, t0);
    }
    // The committed state (also after a restart, where it is not
    // committed through commit())
    m.Ucommitted = U;
    m.restored = false;
    if (m.epsT <= 0)
    {
        // Automatic friction regularisation: the smooth transition of the
        // Coulomb function covers sliding speeds below 1 % of the fastest
        // prescribed tool speed (over the first increment); without moving
        // tools, 1e-4 of the node spacing per unit time
        double speed = 0;
        for (const rigidToolSpec& tool : m.tools)
        {
            if (!tool.translation || !(t1 > t0)) continue;
            speed = std::max
            (
                speed,
                (tool.translation(t1) - tool.translation(t0)).norm()/(t1 - t0)
            );
        }
        const double width = speed > 0 ? 1e-2*speed : 1e-4*m.spacing;
        m.epsT = width*width;
    }
    for (impl::pairData& p : m.pairs)
    {
        std::fill(p.flips.begin(), p.flips.end(), 0);
    }
    for (std::size_t T = 0; T < m.tools.size(); ++T)
    {
        if (m.toolUnknown[T] < 0 || m.toolReleased[T]) continue;
        if (m.tools[T].force(t1) == 0) continue;
        // Approach only when none of the tool's nodes carries force
        bool pressed = false;
        for (const impl::pairData& p : m.pairs)
        {
            if (p.tool != int(T)) continue;
            for (std::size_t a = 0; a < p.nodes.size(); ++a)
            {
                if (p.status[a] == 1) pressed = true;
            }
        }
        if (!pressed) m.approach(int(T), t1, U);
    }
    m.hardStart(t1, U);
}


// The predictor's rule for the contact unknowns (contactModel.H)
void contactModel::keepCommitted(vecX& dx, const vecX& previous) const
{
    for (const auto& p : impl_->pairs)
    {
        // Rigid tools only: between two deformable bodies the forces
        // move with both surfaces (the two-pass elastic punch of
        // tests/cases/contact.sh took 9 iterations per step instead of
        // 8 with its forces held)
        if (p.tool < 0) continue;
        // A force whose last two increments have the same sign grows or
        // falls steadily (a die upsetting a billet) and is extrapolated;
        // one whose increments alternated, or that has no history yet,
        // starts from its committed value
        for (int j = p.first; j < p.first + p.perNode*int(p.nodes.size()); ++j)
        {
            if (previous.size() != dx.size() || dx(j)*previous(j) <= 0)
            {
                dx(j) = 0;
            }
        }
    }
}


// A node that has never carried force (its multiplier exactly zero) but
// touches its rigid tool at the start of the step (gap within the knee,
// e.g. a sheet laid on the die with the holder on it) would start at the
// knee of w, lambda = g = 0, where w_g = w_lambda = 1/2: the first Newton
// update then sees the contact as a spring of stiffness k (1e-4 E per
// node), and a holder force of a few kN drives the sheet millimetres
// through the tools (the square cup stalled there). Started on the hard
// branch instead, lambda = 10 sqrt(epsN) (w_g = 0.99: a gap held to 1 %,
// a nodal force of 1e-6 E l), the first update keeps the node on the
// tool; Newton opens it in the next iteration if it should lift off.
void contactModel::impl::hardStart(double t1, const vecX& U)
{
    const double band = std::sqrt(epsN);
    for (pairData& p : pairs)
    {
        if (p.tool < 0 || !p.active || toolReleased[p.tool]) continue;
        const vec3 d = translation(p.tool, t1);
        for (int a = 0; a < int(p.nodes.size()); ++a)
        {
            const int il = p.first + p.perNode*a;
            if (x(il) != 0 || xCommitted(il) != 0) continue;
            const double gap = nDim == 3
              ? tools[p.tool].surface->project(contactPoint(p, a, U) - d).gap
              : tools[p.tool].profile->project
                (
                    position(p.nodes[a], U) - d.head<2>()
                ).gap;
            if (gap <= band) x(il) = 10*band;
        }
    }
}


int contactModel::impl::updateStatus
(
    pairData& p,
    int a,
    double lambda,
    double gap,
    const vecX& U,
    bool tangent
)
{
    // Status with a dead band: a node whose gap and multiplier are both
    // at round-off level (touching without force, e.g. a flat sheet under
    // a flat punch) keeps its status, so only real open/closed changes
    // count as chattering
    const int node = p.nodes[a];
    const double band = std::max(std::sqrt(epsN), 1e-9*spacing);
    int closed = p.status[a] < 0 ? (lambda > gap ? 1 : 0) : p.status[a];
    if (lambda - gap > band) closed = 1;
    else if (gap - lambda > band) closed = 0;
    nClosed += closed;
    if (closed) p.touched = true;
    if (p.status[a] >= 0 && p.status[a] != closed && tangent)
    {
        if (++p.flips[a] > controls.maxStatusChanges)
        {
            throw numericalError
            (
                "contact status chattering: node " + std::to_string(node)
              + " at (" + formatNumber(position3(node, U)(0)) + " "
              + formatNumber(position3(node, U)(1))
              + (nDim == 3 ? " " + formatNumber(position3(node, U)(2)) : "")
              + ") of pair '"
              + pairSpecs[&p - pairs.data()].name
              + "' switched between open and closed "
              + std::to_string(p.flips[a]) + " times in this step"
                " (maxStatusChanges "
              + std::to_string(controls.maxStatusChanges) + ")"
            );
        }
    }
    if (tangent) p.status[a] = closed;
    return closed;
}


const vecX& contactModel::frictionForces() const
{
    return impl_->friction;
}


void contactModel::evaluate
(
    double t,
    const vecX& U,
    vecX& fext,
    vecX& r,
    std::vector<triplet>* K
)
{
    impl& m = *impl_;
    const double k = m.k;
    const int N = m.nDofs;
    const double dt =
        std::max(t - m.tCommitted, 1e-12*std::max(1.0, std::abs(t)));
    r.setZero(nUnknowns());
    m.tEvaluated = t;
    m.nClosed = 0;
    std::fill(m.toolForce.begin(), m.toolForce.end(), vec3::Zero());
    m.friction.setZero(fext.size());

    const auto add = [K](int i, int j, double v)
    {
        K->emplace_back(i, j, v);
    };

    for (impl::pairData& p : m.pairs)
    {
        if (p.target && p.active)
        {
            m.evaluateDeformable(p, dt, U, fext, r, K);
            continue;
        }
        if (p.surface && p.active)
        {
            m.evaluateDeformable3D(p, dt, U, fext, r, K);
            continue;
        }
        const int T = p.tool;
        const int nNodes = int(p.nodes.size());
        if (!p.active)
        {
            // Released: multipliers driven to zero, no force
            for (int j = 0; j < p.perNode*nNodes; ++j)
            {
                const int q = p.first + j;
                r(q) = -k*m.x(q);
                if (K) add(N + q, N + q, k);
            }
            continue;
        }
        if (m.nDim == 3)
        {
            m.evaluateRigid3D(p, t, dt, U, fext, r, K);
            continue;
        }
        const rigidToolSpec& tool = m.tools[T];
        const Eigen::Vector2d d = m.translation2(T, t);

        for (int a = 0; a < nNodes; ++a)
        {
            const int node = p.nodes[a];
            const Eigen::Vector2d y = m.position(node, U) - d;
            // A diverging iterate: report it (the step is cut back)
            // instead of projecting non-finite or absurd positions
            m.checkPosition(p, node, vec3(y(0), y(1), 0));
            const profileProjection P = tool.profile->project(y);
            impl::nodeTarget q;
            q.dofs = {m.dofs.dof(node, 0), m.dofs.dof(node, 1)};
            q.weight = {1};
            q.gap = P.gap;
            q.dGap = P.normal;
            q.n = P.normal;
            q.dn = P.dNormalDY;
            q.tool = T;
            if (p.perNode == 2)
            {
                // Slip rate over the step (a velocity, so that the
                // friction law does not depend on the step size;
                // setSlipRateLaw)
                q.t = P.tangent;
                q.dt = {matX(R90*P.dNormalDY)};
                p.rate[a] =
                    (
                        m.rateA*(P.xi - p.xiCommitted[a])
                      + m.rateB*p.lastSlip[a]
                    )/dt;
                q.s = vecX::Constant(1, p.rate[a]);
                q.ds = m.rateA/dt*P.dXidY.transpose();
            }
            m.assembleNode(p, a, q, dt, U, fext, r, K);
        }
    }

    // Force-controlled tools
    for (std::size_t T = 0; T < m.tools.size(); ++T)
    {
        const int iz = m.toolUnknown[T];
        if (iz < 0) continue;
        const rigidToolSpec& tool = m.tools[T];
        const double F = m.toolReleased[T] ? 0.0 : tool.force(t);
        if (m.toolReleased[T] || F == 0)
        {
            // Holds its position
            r(iz) = k*(m.xCommitted(iz) - m.x(iz));
            if (K) add(N + iz, N + iz, k);
            continue;
        }
        r(iz) = F - tool.direction.dot(m.toolForce[T]);
    }
}


void contactModel::commit(const vecX& U)
{
    impl& m = *impl_;
    if (m.restored)
    {
        // The commit of a state just read on a restart: it is the written
        // run's committed state. Projecting again would redo the closest
        // points with the contact offsets of the mesh as read (a shell's
        // faces at their initial thickness until the commit updates them:
        // the square cup restarted to 1e-7 instead of bit-identically)
        // and zero the slips of the last step
        m.restored = false;
        m.Ucommitted = U;
        return;
    }
    m.xCommitted = m.x;
    m.tCommitted = m.tEvaluated;
    if (m.nDim == 3)
    {
        for (auto& p : m.pairs) m.commit3D(p, U);
        m.addFrictionDissipation();
        m.Ucommitted = U;
        return;
    }
    std::vector<std::vector<double>> xiOld;
    for (const auto& p : m.pairs) xiOld.push_back(p.xiCommitted);
    m.initialiseXi(U, m.tCommitted);
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        auto& p = m.pairs[i];
        for (std::size_t a = 0; a < p.nodes.size(); ++a)
        {
            p.lastSlip[a] = p.xiCommitted[a] - xiOld[i][a];
            if (!p.target || m.Ucommitted.size() != U.size()) continue;
            // Deformable target: relative tangential slip of the step
            const segmentProjection P = p.target->project
            (
                m.position(p.nodes[a], U), p.nodes[a], U, p.edge[a]
            );
            if (!P.onTarget) { p.lastSlip[a] = 0; continue; }
            Eigen::Vector2d delta =
                m.dofs.vector2(U - m.Ucommitted, p.nodes[a]);
            for (std::size_t b = 0; b < P.nodes.size(); ++b)
            {
                delta -=
                    P.N(b)*m.dofs.vector2(U - m.Ucommitted, P.nodes[b]);
            }
            p.lastSlip[a] = P.tangent.dot(delta);
        }
    }
    m.addFrictionDissipation();
    m.Ucommitted = U;
}


void contactModel::impl::addFrictionDissipation()
{
    // The friction force at the end of the (sub-)step times its slip
    // (backward Euler, the rule of the friction law itself): k |tau| is
    // the node's tangential force (pairResults), lastSlip the slip
    // relative to the tool or target (3D: its magnitude)
    for (const pairData& p : pairs)
    {
        if (!p.active || p.perNode < 2) continue;
        for (std::size_t a = 0; a < p.nodes.size(); ++a)
        {
            const int il = p.first + p.perNode*int(a);
            const double tau = p.perNode == 3
              ? std::hypot(x(il + 1), x(il + 2)) : std::abs(x(il + 1));
            frictionDissipation += k*tau*std::abs(p.lastSlip[a]);
        }
    }
}


double contactModel::frictionDissipation() const
{
    return impl_->frictionDissipation;
}


void contactModel::setSlipRateLaw(double current, double previous)
{
    if (!(current > 0) || !std::isfinite(previous))
    {
        throw numericalError
        (
            "contactModel::setSlipRateLaw: the weight of the current slip"
            " must be positive, got " + std::to_string(current)
        );
    }
    impl_->rateA = current;
    impl_->rateB = previous;
}


void contactModel::revert()
{
    impl& m = *impl_;
    m.x = m.xCommitted;
}


std::vector<std::pair<int, double>> contactModel::releaseTool
(
    const std::string& tool,
    const vecX& U
)
{
    impl& m = *impl_;
    const int T = m.findTool(tool);
    std::vector<std::pair<int, double>> forces;
    const Eigen::Vector2d d = m.translation2(T, m.tCommitted);
    for (impl::pairData& p : m.pairs)
    {
        if (p.tool != T || !p.active) continue;
        for (std::size_t a = 0; a < p.nodes.size() && m.nDim == 3; ++a)
        {
            const int node = p.nodes[a];
            const surfaceProjection P = m.tools[T].surface->project
            (
                m.contactPoint(p, int(a), U) - m.translation(T, m.tCommitted)
            );
            const int il = p.first + p.perNode*int(a);
            vec3 f = m.k*m.xCommitted(il)*P.normal;
            if (p.perNode == 3)
            {
                const tangentFrame F = m.frameOf(p, int(a), P);
                f += m.k*(m.xCommitted(il + 1)*F.t1 + m.xCommitted(il + 2)*F.t2);
            }
            for (int i = 0; i < 3; ++i)
            {
                forces.push_back({m.dofs.dof(node, i), f(i)});
            }
            if (!p.offset.empty())
            {
                // A shell node: the force's moment on its rotation dofs
                const directorState D = m.shells->directorAt(node, m.dofs, U);
                for (int j = 0; j < 2; ++j)
                {
                    forces.push_back
                    (
                        {m.dofs.dof(node, 3 + j), p.offset[a]*D.dV.col(j).dot(f)}
                    );
                }
            }
        }
        for (std::size_t a = 0; a < p.nodes.size() && m.nDim == 2; ++a)
        {
            const int node = p.nodes[a];
            const profileProjection P =
                m.tools[T].profile->project(m.position(node, U) - d);
            const int il = p.first + p.perNode*int(a);
            const double tau = p.perNode == 2 ? m.xCommitted(il + 1) : 0.0;
            const Eigen::Vector2d f =
                m.k*(m.xCommitted(il)*P.normal + tau*P.tangent);
            forces.push_back({m.dofs.dof(node, 0), f(0)});
            forces.push_back({m.dofs.dof(node, 1), f(1)});
        }
        p.active = false;
    }
    m.toolReleased[T] = true;
    return forces;
}


bool contactModel::released(const std::string& tool) const
{
    return impl_->toolReleased[impl_->findTool(tool)];
}


bool contactModel::active() const
{
    for (const impl::pairData& p : impl_->pairs)
    {
        if (p.active) return true;
    }
    return false;
}


const std::vector<rigidToolSpec>& contactModel::tools() const
{
    return impl_->tools;
}


const std::vector<contactPairSpec>& contactModel::pairs() const
{
    return impl_->pairSpecs;
}


vec3 contactModel::toolTranslation
(
    const std::string& tool,
    double t
) const
{
    return impl_->translation(impl_->findTool(tool), t);
}


vec3 contactModel::toolForce(const std::string& tool) const
{
    return impl_->toolForce[impl_->findTool(tool)];
}


} // namespace form
