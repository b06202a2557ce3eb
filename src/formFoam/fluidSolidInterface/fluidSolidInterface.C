/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The geometry of the fluid-solid interface (fluidSolidInterface.H):
    projection, interpolations, the mesh motion's units and equations; the
    kinematic and dynamic conditions. The mesh motion's member functions:
    fluidSolidInterfaceMesh.C.
\*---------------------------------------------------------------------------*/
#include "fluidSolidInterface.H"
#include "quadShape.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include <algorithm>
#include <map>
#include <tuple>
#include <set>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::fluidSolidInterface::solidPoint Foam::fluidSolidInterface::project
(
    const Eigen::Vector2d& q,
    const std::vector<form::feFace>& edges
) const
{
    const form::matX& X = solid_.feMesh().X;
    solidPoint best;
    best.gap = GREAT;
    form::vecX N, dN;
    for (const form::feFace& e : edges)
    {
        const int n = int(e.nodes.size());
        const auto at = [&](double xi, Eigen::Vector2d& x, Eigen::Vector2d& dx)
        {
            form::lineShape(n, xi, N, dN);
            x.setZero();
            dx.setZero();
            for (int a = 0; a < n; ++a)
            {
                x += N(a)*X.row(e.nodes[a]).transpose();
                dx += dN(a)*X.row(e.nodes[a]).transpose();
            }
        };
        // Closest point: the best of a sampling, refined by Gauss-Newton
        Eigen::Vector2d x, dx;
        double xi = -1, d2 = GREAT;
        for (int k = 0; k <= 20; ++k)
        {
            const double s = -1 + 0.1*k;
            at(s, x, dx);
            if ((x - q).squaredNorm() < d2)
            {
                d2 = (x - q).squaredNorm();
                xi = s;
            }
        }
        for (int it = 0; it < 20; ++it)
        {
            at(xi, x, dx);
            const double step = -(x - q).dot(dx)/max(dx.squaredNorm(), VSMALL);
            xi = std::min(1.0, std::max(-1.0, xi + step));
            if (std::abs(step) < 1e-14) break;
        }
        at(xi, x, dx);
        const double gap = (x - q).norm();
        if (gap < best.gap)
        {
            best.gap = gap;
            form::lineShape(n, xi, N, dN);
            best.nodes = e.nodes;
            best.N.assign(N.data(), N.data() + n);
        }
    }
    return best;
}


