/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    constant/contactProperties -> form::contactModel (see solidContact.H).
\*---------------------------------------------------------------------------*/
#include "solidContact.H"
#include <cmath>
#include "dictionaryChecks.H"
#include "formError.H"
#include "OSspecific.H"
#include "vector2D.H"
#include "triSurface.H"
#include <fstream>

// * * * * * * * * * * * * * * * Private Functions  * * * * * * * * * * * * //

Foam::label Foam::solidContact::toolIndex
(
    const word& tool,
    const dictionary& dict
) const
{
    const label i = toolNames_.find(tool);
    if (i < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Unknown tool '" << tool << "' in " << dict.name() << nl
            << "    Tools of constant/contactProperties: " << toolNames_
            << exit(FatalIOError);
    }
    return i;
}


form::rigidToolSpec Foam::solidContact::readTool
(
    const word& name,
    const dictionary& td
)
{
    const bool is3D = solid_.analysis() == form::analysisType::solid3D;
    checkKeywords
    (
        td,
        is3D
      ? wordList{"surface", "motion", "force", "direction", "compliance"}
      : wordList
        {
            "profile", "radii", "radius", "motion", "force", "direction",
            "compliance"
        }
    );
    form::rigidToolSpec tool;
    tool.name = name;
    if (is3D)
    {
        tool.surface = readSurface
        (
            subDictOf(td, "surface", "{ type sphere; centre (0 0 0); radius 1; }")
        );
    }
    else
    {
        tool.profile = readProfile(td);
    }
    readMotion(tool, td);
    // The tool's normal give per unit contact pressure (contactModel.H,
    // "Tool compliance"); absent: rigid
    if (td.found("compliance"))
    {
        tool.compliance = td.get<scalar>("compliance");
        if (!(tool.compliance >= 0) || !std::isfinite(tool.compliance))
        {
            FatalIOErrorInFunction(td)
                << "Entry 'compliance' of tool '" << name << "' in "
                << td.name() << " must be zero (rigid) or positive (the"
                << " tool face's normal give per unit contact pressure),"
                << " got " << tool.compliance << exit(FatalIOError);
        }
    }
    return tool;
}


std::shared_ptr<form::rigidProfile> Foam::solidContact::readProfile
(
    const dictionary& td,
    const word& pointsKey,
    const word& radiiKey,
    const word& radiusKey
)
{
    const List<vector2D> pts = td.get<List<vector2D>>(pointsKey);
    std::vector<Eigen::Vector2d> points;
    for (const vector2D& p : pts) points.emplace_back(p.x(), p.y());
    std::vector<double> radii;
    if (td.found(radiiKey) && td.found(radiusKey))
    {
        FatalIOErrorInFunction(td)
            << "Give either '" << radiiKey << "' or '" << radiusKey
            << "' in " << td.name() << ", not both" << exit(FatalIOError);
    }
    if (td.found(radiiKey))
    {
        for (const scalar r : td.get<scalarList>(radiiKey)) radii.push_back(r);
    }
    else if (td.found(radiusKey))
    {
        radii.push_back(td.get<scalar>(radiusKey));
    }
    std::shared_ptr<form::rigidProfile> profile;
    try
    {
        profile = std::make_shared<form::rigidProfile>(points, radii);
    }
    catch (const form::inputError& e)
    {
        // the profile's entries under the names of this dictionary
        const std::string entry =
            e.entry() == "points" ? pointsKey
          : e.entry() == "radii" ? radiiKey : e.entry();
        fatalInput(td, form::inputError(entry, e.what()));
    }
    return profile;
}


std::shared_ptr<const form::triangulation>
Foam::solidContact::readTriangles(const dictionary& sd) const
{
    fileName name = sd.get<fileName>("file");
    name.expand();
    const fileName path = runTime_.path()/"constant"/"triSurface"/name;
    if (!isFile(path))
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'file' in " << sd.name() << ": no file " << path
            << " (the triangles of a triSurface tool are read from"
            << " constant/triSurface/)" << exit(FatalIOError);
    }
    auto T = std::make_shared<form::triangulation>();
    T->source = name;
    try
    {
        const triSurface surf(path);
        const pointField& pts = surf.points();
        T->points.reserve(pts.size());
        for (const point& p : pts)
        {
            T->points.emplace_back(p.x(), p.y(), p.z());
        }
        T->triangles.reserve(surf.size());
        for (const labelledTri& f : surf)
        {
            T->triangles.push_back({f[0], f[1], f[2]});
        }
    }
    catch (const Foam::error& e)
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'file' in " << sd.name() << ": cannot read " << path
            << ": " << e.message() << exit(FatalIOError);
    }
    return T;
}


