/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidRegion (solidRegion.H): inputs at single nodes, located by a
    point of the polyMesh space (shells: a node of the mid-surface, or a
    point on its initial director within the sheet, e.g. of a face):
    point forces and moments (solidProperties pointLoads), components
    held at a node (solidProperties pin, and the pin of process steps);
    measures over nodes and points (the summary's maxDisplacement and
    angle).
\*---------------------------------------------------------------------------*/
#include "solidRegion.H"
#include "shellSet.H"
#include "dictionaryChecks.H"
#include "Function1.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::solidRegion::nodeAt
(
    const point& pt,
    const dictionary& dict
) const
{
    const form::feMesh& fe = feMesh_->feMesh();
    const form::vecX x = feMesh_->toFe(pt);
    int nearest = -1;
    double d2 = 0;
    for (int n = 0; n < fe.nNodes(); ++n)
    {
        const double d = (fe.X.row(n).transpose() - x).squaredNorm();
        if (nearest < 0 || d < d2)
        {
            nearest = n;
            d2 = d;
        }
    }
    const double size =
        (fe.X.colwise().maxCoeff() - fe.X.colwise().minCoeff()).norm();
    const form::shellSet* shells = model_->shells();
    if (nearest >= 0 && std::sqrt(d2) > 1e-6*size && shells)
    {
        // Shells: any point of a mid-surface node's initial director line
        // within the sheet (e.g. a point of the mesh's top or bottom
        // face) names that node
        for (int n = 0; n < fe.nNodes(); ++n)
        {
            if (shells->shellNode(n) < 0) continue;
            const form::vec3 V = shells->initialDirector(n);
            const form::vec3 d = x - fe.X.row(n).transpose();
            const double along = d.dot(V);
            if
            (
                std::abs(along) <= 0.5*shells->thickness(n)*(1 + 1e-9)
             && (d - along*V).norm() <= 1e-6*size
            )
            {
                return n;
            }
        }
    }
    if (nearest < 0 || std::sqrt(d2) > 1e-6*size)
    {
        FatalIOErrorInFunction(dict)
            << "Point " << pt << " in " << dict.name() << " is not a node"
            << " of solid region '" << name_ << "'"
            << (
                   shells
                 ? " (shells: a node of the mid-surface, or a point on its"
                   " director through the sheet)"
                 : ""
               )
            << "; the nearest node is at distance " << std::sqrt(d2)
            << exit(FatalIOError);
    }
    return nearest;
}


void Foam::solidRegion::pin
(
    const point& p,
    const labelList& components,
    const dictionary& dict
)
{
    const label best = nodeAt(p, dict);
    const form::vecX U = model_->U();
    const form::dofMap dofs = model_->dofs();
    for (const label c : components)
    {
        model_->addNodalConstraint
        (
            {best}, c,
            [U, dofs, c](int node, double) { return U(dofs.dof(node, c)); }
        );
    }
}


void Foam::solidRegion::pinPoints(const dictionary& pd, bool apply)
{
    for (const entry& pe : pd)
    {
        const dictionary& p =
            dictOf(pe, pd, "{ point (x y z); components (x y); }");
        checkKeywords(p, {"point", "components"});
        labelList comps;
        for (const word& c : p.get<wordList>("components"))
        {
            comps.append(solidComponent(c, p, analysis_));
        }
        const point x = p.get<point>("point");
        if (!apply) continue;
        Info<< "    pin " << pe.keyword() << " at " << x
            << " components " << comps << nl;
        pin(x, comps, p);
    }
}


