// Patch tests of the hexahedra on a distorted 2 x 2 x 2 mesh of the unit
// cube (interior vertex moved off-centre, curved mid-side nodes placed on
// the trilinear map), and objectivity of the 27/4 element with finite-
// strain plasticity:
// 1. Linear elasticity, boundary nodes at a linear field u = A X + c:
//    (a) the exact field leaves no residual at the interior nodes,
//    (b) solving for the interior nodes gives back the linear field,
//    to round-off, for every element type (Zienkiewicz & Taylor, The FEM,
//    vol. 1, sec. 10: patch test forms A and B).
// 2. Neo-Hookean, a homogeneous finite deformation u = (F - I) X: the
//    exact field leaves no interior residual (large-strain patch test).
// 3. A Hex27P4 of elastoPlastic steel-like material stretched plastically,
//    then rotated rigidly by 90 deg about an oblique axis in 18 committed
//    increments: the Cauchy stress invariants stay as they were to 1e-8
//    (incremental objectivity of the kinematics and the return mapping).
#include "solidElement.H"
#include "hexShape.H"
#include "materialInput.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace form;

namespace
{

struct hexMesh
{
    matX X;                                //!< nodes x 3
    std::vector<std::vector<int>> cells;   //!< VTK order
    std::vector<bool> boundary;
};

// 2 x 2 x 2 cells of the unit cube; the centre vertex moved to
// (0.58, 0.44, 0.53), the other vertices on the cube; order 1 (Hex8) or
// 2 (Hex27: higher-order nodes on each cell's trilinear map, i.e. the
// shared ones at the means of their vertices)
hexMesh distortedCube(int nNodes)
{
    const int order = nNodes == 27 ? 2 : 1;
    const int N = 2, M = order*N + 1;
    const auto id = [M](int i, int j, int k) { return i + M*(j + M*k); };
    hexMesh m;
    m.X.resize(M*M*M, 3);
    m.boundary.assign(M*M*M, false);
    // Vertex grid (3 x 3 x 3)
    const auto vertex = [](int i, int j, int k)
    {
        Eigen::RowVector3d x(0.5*i, 0.5*j, 0.5*k);
        if (i == 1 && j == 1 && k == 1) x << 0.58, 0.44, 0.53;
        return x;
    };
    for (int k = 0; k < M; ++k)
    for (int j = 0; j < M; ++j)
    for (int i = 0; i < M; ++i)
    {
        // Mean of the vertices around (i, j, k) along its odd directions
        Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
        int n = 0;
        const int oi = i % order, oj = j % order, ok = k % order;
        for (int di : {0, oi}) for (int dj : {0, oj}) for (int dk : {0, ok})
        {
            x += vertex((i - oi + 2*di)/order, (j - oj + 2*dj)/order,
                        (k - ok + 2*dk)/order);
            ++n;
        }
        m.X.row(id(i, j, k)) = x/n;
        m.boundary[id(i, j, k)] =
            i == 0 || j == 0 || k == 0 || i == M - 1 || j == M - 1 || k == M - 1;
    }
    for (int ek = 0; ek < N; ++ek)
    for (int ej = 0; ej < N; ++ej)
    for (int ei = 0; ei < N; ++ei)
    {
        std::vector<int> c(nNodes);
        for (int a = 0; a < nNodes; ++a)
        {
            const Eigen::Vector3d xi = hexShape<27>::node(a);
            c[a] = id
            (
                order*ei + int(std::lround(0.5*order*(1 + xi(0)))),
                order*ej + int(std::lround(0.5*order*(1 + xi(1)))),
                order*ek + int(std::lround(0.5*order*(1 + xi(2))))
            );
        }
        m.cells.push_back(c);
    }
    return m;
}

// Assembled internal forces and tangent at the nodal displacements u
void assemble(const solidElement& el, const hexMesh& m, const matX& u,
              const material& mat, vecX& f, matX& K)
{
    const int n = int(m.X.rows());
    f.setZero(3*n);
    K.setZero(3*n, 3*n);
    std::vector<materialState> s0(el.nQuadrature(), mat.initialState()), s1;
    for (const std::vector<int>& c : m.cells)
    {
        const matX Xe = test::gather(m.X, c), ue = test::gather(u, c);
        vecX fe;
        matX Ke;
        ASSERT_TRUE(el.compute(Xe, ue, mat, s0, s1, fe, &Ke, 0));
        for (std::size_t a = 0; a < c.size(); ++a)
        {
            f.segment<3>(3*c[a]) += fe.segment<3>(3*a);
            for (std::size_t b = 0; b < c.size(); ++b)
            {
                K.block<3, 3>(3*c[a], 3*c[b]) += Ke.block<3, 3>(3*a, 3*b);
            }
        }
    }
}

} // namespace


