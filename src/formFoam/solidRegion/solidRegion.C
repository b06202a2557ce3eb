/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of solidRegion.H: One solid region of a case.
\*---------------------------------------------------------------------------*/
#include "solidRegion.H"
#include "contactModel.H"
#include "dictionaryChecks.H"
#include "Function1.H"
#include "IFstream.H"
#include "IOField.H"
#include "OSspecific.H"
#include "pointFields.H"
#include "pointLocator.H"
#include "materialInput.H"
#include "Tuple2.H"
#include "volFields.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"

// * * * * * * * * * * * * * * * Private Functions  * * * * * * * * * * * * //

namespace
{

// Copy an OpenFOAM dictionary into formCore's materialInput tree: a single
// number -> scalar, a single word -> word, a list of (x y) pairs -> table,
// a sub-dictionary -> sub-tree. Anything else is an error naming the entry.
void toMaterialInput
(
    const Foam::dictionary& dict,
    form::materialInput& in,
    const std::string& path
)
{
    using namespace Foam;
    in.path = path;
    for (const entry& e : dict)
    {
        const std::string key = e.keyword();
        const std::string sub = path.empty() ? key : path + "/" + key;
        if (e.isDict())
        {
            toMaterialInput(e.dict(), in.dicts[key], sub);
            continue;
        }
        ITstream& is = e.stream();
        if (is.size() == 1 && is[0].isNumber())
        {
            in.scalars[key] = is[0].number();
        }
        else if (is.size() == 1 && is[0].isWord())
        {
            in.words[key] = is[0].wordToken();
        }
        else if (is.size() > 1 && is[0].isPunctuation())
        {
            List<Tuple2<scalar, scalar>> pairs;
            is >> pairs;
            form::materialInput::table& t = in.tables[key];
            for (const auto& xy : pairs)
            {
                t.push_back({xy.first(), xy.second()});
            }
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << sub.c_str() << "' in " << dict.name()
                << ": expected a number, a word, a list of (x y) pairs or a"
                << " sub-dictionary"
                << exit(FatalIOError);
        }
    }
}

} // anonymous namespace


void Foam::solidRegion::readMaterial(const dictionary& dict)
{
    materialType_ = dict.get<word>("type");
    const auto& reg = form::material::registry();
    if (reg.find(materialType_) == reg.end())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown material type '" << materialType_ << "' in "
            << dict.name() << nl << "    Valid types: "
            << form::material::validTypes().c_str()
            << exit(FatalIOError);
    }
    form::materialInput input;
    toMaterialInput(dict, input, "");
    // The density belongs to the region (inertia), not to the
    // constitutive law
    if (dict.found("rho"))
    {
        density_ = dict.get<scalar>("rho");
        if (!(density_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'rho' in " << dict.name() << " must be positive,"
                << " got " << density_ << exit(FatalIOError);
        }
        input.scalars.erase("rho");
    }
    try
    {
        material_ = form::material::New(materialType_, input);
    }
    catch (const form::inputError& err)
    {
        fatalInput(dict, err);
    }
}


Foam::wordList Foam::solidRegion::conditionTypes()
{
    return {"fixedDisplacement", "rigidMotion", "traction", "pressure", "free"};
}


