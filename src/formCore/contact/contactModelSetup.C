/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Contact by constraint functions (contactModel.H): set-up. The pairs and
    their contactor nodes from the case, the regularisation (k, epsilonN,
    epsilonT) and its automatic values, the unknowns, the shells' contact
    offsets and through-thickness compliance. The step: contactModel.C.
\*---------------------------------------------------------------------------*/
#include "contactModelImpl.H"
#include "formError.H"
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

namespace form
{

contactModel::contactModel
(
    const feMesh& mesh,
    analysisType analysis,
    double modulus,
    std::vector<rigidToolSpec> tools,
    std::vector<contactPairSpec> pairs,
    contactControls controls
)
:
    impl_(std::make_shared<impl>())
{
    impl& m = *impl_;
    m.mesh = &mesh;
    m.analysis = analysis;
    m.tools = std::move(tools);
    m.pairSpecs = std::move(pairs);
    m.controls = controls;
    m.dofs = dofMap::of(mesh);
    m.nDofs = m.dofs.nDofs();

    m.nDim = mesh.nDim;
    if ((mesh.nDim == 3) != (analysis == analysisType::solid3D))
    {
        throw inputError
        (
            "contact",
            "contact: a " + std::to_string(mesh.nDim) + "D mesh in a "
          + analysisTypeName(analysis) + " analysis"
        );
    }
    if (!(modulus > 0))
    {
        throw inputError("contact", "contactModel needs a positive modulus");
    }
    for (const rigidToolSpec& t : m.tools)
    {
        if (m.nDim == 2 && !t.profile)
        {
            throw inputError(t.name, "tool '" + t.name + "' has no profile");
        }
        if (m.nDim == 3 && !t.surface)
        {
            throw inputError
            (
                t.name,
                "tool '" + t.name + "' has no surface (a 3D model's tools"
                " are surfaces)"
            );
        }
        if (!std::isfinite(t.compliance) || t.compliance < 0)
        {
            char value[32];
            std::snprintf(value, sizeof(value), "%g", t.compliance);
            throw inputError
            (
                t.name + "/compliance",
                "tool '" + t.name + "': compliance out of range: "
              + std::string(value) + " (valid: 0 (rigid) or a positive"
                " normal give per unit pressure)"
            );
        }
        if (t.forceControlled)
        {
            if (!t.force)
            {
                throw inputError
                (
                    t.name + "/force",
                    "force-controlled tool '" + t.name + "' has no force"
                );
            }
            if (std::abs(t.direction.norm() - 1) > 1e-12)
            {
                throw inputError
                (
                    t.name + "/direction",
                    "tool '" + t.name + "': direction must be a unit vector"
                );
            }
        }
    }

    // Contactor nodes and faces per pair; spacing and radius for k, eps
    double lengthSum = 0;
    int nSpacings = 0;
    double radiusSum = 0;
    int nRadius = 0;
    int nUnknowns = 0;
    // The faces of a pair's face set, or an inputError naming the entry
    const auto faces = [&mesh]
    (
        const contactPairSpec& ps,
        const std::string& name,
        const std::string& entry,
        const std::string& role
    ) -> const std::vector<feFace>&
    {
        auto it = mesh.faceSets.find(name);
        if (it == mesh.faceSets.end() || it->second.empty())
        {
            std::string valid;
            for (const auto& s : mesh.faceSets) valid += " " + s.first;
            throw inputError
            (
                ps.name + "/" + entry,
                "pair '" + ps.name + "': unknown or empty " + role
              + " patch '" + name + "'; valid:" + valid
            );
        }
        return it->second;
    };
    for (const contactPairSpec& ps : m.pairSpecs)
    {
        impl::pairData p;
        if (ps.tool.empty() == ps.targetFaceSet.empty())
        {
            throw inputError
            (
                ps.name,
                "pair '" + ps.name + "': give either a tool or a target"
                " patch"
            );
        }
        if (ps.tool.empty() && m.nDim == 3)
        {
            p.tool = -1;
            p.surface = std::make_shared<deformableSurface>
            (
                mesh, faces(ps, ps.targetFaceSet, "targetPatch", "target")
            );
        }
        else if (ps.tool.empty())
        {
            p.tool = -1;
            p.target = std::make_shared<deformableTarget>
            (
                mesh, faces(ps, ps.targetFaceSet, "targetPatch", "target")
            );
        }
        else
        {
            p.tool = m.findTool(ps.tool);
        }
        p.mu = ps.friction;
        if (!(p.mu >= 0))
        {
            throw inputError
            (
                ps.name + "/friction",
                "pair '" + ps.name + "': friction must be >= 0"
            );
        }
        std::set<int> nodeSet;
        for (const feFace& f : faces(ps, ps.faceSet, "patch", "contactor"))
        {
            p.faces.push_back(f.nodes);
            nodeSet.insert(f.nodes.begin(), f.nodes.end());
            // Spacing: face length (its largest node distance, the end
            // nodes) over its node intervals
            const int n = int(f.nodes.size());
            double L = 0;
            for (int a = 0; a < n; ++a)
            {
                for (int b = a + 1; b < n; ++b)
                {
                    L = std::max
                    (
                        L,
                        (mesh.X.row(f.nodes[a]) - mesh.X.row(f.nodes[b])).norm()
                    );
                }
            }
            if (m.nDim == 3)
            {
                // a quad face: its diagonal over sqrt(2), over the node
                // intervals of an edge (1 for 4 nodes, 2 for 9)
                lengthSum += L/std::sqrt(2.0);
                nSpacings += int(std::lround(std::sqrt(double(n)))) - 1;
                continue;
            }
            lengthSum += L;
            nSpacings += n - 1;
        }
        // A node meets a tool once: a node on the patches of two pairs
        // with the same tool (the edge between a billet's top and its
        // side) belongs to the first pair only, or it would carry two
        // multipliers for one constraint and make the matrix singular
        for (const impl::pairData& q : m.pairs)
        {
            if (q.tool < 0 || q.tool != p.tool) continue;
            for (int node : q.nodes) nodeSet.erase(node);
        }
        if (nodeSet.empty())
        {
            throw inputError
            (
                ps.name + "/patch",
                "pair '" + ps.name + "': every node of patch '"
              + ps.faceSet + "' already belongs to another pair with tool '"
              + ps.tool + "'"
            );
        }
        p.nodes.assign(nodeSet.begin(), nodeSet.end());
        for (int node : p.nodes)
        {
            radiusSum += std::abs(mesh.X(node, 0));
            ++nRadius;
        }
        p.perNode = p.mu > 0 ? m.nDim : 1;
        p.first = nUnknowns;
        nUnknowns += p.perNode*int(p.nodes.size());
        p.xiCommitted.assign(p.nodes.size(), 0);
        p.lastSlip.assign(p.nodes.size(), 0);
        p.rate.assign(p.nodes.size(), 0);
        p.status.assign(p.nodes.size(), -1);
        p.edge.assign(p.nodes.size(), -1);
        p.flips.assign(p.nodes.size(), 0);
        p.cCommitted.assign(p.nodes.size(), vec3::Zero());
        p.slip3.assign(p.nodes.size(), vec3::Zero());
        p.ref.assign(p.nodes.size(), vec3::UnitX());
        m.pairs.push_back(std::move(p));
    }
    m.toolUnknown.assign(m.tools.size(), -1);
    for (std::size_t T = 0; T < m.tools.size(); ++T)
    {
        if (m.tools[T].forceControlled) m.toolUnknown[T] = nUnknowns++;
    }
    m.toolReleased.assign(m.tools.size(), false);
    m.toolForce.assign(m.tools.size(), vec3::Zero());

    const double spacing = nSpacings ? lengthSum/nSpacings : 1.0;
    m.spacing = spacing;
    // k scales lambda to a length: per unit depth (plane strain), per
    // full ring (axisymmetric), per tributary length (3D: a nodal force)
    double depth = m.nDim == 3 ? spacing : 1;
    if (analysis == analysisType::axisymmetric)
    {
        const double rbar = nRadius ? radiusSum/nRadius : 0;
        depth = 2*M_PI*std::max(rbar, spacing);
    }
    // Ranges: 0 (or absent) selects the automatic value. The
    // regularisation length sqrt(epsilonN) must stay well below the node
    // spacing, or contact would act across gaps of whole elements
    const auto number = [](double v)
    {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.6g", v);
        return std::string(buf);
    };
    const auto check = [&](const char* key, double v, double max,
                          const std::string& why)
    {
        if (!std::isfinite(v) || v < 0 || v > max)
        {
            throw inputError
            (
                key,
                "out of range: " + number(v) + " (valid: 0 for the"
                " automatic value, or a positive value" + why + ")"
            );
        }
    };
    check
    (
        "epsilonN", controls.epsilonN, std::pow(0.1*spacing, 2),
        " up to (0.1 l)^2 = " + number(std::pow(0.1*spacing, 2))
      + ", l = " + number(spacing) + " the mean spacing of the"
        " contactor nodes: sqrt(epsilonN) is the gap over which the"
        " regularised contact law acts"
    );
    check("epsilonT", controls.epsilonT, HUGE_VAL, "");
    check("stiffness", controls.stiffness, HUGE_VAL, "");
    if
    (
        controls.frictionLaw != "regularised"
     && controls.frictionLaw != "alartCurnier"
    )
    {
        throw inputError
        (
            "frictionLaw",
            "unknown friction law '" + controls.frictionLaw
          + "'; valid: regularised alartCurnier"
        );
    }
    if
    (
        !std::isfinite(controls.frictionAugmentation)
     || !(controls.frictionAugmentation > 0)
    )
    {
        throw inputError
        (
            "frictionAugmentation",
            "out of range: " + number(controls.frictionAugmentation)
          + " (valid: a positive number)"
        );
    }
    // Automatic split of the regularised law g f = epsN k = 1e-10 E l^2:
    // the knee of w at a pressure of about 1e-7 E (contactModel.H)
    m.k = controls.stiffness > 0 ? controls.stiffness : 1e-4*modulus*depth;
    m.modulus = modulus;
    m.epsN =
        controls.epsilonN > 0 ? controls.epsilonN : std::pow(1e-3*spacing, 2);
    // epsT: set at the first increment from the tools' speed (automatic
    // rule) unless given
    m.epsT = controls.epsilonT > 0 ? controls.epsilonT : 0;

    m.x = vecX::Zero(nUnknowns);
    m.xCommitted = m.x;
    for (impl::pairData& p : m.pairs) m.addToolCompliance(p);
}


int contactModel::nUnknowns() const { return int(impl_->x.size()); }
const vecX& contactModel::unknowns() const { return impl_->x; }

void contactModel::addToUnknowns(const vecX& dx)
{
    if (dx.size() != impl_->x.size())
    {
        throw numericalError
        (
            "contactModel::addToUnknowns: size " + std::to_string(dx.size())
          + " for " + std::to_string(impl_->x.size()) + " unknowns"
        );
    }
    impl_->x += dx;
}


void contactModel::setShells(const shellSet* shells)
{
    impl& m = *impl_;
    m.shells = shells;
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        impl::pairData& p = m.pairs[i];
        const contactPairSpec& spec = m.pairSpecs[i];
        p.offset.clear();
        p.compliance.clear();
        if (!shells || m.nDim != 3) continue;
        bool anyShell = false, anySolid = false;
        for (const int n : p.nodes)
        {
            (shells->shellNode(n) >= 0 ? anyShell : anySolid) = true;
        }
        if (!anyShell) continue;
        if (anySolid)
        {
            throw inputError
            (
                spec.name + "/patch",
                "pair '" + spec.name + "': patch '" + spec.faceSet
              + "' has both shell and solid nodes"
            );
        }
        if (p.tool < 0)
        {
            throw inputError
            (
                spec.name,
                "pair '" + spec.name + "': shells touch rigid tools only"
                " (contact of a shell with a deformable target is not"
                " available yet)"
            );
        }
        // The side of each node's director the patch covers: the patch's
        // faces are the elements' mid-surface quadrilaterals (MITC4,
        // MITC4+) or triangles (MITC3+) ordered with the patch's outward
        // normal
        std::map<int, int> side;
        for (const std::vector<int>& f : p.faces)
        {
            if (f.size() != 4 && f.size() != 3)
            {
                throw inputError
                (
                    spec.name + "/patch",
                    "pair '" + spec.name + "': patch '" + spec.faceSet
                  + "' is an edge of the shell; contact acts on the faces"
                    " of the sheet"
                );
            }
            const auto X = [&](int k)
            {
                return vec3(m.mesh->X.row(f[k]).transpose());
            };
            const vec3 n = f.size() == 4
              ? vec3((X(2) - X(0)).cross(X(3) - X(1)))
              : vec3((X(1) - X(0)).cross(X(2) - X(0)));
            for (const int node : f)
            {
                const int s = n.dot(shells->initialDirector(node)) > 0 ? 1 : -1;
                auto it = side.find(node);
                if (it != side.end() && it->second != s)
                {
                    throw inputError
                    (
                        spec.name + "/patch",
                        "pair '" + spec.name + "': patch '" + spec.faceSet
                      + "' covers both faces of the sheet at node "
                      + std::to_string(node)
                    );
                }
                side[node] = s;
            }
        }
        p.offset.resize(p.nodes.size());
        for (std::size_t a = 0; a < p.nodes.size(); ++a)
        {
            const int node = p.nodes[a];
            p.offset[a] = side[node]*0.5*shells->thickness(node);
        }
        // Through-thickness compliance of the contact points: a normal
        // force f on the node's share A of the face (int N_a dA on the
        // mid-surface) compresses the half thickness h by h f/(E A)
        std::map<int, double> area =
            m.faceWeights(p, vecX::Zero(m.nDofs));
        p.compliance.resize(p.nodes.size());
        for (std::size_t a = 0; a < p.nodes.size(); ++a)
        {
            const double A = area[p.nodes[a]];
            p.compliance[a] =
                A > 0 ? std::abs(p.offset[a])/(m.modulus*A) : 0.0;
        }
    }
    // (the tools' own compliance, cleared above with the shells')
    for (impl::pairData& p : m.pairs) m.addToolCompliance(p);
}


void contactModel::setShellThickness(const std::vector<double>& t)
{
    impl& m = *impl_;
    for (impl::pairData& p : m.pairs)
    {
        for (std::size_t a = 0; a < p.offset.size(); ++a)
        {
            const double h = 0.5*t[p.nodes[a]];
            p.offset[a] = p.offset[a] < 0 ? -h : h;
        }
    }
}

} // namespace form