TEST(upHexPatch, linearFieldIsExactOnADistortedMesh)
{
    mat3 A;
    A << 0.011, -0.004, 0.007, 0.002, -0.009, 0.003, 0.005, 0.006, 0.013;
    const vec3 c(0.1, -0.2, 0.05);
    const auto mat = material::New("linearElastic", {{"E", 200}, {"nu", 0.3}});
    for (const char* type : {"Hex8", "Hex27", "Hex8P1", "Hex27P4"})
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        const hexMesh m = distortedCube(el->nNodes());
        const int n = int(m.X.rows());
        matX u = m.X*A.transpose();
        u.rowwise() += c.transpose();
        vecX f;
        matX K;
        assemble(*el, m, u, *mat, f, K);
        std::vector<int> fr, pr;
        for (int a = 0; a < n; ++a)
        {
            for (int i = 0; i < 3; ++i) (m.boundary[a] ? pr : fr).push_back(3*a + i);
        }
        // (a) no residual at the interior nodes for the exact field
        EXPECT_LT(f(fr).norm(), 1e-12*f(pr).norm()) << type;
        // (b) the interior nodes solved from the boundary values
        const vecX uv = u.transpose().reshaped();
        const vecX uf = K(fr, fr).ldlt().solve(-K(fr, pr)*uv(pr));
        EXPECT_LT((uf - uv(fr)).norm(), 1e-12*uv.norm()) << type;
    }
}


TEST(upHexPatch, homogeneousFiniteDeformationIsExact)
{
    mat3 F;
    F << 1.3, 0.2, -0.1, 0.05, 0.85, 0.15, -0.12, 0.1, 1.1;
    const auto mat = material::New("neoHookean", {{"E", 200}, {"nu", 0.45}});
    for (const char* type : {"Hex8", "Hex27", "Hex8P1", "Hex27P4"})
    {
        const auto el = solidElement::New(type, analysisType::solid3D);
        const hexMesh m = distortedCube(el->nNodes());
        const matX u = m.X*(F - mat3::Identity()).transpose();
        vecX f;
        matX K;
        assemble(*el, m, u, *mat, f, K);
        double interior = 0, boundary = 0;
        for (int a = 0; a < int(m.X.rows()); ++a)
        {
            (m.boundary[a] ? boundary : interior) +=
                f.segment<3>(3*a).squaredNorm();
        }
        EXPECT_LT(std::sqrt(interior), 1e-12*std::sqrt(boundary)) << type;
    }
}


TEST(upHexPatch, plasticStateIsObjectiveUnderFiniteRotation)
{
    materialInput in;
    in.words["type"] = "elastoPlastic";
    in.scalars = {{"E", 206000}, {"nu", 0.3}};
    in.dicts["hardening"].path = "hardening";
    in.dicts["hardening"].words["type"] = "swift";
    in.dicts["hardening"].scalars =
        {{"K", 565.32}, {"eps0", 0.007117}, {"n", 0.2589}};
    const auto mat = material::New("elastoPlastic", in);
    const auto el = solidElement::New("Hex27P4", analysisType::solid3D);
    matX X(27, 3);
    for (int a = 0; a < 27; ++a)
    {
        X.row(a) = 0.5*(hexShape<27>::node(a) + vec3::Ones()).transpose();
    }
    std::vector<materialState> s(el->nQuadrature(), mat->initialState()), t;
    vecX f;
    const auto step = [&](const mat3& F) -> elementResult
    {
        const matX u = X*(F - mat3::Identity()).transpose();
        EXPECT_TRUE(el->compute(X, u, *mat, s, t, f, nullptr, 0));
        s = t;
        return el->result(X, u, *mat, s);
    };
    // Plastic stretch with shear, in 10 committed increments
    mat3 F0;
    F0 << 1.08, 0.03, 0, 0, 0.97, 0.02, 0.01, 0, 0.96;
    elementResult r0;
    for (int k = 1; k <= 10; ++k)
    {
        r0 = step(mat3::Identity() + 0.1*k*(F0 - mat3::Identity()));
    }
    ASSERT_GT(r0.equivalentStrain, 0.02);
    const auto invariants = [](const mat3& sigma)
    {
        return vec3
        (
            sigma.trace(),
            0.5*(sigma.trace()*sigma.trace() - (sigma*sigma).trace()),
            sigma.determinant()
        );
    };
    const vec3 I0 = invariants(r0.cauchy);
    const double scale = r0.cauchy.norm();
    // Rigid rotation of the deformed element by 90 deg in 18 increments
    elementResult r;
    for (int k = 1; k <= 18; ++k)
    {
        const mat3 R = test::rotation(vec3(1, -2, 0.7), 0.5*M_PI*k/18);
        r = step(R*F0);
    }
    const vec3 I1 = invariants(r.cauchy);
    EXPECT_NEAR(I1(0), I0(0), 1e-8*scale);
    EXPECT_NEAR(I1(1), I0(1), 1e-8*scale*scale);
    EXPECT_NEAR(I1(2), I0(2), 1e-8*scale*scale*scale);
    EXPECT_NEAR(r.equivalentStrain, r0.equivalentStrain, 1e-12);
    // ... and the stress itself rotated with the body
    const mat3 R = test::rotation(vec3(1, -2, 0.7), 0.5*M_PI);
    EXPECT_LT((r.cauchy - R*r0.cauchy*R.transpose()).norm(), 1e-8*scale);
}
