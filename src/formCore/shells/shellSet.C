/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The shell elements of a solid model and their nodal directors
    (shellSet.H).
\*---------------------------------------------------------------------------*/
#include "shellSet.H"
#include "quadShape.H"
#include "planeStressMaterial.H"
#include <algorithm>
#include <map>
#include <cmath>

namespace form
{

bool shellSet::isShellType(const std::string& type)
{
    return nodesPerElement(type) > 0;
}


int shellSet::nodesPerElement(const std::string& type)
{
    return
        type == "MITC4" || type == "MITC4+" ? 4
      : type == "MITC3+" ? 3
      : 0;
}


std::string shellSet::validTypes()
{
    return "MITC4 MITC4+ MITC3+";
}


void shellSet::assignNodeDofs(feMesh& mesh)
{
    mesh.nodeDofs.assign(mesh.nNodes(), mesh.nDim);
    for (const elementBlock& b : mesh.blocks)
    {
        if (!isShellType(b.elementType)) continue;
        for (const int n : b.connectivity) mesh.nodeDofs[n] = nodeDofs;
    }
}


namespace
{

//- The lamina normal G_r x G_s of a bilinear quadrilateral (X: 4 x 3)
//  or a triangle (3 x 3) at corner k
vec3 cornerNormal(const Eigen::MatrixX3d& X, int k)
{
    if (X.rows() == 3)
    {
        return (X.row(1) - X.row(0)).cross(X.row(2) - X.row(0)).transpose();
    }
    static const double rn[4] = {-1, 1, 1, -1}, sn[4] = {-1, -1, 1, 1};
    quadShape<4>::vecN N;
    quadShape<4>::matN2 dN;
    quadShape<4>::eval(rn[k], sn[k], N, dN);
    const vec3 Gr = X.transpose()*dN.col(0);
    const vec3 Gs = X.transpose()*dN.col(1);
    return Gr.cross(Gs);
}

} // anonymous namespace


shellSet::shellSet
(
    const feMesh& mesh,
    const std::vector<std::shared_ptr<const shellLaw>>& laws
)
:
    shellNode_(mesh.nNodes(), -1),
    quads_(mesh.blocks.size()),
    tris_(mesh.blocks.size()),
    npe_(mesh.blocks.size(), 0),
    connectivity_(mesh.blocks.size())
{
    const std::size_t nb = mesh.blocks.size();
    bool any = false;
    for (std::size_t b = 0; b < nb; ++b)
    {
        const elementBlock& blk = mesh.blocks[b];
        if (!isShellType(blk.elementType)) continue;
        any = true;
        const std::string where = "block '" + blk.name + "'";
        if (mesh.nDim != 3)
        {
            throw inputError
            (
                "elementType",
                where + ": shell elements (" + blk.elementType
              + ") need a 3D analysis (solid3D)"
            );
        }
        npe_[b] = nodesPerElement(blk.elementType);
        if (blk.nodesPerElement != npe_[b])
        {
            throw inputError
            (
                "elementType",
                where + ": " + blk.elementType + " has "
              + std::to_string(npe_[b]) + " nodes, the block "
              + std::to_string(blk.nodesPerElement)
            );
        }
        if (!(blk.shell.thickness > 0) || !std::isfinite(blk.shell.thickness))
        {
            throw inputError
            (
                "thickness",
                where + ": the shell thickness must be a positive number, not "
              + formatNumber(blk.shell.thickness)
            );
        }
        const int minPoints = blk.shell.lobatto ? 3 : 1;
        if (blk.shell.points < minPoints || blk.shell.points > 10)
        {
            throw inputError
            (
                "thicknessPoints",
                where + ": " + std::to_string(minPoints) + " to 10 "
              + (blk.shell.lobatto ? "Gauss-Lobatto" : "Gauss")
              + " points through the thickness, not "
              + std::to_string(blk.shell.points)
            );
        }
        if (b >= laws.size() || !laws[b])
        {
            throw numericalError("shellSet: " + where + " has no lamina law");
        }
        for (const int n : blk.connectivity)
        {
            if (n < 0 || n >= mesh.nNodes())
            {
                throw inputError
                (
                    "mesh",
                    where + " refers to node " + std::to_string(n) + " of "
                  + std::to_string(mesh.nNodes())
                );
            }
            if (shellNode_[n] < 0)
            {
                shellNode_[n] = int(nodeOf_.size());
                nodeOf_.push_back(n);
                thickness_.push_back(blk.shell.thickness);
            }
        }
    }
    if (!any) return;

    // Distinct corners; at most two elements per edge
    // (a branching, non-manifold sheet has no director field)
    std::map<std::pair<int, int>, int> edgeElements;
    for (std::size_t b = 0; b < nb; ++b)
    {
        const elementBlock& blk = mesh.blocks[b];
        if (!isShellType(blk.elementType)) continue;
        for (int e = 0; e < blk.nElements(); ++e)
        {
            const int* n = blk.nodes(e);
            const int npe = npe_[b];
            const std::string where =
                "block '" + blk.name + "' element " + std::to_string(e);
            for (int k = 0; k < npe; ++k)
            {
                for (int l = 0; l < k; ++l)
                {
                    if (n[k] == n[l])
                    {
                        throw inputError
                        (
                            "mesh",
                            where + ": node " + std::to_string(n[k])
                          + " appears twice (a degenerate element; "
                          + blk.elementType + " needs "
                          + std::to_string(npe) + " distinct corners)"
                        );
                    }
                }
                const std::pair<int, int> edge =
                    std::minmax(n[k], n[(k + 1) % npe]);
                if (++edgeElements[edge] > 2)
                {
                    throw inputError
                    (
                        "mesh",
                        where + ": the edge between nodes "
                      + std::to_string(edge.first) + " and "
                      + std::to_string(edge.second) + " belongs to more"
                        " than two shell elements (a non-manifold edge: the"
                        " sheet branches there); mesh the branches as"
                        " separate sheets"
                    );
                }
            }
        }
    }

    const dofMap dofs = dofMap::of(mesh);
    for (const int n : nodeOf_)
    {
        if (dofs.count(n) != nodeDofs)
        {
            throw inputError
            (
                "mesh",
                "shell node " + std::to_string(n) + " carries "
              + std::to_string(dofs.count(n)) + " dofs instead of 5"
                " (shellSet::assignNodeDofs)"
            );
        }
    }

    // Initial directors: the normalised sums of the corner normals
    const auto corners = [&](const elementBlock& blk, int e)
    {
        Eigen::MatrixX3d X(blk.nodesPerElement, 3);
        for (int k = 0; k < blk.nodesPerElement; ++k)
        {
            X.row(k) = mesh.X.row(blk.nodes(e)[k]);
        }
        return X;
    };
    std::vector<vec3> sum(nodeOf_.size(), vec3::Zero());
    for (std::size_t b = 0; b < nb; ++b)
    {
        const elementBlock& blk = mesh.blocks[b];
        if (!isShellType(blk.elementType)) continue;
        for (int e = 0; e < blk.nElements(); ++e)
        {
            const Eigen::MatrixX3d X = corners(blk, e);
            for (int k = 0; k < blk.nodesPerElement; ++k)
            {
                const vec3 n = cornerNormal(X, k);
                if (!(n.norm() > 0))
                {
                    throw inputError
                    (
                        "mesh",
                        "block '" + blk.name + "' element "
                      + std::to_string(e) + ": degenerate at node "
                      + std::to_string(blk.nodes(e)[k])
                    );
                }
                sum[shellNode_[blk.nodes(e)[k]]] += n.normalized();
            }
        }
    }
    V0_.resize(nodeOf_.size());
    for (std::size_t s = 0; s < nodeOf_.size(); ++s)
    {
        if (!(sum[s].norm() > 1e-8))
        {
            throw inputError
            (
                "mesh",
                "shell node " + std::to_string(nodeOf_[s]) + ": the normals"
                " of its elements cancel (elements oriented oppositely)"
            );
        }
        V0_[s] = sum[s].normalized();
        // A director given by the mesh (a sheet's through-thickness
        // edge: the exact normal of a curved sheet, also at its edges and
        // symmetry planes), on the elements' side
        if (mesh.directors.rows() == mesh.nNodes())
        {
            const vec3 d = mesh.directors.row(nodeOf_[s]).transpose();
            if (d.norm() > 0)
            {
                V0_[s] = d.dot(V0_[s]) < 0 ? vec3(-d.normalized()) : vec3(d.normalized());
            }
        }
    }
    const double cosLimit = std::cos(M_PI/4);
    for (std::size_t b = 0; b < nb; ++b)
    {
        const elementBlock& blk = mesh.blocks[b];
        if (!isShellType(blk.elementType)) continue;
        const auto law = laws[b];
        connectivity_[b] = blk.connectivity;
        for (int e = 0; e < blk.nElements(); ++e)
        {
            const int npe = npe_[b];
            const Eigen::MatrixX3d X = corners(blk, e);
            Eigen::MatrixX3d V0(npe, 3);
            for (int k = 0; k < npe; ++k)
            {
                const int s = shellNode_[blk.nodes(e)[k]];
                V0.row(k) = V0_[s].transpose();
                if (cornerNormal(X, k).normalized().dot(V0_[s]) < cosLimit)
                {
                    throw inputError
                    (
                        "mesh",
                        "shell node " + std::to_string(nodeOf_[s])
                      + ": the surface folds, kinks or branches there (an"
                        " element normal departs from the node's director"
                        " by more than 45 degrees, or the elements are"
                        " oriented oppositely); nodes with a drilling"
                        " rotation are not supported: round the kink"
                        " with a radius of a few elements"
                    );
                }
            }
            try
            {
                if (npe == 3)
                {
                    tris_[b].emplace_back
                    (
                        X, V0, Eigen::Vector3d::Constant(blk.shell.thickness),
                        law, blk.shell.points, blk.shell.lobatto
                    );
                }
                else
                {
                    quads_[b].emplace_back
                    (
                        X, V0, Eigen::Vector4d::Constant(blk.shell.thickness),
                        law, blk.shell.points, blk.shell.lobatto,
                        blk.elementType == "MITC4+"
                    );
                }
            }
            catch (const numericalError& err)
            {
                throw inputError
                (
                    "mesh",
                    "block '" + blk.name + "' element " + std::to_string(e)
                  + ": " + err.what()
                );
            }
        }
    }
    frames_.reserve(V0_.size());
    for (const vec3& v : V0_)
    {
        // the frame's director exactly the element's initial one (the
        // committed change V - V0 is then zero before the first fold)
        frames_.push_back(shellDirector::of(v));
        frames_.back().V = v;
    }
    ref_.assign(V0_.size(), Eigen::Vector2d::Zero());
}


directorState shellSet::directorAt
(
    int node,
    const dofMap& dofs,
    const vecX& U
) const
{
    const int s = shellNode_[node];
    const Eigen::Vector2d d = increment(s, dofs, U);
    return frames_[s].at(d(0), d(1));
}


vec3 shellSet::director(int node, const dofMap& dofs, const vecX& U) const
{
    const int s = shellNode_[node];
    const Eigen::Vector2d d = increment(s, dofs, U);
    return frames_[s].at(d(0), d(1)).V;
}


void shellSet::alignFrame(int node, const vec3& axis)
{
    const int s = shellNode_[node];
    if (s < 0)
    {
        throw numericalError
        (
            "shellSet::alignFrame: node " + std::to_string(node)
          + " is not a shell node"
        );
    }
    shellDirector& f = frames_[s];
    const vec3 a = axis - axis.dot(f.V)*f.V;
    if (!(a.norm() > 1e-6*axis.norm()))
    {
        throw inputError
        (
            "normal",
            "shell node " + std::to_string(node) + ": the direction "
          + formatNumber(axis(0)) + " " + formatNumber(axis(1)) + " "
          + formatNumber(axis(2)) + " is along the shell's normal there"
            " (a symmetry plane must cut the sheet, not lie in it)"
        );
    }
    f.V1 = a.normalized();
    f.V2 = f.V.cross(f.V1);
}


void shellSet::commit(const dofMap& dofs, const vecX& U)
{
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        const Eigen::Vector2d d = increment(int(s), dofs, U);
        frames_[s].commit(d(0), d(1));
        ref_[s] += d;
    }
}


