/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidModel set-up (see solidModel.H): the element blocks and their
    materials from the mesh, the dof numbering, the faces of named
    patches, and the fixed sparsity pattern of the system matrix the
    assembly scatters into. The step: solidModel.C.
\*---------------------------------------------------------------------------*/
#include "solidModelImpl.H"
#include "formError.H"
#include "planeStressMaterial.H"
#include <algorithm>
#include <stdexcept>

namespace form
{

void solidModel::impl::buildSystemMatrix()
{
    const int nFree = numbering.nFree();
    const int nAll = nFree + nCoupled();
    const int N = nDofs();
    std::vector<Eigen::Triplet<double>> all;
    all.reserve(Kff.nonZeros() + triplets.size());
    for (int j = 0; j < Kff.outerSize(); ++j)
    {
        for (sparseMatrix::InnerIterator it(Kff, j); it; ++it)
        {
            all.emplace_back(int(it.row()), int(it.col()), it.value());
        }
    }
    const auto map = [&](int i)
    {
        return i < N ? numbering.equation[i] : nFree + (i - N);
    };
    for (const auto& tr : triplets)
    {
        const int i = map(tr.row());
        const int j = map(tr.col());
        if (i >= 0 && j >= 0) all.emplace_back(i, j, tr.value());
    }
    sparseMatrix K(nAll, nAll);
    K.setFromTriplets(all.begin(), all.end());
    K.makeCompressed();
    const bool same =
        Ksys.rows() == nAll
     && Ksys.nonZeros() == K.nonZeros()
     && std::equal
        (
            K.outerIndexPtr(), K.outerIndexPtr() + nAll + 1,
            Ksys.outerIndexPtr()
        )
     && std::equal
        (
            K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros(),
            Ksys.innerIndexPtr()
        );
    Ksys = std::move(K);
    if (!same) ++revision;
}


std::vector<solidModel::impl::faceRef>
solidModel::impl::locateFaces(const std::string& name) const
{
    std::vector<faceRef> refs;
    for (const feFace& f : faceSet(name))
    {
        if (f.block < 0 || f.block >= int(mesh.blocks.size())
         || f.element < 0 || f.element >= mesh.blocks[f.block].nElements())
        {
            throw inputError
            (
                name,
                "face set '" + name + "' refers to a non-existent element"
            );
        }
        const elementBlock& b = mesh.blocks[f.block];
        const int* nodes = b.nodes(f.element);
        faceRef r;
        r.element = blocks[f.block].firstElement + f.element;
        r.nodes = f.nodes;
        for (int node : f.nodes)
        {
            const int* it = std::find(nodes, nodes + b.nodesPerElement, node);
            if (it == nodes + b.nodesPerElement)
            {
                throw inputError
                (
                    name,
                    "face set '" + name + "': node " + std::to_string(node)
                  + " is not a node of its element "
                  + std::to_string(f.element) + " in block '" + b.name + "'"
                );
            }
            r.localNodes.push_back(int(it - nodes));
        }
        refs.push_back(std::move(r));
    }
    return refs;
}


void solidModel::impl::build()
{
    const int n = nDofs();
    std::vector<bool> constrained(orphan);
    for (const auto& c : constraints) constrained[c.first] = true;
    numbering.build(constrained);

    std::vector<std::size_t> offsets(1, 0);
    std::vector<int> elementDofs;
    for (std::size_t e = 0; e < elemBlock.size(); ++e)
    {
        const elementBlock& b = mesh.blocks[elemBlock[e]];
        const int* nodes = b.nodes(elemLocal[e]);
        const int nd = blocks[elemBlock[e]].nodeDofs;
        for (int a = 0; a < b.nodesPerElement; ++a)
        {
            for (int i = 0; i < nd; ++i)
            {
                elementDofs.push_back(dofs.dof(nodes[a], i));
            }
        }
        offsets.push_back(elementDofs.size());
    }
    pattern.build(numbering, offsets, elementDofs, Kff, Kfp);

    for (auto& l : tractions) l.faces = locateFaces(l.faceSet);
    for (auto& l : pressures) l.faces = locateFaces(l.faceSet);

    fint = vecX::Zero(n);
    fcontact = vecX::Zero(n);
    fext = vecX::Zero(n);
    finalised = true;
    ++revision;
}


solidModel::solidModel
(
    feMesh mesh,
    analysisType analysis,
    std::map<std::string, std::shared_ptr<material>> materials
)
:
    impl_(std::make_shared<impl>())
{
    impl& m = *impl_;
    m.mesh = std::move(mesh);
    m.analysis = analysis;
    m.materials = std::move(materials);
    m.nDim = m.mesh.nDim;

    if (m.mesh.X.cols() != m.nDim)
    {
        throw inputError
        (
            "mesh",
            "mesh coordinates have " + std::to_string(m.mesh.X.cols())
          + " columns but nDim = " + std::to_string(m.nDim)
        );
    }
    // The material of a block (inputError naming the block if unknown)
    const auto blockMaterial = [&m](const elementBlock& b)
    {
        auto mit = m.materials.find(b.materialName);
        if (mit == m.materials.end() || !mit->second)
        {
            std::string valid;
            for (const auto& p : m.materials) valid += " " + p.first;
            throw inputError
            (
                "material",
                "block '" + b.name + "': unknown material '" + b.materialName
              + "'; defined:" + valid
            );
        }
        return mit->second;
    };

    // Shell elements and their nodes (5 dofs: translations and two
    // rotations); every other node carries nDim displacement dofs
    {
        std::vector<std::shared_ptr<const shellLaw>> laws;
        bool any = false;
        for (const elementBlock& b : m.mesh.blocks)
        {
            laws.emplace_back();
            if (!shellSet::isShellType(b.elementType)) continue;
            any = true;
            laws.back() = std::make_shared<planeStressMaterial>
            (
                blockMaterial(b), b.shell.shearCorrection
            );
        }
        if (any) m.shells = std::make_unique<shellSet>(m.mesh, laws);
    }
    for (int node = 0; node < int(m.mesh.nodeDofs.size()); ++node)
    {
        const int c = m.mesh.nodeDofs[node];
        const bool shellNode = m.shells && m.shells->shellNode(node) >= 0;
        if (c != m.nDim && !shellNode)
        {
            throw inputError
            (
                "mesh",
                "node " + std::to_string(node) + " with " + std::to_string(c)
              + " dofs: the solid elements carry nDim = "
              + std::to_string(m.nDim) + " displacement dofs per node"
                " (rotational dofs belong to shell nodes)"
            );
        }
    }
    try
    {
        m.dofs = dofMap::of(m.mesh);
    }
    catch (const std::invalid_argument& e)
    {
        throw inputError("mesh", e.what());
    }

    const int nNodes = m.mesh.nNodes();
    std::vector<bool> used(nNodes, false);
    for (const elementBlock& b : m.mesh.blocks)
    {
        impl::blockData d;
        const bool shell = shellSet::isShellType(b.elementType);
        d.nodeDofs = shell ? shellSet::nodeDofs : m.nDim;
        if (!shell) d.kernel = solidElement::New(b.elementType, analysis);
        if (!shell && d.kernel->nNodes() != b.nodesPerElement)
        {
            throw inputError
            (
                "elementType",
                "block '" + b.name + "': element type " + b.elementType
              + " has " + std::to_string(d.kernel->nNodes())
              + " nodes but the block has "
              + std::to_string(b.nodesPerElement) + " nodes per element"
            );
        }
        if (!shell && d.kernel->nDim() != m.nDim)
        {
            throw inputError
            (
                "elementType",
                "block '" + b.name + "': element type " + b.elementType
              + " is " + std::to_string(d.kernel->nDim()) + "D, the mesh "
              + std::to_string(m.nDim) + "D"
            );
        }
        d.mat = blockMaterial(b);
        d.firstElement = int(m.elemBlock.size());

        const int blockIndex = int(m.blocks.size());
        for (int e = 0; e < b.nElements(); ++e)
        {
            const int* nodes = b.nodes(e);
            for (int a = 0; a < b.nodesPerElement; ++a)
            {
                if (nodes[a] < 0 || nodes[a] >= nNodes)
                {
                    throw inputError
                    (
                        "mesh",
                        "block '" + b.name + "' element " + std::to_string(e)
                      + " refers to node " + std::to_string(nodes[a])
                      + " of " + std::to_string(nNodes)
                    );
                }
                used[nodes[a]] = true;
            }
            m.elemBlock.push_back(blockIndex);
            m.elemLocal.push_back(e);
            if (shell)
            {
                m.committed.push_back(m.shells->initialStates(blockIndex));
            }
            else
            {
                m.committed.emplace_back
                (
                    d.kernel->nQuadrature(), d.mat->initialState()
                );
            }
        }
        m.blocks.push_back(std::move(d));
    }
    m.trial = m.committed;
    m.resetPressureLinearisations();

    m.orphan.assign(m.nDofs(), false);
    for (int node = 0; node < nNodes; ++node)
    {
        if (!used[node])
        {
            for (int i = 0; i < m.nDim; ++i) m.orphan[m.dofs.dof(node, i)] = true;
        }
    }

    m.U = vecX::Zero(m.nDofs());
    m.Ucommitted = m.U;
}


void solidModel::finalise()
{
    impl_->build();
}

} // namespace form