const std::vector<int>& Foam::solidRegion::patchNodes
(
    const word& patch,
    const dictionary& dict
) const
{
    const auto& sets = feMesh_->feMesh().nodeSets;
    const auto it = sets.find(patch);
    if (it == sets.end() || mesh_->boundaryMesh().findPatchID(patch) < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Unknown patch '" << patch << "' of solid region '" << name_
            << "' in " << dict.name() << nl << "    Patches: "
            << mesh_->boundaryMesh().names() << exit(FatalIOError);
    }
    return it->second;
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
                << (analysis_ == form::analysisType::axisymmetric
                    ? (c == 0 ? "r" : "z") : (c == 0 ? "x" : "y"))
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


void Foam::solidRegion::pin
(
    const point& p,
    const labelList& components,
    const dictionary& dict
)
{
    const form::feMesh& fe = feMesh_->feMesh();
    const Eigen::Vector2d x = feMesh_->toPlane(p);
    int best = -1;
    double dmin = GREAT;
    for (int n = 0; n < fe.nNodes(); ++n)
    {
        const double d = (fe.X.row(n).transpose() - x).norm();
        if (d < dmin) { dmin = d; best = n; }
    }
    const double size =
        (fe.X.colwise().maxCoeff() - fe.X.colwise().minCoeff()).norm();
    if (best < 0 || dmin > 1e-6*size)
    {
        FatalIOErrorInFunction(dict)
            << "No node of solid region '" << name_ << "' at point " << p
            << " (nearest at distance " << dmin << ") in " << dict.name()
            << exit(FatalIOError);
    }
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
            comps = labelList({0, 1});
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
    else if (type == "traction")
    {
        checkKeywords(pd, {"type", "traction", "value"});
        std::shared_ptr<Function1<vector>> tr
        (
            Function1<vector>::New("traction", pd).ptr()
        );
        // Components in the FE plane (x y, or r z of a wedge); the third
        // is out of the plane and must be zero
        const fileName file = pd.name();
        model_->addTraction
        (
            patch,
            [tr, file](double t)
            {
                const vector v = tr->value(t);
                if (v.z() != 0)
                {
                    FatalErrorInFunction
                        << "Entry 'traction' in " << file << ": " << v
                        << " at t = " << t << " has an out-of-plane (z)"
                        << " component in a 2D analysis" << exit(FatalError);
                }
                return form::vec3(v.x(), v.y(), 0);
            }
        );
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
        // x = o + c(t) + R(theta(t)) (X - o) on the patch: a rigid rotation
        // by theta (counter-clockwise in the FE plane) about the origin o,
        // then a translation c; both components are prescribed
        checkKeywords(pd, {"type", "origin", "angle", "translation", "value"});
        const Eigen::Vector2d o = feMesh_->toPlane(pd.get<point>("origin"));
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
        for (const label c : {0, 1})
        {
            model_->addNodalConstraint
            (
                nodes,
                c,
                [=](int node, double t)
                {
                    const double th = angle->value(t);
                    const Eigen::Vector2d d = X.row(node).transpose() - o;
                    Eigen::Matrix2d R;
                    R << std::cos(th), -std::sin(th),
                         std::sin(th), std::cos(th);
                    Eigen::Vector2d u = R*d - d;
                    if (translation)
                    {
                        const vector v = translation->value(t);
                        u += Eigen::Vector2d(v.x(), v.y());
                    }
                    return u(c);
                }
            );
        }
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::solidRegion::solidRegion(Time& runTime, const word& name)
:
    runTime_(runTime),
    name_(name),
    properties_
    (
        IOobject
        (
            "solidProperties",
            runTime.constant(),
            name,
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    )
{
    checkInput(properties_, properties_.objectPath());
    checkKeywords
    (
        properties_, {"analysisType", "elementType", "material", "bodyForce"}
    );
    const word analysisName = properties_.get<word>("analysisType");
    try
    {
        analysis_ = form::analysisTypeFromName(analysisName);
        if (analysis_ == form::analysisType::solid3D)
        {
            throw form::inputError
            (
                "analysisType",
                "3D solid elements are not available yet; valid: "
                "planeStrain axisymmetric"
            );
        }
    }
    catch (const form::inputError& err)
    {
        fatalInput(properties_, err);
    }

    elementType_ = properties_.get<word>("elementType");
    label nodesPerElement = 0;
    try
    {
        nodesPerElement =
            form::solidElement::New(elementType_, analysis_)->nNodes();
    }
    catch (const form::inputError& err)
    {
        fatalInput(properties_, err);
    }

    readMaterial(subDictOf(properties_, "material", "{ type ...; E ...; }"));

    // The region's mesh: constant/<solid>/polyMesh (OpenFOAM's own message
    // would only name a missing "points" file)
    const fileName meshDir =
        runTime.path()/runTime.constant()/name/polyMesh::meshSubDir;
    for (const word f : {"points", "faces", "owner", "neighbour", "boundary"})
    {
        if (!isFile(meshDir/f) && !isFile(meshDir/f + ".gz"))
        {
            FatalErrorInFunction
                << "Solid region '" << name << "' has no mesh: "
                << ("constant"/name/polyMesh::meshSubDir/f).c_str()
                << " is missing; run blockMesh -region " << name.c_str()
                << exit(FatalError);
        }
    }

    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                name,
                runTime.timeName(),
                runTime,
                IOobject::MUST_READ
            )
        )
    );

    feMesh_.reset
    (
        new polyMeshToFeMesh(*mesh_, nodesPerElement, elementType_, "material")
    );

    if
    (
        analysis_ == form::analysisType::axisymmetric
     && feMesh_->feMesh().X.col(0).minCoeff() < -SMALL
    )
    {
        FatalIOErrorInFunction(properties_)
            << "Axisymmetric solid region '" << name_ << "' has points at"
            << " negative radius (x < 0); the axis is x = 0"
            << exit(FatalIOError);
    }

    std::map<std::string, std::shared_ptr<form::material>> materials
    {
        {"material", material_}
    };
    model_.reset
    (
        new form::solidModel(feMesh_->feMesh(), analysis_, materials)
    );
    if (analysis_ == form::analysisType::axisymmetric)
    {
        // Nodes on the axis (r = 0) stay on it by symmetry: u_r = 0 (the
        // collapsed axis patch of a wedge mesh has no faces to carry a
        // boundary condition); a condition of 0/<region>/D on the same
        // dofs overrides it
        const form::matX& X = feMesh_->feMesh().X;
        const scalar tol = 1e-9*max(X.cwiseAbs().maxCoeff(), 1.0);
        std::vector<int> onAxis;
        for (int n = 0; n < X.rows(); ++n)
        {
            if (X(n, 0) <= tol) onAxis.push_back(n);
        }
        if (!onAxis.empty()) model_->addConstraint(onAxis, 0);
    }
    readBoundaryConditions();
    model_->finalise();

    // Body force per unit mass (gravity), a Function1 of time
    if (properties_.found("bodyForce"))
    {
        if (!(density_ > 0))
        {
            FatalIOErrorInFunction(properties_)
                << "Entry 'bodyForce' in constant/" << name_
                << "/solidProperties needs the density: give 'rho' in its"
                << " material" << exit(FatalIOError);
        }
        std::shared_ptr<Function1<vector>> g
        (
            Function1<vector>::New("bodyForce", properties_).ptr()
        );
        bodyForce_ = g;
        const polyMeshToFeMesh* fe = feMesh_.get();
        model_->setBodyForce
        (
            density_,
            [g, fe](double t)
            {
                // In the FE plane: (x, y) of a plane mesh; (r, z) of a
                // wedge: the axial component only (a radial body force is
                // not axisymmetric)
                const vector v = g->value(t);
                if (fe->proj() == polyMeshToFeMesh::projection::planar)
                {
                    return form::vec3(v.x(), v.y(), 0);
                }
                const vector axis =
                    fe->toSpace(point(1, 1, 1), Eigen::Vector2d(0, 1));
                return form::vec3(0, v & axis, 0);
            }
        );
    }

    vtk_.reset(new form::vtkWriter(runTime.path()/"VTK", name_));
}


Foam::solidRegion::~solidRegion() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::string Foam::solidRegion::describe() const
{
    OStringStream os;
    os  << "solid region '" << name_ << "': "
        << form::analysisTypeName(analysis_) << ", "
        << feMesh_->feMesh().nElements() << " " << elementType_
        << " elements, " << materialType_ << ", "
        << feMesh_->feMesh().nNodes() << " nodes, "
        << model_->nFreeDofs() << " free dofs, "
        << model_->nPrescribedDofs() << " constrained";
    return os.str();
}


Foam::scalar Foam::solidRegion::displacementAt
(
    const point& pt,
    label component,
    const dictionary& dict
) const
{
    const form::feMesh& fe = feMesh_->feMesh();
    const form::pointLocation loc =
        form::locatePoint(fe, feMesh_->toPlane(pt), 1e-6);
    if (!loc.found())
    {
        FatalIOErrorInFunction(dict)
            << "Point " << pt << " in " << dict.name()
            << " lies outside the mesh of solid region '" << name_ << "'"
            << exit(FatalIOError);
    }
    return form::interpolate(fe, loc, model_->displacement())(component);
}


Foam::scalar Foam::solidRegion::reaction
(
    const word& patch,
    label component,
    const dictionary& dict
) const
{
    const auto iter = feMesh_->feMesh().nodeSets.find(patch);
    if (iter == feMesh_->feMesh().nodeSets.end())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown patch '" << patch << "' in " << dict.name()
            << " (solid region '" << name_ << "')" << nl << "    Patches: "
            << mesh_->boundaryMesh().names()
            << exit(FatalIOError);
    }
    return model_->reaction(iter->second)(component);
}


