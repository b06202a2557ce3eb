/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidModel: constraints (fixed, prescribed, released) and loads
    (point loads, tractions, follower pressures, body force), and their
    assembly into f_ext and the load stiffness (see solidModel.H).
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

const std::vector<feFace>& solidModel::impl::shellEdges
(
    const std::string& name,
    const std::string& what,
    const std::string& hint
) const
{
    const std::vector<feFace>& faces = faceSet(name);
    for (const feFace& face : faces)
    {
        if (nDim != 3 || face.nodes.size() != 2)
        {
            throw inputError
            (
                name,
                what + " on '" + name + "', which is not a side (edge) of"
                " a shell sheet" + hint
            );
        }
    }
    return faces;
}


void solidModel::impl::assembleExternal(double t, bool wantTangent)
{
    matX X, u, K;
    vecX f;
    if (bodyForce)
    {
        const vec3 g = inPlane(bodyForce(t), "bodyForce");
        for (int k = 0; k < bodyWeights.size(); ++k)
        {
            const int c = dofs.component(k);   // shells: 3, 4 rotations
            if (c < 3) fext(k) += bodyWeights(k)*g(c);
        }
    }
    for (const auto& l : nodalLoads) fext(l.first) += l.second(t);
    for (const momentLoad& l : moments)
    {
        const vec3 mt = l.m(t);
        for (const auto& nw : l.nodes)
        {
            const shellDirector& fr = shells->frame(nw.first);
            fext(dofs.dof(nw.first, 3)) += nw.second*mt.dot(fr.V1);
            fext(dofs.dof(nw.first, 4)) += nw.second*mt.dot(fr.V2);
        }
    }
    for (const auto& l : tractions)
    {
        const vec3 tv = inPlane(l.t(t), l.faceSet);
        for (const faceRef& face : l.faces)
        {
            gatherFace(face, X, u);
            if (nDim == 3 && face.nodes.size() == 2)
            {
                // A shell edge: the traction acts on the side face of
                // the sheet, its length times the thickness; a line load
                // on its length
                const double area =
                    (X.row(1) - X.row(0)).norm()
                   *(
                        l.perLength ? 1.0
                      : mesh.blocks[elemBlock[face.element]].shell.thickness
                    );
                f.resize(6);
                f << 0.5*area*tv, 0.5*area*tv;
            }
            else
            {
                f =
                    nDim == 3
                  ? faceLoad::deadTraction(X, tv)
                  : edgeLoad::deadTraction(X, tv.head<2>(), analysis);
            }
            for (std::size_t a = 0; a < face.nodes.size(); ++a)
            {
                for (int i = 0; i < nDim; ++i)
                {
                    fext(dofs.dof(face.nodes[a], i)) += f(elementDof(nDim, a, i));
                }
            }
        }
    }

    double* ff = Kff.valuePtr();
    double* fp = Kfp.valuePtr();
    for (const auto& l : pressures)
    {
        const double p = l.p(t);
        for (const faceRef& face : l.faces)
        {
            gatherFace(face, X, u);
            if (nDim == 3)
            {
                faceLoad::followerPressure
                (
                    X, u, p, f, wantTangent ? &K : nullptr
                );
            }
            else
            {
                edgeLoad::followerPressure
                (
                    X, u, p, analysis, f, wantTangent ? &K : nullptr
                );
            }
            const int nf = int(face.nodes.size());
            for (int a = 0; a < nf; ++a)
            {
                for (int i = 0; i < nDim; ++i)
                {
                    fext(dofs.dof(face.nodes[a], i)) += f(elementDof(nDim, a, i));
                }
            }
            if (!wantTangent) continue;

            const int nE = pattern.nElementDofs(face.element);
            const int* code = pattern.scatter(face.element);
            // Dofs per node of the owning element (5 for shells)
            const int nd = blocks[elemBlock[face.element]].nodeDofs;
            for (int b = 0; b < nf; ++b)
            {
                for (int j = 0; j < nDim; ++j)
                {
                    const int lb = face.localNodes[b]*nd + j;
                    for (int a = 0; a < nf; ++a)
                    {
                        for (int i = 0; i < nDim; ++i)
                        {
                            const int la = face.localNodes[a]*nd + i;
                            const int c = code[la + nE*lb];
                            const double v = K(elementDof(nDim, a, i), elementDof(nDim, b, j));
                            if (c >= 0) ff[c] += v;
                            else if (c <= -2) fp[-2 - c] += v;
                        }
                    }
                }
            }
        }
    }
}


