/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    ALENavierStokes: the derivatives of the fluid's residual and of its
    forces on the solid with respect to the mesh's points (the shape
    derivative), exact, by forward-mode differentiation (dualNumber.H) of
    the residual (ALENavierStokesResidual.H) on the geometry of the points
    (ALEGeometry.H) in sparse dual numbers (sparseDual.H); the fvMesh does
    not move.
\*---------------------------------------------------------------------------*/
#include "ALENavierStokesResidual.H"
#include "wallClock.H"
#include "fluidSolidInterface.H"
#include "solidModel.H"

template<class T>
Foam::ALEResidual<T> Foam::ALENavierStokes::residualAt
(
    const std::vector<geomVector<T>>& x
) const
{
    ALEGeometry<T> g;
    g.fromPoints(mesh_, x);
    const faceList& faces = mesh_.faces();
    const label nI = mesh_.nInternalFaces();
    // Mesh fluxes: the residual uses none of empty, wedge and interface
    // faces (no flux crosses them)
    std::vector<T> Fm(faces.size(), T(0.0));
    forAll(faces, f)
    {
        if (f >= nI)
        {
            const velocityBC bc =
                uBC_[mesh_.boundaryMesh().whichPatch(f)];
            if
            (
                bc == velocityBC::empty || bc == velocityBC::wedge
             || bc == velocityBC::interface
            )
            {
                continue;
            }
        }
        if constexpr (std::is_same<T, form::sparseDual>::value)
        {
            Fm[f] = meshFlux(f, sweptVolumeSparse(faces[f], points0_, x));
        }
        else
        {
            Fm[f] = meshFlux(f, sweptVolume<T>(faces[f], points0_, x));
        }
    }
    ALEResidual<T> out;
    residual(g, Fm, out);
    return out;
}

template Foam::ALEResidual<Foam::scalar>
Foam::ALENavierStokes::residualAt(const std::vector<vector>&) const;
template Foam::ALEResidual<form::dual<1>>
Foam::ALENavierStokes::residualAt
(
    const std::vector<dualVector<form::dual<1>>>&
) const;
template Foam::ALEResidual<form::sparseDual>
Foam::ALENavierStokes::residualAt
(
    const std::vector<dualVector<form::sparseDual>>&
) const;


void Foam::ALENavierStokes::addMeshDerivative
(
    const pointField& base,
    label off,
    std::vector<triplet>& K
)
{
    const fluidSolidInterface& itf = *interface_;
    const label nI = mesh_.nInternalFaces();
    const auto& fi = itf.faceInterpolation();
    const auto& pi = itf.pointInterpolation();
    // R (the fluid's residuals and its forces on the solid) depends on
    // the mesh points x: a free unit's points on its mesh unknowns, an
    // interface unit's on the solid's dofs by (1) of fluidSolidInterface.H,
    //     dR/dd_u = dR/dx_u,   dR/dU_a = sum_i dR/dx_i N_a(xi_i),
    // x_u = x_u,0 + sum_c d_u,c e_c. dR/dx_u exactly, by sparse
    // forward-mode differentiation (sparseDual.H) of the residual on the
    // geometry of the points (ALEGeometry.H), the in-plane coordinate c of
    // every moving unit u a variable (2u + c): one evaluation gives the
    // whole sparse dR/dx. The fvMesh does not move.
    const auto start = std::chrono::steady_clock::now();
    using S = form::sparseDual;
    const label nCU = nCellUnknowns();
    const List<labelList>& units = itf.motionUnits();

    // The points as functions of the units' coordinates, and each
    // variable's columns in K (with their weights)
    std::vector<dualVector<S>> xd(base.size());
    forAll(base, p) xd[p] = dualVector<S>(base[p]);
    std::vector<std::vector<std::pair<label, scalar>>> columns(2*units.size());
    forAll(units, u)
    {
        for (label cc = 0; cc < 2; ++cc)
        {
            const label kind = itf.unitKind(u, cc);
            if (kind == fluidSolidInterface::fixedUnit) continue;
            for (const label p : units[u])
            {
                const vector& e = itf.direction(p, cc);
                if (e.x() != 0) xd[p].x.add(2*u + cc, e.x());
                if (e.y() != 0) xd[p].y.add(2*u + cc, e.y());
                if (e.z() != 0) xd[p].z.add(2*u + cc, e.z());
            }
            auto& col = columns[2*u + cc];
            if (kind == fluidSolidInterface::freeUnit)
            {
                col.emplace_back(off + nCU + itf.meshUnknown(u, cc), 1.0);
                continue;
            }
            for (std::size_t a = 0; a < pi[kind].nodes.size(); ++a)
            {
                col.emplace_back
                (
                    solid_->dofs().dof(pi[kind].nodes[a], cc), pi[kind].N[a]
                );
            }
        }
    }
    const ALEResidual<S> res = residualAt<S>(xd);

    // K = -dR/dq: R = r for the fluid rows, f_ext for the solid's
    const auto add = [&](label row, const S& v, scalar factor)
    {
        for (int j = 0; j < v.size(); ++j)
        {
            const scalar val = -factor*v.derivative(j);
            if (val == 0) continue;
            for (const auto& cw : columns[v.index(j)])
            {
                K.emplace_back(row, cw.first, val*cw.second);
            }
        }
    };
    for (label row = 0; row < nCU; ++row)
    {
        add(off + row, res.r[row], 1);
    }
    const labelList& faces = itf.faces();
    forAll(faces, j)
    {
        const dualVector<S>& Fw = res.Fw[faces[j] - nI];
        for (label cb = 0; cb < 2; ++cb)
        {
            const vector& e = itf.faceDirection(j, cb);
            const S v = depth_*(Fw.x*e.x() + Fw.y*e.y() + Fw.z*e.z());
            for (std::size_t a = 0; a < fi[j].nodes.size(); ++a)
            {
                add(solid_->dofs().dof(fi[j].nodes[a], cb), v, fi[j].N[a]);
            }
        }
    }
    meshDerivativeTime_ += form::secondsSince(start);
}


// ************************************************************************* //