void Foam::solidRegion::readPointLoads()
{
    // solidProperties pointLoads { <name> { point p; force f; moment m; } }:
    // dead forces (and, on shell nodes, moments) at the node at p (a node
    // of the mid-surface for shells), each a Function1 of time
    if (!properties_.found("pointLoads")) return;
    const dictionary& loads = subDictOf
    (
        properties_, "pointLoads", "{ <name> { point (x y z); force ...; } }"
    );
    const form::feMesh& fe = feMesh_->feMesh();
    if (feMesh_->proj() == polyMeshToFeMesh::projection::wedge)
    {
        FatalIOErrorInFunction(loads)
            << "Entry 'pointLoads' in " << loads.name() << ": a point of an"
            << " axisymmetric (wedge) region is a ring; give a traction on"
            << " a patch instead" << exit(FatalIOError);
    }
    for (const entry& e : loads)
    {
        const dictionary& d = dictOf(e, loads, "{ point (x y z); force ...; }");
        checkKeywords(d, {"point", "force", "moment"});
        if (!d.found("force") && !d.found("moment"))
        {
            FatalIOErrorInFunction(d)
                << "Point load " << d.name() << " has neither 'force' nor"
                << " 'moment'" << exit(FatalIOError);
        }
        const point p = d.get<point>("point");
        const label node = nodeAt(p, d);
        if (d.found("force"))
        {
            std::shared_ptr<Function1<vector>> f
            (
                Function1<vector>::New("force", d).ptr()
            );
            // Components in the FE space: x y z, or x y of a plane mesh
            // (whose z must be zero)
            const fileName file = d.name();
            const bool plane = fe.nDim == 2;
            for (label c = 0; c < fe.nDim; ++c)
            {
                model_->addNodalLoad
                (
                    {int(node)}, c,
                    [f, c, plane, file](double t)
                    {
                        const vector v = f->value(t);
                        if (plane && v.z() != 0)
                        {
                            FatalErrorInFunction
                                << "Entry 'force' in " << file << ": " << v
                                << " at t = " << t << " has an out-of-plane"
                                << " (z) component in a 2D analysis"
                                << exit(FatalError);
                        }
                        return v[c];
                    }
                );
            }
        }
        if (d.found("moment"))
        {
            try
            {
                model_->addMoment({int(node)}, vectorFunction(d, "moment"));
            }
            catch (const form::inputError& err)
            {
                fatalInput(d, err);
            }
        }
    }
}


Foam::scalar Foam::solidRegion::maxDisplacement
(
    const word& patch,
    const vector& normalTo,
    const form::matX* ref,
    const dictionary& dict
) const
{
    const form::feMesh& fe = feMesh_->feMesh();
    std::vector<int> all;
    if (patch.empty())
    {
        all.resize(fe.nNodes());
        for (int n = 0; n < fe.nNodes(); ++n) all[n] = n;
    }
    const std::vector<int>& nodes = patch.empty() ? all : patchNodes(patch, dict);
    form::matX U = model_->displacement();
    if (ref) U -= *ref;
    form::vecX d = form::vecX::Zero(fe.nDim);
    const scalar m = mag(normalTo);
    for (int c = 0; c < fe.nDim; ++c) d(c) = m > 0 ? normalTo[c]/m : 0;
    scalar value = 0;
    for (const int n : nodes)
    {
        const form::vecX u = U.row(n).transpose();
        value = max(value, (u - d*d.dot(u)).norm());
    }
    return value;
}


Foam::scalar Foam::solidRegion::lineAngle
(
    const List<point>& pts,
    const dictionary& dict
) const
{
    const form::feMesh& fe = feMesh_->feMesh();
    const form::matX U = model_->displacement();
    // the current position of a material point: shells the mid-surface
    // node's, solids interpolated
    auto current = [&](const point& p) -> form::vecX
    {
        if (model_->shells())
        {
            const label n = nodeAt(p, dict);
            return (fe.X.row(n) + U.row(n)).transpose();
        }
        form::vecX x = feMesh_->toFe(p);
        for (int c = 0; c < fe.nDim; ++c) x(c) += displacementAt(p, c, dict);
        return x;
    };
    const form::vecX a = current(pts[1]) - current(pts[0]);
    const form::vecX b = current(pts[3]) - current(pts[2]);
    if (!(a.norm() > 0 && b.norm() > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'points' in " << dict.name() << ": A and B, or C and"
            << " D, are the same point: no line" << exit(FatalIOError);
    }
    return std::acos(max(-1.0, min(1.0, a.dot(b)/(a.norm()*b.norm()))));
}


// ************************************************************************* //