std::shared_ptr<form::rigidSurface> Foam::solidContact::readSurface
(
    const dictionary& sd
) const
{
    const word type = sd.get<word>("type");
    const std::map<word, wordList> keys
    {
        {"plane", {"point", "normal"}},
        {"sphere", {"centre", "radius"}},
        {"cylinder", {"point", "axis", "radius"}},
        {"extrudedProfile", {"origin", "xAxis", "yAxis", "profile", "radii", "radius"}},
        {"revolvedProfile", {"origin", "axis", "profile", "radii", "radius"}},
        {"sweptProfile", {"origin", "axis", "xAxis", "coreX", "coreY", "profile", "radii", "radius"}},
        {"pathProfile", {"origin", "axis", "xAxis", "path", "pathRadii", "pathRadius", "profile", "radii", "radius"}},
        {"triSurface", {"file", "flipNormals", "featureAngle"}}
    };
    const auto it = keys.find(type);
    if (it == keys.end())
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'type' in " << sd.name() << ": unknown surface type '"
            << type << "'; valid: " << form::rigidSurface::validTypes().c_str()
            << exit(FatalIOError);
    }
    wordList valid(it->second);
    valid.append("type");
    checkKeywords(sd, valid);
    std::map<std::string, form::vec3> vectors;
    std::map<std::string, double> scalars;
    std::shared_ptr<form::rigidProfile> profile;
    const bool profiled =
        type == "extrudedProfile" || type == "revolvedProfile"
     || type == "sweptProfile" || type == "pathProfile";
    for (const word& k : it->second)
    {
        if
        (
            k == "profile" || k == "radii" || k == "file" || k == "path"
         || k == "pathRadii" || k == "pathRadius"
        )
        {
            continue;
        }
        if (k == "flipNormals")
        {
            scalars[k] = sd.getOrDefault<bool>(k, false) ? 1 : 0;
            continue;
        }
        if (k == "coreX" || k == "coreY")
        {
            if (sd.found(k)) scalars[k] = sd.get<scalar>(k);
            continue;
        }
        if (k == "featureAngle")
        {
            if (sd.found(k)) scalars[k] = sd.get<scalar>(k);
            continue;
        }
        if (k == "radius")
        {
            // a sphere's or cylinder's radius; a profile's fillet radius
            if (!profiled && sd.found(k)) scalars[k] = sd.get<scalar>(k);
            continue;
        }
        if (sd.found(k))
        {
            const vector v = sd.get<vector>(k);
            vectors[k] = form::vec3(v.x(), v.y(), v.z());
        }
    }
    if (profiled) profile = readProfile(sd);
    std::shared_ptr<form::rigidProfile> path;
    if (type == "pathProfile" && sd.found("path"))
    {
        path = readProfile(sd, "path", "pathRadii", "pathRadius");
    }
    std::shared_ptr<const form::triangulation> triangles;
    if (type == "triSurface") triangles = readTriangles(sd);
    std::shared_ptr<form::rigidSurface> surface;
    try
    {
        surface = form::rigidSurface::New
        (
            type, vectors, scalars, profile, triangles, path
        );
    }
    catch (const form::inputError& e)
    {
        fatalInput(sd, e);
    }
    return surface;
}


