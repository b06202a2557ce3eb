/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The shape derivative of the ALE fluid (ALENavierStokesShape.C): the
    derivatives of the residual and of the boundary forces with respect to
    every in-plane coordinate of every mesh point, computed with dual
    numbers (exact), against central differences of the residual
    evaluated on the moved points (and equal to those of sparse dual
    numbers, the production path, to round-off), scaled per row (max_j |J_ij - J_fd,ij|
    / max_j |J_ij|: a row's small entries count as much as its large ones,
    so the mass rows of a compressible fluid, whose scale is the bulk
    modulus, do not hide errors of the momentum rows). The residual on the
    points also equals the residual the Newton iteration assembles on the
    fvMesh (to round-off). Cases: the transient compressible channel on
    a skewed mesh (linear convection, corrected Laplacian, Rhie-Chow at a
    fixed-pressure outlet), the steady upwind uncorrected one, and an
    incompressible axisymmetric wedge with prisms on its axis, a slip
    wall, an inlet and a pressure outlet.
\*---------------------------------------------------------------------------*/
#include "ALENavierStokes.H"
#include "scratchCase.H"
#include "fluidTestMeshes.H"
#include "../fdCheck.H"
#include <gtest/gtest.h>
#include <random>

using namespace form;
using namespace form::test;

namespace
{

// The residual and the boundary forces as one vector (the rows)
template<class T, class F>
vecX rows(const Foam::ALEResidual<T>& a, F get)
{
    vecX v(a.r.size() + 3*a.Fw.size());
    for (std::size_t i = 0; i < a.r.size(); ++i) v(i) = get(a.r[i]);
    for (std::size_t b = 0; b < a.Fw.size(); ++b)
    {
        v(a.r.size() + 3*b) = get(a.Fw[b].x);
        v(a.r.size() + 3*b + 1) = get(a.Fw[b].y);
        v(a.r.size() + 3*b + 2) = get(a.Fw[b].z);
    }
    return v;
}

// The points x moving along m: dual<1> numbers
std::vector<Foam::dualVector<dual<1>>> along
(
    const Foam::pointField& x,
    const Foam::vectorField& m
)
{
    std::vector<Foam::dualVector<dual<1>>> xd(x.size());
    forAll(x, p)
    {
        xd[p] = Foam::dualVector<dual<1>>(x[p]);
        xd[p].x.d[0] = m[p].x();
        xd[p].y.d[0] = m[p].y();
        xd[p].z.d[0] = m[p].z();
    }
    return xd;
}

// The largest row-scaled difference between dR/dx by dual numbers and by
// central differences (step h) at the points x; and between the dual
// numbers' dR/dx and the sparse one (sparseDual, every coordinate 3p + c
// a variable), in sparseError
double meshDerivativeError
(
    const Foam::ALENavierStokes& f,
    const Foam::pointField& x,
    double h,
    int& nColumns,
    int& nRows,
    double& sparseError
)
{
    const Foam::fvMesh& mesh = f.mesh();
    std::vector<std::pair<Foam::label, Foam::vector>> cols;
    forAll(x, p)
    {
        for (const Foam::vector& e : inPlaneDirections(mesh, p))
        {
            cols.emplace_back(p, e);
        }
    }
    const Foam::vectorField none(x.size(), Foam::Zero);
    const auto plain = [&](const Foam::pointField& y)
    {
        return rows(f.residualAt<dual<1>>(along(y, none)), [](auto& d) { return d.v; });
    };
    const int n = plain(x).size();
    matX J(n, cols.size()), Jfd(n, cols.size()), Js(n, cols.size());
    // the sparse Jacobian with respect to all coordinates
    std::vector<Foam::dualVector<sparseDual>> xs(x.size());
    forAll(x, p)
    {
        xs[p] = Foam::dualVector<sparseDual>
        (
            sparseDual::variable(x[p].x(), 3*p),
            sparseDual::variable(x[p].y(), 3*p + 1),
            sparseDual::variable(x[p].z(), 3*p + 2)
        );
    }
    const auto rs = f.residualAt<sparseDual>(xs);
    for (std::size_t j = 0; j < cols.size(); ++j)
    {
        Foam::vectorField m(none);
        m[cols[j].first] = cols[j].second;
        J.col(j) = rows(f.residualAt<dual<1>>(along(x, m)), [](auto& d) { return d.d[0]; });
        Js.col(j) = rows(rs, [&](const sparseDual& d)
        {
            double v = 0;
            for (int k = 0; k < d.size(); ++k)
            {
                if (d.index(k)/3 == cols[j].first)
                {
                    v += d.derivative(k)*cols[j].second[d.index(k) % 3];
                }
            }
            return v;
        });
        Jfd.col(j) = (plain(x + h*m) - plain(x - h*m))/(2*h);
    }
    sparseError = (J - Js).cwiseAbs().maxCoeff()/J.cwiseAbs().maxCoeff();
    // Rows without derivatives (the forces of empty faces, components
    // normal to a wedge's plane of symmetry) are zero up to round-off: no
    // row's scale is taken below 1e-9 of the largest entry
    const double floor = 1e-9*J.cwiseAbs().maxCoeff();
    double err = 0;
    nRows = 0;
    for (int i = 0; i < n; ++i)
    {
        const double scale = J.row(i).cwiseAbs().maxCoeff();
        if (scale < floor)
        {
            EXPECT_LT(Jfd.row(i).cwiseAbs().maxCoeff(), 100*floor) << i;
            continue;
        }
        ++nRows;
        const double e = (J.row(i) - Jfd.row(i)).cwiseAbs().maxCoeff()/scale;
        err = std::max(err, e);
    }
    nColumns = cols.size();
    return err;
}

vecX randomState(int n, unsigned seed, double shift)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uni(-1, 1);
    vecX x(n);
    for (int i = 0; i < n; ++i) x(i) = uni(rng) + (i % 3 == 0 ? shift : 0);
    return x;
}

