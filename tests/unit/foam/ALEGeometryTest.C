/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The fluid's geometry as a function of the points (ALEGeometry.H):
    - recomputed from the points it equals OpenFOAM's fvMesh geometry
      (face centres and areas, cell centres and volumes, weights,
      non-orthogonal delta coefficients and correction vectors, boundary
      normals, deltas and delta coefficients) and face::sweptVol to
      round-off, on a skewed plane mesh, a wedge with prisms on its axis
      (triangular faces) and a randomly distorted 3D box, after moving
      its points;
    - evaluated with dual numbers it carries derivatives with respect to
      the points that agree with central differences of the scalar
      geometry along random point motions (every quantity, scaled per
      quantity).
\*---------------------------------------------------------------------------*/
#include "ALEGeometry.H"
#include "scratchCase.H"
#include "fluidTestMeshes.H"
#include "../fdCheck.H"
#include <gtest/gtest.h>
#include <map>
#include <random>

using namespace form;
using namespace form::test;

namespace
{

const std::string box3D =
    "vertices ((0 0 0) (1 0 0) (1 1 0) (0 1 0)"
    " (0 0 1) (1 0 1) (1 1 1) (0 1 1));\n"
    "blocks (hex (0 1 2 3 4 5 6 7) (3 3 2) simpleGrading (1 1 1));\n"
    "boundary (\n"
    " walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)"
    " (0 3 2 1) (4 5 6 7)); }\n);\n";

const std::string zeroU =
    "internalField uniform (0 0 0);\nboundaryField { \".*\" { type noSlip; }"
    " frontAndBack { type empty; } axis { type empty; }"
    " front { type wedge; } back { type wedge; } }\n";
const std::string zeroP =
    "internalField uniform 0;\nboundaryField { \".*\" { type zeroGradient; }"
    " frontAndBack { type empty; } axis { type empty; }"
    " front { type wedge; } back { type wedge; } }\n";

// The files of a scratch fluid case on a blockMeshDict (the geometry does
// not depend on the schemes or the conditions)
std::map<std::string, std::string> geometryCase
(
    const std::string& blockMesh,
    const std::string& U = zeroU,
    const std::string& p = zeroP
)
{
    return fluidCaseFiles("fluid", blockMesh, "Euler", "Gauss linear",
                          "Gauss linear corrected", U, p);
}

// Largest |a - b| over a list, relative to the largest |b|
template<class A, class B>
double relDiff(const A& a, const B& b)
{
    double d = 0, s = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        d = std::max(d, double(Foam::mag(a[i] - b[i])));
        s = std::max(s, double(Foam::mag(b[i])));
    }
    return s > 0 ? d/s : d;
}

struct meshCase
{
    const char* name;
    const std::string* blockMesh;
};

} // namespace