Foam::fluidSolidInterface::fluidSolidInterface
(
    const fvMesh& fluid,
    const pointField& referencePoints,
    const wordList& fluidPatches,
    const polyMeshToFeMesh& solid,
    const wordList& solidPatches,
    const wordList& slipPatches,
    const fileName& file,
    const meshDiffusivity& diffusivity
)
:
    fluid_(fluid),
    solid_(solid),
    dofMap_(form::dofMap::of(solid.feMesh())),
    diffusivity_(diffusivity),
    points0_(referencePoints)
{
    const polyBoundaryMesh& bm = fluid_.boundaryMesh();
    const word& region = fluid_.name();
    const bool axi = solid_.proj() == polyMeshToFeMesh::projection::wedge;

    // The solid's wetted edges
    std::vector<form::feFace> edges;
    for (const word& sp : solidPatches)
    {
        const auto it = solid_.feMesh().faceSets.find(sp);
        if (it != solid_.feMesh().faceSets.end())
        {
            edges.insert(edges.end(), it->second.begin(), it->second.end());
        }
    }

    // In-plane coordinates and directions of every point
    const label nP = points0_.size();
    List<Eigen::Vector2d> q(nP);
    er_.setSize(nP);
    ez_.setSize(nP);
    forAll(points0_, p)
    {
        q[p] = solid_.toPlane(points0_[p]);
        er_[p] = solid_.toSpace(points0_[p], Eigen::Vector2d(1, 0));
        ez_[p] = solid_.toSpace(points0_[p], Eigen::Vector2d(0, 1));
    }
    const scalar L = mag(boundBox(points0_).span());
    const scalar tol = 1e-9*L;

    // Interface faces and points
    std::map<label, label> pointTo2D;    // 3D point -> interface point
    std::vector<Eigen::Vector2d> q2D;
    const auto interfacePoint = [&](label p)
    {
        const auto it = pointTo2D.find(p);
        if (it != pointTo2D.end()) return it->second;
        for (std::size_t i = 0; i < q2D.size(); ++i)
        {
            if ((q2D[i] - q[p]).norm() < tol)
            {
                pointTo2D[p] = label(i);
                pointIds_[i].append(p);
                return label(i);
            }
        }
        q2D.push_back(q[p]);
        pointIds_.append(labelList(1, p));
        pointTo2D[p] = label(q2D.size() - 1);
        return label(q2D.size() - 1);
    };
    std::vector<scalar> pointFaceLength;
    // The interface faces' in-plane segments (the diffusivity's distance)
    std::vector<std::array<Eigen::Vector2d, 2>> segments;
    for (const word& name : fluidPatches)
    {
        const label patchi = bm.findPatchID(name);
        if (patchi < 0)
        {
            FatalErrorInFunction
                << "Entry 'fluidInterface' in " << file.c_str() << ": '" << name
                << "' is not a patch of fluid region '" << region << "'"
                << nl << "    Patches: " << bm.names() << exit(FatalError);
        }
        patches_.append(patchi);
        const polyPatch& pp = bm[patchi];
        forAll(pp, i)
        {
            const face& f = pp[i];
            // The face's in-plane segment: its two distinct points
            labelList ends;
            for (const label p : f)
            {
                const label k = interfacePoint(p);
                if (!ends.found(k)) ends.append(k);
            }
            if (ends.size() != 2)
            {
                FatalErrorInFunction
                    << "Fluid region '" << region << "', patch '" << name
                    << "' (" << file.c_str() << ", fluidInterface): face " << i
                    << " is not an edge of the 2D mesh (" << ends.size()
                    << " distinct in-plane points); the interface needs a"
                    << " one-cell-thick plane or wedge fluid mesh"
                    << exit(FatalError);
            }
            const scalar len = (q2D[ends[0]] - q2D[ends[1]]).norm();
            minFaceLength_ = min(minFaceLength_, len);
            segments.push_back({q2D[ends[0]], q2D[ends[1]]});
            pointFaceLength.resize(q2D.size(), GREAT);
            for (const label k : ends)
            {
                pointFaceLength[k] = min(pointFaceLength[k], len);
            }
            faces_.append(pp.start() + i);
            // The face's mean of the solid's shape functions: the face is
            // cut where solid nodes lie on it (the ends of the wetted
            // edges), and a 3-point Gauss rule on each piece, each point
            // projected (exact for straight quadratic edges)
            const Eigen::Vector2d qa = q2D[ends[0]], qb = q2D[ends[1]];
            const Eigen::Vector2d ab = qb - qa;
            std::vector<double> cuts{0.0, 1.0};
            for (const form::feFace& e : edges)
            {
                for (int k = 0; k < 2; ++k)
                {
                    const Eigen::Vector2d x =
                        solid_.feMesh().X.row(e.nodes[k]).transpose();
                    const double t = (x - qa).dot(ab)/ab.squaredNorm();
                    if (t <= 1e-9 || t >= 1 - 1e-9) continue;
                    if ((qa + t*ab - x).norm() < 1e-3*len + tol)
                    {
                        cuts.push_back(t);
                    }
                }
            }
            std::sort(cuts.begin(), cuts.end());
            cuts.erase
            (
                std::unique
                (
                    cuts.begin(), cuts.end(),
                    [](double a, double b) { return b - a < 1e-9; }
                ),
                cuts.end()
            );
            const double g = std::sqrt(0.6);
            const double xg[3] = {-g, 0, g}, wg[3] = {5/18.0, 8/18.0, 5/18.0};
            std::map<int, double> weights;
            double wsum = 0;
            solidPoint sp;
            for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece)
            {
                const double t0 = cuts[piece], t1 = cuts[piece + 1];
                for (int k = 0; k < 3; ++k)
                {
                    const double t = 0.5*(t0 + t1) + 0.5*(t1 - t0)*xg[k];
                    const Eigen::Vector2d c = qa + t*ab;
                    const solidPoint gp = project(c, edges);
                    if (gp.gap > 1e-3*len + tol)
                    {
                        FatalErrorInFunction
                            << "Fluid region '" << region << "', patch '"
                            << name << "' (" << file.c_str()
                            << ", fluidInterface): the point (" << c(0)
                            << ' ' << c(1) << ") of face " << i << " is "
                            << gp.gap << " away from the solid's wetted"
                            << " patches " << solidPatches << " (entry"
                            << " 'interface'); the fluid and solid meshes"
                            << " must share the interface" << exit(FatalError);
                    }
                    sp.gap = max(sp.gap, gp.gap);
                    // Axisymmetric: the area element is 2 pi r ds
                    const double wr = (t1 - t0)*wg[k]*(axi ? c(0) : 1.0);
                    wsum += wr;
                    for (std::size_t a = 0; a < gp.nodes.size(); ++a)
                    {
                        weights[gp.nodes[a]] += wr*gp.N[a];
                    }
                }
            }
            for (const auto& nw : weights)
            {
                sp.nodes.push_back(nw.first);
                sp.N.push_back(nw.second/wsum);
            }
            faceInterp_.push_back(sp);
            const point& Cf = pp.faceCentres()[i];
            faceEr_.append(solid_.toSpace(Cf, Eigen::Vector2d(1, 0)));
            faceEz_.append(solid_.toSpace(Cf, Eigen::Vector2d(0, 1)));
        }
    }
    for (std::size_t i = 0; i < q2D.size(); ++i)
    {
        solidPoint sp = project(q2D[i], edges);
        if (sp.gap > 1e-3*pointFaceLength[i] + tol)
        {
            FatalErrorInFunction
                << "Fluid region '" << region << "' (" << file.c_str()
                << ", fluidInterface): the interface point (" << q2D[i](0)
                << ' ' << q2D[i](1) << ") is " << sp.gap << " away from the"
                << " solid's wetted patches " << solidPatches << " (entry"
                << " 'interface'); the fluid and solid meshes must share the"
                << " interface" << exit(FatalError);
        }
        pointInterp_.push_back(sp);
    }

    // Dirichlet points of the mesh motion per component: -1 free,
    // -2 fixed (zero), k >= 0 interface point k
    labelList kind[2] = {labelList(nP, -1), labelList(nP, -1)};
    forAll(bm, patchi)
    {
        const polyPatch& pp = bm[patchi];
        if (isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp)) continue;
        if (patches_.found(patchi)) continue;
        const bool slip = slipPatches.found(pp.name());
        forAll(pp, i)
        {
            bool fix[2] = {true, true};
            if (slip)
            {
                // Slide along the patch if its normal is in-plane r or z
                const vector n = pp.faceNormals()[i];
                const point& c = pp.faceCentres()[i];
                const vector e0 = solid_.toSpace(c, Eigen::Vector2d(1, 0));
                const vector e1 = solid_.toSpace(c, Eigen::Vector2d(0, 1));
                if (mag(n & e0) > 0.999) fix[1] = false;
                else if (mag(n & e1) > 0.999) fix[0] = false;
            }
            for (const label p : pp[i])
            {
                for (label c = 0; c < 2; ++c)
                {
                    if (fix[c]) kind[c][p] = -2;
                }
            }
        }
    }
    forAll(points0_, p)
    {
        // On the axis of a wedge: no radial motion
        if (mag(er_[p]) < 0.5) kind[0][p] = -2;
    }
    for (const auto& pk : pointTo2D)
    {
        kind[0][pk.first] = pk.second;
        kind[1][pk.first] = pk.second;
    }

    // Motion units: the points joined by mesh edges without in-plane
    // length (the copies of one in-plane point), split where their kinds
    // differ
    const edgeList& meshEdges = fluid_.edges();
    labelList root(identity(nP));
    const auto find = [&](label p)
    {
        while (root[p] != p) p = root[p] = root[root[p]];
        return p;
    };
    for (const edge& e : meshEdges)
    {
        if ((q[e[0]] - q[e[1]]).norm() < tol)
        {
            root[find(e[0])] = find(e[1]);
        }
    }
    std::map<std::tuple<label, label, label>, label> unitOf;
    labelList pointUnit(nP, -1);
    for (label p = 0; p < nP; ++p)
    {
        const auto key = std::make_tuple(find(p), kind[0][p], kind[1][p]);
        auto it = unitOf.find(key);
        if (it == unitOf.end())
        {
            it = unitOf.emplace(key, units_.size()).first;
            units_.append(labelList());
            for (label c = 0; c < 2; ++c)
            {
                const label k = kind[c][p];
                unitKind_[c].append(k == -1 ? freeUnit : k == -2 ? fixedUnit : k);
                unknown_[c].append(k == -1 ? nUnknowns_[c]++ : -1);
            }
        }
        units_[it->second].append(p);
        pointUnit[p] = it->second;
    }

    buildMeshEquations(q, pointUnit, segments, q2D.size(), tol, file);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField>