void solidModel::addConstraint
(
    const std::vector<int>& nodes,
    int component,
    timeFunction value
)
{
    impl& m = *impl_;
    // (no nodes: nothing to hold, e.g. the rotations a symmetry plane
    // holds on the shell nodes of a region that has none)
    if (nodes.empty()) return;
    const int nComponents = m.shells ? shellSet::nodeDofs : m.nDim;
    if (component < 0 || component >= nComponents)
    {
        throw inputError
        (
            "component",
            "constraint component " + std::to_string(component)
          + " out of range 0.." + std::to_string(nComponents - 1)
        );
    }
    for (int node : nodes)
    {
        if (node < 0 || node >= m.mesh.nNodes())
        {
            throw inputError
            (
                "nodes",
                "constraint on non-existent node " + std::to_string(node)
            );
        }
        if (component >= m.dofs.count(node))
        {
            throw inputError
            (
                "component",
                "constraint component " + std::to_string(component)
              + " of node " + std::to_string(node) + ", which carries "
              + std::to_string(m.dofs.count(node)) + " dofs (the rotations"
                " 3 and 4 belong to shell nodes)"
            );
        }
        m.constraints[m.dofs.dof(node, component)] = value;
    }
    if (m.finalised) m.build();
}


void solidModel::addNodalConstraint
(
    const std::vector<int>& nodes,
    int component,
    const std::function<double(int, double)>& value
)
{
    impl& m = *impl_;
    const bool wasFinalised = m.finalised;
    m.finalised = false;
    for (int node : nodes)
    {
        addConstraint
        (
            {node},
            component,
            [value, node](double t) { return value(node, t); }
        );
    }
    m.finalised = wasFinalised;
    if (m.finalised) m.build();
}


void solidModel::releaseConstraint
(
    const std::vector<int>& nodes,
    int component,
    double t0,
    double t1
)
{
    impl& m = *impl_;
    if (!(t1 > t0))
    {
        throw inputError("endTime", "release ramp needs t1 > t0");
    }
    // Reaction at the last (converged) evaluation: f_int - f_ext
    if (m.fint.size() == m.nDofs())
    {
        for (int node : nodes)
        {
            const int d = m.dofs.dof(node, component);
            if (node >= 0 && node < m.mesh.nNodes() && m.constraints.count(d))
            {
                m.released.push_back({d, m.fint(d) - m.fext(d), t0, t1});
            }
        }
    }
    releaseConstraint(nodes, component);
}


bool solidModel::constrained(int dof) const
{
    return impl_->constraints.count(dof) > 0;
}


void solidModel::addTraction(const std::string& faceSet, vectorTimeFunction t)
{
    impl& m = *impl_;
    m.faceSet(faceSet);
    m.tractions.push_back({faceSet, std::move(t), {}});
    if (m.finalised) m.tractions.back().faces = m.locateFaces(faceSet);
}


void solidModel::addLineLoad(const std::string& faceSet, vectorTimeFunction f)
{
    impl& m = *impl_;
    m.shellEdges(faceSet, "a line load", ": use a traction");
    addTraction(faceSet, std::move(f));
    m.tractions.back().perLength = true;
}


void solidModel::addNodalLoad
(
    const std::vector<int>& nodes,
    int component,
    timeFunction value
)
{
    impl& m = *impl_;
    if (!value)
    {
        throw numericalError("solidModel::addNodalLoad: no load function");
    }
    for (int node : nodes)
    {
        if (node < 0 || node >= m.mesh.nNodes())
        {
            throw inputError
            (
                "nodes",
                "point load on non-existent node " + std::to_string(node)
            );
        }
        if (component < 0 || component >= m.dofs.count(node))
        {
            throw inputError
            (
                "component",
                "point load component " + std::to_string(component)
              + " of node " + std::to_string(node) + ", which carries "
              + std::to_string(m.dofs.count(node)) + " dofs"
            );
        }
        m.nodalLoads.emplace_back(m.dofs.dof(node, component), value);
    }
}