struct derivativeCase
{
    const char* name;
    const std::string* mesh;
    const char* ddt;
    const char* div;
    const char* laplacian;
    const std::string* U;
    const std::string* p;
    bool incompressible;
};

} // namespace


TEST(ALENavierStokes, MeshDerivativeAgreesWithCentralDifferences)
{
    for (const derivativeCase& dc :
    {
        derivativeCase{"transient compressible channel", &skewedMesh, "Euler",
            "Gauss linear", "Gauss linear corrected", &channelU, &channelP, false},
        derivativeCase{"steady upwind channel", &skewedMesh, "steadyState",
            "Gauss upwind", "Gauss linear uncorrected", &channelU, &channelP, true},
        derivativeCase{"incompressible wedge", &wedgeAxisMesh, "Euler",
            "Gauss linear", "Gauss linear corrected", &wedgeFlowU, &wedgeFlowP, true}
    })
    {
        scratchCase c
        (
            fluidCaseFiles("fluid", *dc.mesh, dc.ddt, dc.div, dc.laplacian,
                           *dc.U, *dc.p),
            {"fluid"}
        );
        Foam::ALEFluidSettings set;
        set.rho = 1.3;
        set.mu = 0.1;
        set.incompressible = dc.incompressible;
        set.bulkModulus = dc.incompressible ? Foam::GREAT : 50;
        Foam::ALENavierStokes f(c.runTime(), c.mesh(), set);
        const int n = f.nUnknowns();
        f.addToUnknowns(randomState(n, 1, 0));
        f.commit(vecX());
        f.beginIncrement(0.1, 0.2, vecX());
        f.addToUnknowns(0.3*randomState(n, 2, 1));
        // the points moved from the step's start (swept volumes)
        const Foam::pointField x(c.mesh().points() + randomMotion(c.mesh(), 0.03, 5));

        // the residual on the points equals the assembled one on the mesh
        {
            // (the step begun again on the moved mesh: its mesh fluxes
            // from the committed points)
            c.mesh().movePoints(x);
            f.beginIncrement(0.1, 0.2, vecX());
            vecX fext, r;
            f.evaluate(0.2, vecX(), fext, r, nullptr);
            const auto a = f.residualAt<Foam::scalar>
            (
                std::vector<Foam::vector>(x.begin(), x.end())
            );
            double e = 0;
            for (int i = 0; i < n; ++i) e = std::max(e, std::abs(a.r[i] - r(i)));
            EXPECT_LT(e, 1e-13*f.residualScale()) << dc.name;
        }

        int nCols = 0, nRows = 0;
        double sparseErr = 0;
        const double err =
            meshDerivativeError(f, x, 1e-6, nCols, nRows, sparseErr);
        std::cout << "    " << dc.name << ": dR/dx " << nRows << " rows x "
                  << nCols << " point coordinates, row-scaled error " << err
                  << ", sparse against dual " << sparseErr << '\n';
        EXPECT_LT(sparseErr, 1e-13) << dc.name;
        EXPECT_GT(nRows, n);
        EXPECT_TRUE(test::fdError("ALE fluid mesh derivative", err, 5e-8)) << dc.name;
    }
}
