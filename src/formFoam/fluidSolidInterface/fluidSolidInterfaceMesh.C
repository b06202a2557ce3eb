/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    fluidSolidInterface: the mesh motion (fluidSolidInterface.H, eq. (4)):
    the diffusivity, the mesh equations and their matrix, the interface
    points' displacements, the harmonic solution, the points of a state and the mesh
    unknowns of given points.
\*---------------------------------------------------------------------------*/
#include "fluidSolidInterface.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::meshDiffusivity Foam::meshDiffusivity::read
(
    const dictionary& md,
    const fileName& file
)
{
    meshDiffusivity k;
    k.type = md.getOrDefault<word>("diffusivity", k.type);
    if (!types().found(k.type))
    {
        FatalIOErrorInFunction(md)
            << "Entry 'meshMotion/diffusivity' in " << file.c_str()
            << ": unknown '" << k.type << "'; valid: " << types()
            << exit(FatalIOError);
    }
    if (md.found("exponent"))
    {
        if (k.type != "inverseDistance")
        {
            FatalIOErrorInFunction(md)
                << "Entry 'meshMotion/exponent' in " << file.c_str()
                << " belongs to diffusivity inverseDistance (the diffusivity"
                << " is " << k.type << ")" << exit(FatalIOError);
        }
        k.exponent = md.get<scalar>("exponent");
        if (!(k.exponent > 0 && k.exponent <= 4))
        {
            FatalIOErrorInFunction(md)
                << "Entry 'meshMotion/exponent' in " << file.c_str()
                << " is out of range: " << k.exponent << " (valid: (0, 4];"
                << " 1 inverse, 2 quadratic inverse distance)"
                << exit(FatalIOError);
        }
    }
    return k;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fluidSolidInterface::diffusivity
(
    const Eigen::Vector2d& x,
    const std::vector<std::array<Eigen::Vector2d, 2>>& segments
) const
{
    if (diffusivity_.type != "inverseDistance") return 1;
    // In-plane distance to the interface: its nearest face segment
    scalar r2 = GREAT;
    for (const auto& ab : segments)
    {
        const Eigen::Vector2d t = ab[1] - ab[0];
        const scalar s =
            std::min(1.0, std::max(0.0, (x - ab[0]).dot(t)/t.squaredNorm()));
        r2 = min(r2, (ab[0] + s*t - x).squaredNorm());
    }
    const scalar r0 = minFaceLength_;
    return std::pow(r0/max(std::sqrt(r2), r0), diffusivity_.exponent);
}


void Foam::fluidSolidInterface::buildMeshEquations
(
    const List<Eigen::Vector2d>& q,
    const labelList& pointUnit,
    const std::vector<std::array<Eigen::Vector2d, 2>>& segments,
    label nI,
    scalar tol,
    const fileName& file
)
{
    const edgeList& meshEdges = fluid_.edges();
    scalar l2 = 0;
    label nEdges = 0;
    for (const edge& e : meshEdges)
    {
        const scalar len = (q[e[0]] - q[e[1]]).norm();
        if (len < tol) continue;
        l2 += sqr(len);
        ++nEdges;
    }
    l2 /= max(nEdges, label(1));
    for (label c = 0; c < 2; ++c)
    {
        const label nF = nUnknowns_[c];
        std::vector<Eigen::Triplet<double>> tL, tB;
        for (const edge& e : meshEdges)
        {
            const scalar len = (q[e[0]] - q[e[1]]).norm();
            if (len < tol) continue;
            const scalar w =
                l2/sqr(len)*diffusivity(0.5*(q[e[0]] + q[e[1]]), segments);
            for (label s = 0; s < 2; ++s)
            {
                const label u = pointUnit[s ? e[1] : e[0]];
                const label o = pointUnit[s ? e[0] : e[1]];
                const label row = unknown_[c][u];
                if (row < 0) continue;
                tL.emplace_back(row, row, w);
                if (unknown_[c][o] >= 0)
                {
                    tL.emplace_back(row, unknown_[c][o], -w);
                }
                else if (unitKind_[c][o] >= 0)
                {
                    tB.emplace_back(row, unitKind_[c][o], -w);
                }
            }
        }
        L_[c].resize(nF, nF);
        L_[c].setFromTriplets(tL.begin(), tL.end());
        B_[c].resize(nF, nI);
        B_[c].setFromTriplets(tB.begin(), tB.end());
        if (!nF) continue;
        ldlt_[c].compute(L_[c]);
        if
        (
            ldlt_[c].info() != Eigen::Success
         || !(
                (
                    ldlt_[c].vectorD().array()
                  - 1e-12*(ldlt_[c].permutationP()*L_[c].diagonal()).array()
                ).minCoeff() > 0
             )
        )
        {
            FatalErrorInFunction
                << "Fluid region '" << fluid_.name() << "' (" << file.c_str() << "): the"
                << " mesh motion has points free in the "
                << (c ? "axial (y)" : "radial (x)") << " direction that no"
                << " wall, inlet, outlet or interface holds; fix a patch"
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

std::array<form::vecX, 2> Foam::fluidSolidInterface::interfaceDisplacement
(
    const form::vecX& U
) const
{
    const label nI = pointIds_.size();
    std::array<form::vecX, 2> dI{form::vecX::Zero(nI), form::vecX::Zero(nI)};
    for (label i = 0; i < nI; ++i)
    {
        const solidPoint& sp = pointInterp_[i];
        for (std::size_t a = 0; a < sp.nodes.size(); ++a)
        {
            for (label c = 0; c < 2; ++c)
            {
                dI[c](i) += sp.N[a]*U(dofMap_.dof(sp.nodes[a], c));
            }
        }
    }
    return dI;
}


form::vecX Foam::fluidSolidInterface::harmonicDisplacement
(
    const form::vecX& U
) const
{
    const std::array<form::vecX, 2> dI = interfaceDisplacement(U);
    form::vecX d(nMeshUnknowns());
    label off = 0;
    for (label c = 0; c < 2; ++c)
    {
        if (nUnknowns_[c])
        {
            d.segment(off, nUnknowns_[c]) = ldlt_[c].solve(-(B_[c]*dI[c]));
        }
        off += nUnknowns_[c];
    }
    return d;
}


void Foam::fluidSolidInterface::meshEquations
(
    const form::vecX& U,
    const form::vecX& d,
    form::vecX& r,
    label off,
    std::vector<Eigen::Triplet<double>>* K
) const
{
    const std::array<form::vecX, 2> dI = interfaceDisplacement(U);
    r.resize(nMeshUnknowns());
    label start = 0;
    for (label c = 0; c < 2; ++c)
    {
        const label n = nUnknowns_[c];
        if (n)
        {
            r.segment(start, n) = -(L_[c]*d.segment(start, n) + B_[c]*dI[c]);
        }
        if (K)
        {
            // K = -dr/dq = [L_c, B_c dd_I/dU]
            for (int k = 0; k < L_[c].outerSize(); ++k)
            {
                for (Eigen::SparseMatrix<double>::InnerIterator it(L_[c], k); it; ++it)
                {
                    K->emplace_back
                    (
                        off + start + it.row(), off + start + it.col(), it.value()
                    );
                }
            }
            for (int i = 0; i < B_[c].outerSize(); ++i)
            {
                const solidPoint& sp = pointInterp_[i];
                for (Eigen::SparseMatrix<double>::InnerIterator it(B_[c], i); it; ++it)
                {
                    for (std::size_t a = 0; a < sp.nodes.size(); ++a)
                    {
                        K->emplace_back
                        (
                            off + start + it.row(), dofMap_.dof(sp.nodes[a], c),
                            it.value()*sp.N[a]
                        );
                    }
                }
            }
        }
        start += n;
    }
}


Foam::tmp<Foam::pointField> Foam::fluidSolidInterface::points
(
    const form::vecX& U,
    const form::vecX& d
) const
{
    const std::array<form::vecX, 2> dI = interfaceDisplacement(U);
    tmp<pointField> tpts(new pointField(points0_));
    pointField& pts = tpts.ref();
    forAll(units_, u)
    {
        for (label c = 0; c < 2; ++c)
        {
            const label k = unitKind_[c][u];
            const scalar dc =
                k == freeUnit ? d(meshUnknown(u, c))
              : k == fixedUnit ? 0.0
              : dI[c](k);
            if (dc == 0) continue;
            for (const label p : units_[u])
            {
                pts[p] += dc*direction(p, c);
            }
        }
    }
    return tpts;
}


form::vecX Foam::fluidSolidInterface::meshUnknowns(const pointField& pts) const
{
    form::vecX d(nMeshUnknowns());
    forAll(units_, u)
    {
        for (label c = 0; c < 2; ++c)
        {
            const label k = meshUnknown(u, c);
            if (k < 0) continue;
            const label p = units_[u][0];
            d(k) = (pts[p] - points0_[p]) & direction(p, c);
        }
    }
    return d;
}


// ************************************************************************* //