void solidModel::addMoment
(
    const std::vector<int>& nodes,
    vectorTimeFunction m
)
{
    impl& m_ = *impl_;
    if (!m)
    {
        throw numericalError("solidModel::addMoment: no moment function");
    }
    impl::momentLoad load;
    for (int node : nodes)
    {
        if
        (
            node < 0 || node >= m_.mesh.nNodes() || !m_.shells
         || m_.shells->shellNode(node) < 0
        )
        {
            throw inputError
            (
                "moment",
                "a moment on node " + std::to_string(node) + ", which is"
                " not a shell node (only shell nodes carry rotations)"
            );
        }
        load.nodes.emplace_back(node, 1.0);
    }
    load.m = std::move(m);
    m_.moments.push_back(std::move(load));
}


void solidModel::addLineMoment
(
    const std::string& faceSet,
    vectorTimeFunction m
)
{
    impl& m_ = *impl_;
    std::map<int, double> weight;
    for (const feFace& face : m_.shellEdges(faceSet, "a line moment", ""))
    {
        const double L =
            (m_.mesh.X.row(face.nodes[1]) - m_.mesh.X.row(face.nodes[0]))
           .norm();
        for (const int node : face.nodes) weight[node] += 0.5*L;
    }
    std::vector<int> nodes;
    for (const auto& nw : weight) nodes.push_back(nw.first);
    addMoment(nodes, std::move(m));
    std::vector<std::pair<int, double>>& w = m_.moments.back().nodes;
    for (auto& nw : w) nw.second = weight.at(nw.first);
}


void solidModel::addPressure(const std::string& faceSet, timeFunction p)
{
    impl& m = *impl_;
    for (const feFace& f : m.faceSet(faceSet))
    {
        if (m.nDim == 3 && f.nodes.size() == 2)
        {
            throw inputError
            (
                faceSet,
                "a pressure on '" + faceSet + "', a side (edge) of a shell:"
                " pressures act on the faces of the sheet"
            );
        }
    }
    m.pressures.push_back({faceSet, std::move(p), {}});
    if (m.finalised) m.pressures.back().faces = m.locateFaces(faceSet);
}


void solidModel::releaseConstraint(const std::vector<int>& nodes, int component)
{
    impl& m = *impl_;
    const int nComponents = m.shells ? shellSet::nodeDofs : m.nDim;
    if (component < 0 || component >= nComponents)
    {
        throw inputError
        (
            "component",
            "released component " + std::to_string(component)
          + " out of range 0.." + std::to_string(nComponents - 1)
        );
    }
    for (int node : nodes)
    {
        if
        (
            node >= 0 && node < m.mesh.nNodes()
         && component < m.dofs.count(node)
        )
        {
            m.constraints.erase(m.dofs.dof(node, component));
        }
    }
    if (m.finalised) m.build();
}


void solidModel::setBodyForce(double rho, vectorTimeFunction g)
{
    impl& m = *impl_;
    m.requireFinalised("setBodyForce");
    if (!(rho > 0) || !std::isfinite(rho))
    {
        throw inputError
        (
            "rho", "body force: the density must be positive, got "
          + std::to_string(rho)
        );
    }
    m.bodyWeights.setZero(m.nDofs());
    matX X, u;
    for (int e = 0; e < int(m.elemBlock.size()); ++e)
    {
        const impl::blockData& b = m.blocks[m.elemBlock[e]];
        const elementBlock& blk = m.mesh.blocks[m.elemBlock[e]];
        vecX rowSum;
        if (b.kernel)
        {
            m.gather(e, X, u);
            rowSum = rho*b.kernel->massMatrix(X).rowwise().sum();
        }
        else
        {
            // shells: the translations' masses (the rotations carry no
            // weight)
            rowSum = m.shells->massMatrix
            (
                m.elemBlock[e], m.elemLocal[e], rho, true
            ).diagonal();
            for (int a = 0; a < blk.nodesPerElement; ++a)
            {
                rowSum(5*a + 3) = rowSum(5*a + 4) = 0;
            }
        }
        const int* nodes = blk.nodes(m.elemLocal[e]);
        const int nd = b.nodeDofs;
        for (int p = 0; p < rowSum.size(); ++p)
        {
            m.bodyWeights(m.dofs.dof(nodes[p/nd], p%nd)) += rowSum(p);
        }
    }
    m.bodyForce = std::move(g);
}

} // namespace form