TEST(ALEGeometry, fromPointsEqualsTheFvMeshGeometry)
{
    for (const meshCase& mc :
        {meshCase{"skewed", &skewedMesh}, meshCase{"wedge", &wedgeAxisMesh},
         meshCase{"box3D", &box3D}})
    {
        const std::string bc = std::string(mc.name) == "box3D"
          ? "internalField uniform (0 0 0);\nboundaryField { walls { type noSlip; } }\n"
          : zeroU;
        const std::string bp = std::string(mc.name) == "box3D"
          ? "internalField uniform 0;\nboundaryField { walls { type zeroGradient; } }\n"
          : zeroP;
        scratchCase c
        (
            geometryCase(*mc.blockMesh, bc, bp),
            {"fluid"}
        );
        Foam::fvMesh& mesh = c.mesh();
        const Foam::pointField x0(mesh.points());
        // a moved mesh (the fvMesh recomputes its geometry)
        const Foam::pointField x1(x0 + randomMotion(mesh, 0.05, 7));
        mesh.movePoints(x1);
        Foam::ALEGeometry<Foam::scalar> g0, g1;
        g0.fromMesh(mesh);
        g1.fromPoints(mesh, std::vector<Foam::vector>(x1.begin(), x1.end()));
        const double tol = 1e-13;
        EXPECT_LT(relDiff(g1.Cf, g0.Cf), tol) << mc.name;
        EXPECT_LT(relDiff(g1.Sf, g0.Sf), tol) << mc.name;
        EXPECT_LT(relDiff(g1.C, g0.C), tol) << mc.name;
        EXPECT_LT(relDiff(g1.V, g0.V), tol) << mc.name;
        EXPECT_LT(relDiff(g1.w, g0.w), tol) << mc.name;
        EXPECT_LT(relDiff(g1.dc, g0.dc), tol) << mc.name;
        EXPECT_LT(relDiff(g1.kv, g0.kv), 1e-12) << mc.name;
        // boundary faces of non-empty patches
        const Foam::label nI = mesh.nInternalFaces();
        double dn = 0, dd = 0, ddc = 0, dsv = 0, sv = 0;
        forAll(mesh.boundary(), patchi)
        {
            const Foam::fvPatch& fp = mesh.boundary()[patchi];
            forAll(fp, i)
            {
                const Foam::label b = fp.start() + i - nI;
                dn = std::max(dn, double(Foam::mag(g1.nf[b] - g0.nf[b])));
                dd = std::max(dd, double(Foam::mag(g1.delta[b] - g0.delta[b]))
                                 /Foam::mag(g0.delta[b]));
                ddc = std::max(ddc, std::abs(g1.dcb[b] - g0.dcb[b])/g0.dcb[b]);
            }
        }
        EXPECT_LT(dn, tol) << mc.name;
        EXPECT_LT(dd, 1e-12) << mc.name;
        EXPECT_LT(ddc, 1e-12) << mc.name;
        // swept volumes
        const std::vector<Foam::vector> x1v(x1.begin(), x1.end());
        forAll(mesh.faces(), f)
        {
            const double a = mesh.faces()[f].sweptVol(x0, x1);
            const double b = Foam::sweptVolume<Foam::scalar>(mesh.faces()[f], x0, x1v);
            dsv = std::max(dsv, std::abs(a - b));
            sv = std::max(sv, std::abs(a));
        }
        EXPECT_GT(sv, 0) << mc.name;
        EXPECT_LT(dsv, 1e-13*sv) << mc.name;
        std::cout << "    " << mc.name << ": " << mesh.nCells() << " cells, "
                  << mesh.nFaces() << " faces; geometry from points = fvMesh's"
                  << " to round-off (swept volumes " << dsv/sv << ")\n";
    }
}