Foam::fluidSolidInterface::faceVelocities(const form::vecX& v) const
{
    tmp<vectorField> tu(new vectorField(faces_.size(), Zero));
    vectorField& u = tu.ref();
    forAll(faces_, j)
    {
        const solidPoint& sp = faceInterp_[j];
        scalar vr = 0, vz = 0;
        for (std::size_t a = 0; a < sp.nodes.size(); ++a)
        {
            vr += sp.N[a]*v(dofMap_.dof(sp.nodes[a], 0));
            vz += sp.N[a]*v(dofMap_.dof(sp.nodes[a], 1));
        }
        u[j] = vr*faceDirection(j, 0) + vz*faceDirection(j, 1);
    }
    return tu;
}


void Foam::fluidSolidInterface::addForces
(
    const vectorField& F,
    scalar factor,
    form::vecX& f
) const
{
    forAll(faces_, j)
    {
        const solidPoint& sp = faceInterp_[j];
        const scalar Fr = factor*(F[j] & faceDirection(j, 0));
        const scalar Fz = factor*(F[j] & faceDirection(j, 1));
        for (std::size_t a = 0; a < sp.nodes.size(); ++a)
        {
            f(dofMap_.dof(sp.nodes[a], 0)) += sp.N[a]*Fr;
            f(dofMap_.dof(sp.nodes[a], 1)) += sp.N[a]*Fz;
        }
    }
}