void Foam::solidContact::readMotion
(
    form::rigidToolSpec& tool,
    const dictionary& td
) const
{
    const word& name = tool.name;
    const bool is3D = solid_.analysis() == form::analysisType::solid3D;
    if (td.found("force"))
    {
        if (td.found("motion"))
        {
            FatalIOErrorInFunction(td)
                << "Tool '" << name << "' in " << td.name() << " has both"
                << " 'motion' and 'force': a tool is either motion- or"
                << " force-controlled" << exit(FatalIOError);
        }
        std::shared_ptr<Function1<scalar>> f
        (
            Function1<scalar>::New("force", td).ptr()
        );
        const vector dir = td.get<vector>("direction");
        const scalar m =
            is3D ? mag(dir) : Foam::sqrt(sqr(dir.x()) + sqr(dir.y()));
        if (is3D && !(m > SMALL))
        {
            FatalIOErrorInFunction(td)
                << "Entry 'direction' of tool '" << name << "' in "
                << td.name() << " must be a non-zero vector, got " << dir
                << exit(FatalIOError);
        }
        if (!is3D && (m < SMALL || mag(dir.z()) > SMALL*max(m, 1)))
        {
            FatalIOErrorInFunction(td)
                << "Entry 'direction' of tool '" << name << "' in "
                << td.name() << " must be a non-zero vector in the FE plane"
                << " (x y 0), got " << dir << exit(FatalIOError);
        }
        tool.forceControlled = true;
        tool.direction =
            form::vec3(dir.x()/m, dir.y()/m, is3D ? dir.z()/m : 0);
        tool.force = [f](double t) { return f->value(t); };
    }
    else if (td.found("motion"))
    {
        std::shared_ptr<Function1<vector>> d
        (
            Function1<vector>::New("motion", td).ptr()
        );
        tool.translation = [d, is3D](double t)
        {
            const vector v = d->value(t);
            return form::vec3(v.x(), v.y(), is3D ? v.z() : 0);
        };
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

bool Foam::solidContact::declared(const Time& runTime)
{
    return isFile(runTime.path()/"constant"/"contactProperties");
}


void Foam::solidContact::checkOrientation
(
    const std::vector<form::rigidToolSpec>& tools,
    const std::vector<form::contactPairSpec>& pairs
) const
{
    if (solid_.analysis() == form::analysisType::solid3D)
    {
        checkOrientation3D(tools, pairs);
        return;
    }
    const form::feMesh& fe = solid_.feMesh().feMesh();
    const scalar t0 = runTime_.startTime().value();
    for (const form::contactPairSpec& ps : pairs)
    {
        if (ps.tool.empty()) continue;
        const form::rigidToolSpec* tool = nullptr;
        for (const auto& t : tools) if (t.name == ps.tool) tool = &t;
        if (!tool) continue;
        const Eigen::Vector2d d =
            tool->translation && !tool->forceControlled
          ? Eigen::Vector2d(tool->translation(t0).head<2>())
          : Eigen::Vector2d::Zero();

        // Outward normals of the patch at its nodes: the sum of the unit
        // normals of its faces, each pointing away from its element
        std::map<int, Eigen::Vector2d> normals;
        for (const form::feFace& f : fe.faceSets.at(ps.faceSet))
        {
            const form::elementBlock& blk = fe.blocks[f.block];
            const int* en = blk.nodes(f.element);
            Eigen::Vector2d centre = Eigen::Vector2d::Zero();
            for (int a = 0; a < blk.nodesPerElement; ++a)
            {
                centre += fe.X.row(en[a]).transpose();
            }
            centre /= blk.nodesPerElement;
            const Eigen::Vector2d A = fe.X.row(f.nodes.front()).transpose();
            const Eigen::Vector2d B = fe.X.row(f.nodes.back()).transpose();
            Eigen::Vector2d n(B(1) - A(1), A(0) - B(0));
            if (n.norm() == 0) continue;
            n.normalize();
            if ((centre - 0.5*(A + B)).dot(n) > 0) n = -n;
            for (const int node : f.nodes)
            {
                auto it = normals.emplace(node, Eigen::Vector2d::Zero()).first;
                it->second += n;
            }
        }
        // A reversed profile puts the body on the tool's inner side (gap
        // <= 0: touching or inside) with the tool's outward normal along
        // the patch's own (backing it). A node behind a tool at a positive
        // gap is not wrong: a tool may reach a face only after the body
        // has turned (a hemming flange). End points and sharp corners
        // (whose normal points at any node) do not tell.
        const scalar tol = 1e-9*tool->profile->length();
        label considered = 0, reversed = 0;
        for (const auto& nn : normals)
        {
            const Eigen::Vector2d y = fe.X.row(nn.first).transpose() - d;
            const form::profileProjection p = tool->profile->project(y);
            if (p.vertex || nn.second.norm() == 0) continue;
            ++considered;
            const scalar c = p.normal.dot(nn.second.normalized());
            if (c > 0.1 && p.gap <= tol) ++reversed;
        }
        if (considered > 0 && reversed == considered)
        {
            reportReversed
            (
                ps,
                "walking along the points of 'profile', the tool's solid"
                " lies on the LEFT (counter-clockwise around the tool), so"
                " that its outward normal points towards the body. Reverse"
                " the order of the points of tools/" + ps.tool + "/profile."
            );
        }
    }
}


void Foam::solidContact::reportReversed
(
    const form::contactPairSpec& ps,
    const std::string& rule
) const
{
    FatalIOErrorInFunction(dict_)
        << "Tool '" << ps.tool.c_str() << "' in " << dict_.name()
        << " turns its back on patch '" << ps.faceSet.c_str()
        << "' of pair '" << ps.name.c_str() << "': every node of"
        << " the patch lies on the tool's inner side (touching or"
        << " inside it), where the tool's outward normal points the"
        << " same way as the body's." << nl
        << "    Rule: " << rule.c_str() << exit(FatalIOError);
}


void Foam::solidContact::checkOrientation3D
(
    const std::vector<form::rigidToolSpec>& tools,
    const std::vector<form::contactPairSpec>& pairs
) const
{
    // As in 2D: a surface given inside out (a plane's normal pointing
    // into the tool) puts every node of the patch on the tool's inner
    // side, with the tool's outward normal along the body's own
    const form::feMesh& fe = solid_.feMesh().feMesh();
    const scalar t0 = runTime_.startTime().value();
    for (const form::contactPairSpec& ps : pairs)
    {
        const form::rigidToolSpec* tool = nullptr;
        for (const auto& t : tools) if (t.name == ps.tool) tool = &t;
        if (!tool) continue;
        const form::vec3 d =
            tool->translation && !tool->forceControlled
          ? tool->translation(t0) : form::vec3::Zero();
        std::map<int, form::vec3> normals;
        scalar size = 0;
        for (const form::feFace& f : fe.faceSets.at(ps.faceSet))
        {
            // corners counter-clockwise seen from outside (hexFaceNodes;
            // a prism's triangle: its three corners), the corners first
            const std::size_t last = f.nodes.size() == 3 ? 2 : 3;
            const form::vec3 X0 = fe.X.row(f.nodes[0]).transpose();
            const form::vec3 X1 = fe.X.row(f.nodes[1]).transpose();
            const form::vec3 X3 = fe.X.row(f.nodes[last]).transpose();
            const form::vec3 n = (X1 - X0).cross(X3 - X0);
            size = max(size, (X1 - X0).norm());
            if (n.norm() == 0) continue;
            for (const int node : f.nodes)
            {
                normals.emplace(node, form::vec3::Zero()).first->second +=
                    n.normalized();
            }
        }
        label considered = 0, reversed = 0;
        for (const auto& nn : normals)
        {
            if (nn.second.norm() == 0) continue;
            const form::surfaceProjection p = tool->surface->project
            (
                fe.X.row(nn.first).transpose() - d
            );
            ++considered;
            const scalar c = p.normal.dot(nn.second.normalized());
            if (c > 0.1 && p.gap <= 1e-9*size) ++reversed;
        }
        if (considered > 0 && reversed == considered)
        {
            reportReversed
            (
                ps,
                "a surface's normal points out of the tool, towards the body"
                " (a plane's 'normal'; spheres and cylinders are solid; a"
                " profile's tool lies on the left of its points; a"
                " triSurface's triangles turn counter-clockwise seen from"
                " the body: 'flipNormals true' turns them all)."
            );
        }
    }
}


Foam::solidContact::solidContact(const Time& runTime, solidRegion& solid)
:
    runTime_(runTime),
    solid_(solid),
    dict_
    (
        IOobject
        (
            "contactProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    )
{
    checkInput(dict_, dict_.objectPath());
    checkKeywords
    (
        dict_,
        {"tools", "pairs", "epsilonN", "epsilonT", "stiffness",
         "maxStatusChanges", "frictionLaw", "frictionAugmentation"}
    );

    // Rigid tools (optional when every pair has a deformable target)
    std::vector<form::rigidToolSpec> tools;
    const dictionary& tdict =
        dict_.found("tools")
      ? subDictOf(dict_, "tools", "{ <tool> { type ...; } }")
      : dictionary::null;
    for (const entry& e : tdict)
    {
        const dictionary& td = dictOf(e, tdict, "{ type ...; }");
        toolNames_.append(e.keyword());
        tools.push_back(readTool(e.keyword(), td));
    }

    std::vector<form::contactPairSpec> pairs;
    const dictionary& pdict =
        subDictOf(dict_, "pairs", "{ <pair> { patch ...; tool ...; } }");
    const auto& faceSets = solid_.feMesh().feMesh().faceSets;
    for (const entry& e : pdict)
    {
        const dictionary& pd =
            dictOf(e, pdict, "{ patch ...; tool ...; friction ...; }");
        checkKeywords(pd, {"patch", "tool", "targetPatch", "friction"});
        form::contactPairSpec ps;
        ps.name = e.keyword();
        ps.faceSet = pd.get<word>("patch");
        ps.friction = pd.getOrDefault<scalar>("friction", 0);
        if (pd.found("tool") == pd.found("targetPatch"))
        {
            FatalIOErrorInFunction(pd)
                << "Pair '" << e.keyword() << "' in " << pd.name()
                << " needs either 'tool' (a rigid tool of 'tools') or"
                << " 'targetPatch' (a patch of the solid region: contact"
                << " with a deformable body)" << exit(FatalIOError);
        }
        if (pd.found("tool"))
        {
            ps.tool = pd.get<word>("tool");
            toolIndex(ps.tool, pd);
        }
        else
        {
            ps.targetFaceSet = pd.get<word>("targetPatch");
        }
        for (const std::string& patch : {ps.faceSet, ps.targetFaceSet})
        {
            if (patch.empty()) continue;
            if
            (
                !faceSets.count(patch)
             && solid_.mesh().boundaryMesh().findPatchID(patch) >= 0
            )
            {
                FatalIOErrorInFunction(pd)
                    << "Patch '" << patch.c_str() << "' in " << pd.name()
                    << " (entry '"
                    << (patch == ps.faceSet ? "patch" : "targetPatch")
                    << "') is an empty or wedge patch (the front and back"
                    << " of the 2D mesh): it has no edges in the plane and"
                    << " cannot carry contact. Use a patch on the outline"
                    << " of the region" << exit(FatalIOError);
            }
            if (!faceSets.count(patch)
             || solid_.mesh().boundaryMesh().findPatchID(patch) < 0)
            {
                FatalIOErrorInFunction(pd)
                    << "Unknown patch '" << patch.c_str() << "' of solid"
                    << " region '" << solid_.name() << "' in " << pd.name()
                    << " (entry '"
                    << (patch == ps.faceSet ? "patch" : "targetPatch")
                    << "')" << nl
                    << "    Patches: " << solid_.mesh().boundaryMesh().names()
                    << exit(FatalIOError);
            }
        }
        if (!(ps.friction >= 0))
        {
            FatalIOErrorInFunction(pd)
                << "Entry 'friction' in " << pd.name() << " must be >= 0,"
                << " got " << ps.friction << exit(FatalIOError);
        }
        pairs.push_back(ps);
    }
    if (pairs.empty())
    {
        FatalIOErrorInFunction(pdict)
            << "No contact pairs in " << pdict.name() << exit(FatalIOError);
    }

    checkOrientation(tools, pairs);

    form::contactControls controls;
    controls.epsilonN = dict_.getOrDefault<scalar>("epsilonN", 0);
    controls.epsilonT = dict_.getOrDefault<scalar>("epsilonT", 0);
    controls.stiffness = dict_.getOrDefault<scalar>("stiffness", 0);
    controls.frictionLaw =
        dict_.getOrDefault<word>("frictionLaw", controls.frictionLaw);
    controls.frictionAugmentation = dict_.getOrDefault<scalar>
    (
        "frictionAugmentation", controls.frictionAugmentation
    );
    controls.maxStatusChanges =
        dict_.getOrDefault<label>("maxStatusChanges", 8);
    if (controls.maxStatusChanges < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'maxStatusChanges' in " << dict_.name()
            << " must be >= 1" << exit(FatalIOError);
    }

    // Young's modulus of the contactor material from its elastic moduli
    const form::material& mat = solid_.material();
    const scalar K = mat.bulkModulus(), G = mat.shearModulus();
    const scalar E = 9*K*G/(3*K + G);
    try
    {
        model_ = std::make_shared<form::contactModel>
        (
            solid_.feMesh().feMesh(), solid_.analysis(), E, tools, pairs,
            controls
        );
        // (the shells' checks of the pairs run here: a pair on a sheet's
        // side, on triangles, against a deformable target)
        solid_.model().setContact(model_);
    }
    catch (const form::inputError& e)
    {
        fatalInput(dict_, e);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::string Foam::solidContact::describe() const
{
    return model_->describe();
}


void Foam::solidContact::releaseTools
(
    const wordList& tools,
    const dictionary& dict,
    scalar t0,
    scalar t1
)
{
    for (const word& t : tools)
    {
        toolIndex(t, dict);
        if (model_->released(t)) continue;
        solid_.model().releaseTool(t, t0, t1);
    }
}


Foam::scalar Foam::solidContact::toolForce
(
    const word& tool,
    label component,
    const dictionary& dict
) const
{
    toolIndex(tool, dict);
    return model_->toolForce(tool)(component);
}


Foam::scalar Foam::solidContact::toolPosition
(
    const word& tool,
    label component,
    scalar t,
    const dictionary& dict
) const
{
    toolIndex(tool, dict);
    return model_->toolTranslation(tool, t)(component);
}


bool Foam::solidContact::write(const word& timeName, scalar t) const
{
    const fileName dir = runTime_.path()/"postProcessing"/"contact"/timeName;
    mkDir(dir);
    const form::vecX& U = solid_.model().U();
    bool ok = true;
    for (const form::contactPairSpec& ps : model_->pairs())
    {
        std::ofstream os(dir/(ps.name + ".dat"));
        os.precision(10);
        os  << "# pair " << ps.name << ": patch " << ps.faceSet
            << (ps.tool.empty()
                ? ", target patch " + ps.targetFaceSet : ", tool " + ps.tool)
            << ", time " << t << '\n'
            << (
                   solid_.feMesh().feMesh().nDim == 3
                 ? "# node X Y Z x y z gap"
                 : "# node X Y x y gap"
               )
            << " normalForce tangentialForce weight"
               " pressure shear slip closed slipRate\n";
        const form::feMesh& fe = solid_.feMesh().feMesh();
        for (const auto& r : model_->pairResults(ps.name, U, t))
        {
            os  << r.node;
            for (int i = 0; i < fe.nDim; ++i) os << ' ' << fe.X(r.node, i);
            for (int i = 0; i < fe.nDim; ++i) os << ' ' << r.x(i);
            os  << ' ' << r.gap << ' '
                << r.normalForce << ' ' << r.tangentialForce << ' '
                << r.weight << ' ' << r.pressure << ' ' << r.shear << ' '
                << r.slip << ' ' << (r.closed ? 1 : 0) << ' ' << r.slipRate
                << '\n';
        }
        os.flush();
        ok = bool(os) && ok;
    }
    std::ofstream os(dir/"tools.dat");
    os.precision(10);
    if (solid_.analysis() == form::analysisType::solid3D)
    {
        // 3D: each tool's surface type, translation and force
        os << "# tool type dx dy dz Fx Fy Fz\n";
        for (const form::rigidToolSpec& tool : model_->tools())
        {
            const form::vec3 d = model_->toolTranslation(tool.name, t);
            const form::vec3 F = model_->toolForce(tool.name);
            os << tool.name << ' ' << tool.surface->type() << ' ' << d(0)
               << ' ' << d(1) << ' ' << d(2) << ' ' << F(0) << ' ' << F(1)
               << ' ' << F(2) << '\n';
        }
        os.flush();
        return bool(os) && ok;
    }
    os << "# tool x y (current outline)\n";
    for (const form::rigidToolSpec& tool : model_->tools())
    {
        const Eigen::Vector2d d =
            model_->toolTranslation(tool.name, t).head<2>();
        const double ds = tool.profile->length()/2000;
        for (const Eigen::Vector2d& p : tool.profile->sample(ds))
        {
            os << tool.name << ' ' << p(0) + d(0) << ' ' << p(1) + d(1)
               << '\n';
        }
        os << "\n\n";
    }
    os.flush();
    return bool(os) && ok;
}


void Foam::solidContact::reportUntouched() const
{
    for (const form::rigidToolSpec& tool : model_->tools())
    {
        if (!model_->touched(tool.name))
        {
            WarningInFunction
                << "Tool '" << tool.name << "' of " << dict_.name()
                << " never touched the body: check its profile, its motion"
                << " and the patches of its pairs" << endl;
        }
    }
}


// ************************************************************************* //
