/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    solidRegion: boundary conditions (solidRegion.H): 0/<region>/D read and
    applied per patch (fixedDisplacement, clamped, symmetryPlane,
    diaphragm, rigidMotion, traction, lineLoad, lineMoment, pressure,
    free), and the process-step actions on patches (release, hold); the
    inputs at single nodes are in solidRegionPoints.C
\*---------------------------------------------------------------------------*/
#include "solidRegion.H"
#include "shellSet.H"
#include "dictionaryChecks.H"
#include "Function1.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

std::vector<int> Foam::solidRegion::shellNodesOf
(
    const std::vector<int>& nodes
) const
{
    std::vector<int> s;
    const form::shellSet* shells = model_->shells();
    if (!shells) return s;
    for (const int n : nodes)
    {
        if (shells->shellNode(n) >= 0) s.push_back(n);
    }
    return s;
}


void Foam::solidRegion::applyRigidMotion
(
    const std::vector<int>& nodes,
    const dictionary& pd
)
{
    // x = o + c(t) + R(theta(t)) (X - o) on the patch: a rigid rotation by
    // theta about the origin o (2D: counter-clockwise in the FE plane; 3D:
    // right-handed about the unit 'axis', Rodrigues' formula), then a
    // translation c; every component is prescribed
    const form::feMesh& fe = feMesh_->feMesh();
    const int nDim = fe.nDim;
    if (nDim == 3)
    {
        checkKeywords
        (
            pd, {"type", "origin", "axis", "angle", "translation", "value"}
        );
    }
    else
    {
        checkKeywords(pd, {"type", "origin", "angle", "translation", "value"});
    }
    const form::vecX o = feMesh_->toFe(pd.get<point>("origin"));
    form::vec3 n(0, 0, 1);
    if (nDim == 3)
    {
        const vector a = pd.get<vector>("axis");
        if (!(mag(a) > 0) || !std::isfinite(mag(a)))
        {
            FatalIOErrorInFunction(pd)
                << "Entry 'axis' in " << pd.name() << ": " << a
                << " is not a direction (zero or not finite)"
                << exit(FatalIOError);
        }
        n = form::vec3(a.x(), a.y(), a.z())/mag(a);
    }
    std::shared_ptr<Function1<scalar>> angle
    (
        Function1<scalar>::New("angle", pd).ptr()
    );
    std::shared_ptr<Function1<vector>> translation;
    if (pd.found("translation"))
    {
        translation.reset(Function1<vector>::New("translation", pd).ptr());
    }
    const form::matX X = fe.X;
    for (label c = 0; c < nDim; ++c)
    {
        model_->addNodalConstraint
        (
            nodes,
            c,
            [=](int node, double t)
            {
                const double th = angle->value(t);
                form::vec3 d = form::vec3::Zero();
                d.head(nDim) = X.row(node).transpose() - o;
                form::mat3 R;
                if (nDim == 2)
                {
                    R << std::cos(th), -std::sin(th), 0,
                         std::sin(th), std::cos(th), 0,
                         0, 0, 1;
                }
                else
                {
                    form::mat3 W;
                    W << 0, -n(2), n(1), n(2), 0, -n(0), -n(1), n(0), 0;
                    R = form::mat3::Identity() + std::sin(th)*W
                      + (1 - std::cos(th))*W*W;
                }
                form::vec3 u = R*d - d;
                if (translation)
                {
                    const vector v = translation->value(t);
                    u += form::vec3(v.x(), v.y(), v.z());
                }
                return u(c);
            }
        );
    }
}