Eigen::MatrixXd Foam::solidRegion::patchPoints
(
    const word& patch,
    const dictionary& dict,
    const bool current
) const
{
    const std::vector<int>& nodes = patchNodes(patch, dict);
    const form::feMesh& fe = feMesh_->feMesh();
    const form::matX U = model_->displacement();
    Eigen::MatrixXd P(nodes.size(), 2);
    for (std::size_t k = 0; k < nodes.size(); ++k)
    {
        P.row(k) = fe.X.row(nodes[k]);
        if (current) P.row(k) += U.row(nodes[k]);
    }
    return P;
}


Foam::scalar Foam::solidRegion::circleRadius
(
    const word& patch,
    const dictionary& dict
) const
{
    // Pratt's algebraic fit (Pratt, Computer Graphics 21 (1987) 145-152):
    // circle A (x^2 + y^2) + B x + C y + D = 0 minimising sum of squared
    // algebraic distances subject to B^2 + C^2 - 4 A D = 1, i.e. the
    // generalised eigenproblem M a = eta N a (smallest eta >= 0); then
    // R = 1/(2|A|). Unlike the Kasa fit it stays exact for short arcs and
    // gives R -> infinity (A -> 0) for collinear points. Coordinates are
    // shifted to the centroid and scaled for conditioning.
    Eigen::MatrixXd P = patchPoints(patch, dict, true);
    const int n = int(P.rows());
    const Eigen::RowVector2d c0 = P.colwise().mean();
    P.rowwise() -= c0;
    const double L = std::max(P.cwiseAbs().maxCoeff(), VSMALL);
    P /= L;
    if (n < 3)
    {
        FatalIOErrorInFunction(dict)
            << "circleRadius of patch '" << patch << "' in " << dict.name()
            << " needs at least 3 nodes" << exit(FatalIOError);
    }
    Eigen::MatrixXd Z(n, 4);
    for (int k = 0; k < n; ++k)
    {
        Z.row(k) << P.row(k).squaredNorm(), P(k, 0), P(k, 1), 1;
    }
    const Eigen::Matrix4d M = Z.transpose()*Z/n;
    Eigen::Matrix4d Ninv = Eigen::Matrix4d::Zero();
    Ninv(0, 3) = Ninv(3, 0) = -0.5;
    Ninv(1, 1) = Ninv(2, 2) = 1;
    Eigen::EigenSolver<Eigen::Matrix4d> eig(Ninv*M);
    double best = GREAT;
    double R = GREAT;
    for (int i = 0; i < 4; ++i)
    {
        const double eta = eig.eigenvalues()(i).real();
        if (std::abs(eig.eigenvalues()(i).imag()) > 1e-12*(1 + std::abs(eta)))
        {
            continue;
        }
        const Eigen::Vector4d v = eig.eigenvectors().col(i).real();
        const double c = v(1)*v(1) + v(2)*v(2) - 4*v(0)*v(3);
        if (!(c > 0) || eta < -1e-10 || eta >= best) continue;
        best = eta;
        const double A = std::abs(v(0))/std::sqrt(c);
        R = A > 0.5/GREAT ? L/(2*A) : GREAT;
    }
    return R;
}


Foam::scalar Foam::solidRegion::patchRotation
(
    const word& patch,
    const dictionary& dict
) const
{
    Eigen::MatrixXd A = patchPoints(patch, dict, false);
    Eigen::MatrixXd B = patchPoints(patch, dict, true);
    A.rowwise() -= A.colwise().mean();
    B.rowwise() -= B.colwise().mean();
    double cross = 0, dot = 0;
    for (int k = 0; k < A.rows(); ++k)
    {
        cross += A(k, 0)*B(k, 1) - A(k, 1)*B(k, 0);
        dot += A.row(k).dot(B.row(k));
    }
    return std::atan2(cross, dot);
}
