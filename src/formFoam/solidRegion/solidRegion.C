/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of solidRegion.H: One solid region of a case.
\*---------------------------------------------------------------------------*/
#include "solidRegion.H"
#include "shellSet.H"
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
    return
    {
        "fixedDisplacement", "clamped", "symmetryPlane", "diaphragm",
        "rigidMotion",
        "traction", "lineLoad", "lineMoment", "pressure", "free"
    };
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
        properties_,
        {
            "analysisType", "elementType", "material", "bodyForce", "shell",
            "pointLoads", "pin", "formingLimit"
        }
    );
    const word analysisName = properties_.get<word>("analysisType");
    try
    {
        analysis_ = form::analysisTypeFromName(analysisName);
    }
    catch (const form::inputError& err)
    {
        fatalInput(properties_, err);
    }

    elementType_ = properties_.get<word>("elementType");
    label nodesPerElement = 0;
    form::shellSection shell;
    if (form::shellSet::isShellType(elementType_))
    {
        nodesPerElement = 4;
        shell = readShellSection();
    }
    else
    {
        try
        {
            nodesPerElement =
                form::solidElement::New(elementType_, analysis_)->nNodes();
        }
        catch (const form::inputError& err)
        {
            // The solid elements' list, and the shells
            fatalInput
            (
                properties_,
                form::inputError
                (
                    err.entry(),
                    std::string(err.what()) + "; shell elements: "
                  + form::shellSet::validTypes()
                )
            );
        }
        if (properties_.found("shell"))
        {
            FatalIOErrorInFunction(properties_)
                << "Entry 'shell' in " << properties_.objectPath()
                << ": a shell section, but elementType " << elementType_
                << " is a solid element (shell elements: "
                << form::shellSet::validTypes().c_str() << ")"
                << exit(FatalIOError);
        }
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
        new polyMeshToFeMesh
        (
            *mesh_,
            analysis_ == form::analysisType::solid3D ? 3 : 2,
            properties_.objectPath(),
            nodesPerElement,
            elementType_,
            "material",
            shell
        )
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
    readPointLoads();
    readFormingLimit();
    model_->finalise();
    if (properties_.found("pin"))
    {
        // Points held from the start (a rigid-body mode of a model with
        // symmetry planes): their displacement at t = 0, zero
        pinPoints
        (
            subDictOf
            (
                properties_, "pin",
                "{ <name> { point (x y z); components (x y); } }"
            ),
            true
        );
    }

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
                // not axisymmetric); 3D: (x, y, z)
                const vector v = g->value(t);
                if (fe->proj() == polyMeshToFeMesh::projection::space)
                {
                    return form::vec3(v.x(), v.y(), v.z());
                }
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


form::shellSection Foam::solidRegion::readShellSection() const
{
    const fileName file = properties_.objectPath();
    if (analysis_ != form::analysisType::solid3D)
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'elementType' in " << file << ": shell elements ("
            << elementType_ << ") need analysisType solid3D"
            << exit(FatalIOError);
    }
    form::shellSection section;
    if (!properties_.found("shell")) return section;
    const dictionary& sd = subDictOf
    (
        properties_, "shell", "{ thickness 1e-3; thicknessPoints 5; }"
    );
    checkKeywords
    (
        sd, {"thickness", "thicknessPoints", "thicknessRule", "shearCorrection"}
    );
    if (sd.found("thickness"))
    {
        section.thickness = sd.get<scalar>("thickness");
        if (!(section.thickness > 0) || !std::isfinite(section.thickness))
        {
            FatalIOErrorInFunction(sd)
                << "Entry 'shell/thickness' in " << file << ": "
                << section.thickness << " is not a positive thickness"
                << exit(FatalIOError);
        }
    }
    const word rule = sd.getOrDefault<word>("thicknessRule", "Gauss");
    if (rule != "Gauss" && rule != "Lobatto")
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'shell/thicknessRule' in " << file << ": unknown '"
            << rule << "'; valid: Gauss Lobatto" << exit(FatalIOError);
    }
    section.lobatto = rule == "Lobatto";
    section.points = sd.getOrDefault<label>("thicknessPoints", section.points);
    const label minPoints = section.lobatto ? 3 : 1;
    if (section.points < minPoints || section.points > 10)
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'shell/thicknessPoints' in " << file << ": "
            << section.points << " " << rule << " points through the"
            << " thickness; valid: " << minPoints << " to 10"
            << exit(FatalIOError);
    }
    section.shearCorrection =
        sd.getOrDefault<scalar>("shearCorrection", section.shearCorrection);
    if (!(section.shearCorrection > 0 && section.shearCorrection <= 1))
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'shell/shearCorrection' in " << file << ": "
            << section.shearCorrection << " is not in (0, 1]"
            << exit(FatalIOError);
    }
    return section;
}


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
    if (model_->shells())
    {
        // Shells: the displacement of the mid-surface node at the point
        return model_->displacement()(nodeAt(pt, dict), component);
    }
    const form::pointLocation loc =
        form::locatePoint(fe, feMesh_->toFe(pt), 1e-6);
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
    Eigen::MatrixXd P(nodes.size(), fe.nDim);
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
