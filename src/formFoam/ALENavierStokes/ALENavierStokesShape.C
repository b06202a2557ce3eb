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
#include <map>

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
            Fm[f] = sweptVolumeSparse(faces[f], points0_, x)/dt_;
        }
        else
        {
            Fm[f] = sweptVolume<T>(faces[f], points0_, x)/dt_;
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
    std::vector<triplet>& Kt
)
{
    std::vector<triplet>* K = &Kt;
    const fluidSolidInterface& itf = *interface_;
    const label nI = mesh_.nInternalFaces();
    const auto& fi = itf.faceInterpolation();
    // R (the fluid's residuals and its forces on the solid) depends on
    // the mesh points x; the points on the interface point displacements
    // d_i by the harmonic extension, and d_i on U by (1) of
    // fluidSolidInterface.H:
    //     dR/dU = sum_units dR/dx_u (dx_u/dd_i) (dd_i/dU),
    // dx_u/dd_i = 1 for the unit of interface point i, H_c(u, i) for a
    // free unit, 0 for a fixed one. dR/dx_u exactly, by sparse
    // forward-mode differentiation (sparseDual.H) of the residual on the
    // geometry of the points (ALEGeometry.H), every in-plane coordinate of
    // every moving unit a variable (2u + c): one evaluation gives the
    // whole sparse dR/dx. The fvMesh does not move.
    const auto start = std::chrono::steady_clock::now();
    using S = form::sparseDual;
    const std::vector<int> dofs = itf.dofs();
    std::map<int, label> local;
    forAll(dofs, k) local[dofs[k]] = k;
    const label nF = x_.size(), nd = dofs.size();
    const List<labelList>& units = itf.motionUnits();

    // The points as functions of the units' coordinates
    std::vector<dualVector<S>> xd(base.size());
    forAll(base, p) xd[p] = dualVector<S>(base[p]);
    forAll(units, u)
    {
        for (label cc = 0; cc < 2; ++cc)
        {
            if (itf.unitKind(u, cc) == fluidSolidInterface::fixedUnit) continue;
            for (const label p : units[u])
            {
                const vector& e = itf.direction(p, cc);
                if (e.x() != 0) xd[p].x.add(2*u + cc, e.x());
                if (e.y() != 0) xd[p].y.add(2*u + cc, e.y());
                if (e.z() != 0) xd[p].z.add(2*u + cc, e.z());
            }
        }
    }
    const ALEResidual<S> res = residualAt<S>(xd);

    // dR/dx_u as a sparse matrix, rows: the fluid's residuals, then the
    // forces on the interface dofs (nF + local dof), columns 2u + c
    std::vector<Eigen::Triplet<double>> t;
    for (label row = 0; row < nF; ++row)
    {
        const S& r = res.r[row];
        for (int j = 0; j < r.size(); ++j)
        {
            t.emplace_back(row, r.index(j), r.derivative(j));
        }
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
                const label row =
                    nF + local[solid_->dofs().dof(fi[j].nodes[a], cb)];
                for (int k = 0; k < v.size(); ++k)
                {
                    t.emplace_back(row, v.index(k), fi[j].N[a]*v.derivative(k));
                }
            }
        }
    }
    Eigen::SparseMatrix<double> dRdx(nF + nd, 2*units.size());
    dRdx.setFromTriplets(t.begin(), t.end());

    // Chain with dx_u/dU, column by column: the rows of DgT^T = dR/dU
    // (transposed, so that a row's columns are contiguous)
    // (kept between iterations: a fresh allocation of this size costs
    // its page faults every time)
    form::matX& DgT = DgT_;
    DgT.setZero(nd, nF + nd);
    const auto& pi = itf.pointInterpolation();
    form::vecX coef(nd);
    for (int col = 0; col < dRdx.outerSize(); ++col)
    {
        if (dRdx.outerIndexPtr()[col + 1] == dRdx.outerIndexPtr()[col]) continue;
        const label u = col/2, cc = col % 2;
        // dx_u/dU: the columns of the solid's dofs (component cc)
        coef.setZero();
        const label kind = itf.unitKind(u, cc);
        for (label i = 0; i < itf.nPoints(); ++i)
        {
            const scalar w =
                kind == fluidSolidInterface::freeUnit
              ? itf.unitWeight(u, cc, i)
              : scalar(kind == i);
            if (w == 0) continue;
            for (std::size_t a = 0; a < pi[i].nodes.size(); ++a)
            {
                const int d = solid_->dofs().dof(pi[i].nodes[a], cc);
                coef(local[d]) += w*pi[i].N[a];
            }
        }
        for (Eigen::SparseMatrix<double>::InnerIterator it(dRdx, col); it; ++it)
        {
            if (it.value() != 0) DgT.col(it.row()) += it.value()*coef;
        }
    }
    for (label row = 0; row < nF + nd; ++row)
    {
        for (label col = 0; col < nd; ++col)
        {
            const scalar val = DgT(col, row);
            if (val == 0) continue;
            // K = -dR/dU: R = r for the fluid rows, f_ext for the solid's
            K->emplace_back
            (
                row < nF ? off + row : dofs[row - nF], dofs[col], -val
            );
        }
    }
    meshDerivativeTime_ += form::secondsSince(start);
}


// ************************************************************************* //
