/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    fluidSolidInterface: the mesh motion (fluidSolidInterface.H, eq. (4)):
    the interface points' displacements, the mesh equations and their
    matrix, their harmonic solution, the points of a state and the mesh
    unknowns of given points.
\*---------------------------------------------------------------------------*/
#include "fluidSolidInterface.H"

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