void Foam::solidRegion::release
(
    const word& patch,
    const labelList& components,
    const dictionary& dict,
    const scalar t0,
    const scalar t1
)
{
    const std::vector<int>& nodes = patchNodes(patch, dict);
    if (!(t1 > t0))
    {
        // Restored release (a step begun before a restart): its loads
        // come with the restart state
        for (const label c : components) model_->releaseConstraint(nodes, c);
        return;
    }
    // Something to release: the patch's own constraint in each component
    // named (most of its nodes held; a free patch's end nodes may be held
    // by a neighbouring patch, whose constraint is not the one meant)
    for (const label c : components)
    {
        label held = 0;
        for (const int n : nodes)
        {
            held += model_->constrained(model_->dofs().dof(n, c));
        }
        if (2*held < label(nodes.size()))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'release' in " << dict.name() << ": patch '"
                << patch << "' has no constraint in component "
                << solidComponentName(c, analysis_)
                << " to release: " << held << " of its " << label(nodes.size())
                << " nodes are held (by a neighbouring patch), the others"
                << " are free or already released" << exit(FatalIOError);
        }
    }
    // Current reactions
    form::vecX r;
    model_->evaluate(t0, r, false);
    for (const label c : components)
    {
        model_->releaseConstraint(nodes, c, t0, t1);
    }
}


void Foam::solidRegion::hold
(
    const word& patch,
    const labelList& components,
    const dictionary& dict
)
{
    const std::vector<int>& nodes = patchNodes(patch, dict);
    const form::vecX U = model_->U();
    const form::dofMap dofs = model_->dofs();
    for (const label c : components)
    {
        model_->addNodalConstraint
        (
            nodes, c,
            [U, dofs, c](int node, double) { return U(dofs.dof(node, c)); }
        );
    }
}


form::vectorTimeFunction Foam::solidRegion::vectorFunction
(
    const dictionary& dict,
    const word& key
)
{
    std::shared_ptr<Function1<vector>> f
    (
        Function1<vector>::New(key, dict).ptr()
    );
    return [f](double t)
    {
        const vector v = f->value(t);
        return form::vec3(v.x(), v.y(), v.z());
    };
}


Foam::label Foam::solidRegion::axisOf
(
    const vector& n,
    const char* what,
    const dictionary& dict
) const
{
    const label nDim = feMesh_->feMesh().nDim;
    label c = -1;
    for (direction i = 0; i < 3; ++i)
    {
        const vector e(i == 0, i == 1, i == 2);
        if (mag(n) > 0 && mag((n/mag(n)) ^ e) < 1e-9) c = i;
    }
    if
    (
        c < 0 || c >= nDim
     || feMesh_->proj() == polyMeshToFeMesh::projection::wedge
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'normal' in " << dict.name() << ": " << n
            << "; " << what << " normal must be a coordinate axis"
            << " of the FE space (x, y" << (nDim == 3 ? ", z" : "")
            << ")" << exit(FatalIOError);
    }
    return c;
}