std::vector<int> Foam::fluidSolidInterface::dofs() const
{
    std::set<int> s;
    for (const auto* list : {&faceInterp_, &pointInterp_})
    {
        for (const solidPoint& sp : *list)
        {
            for (const int a : sp.nodes)
            {
                s.insert(dofMap_.dof(a, 0));
                s.insert(dofMap_.dof(a, 1));
            }
        }
    }
    return std::vector<int>(s.begin(), s.end());
}


std::string Foam::fluidSolidInterface::describe() const
{
    scalar gap = 0;
    for (const auto* list : {&faceInterp_, &pointInterp_})
    {
        for (const solidPoint& sp : *list) gap = max(gap, sp.gap);
    }
    std::ostringstream os;
    os  << "interface: " << faces_.size() << " fluid faces, "
        << pointIds_.size() << " interface points projected onto the solid"
        << " (largest distance " << gap << "); mesh motion: harmonic"
        << " (diffusivity " << diffusivity_.type;
    if (diffusivity_.type == "inverseDistance")
    {
        os  << ", exponent " << diffusivity_.exponent;
    }
    os  << "; discrete Laplace equations of " << nUnknowns_[0] << '/'
        << nUnknowns_[1] << " free points (r/z) in the Newton system)";
    return os.str();
}


// ************************************************************************* //