void shellSet::foldedRotations(const dofMap& dofs, vecX& U) const
{
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        U(dofs.dof(nodeOf_[s], 3)) = ref_[s](0);
        U(dofs.dof(nodeOf_[s], 4)) = ref_[s](1);
    }
}


std::vector<double> shellSet::state() const
{
    std::vector<double> v;
    v.reserve(11*frames_.size());
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        for (const vec3* a : {&frames_[s].V, &frames_[s].V1, &frames_[s].V2})
        {
            v.insert(v.end(), a->data(), a->data() + 3);
        }
        v.push_back(ref_[s](0));
        v.push_back(ref_[s](1));
    }
    return v;
}


void shellSet::setState(const std::vector<double>& v)
{
    if (v.size() != 11*frames_.size())
    {
        throw numericalError
        (
            "shellSet::setState: " + std::to_string(v.size())
          + " values for " + std::to_string(frames_.size())
          + " shell nodes (11 each)"
        );
    }
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        const double* p = v.data() + 11*s;
        shellDirector f;
        f.V = vec3(p[0], p[1], p[2]);
        f.V1 = vec3(p[3], p[4], p[5]);
        f.V2 = vec3(p[6], p[7], p[8]);
        const double err =
            std::abs(f.V.norm() - 1) + std::abs(f.V1.norm() - 1)
          + std::abs(f.V2.norm() - 1) + (f.V1.cross(f.V2) - f.V).norm();
        if (!(err < 1e-8))
        {
            throw numericalError
            (
                "shellSet::setState: the frame of shell node "
              + std::to_string(nodeOf_[s]) + " is not orthonormal"
            );
        }
        frames_[s] = f;
        ref_[s] = Eigen::Vector2d(p[9], p[10]);
    }
}

} // namespace form