TEST(ALEGeometry, dualDerivativesAgreeWithCentralDifferences)
{
    using D = form::dual<2>;
    for (const meshCase& mc :
        {meshCase{"skewed", &skewedMesh}, meshCase{"wedge", &wedgeAxisMesh}})
    {
        scratchCase c
        (
            geometryCase(*mc.blockMesh),
            {"fluid"}
        );
        Foam::fvMesh& mesh = c.mesh();
        const Foam::pointField x0(mesh.points());
        const Foam::pointField x1(x0 + randomMotion(mesh, 0.05, 11));
        // two directions of motion at once
        const Foam::vectorField m0(randomMotion(mesh, 1, 12));
        const Foam::vectorField m1(randomMotion(mesh, 1, 13));
        std::vector<Foam::dualVector<D>> xd(x1.size());
        forAll(x1, p)
        {
            for (Foam::direction k = 0; k < 3; ++k)
            {
                D v(x1[p][k]);
                v.d[0] = m0[p][k];
                v.d[1] = m1[p][k];
                (k == 0 ? xd[p].x : k == 1 ? xd[p].y : xd[p].z) = v;
            }
        }
        Foam::ALEGeometry<D> gd;
        gd.fromPoints(mesh, xd);
        const double h = 1e-6;
        for (int k = 0; k < 2; ++k)
        {
            const Foam::vectorField& m = k ? m1 : m0;
            Foam::ALEGeometry<Foam::scalar> gp, gm;
            const Foam::pointField xp(x1 + h*m), xm(x1 - h*m);
            gp.fromPoints(mesh, std::vector<Foam::vector>(xp.begin(), xp.end()));
            gm.fromPoints(mesh, std::vector<Foam::vector>(xm.begin(), xm.end()));
            // the largest difference per quantity, relative to the
            // quantity's largest derivative
            const auto checkS = [&](const char* what, const std::vector<D>& a,
                                    const std::vector<double>& p,
                                    const std::vector<double>& q)
            {
                double e = 0, s = 0;
                for (std::size_t i = 0; i < a.size(); ++i)
                {
                    const double fd = (p[i] - q[i])/(2*h);
                    e = std::max(e, std::abs(a[i].d[k] - fd));
                    s = std::max(s, std::abs(fd));
                }
                EXPECT_GT(s, 0) << mc.name << ' ' << what;
                EXPECT_TRUE(test::fdError(std::string("fluid geometry ") + what, e/s, 1e-8))
                    << mc.name;
            };
            const auto checkV = [&](const char* what,
                                    const std::vector<Foam::dualVector<D>>& a,
                                    const std::vector<Foam::vector>& p,
                                    const std::vector<Foam::vector>& q)
            {
                std::vector<D> as;
                std::vector<double> ps, qs;
                for (std::size_t i = 0; i < a.size(); ++i)
                {
                    for (Foam::direction j = 0; j < 3; ++j)
                    {
                        as.push_back(a[i][j]);
                        ps.push_back(p[i][j]);
                        qs.push_back(q[i][j]);
                    }
                }
                checkS(what, as, ps, qs);
            };
            checkV("Cf", gd.Cf, gp.Cf, gm.Cf);
            checkV("Sf", gd.Sf, gp.Sf, gm.Sf);
            checkS("magSf", gd.magSf, gp.magSf, gm.magSf);
            checkV("C", gd.C, gp.C, gm.C);
            checkS("V", gd.V, gp.V, gm.V);
            checkS("w", gd.w, gp.w, gm.w);
            checkS("dc", gd.dc, gp.dc, gm.dc);
            checkV("kv", gd.kv, gp.kv, gm.kv);
            checkV("nf", gd.nf, gp.nf, gm.nf);
            checkV("delta", gd.delta, gp.delta, gm.delta);
            checkS("dcb", gd.dcb, gp.dcb, gm.dcb);
            // swept volumes from x0
            std::vector<D> sd;
            std::vector<double> sp, sm;
            const std::vector<Foam::vector> xpv(xp.begin(), xp.end());
            const std::vector<Foam::vector> xmv(xm.begin(), xm.end());
            forAll(mesh.faces(), f)
            {
                sd.push_back(Foam::sweptVolume<D>(mesh.faces()[f], x0, xd));
                sp.push_back(Foam::sweptVolume<Foam::scalar>(mesh.faces()[f], x0, xpv));
                sm.push_back(Foam::sweptVolume<Foam::scalar>(mesh.faces()[f], x0, xmv));
            }
            checkS("swept volume", sd, sp, sm);
        }
    }
}


// The points as functions of variables, in one of three ways (the faces'
// geometry and swept volumes in dense local derivatives over a face's
// variables take dual<4>, dual<12> or sparse arithmetic by their count):
enum class seeding
{
    coordinates,    // every coordinate a variable 3p + c: 12 per quadrilateral
    planarUnits,    // the points of one (x, y) share 2 variables, z fixed:
                    // 4 per face of a planar mesh (the ALE fluid's seeding)
    shared          // 3p + c plus a variable per pair of points: 14-16 per
                    // quadrilateral, more than dense local derivatives hold
};

