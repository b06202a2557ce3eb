/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidModel: dof numbering, fixed-pattern assembly, evaluate, coupled
    blocks and the state (see solidModel.H). Constraints and loads:
    solidModelLoads.C; inertia: solidModelDynamics.C; log note, forces,
    reactions and results: solidModelOutput.C; private state:
    solidModelImpl.H.
\*---------------------------------------------------------------------------*/
#include "solidModelImpl.H"
#include "contactModel.H"
#include "coupledBlock.H"
#include "formError.H"
#include "planeStressMaterial.H"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

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


// Dead tractions and follower pressures: f_ext, and for follower loads the
// load stiffness K_L = -d f_ext / d u added to K (Simo & Hughes 1998 ch. 9;
// it is unsymmetric unless the loaded boundary is closed). Edge nodes are
// nodes of the owning element, so K_L scatters through the element's map.


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