void Foam::solidRegion::applyCondition(const word& patch, const dictionary& pd)
{
    const word type = pd.get<word>("type");
    const form::feMesh& fe = feMesh_->feMesh();
    if (type == "free")
    {
        checkKeywords(pd, {"type", "value"});
        return;
    }
    const std::vector<int>& nodes = patchNodes(patch, pd);
    if (type == "fixedDisplacement")
    {
        checkKeywords(pd, {"type", "components", "displacement", "value"});
        labelList comps;
        if (pd.found("components"))
        {
            for (const word& c : pd.get<wordList>("components"))
            {
                comps.append(solidComponent(c, pd, analysis_));
            }
        }
        else
        {
            comps = identity(fe.nDim);
        }
        std::shared_ptr<Function1<vector>> disp;
        if (pd.found("displacement"))
        {
            disp.reset(Function1<vector>::New("displacement", pd).ptr());
        }
        for (const label c : comps)
        {
            form::timeFunction f = nullptr;
            if (disp)
            {
                f = [disp, c](double t) { return disp->value(t)[c]; };
            }
            model_->addConstraint(nodes, c, f);
        }
    }
    else if (type == "clamped")
    {
        // Translations and, on shell nodes, the director held
        checkKeywords(pd, {"type", "value"});
        for (label c = 0; c < fe.nDim; ++c) model_->addConstraint(nodes, c);
        const std::vector<int> shellNodes = shellNodesOf(nodes);
        if (!shellNodes.empty())
        {
            model_->addConstraint(shellNodes, 3);
            model_->addConstraint(shellNodes, 4);
        }
    }
    else if (type == "diaphragm")
    {
        // A rigid diaphragm in the plane normal to n: the displacements in
        // that plane held; on shell nodes the director does not turn about
        // n (it stays in its plane through n), as the diaphragm ends of
        // the pinched cylinder and the Scordelis-Lo roof
        checkKeywords(pd, {"type", "normal", "value"});
        const vector n = pd.get<vector>("normal");
        const label c = axisOf(n, "a diaphragm's", pd);
        for (label i = 0; i < fe.nDim; ++i)
        {
            if (i != c) model_->addConstraint(nodes, i);
        }
        const std::vector<int> shellNodes = shellNodesOf(nodes);
        try
        {
            model_->alignShellFrames
            (
                shellNodes, form::vec3(n.x(), n.y(), n.z())
            );
        }
        catch (const form::inputError& err)
        {
            fatalInput(pd, err);
        }
        model_->addConstraint(shellNodes, 3);
    }
    else if (type == "symmetryPlane")
    {
        // u . n = 0; on shell nodes the director turns only about n
        checkKeywords(pd, {"type", "normal", "value"});
        const vector n = pd.get<vector>("normal");
        const label c = axisOf(n, "a symmetry plane's", pd);
        model_->addConstraint(nodes, c);
        // Shell nodes: the frame's V1 along n, beta (the rotation about
        // the other tangent axis) held; a node on two symmetry planes
        // (a corner) turns about neither normal: both rotations held
        std::vector<int> align, corner;
        for (const int node : shellNodesOf(nodes))
        {
            const auto it = symmetryNormal_.find(node);
            if (it == symmetryNormal_.end())
            {
                symmetryNormal_[node] = c;
                align.push_back(node);
            }
            else if (it->second != c)
            {
                corner.push_back(node);
            }
        }
        try
        {
            model_->alignShellFrames(align, form::vec3(n.x(), n.y(), n.z()));
        }
        catch (const form::inputError& err)
        {
            fatalInput(pd, err);
        }
        model_->addConstraint(align, 4);
        model_->addConstraint(corner, 3);
        model_->addConstraint(corner, 4);
    }
    else if (type == "traction")
    {
        checkKeywords(pd, {"type", "traction", "value"});
        std::shared_ptr<Function1<vector>> tr
        (
            Function1<vector>::New("traction", pd).ptr()
        );
        // Components in the FE plane (x y, or r z of a wedge); the third
        // is out of the plane and must be zero (3D: x y z)
        const fileName file = pd.name();
        const bool plane = fe.nDim == 2;
        model_->addTraction
        (
            patch,
            [tr, file, plane](double t)
            {
                const vector v = tr->value(t);
                if (plane && v.z() != 0)
                {
                    FatalErrorInFunction
                        << "Entry 'traction' in " << file << ": " << v
                        << " at t = " << t << " has an out-of-plane (z)"
                        << " component in a 2D analysis" << exit(FatalError);
                }
                return form::vec3(v.x(), v.y(), v.z());
            }
        );
    }
    else if (type == "lineLoad")
    {
        // A force per unit length on the sides of a shell sheet
        checkKeywords(pd, {"type", "lineLoad", "value"});
        try
        {
            model_->addLineLoad(patch, vectorFunction(pd, "lineLoad"));
        }
        catch (const form::inputError& err)
        {
            fatalInput(pd, err);
        }
    }
    else if (type == "lineMoment")
    {
        // A moment per unit length (a vector) on the sides of a shell
        // sheet, acting on the rotations of the edge's nodes
        checkKeywords(pd, {"type", "lineMoment", "value"});
        try
        {
            model_->addLineMoment(patch, vectorFunction(pd, "lineMoment"));
        }
        catch (const form::inputError& err)
        {
            fatalInput(pd, err);
        }
    }
    else if (type == "pressure")
    {
        checkKeywords(pd, {"type", "pressure", "value"});
        std::shared_ptr<Function1<scalar>> pr
        (
            Function1<scalar>::New("pressure", pd).ptr()
        );
        model_->addPressure
        (
            patch,
            [pr](double t) { return pr->value(t); }
        );
        hasFollowerLoads_ = true;
    }
    else if (type == "rigidMotion")
    {
        applyRigidMotion(nodes, pd);
    }
    else
    {
        FatalIOErrorInFunction(pd)
            << "Unknown boundary condition type '" << type
            << "' for patch '" << patch << "' in " << pd.name() << nl
            << "    Valid types: " << conditionTypes()
            << exit(FatalIOError);
    }
}