TEST(ALEGeometry, sparseGradientsAreTheDualDerivatives)
{
    // The sparse gradients, contracted with a direction mv in the space of
    // the variables, are the directional derivatives along mv (dual<1>),
    // for every quantity and the swept volumes
    using D = form::dual<1>;
    using S = form::sparseDual;
    for (const std::string* mesh : {&skewedMesh, &wedgeAxisMesh})
    for
    (
        const seeding how :
        {seeding::coordinates, seeding::planarUnits, seeding::shared}
    )
    {
        SCOPED_TRACE("seeding " + std::to_string(int(how)));
        scratchCase c
        (
            geometryCase(*mesh),
            {"fluid"}
        );
        const Foam::fvMesh& fm = c.mesh();
        const Foam::pointField x0(fm.points());
        const Foam::pointField x1(x0 + randomMotion(fm, 0.05, 21));
        std::mt19937 gen(22);
        std::uniform_real_distribution<double> uni(-1, 1);
        std::vector<double> mv(4*x1.size());
        for (double& v : mv) v = uni(gen);
        // planar units: the points of one in-plane position
        std::map<std::pair<long, long>, int> unitOf;
        std::vector<Foam::dualVector<D>> xd(x1.size());
        std::vector<Foam::dualVector<S>> xs(x1.size());
        forAll(x1, p)
        {
            const std::pair<long, long> key
            (
                std::lround(1e9*x0[p].x()), std::lround(1e9*x0[p].y())
            );
            const int u = unitOf.emplace(key, int(unitOf.size())).first->second;
            for (Foam::direction k = 0; k < 3; ++k)
            {
                S v(x1[p][k]);
                if (how == seeding::coordinates)
                {
                    v.add(3*p + k, 1);
                }
                else if (how == seeding::planarUnits)
                {
                    if (k < 2) v.add(2*u + k, 1);
                }
                else
                {
                    v.add(3*p + k, 1).add(3*x1.size() + p/2, 0.5 + k);
                }
                D w(v.v);
                for (int j = 0; j < v.size(); ++j)
                {
                    w.d[0] += v.derivative(j)*mv[v.index(j)];
                }
                (k == 0 ? xd[p].x : k == 1 ? xd[p].y : xd[p].z) = w;
                (k == 0 ? xs[p].x : k == 1 ? xs[p].y : xs[p].z) = v;
            }
        }
        Foam::ALEGeometry<D> gd;
        Foam::ALEGeometry<S> gs;
        gd.fromPoints(fm, xd);
        gs.fromPoints(fm, xs);
        double worst = 0;
        const auto along = [&](const S& a, const D& b)
        {
            double v = 0;
            for (int j = 0; j < a.size(); ++j)
            {
                v += a.derivative(j)*mv[a.index(j)];
            }
            worst = std::max(worst, std::abs(a.v - b.v)/(1 + std::abs(b.v)));
            worst = std::max(worst, std::abs(v - b.d[0])/(1 + std::abs(b.d[0])));
        };
        const auto alongV = [&](const Foam::dualVector<S>& a, const Foam::dualVector<D>& b)
        {
            along(a.x, b.x); along(a.y, b.y); along(a.z, b.z);
        };
        for (std::size_t f = 0; f < gd.Cf.size(); ++f)
        {
            alongV(gs.Cf[f], gd.Cf[f]);
            alongV(gs.Sf[f], gd.Sf[f]);
            along(gs.magSf[f], gd.magSf[f]);
            along
            (
                Foam::sweptVolumeSparse(fm.faces()[f], x0, xs),
                Foam::sweptVolume<D>(fm.faces()[f], x0, xd)
            );
        }
        for (std::size_t i = 0; i < gd.C.size(); ++i)
        {
            alongV(gs.C[i], gd.C[i]);
            along(gs.V[i], gd.V[i]);
        }
        for (std::size_t f = 0; f < gd.w.size(); ++f)
        {
            along(gs.w[f], gd.w[f]);
            along(gs.dc[f], gd.dc[f]);
            alongV(gs.kv[f], gd.kv[f]);
        }
        for (std::size_t b = 0; b < gd.nf.size(); ++b)
        {
            alongV(gs.nf[b], gd.nf[b]);
            alongV(gs.delta[b], gd.delta[b]);
            along(gs.dcb[b], gd.dcb[b]);
        }
        std::cout << "    sparse gradients against dual<1>: largest relative"
                  << " difference " << worst << '\n';
        EXPECT_LT(worst, 1e-12);
    }
}