void Foam::solidRegion::readBoundaryConditions()
{
    // The conditions are input: they live in the case's initial time
    // directory (the earliest with <region>/D), also when restarting from a
    // later time, whose D holds results
    fileName path = runTime_.path()/runTime_.timeName()/name_/"D";
    for (const instant& t : runTime_.times())
    {
        const fileName p = runTime_.path()/t.name()/name_/"D";
        if (t.name() != runTime_.constant() && isFile(p))
        {
            path = p;
            break;
        }
    }
    if (!isFile(path))
    {
        FatalErrorInFunction
            << "Missing boundary conditions of solid region '" << name_
            << "': file " << path << " not found"
            << exit(FatalError);
    }
    IFstream is(path);
    const dictionary fieldDict(is);
    checkInput(fieldDict, path);
    // The run starts from the undeformed state: an initial displacement in
    // internalField would be ignored, so anything but zero is an error
    if (fieldDict.found("internalField"))
    {
        const ITstream& is = fieldDict.lookup("internalField");
        const std::string text = is.toString();
        bool zero = false;
        try
        {
            ITstream copy(is);
            copy.rewind();
            word kind;
            copy >> kind;
            vector v;
            copy >> v;
            zero = kind == "uniform" && mag(v) == 0 && copy.eof();
        }
        catch (const Foam::error&) {}
        if (!zero)
        {
            FatalIOErrorInFunction(fieldDict)
                << "Entry 'internalField' in " << path << ": '" << text.c_str()
                << "'; formFoam starts from the undeformed state, so it must"
                << " be uniform (0 0 0) (displacements are prescribed on"
                << " patches in boundaryField)" << exit(FatalIOError);
        }
    }
    const dictionary& bf =
        subDictOf(fieldDict, "boundaryField", "{ <patch> { type ...; } }");

    wordList validTypes(conditionTypes());
    validTypes.append("empty");
    validTypes.append("wedge");

    for (const polyPatch& pp : mesh_->boundaryMesh())
    {
        const bool frontBack =
            isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp);
        if (!bf.found(pp.name()))
        {
            if (frontBack) continue;
            FatalIOErrorInFunction(bf)
                << "No boundary condition for patch '" << pp.name()
                << "' of solid region '" << name_ << "' in " << bf.name()
                << nl << "    Valid types: " << validTypes
                << exit(FatalIOError);
        }
        const dictionary& pd =
            subDictOf(bf, pp.name(), "{ type fixedDisplacement; ... }");
        const word type = pd.get<word>("type");
        if (!validTypes.found(type))
        {
            FatalIOErrorInFunction(pd)
                << "Unknown boundary condition type '" << type
                << "' for patch '" << pp.name() << "' in " << pd.name() << nl
                << "    Valid types: " << validTypes
                << exit(FatalIOError);
        }
        if (frontBack != (type == "empty" || type == "wedge"))
        {
            FatalIOErrorInFunction(pd)
                << "Patch '" << pp.name() << "' is of mesh type "
                << pp.type() << " but its condition is '" << type << "'"
                << exit(FatalIOError);
        }
        if (frontBack)
        {
            checkKeywords(pd, {"type", "value"});
            continue;
        }

        applyCondition(pp.name(), pd);
    }
    // entries for patches that do not exist
    for (const entry& e : bf)
    {
        if (mesh_->boundaryMesh().findPatchID(e.keyword()) < 0)
        {
            FatalIOErrorInFunction(bf)
                << "Boundary condition for patch '" << e.keyword()
                << "', which the mesh of solid region '" << name_
                << "' does not have" << nl << "    Patches: "
                << mesh_->boundaryMesh().names()
                << exit(FatalIOError);
        }
    }
}



// ************************************************************************* //
