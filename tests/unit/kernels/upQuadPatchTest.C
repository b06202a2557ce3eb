// Patch tests (Irons; Bathe FEP sec. 4.4.3, Zienkiewicz & Taylor vol. 1
// ch. 10): on a distorted 3x3-element patch, prescribe a linear displacement
// field on the boundary nodes, solve the assembled linear-elastic system for
// the interior nodes and recover the field and the uniform stress exactly.
// Plane strain: u = c + A x (any A). Axisymmetric: u_r = a r, u_z = b z + c,
// an exact solution (uniform e_rr = e_tt = a, e_zz = b); the patch touches
// the axis r = 0.
#include "solidElement.H"
#include "kernelTestTools.H"
#include <gtest/gtest.h>

using namespace form;

namespace
{
struct patchResult
{
    double uError;        //!< max |u_h - u| over the interior nodes
    double stressError;   //!< max over elements |sigma_h - sigma| / |sigma|
    double pressureError; //!< max over elements |p_h - p| / |p|
    int nInterior;
};

patchResult runPatch(const std::string& type, analysisType a, double nu)
{
    const auto el = solidElement::New(type, a);
    const double E = 1000;
    const auto mat = material::New("linearElastic", {{"E", E}, {"nu", nu}});
    const bool axi = a == analysisType::axisymmetric;
    const test::quadMesh mesh = test::structuredMesh
    (
        el->nNodes(), 3, axi ? 0.0 : 0.3, -0.4, 1.2, 0.3, 11
    );
    const int nn = mesh.nNodes();

    // Exact linear field and its strain (Voigt xx, yy, zz; xy tensor)
    Eigen::Matrix2d A;
    A << 0.012, -0.007, 0.004, -0.009;
    Eigen::Vector2d c(0.003, -0.002);
    if (axi) { A(0, 1) = A(1, 0) = 0; c(0) = 0; }
    matX uExact(nn, 2);
    for (int i = 0; i < nn; ++i)
    {
        uExact.row(i) = (c + A*mesh.X.row(i).transpose()).transpose();
    }
    mat3 eps = mat3::Zero();
    eps.topLeftCorner<2, 2>() = 0.5*(A + A.transpose());
    if (axi) eps(2, 2) = A(0, 0);   // u_r/r = a
    const double G = E/(2*(1 + nu)), lambda = E*nu/((1 + nu)*(1 - 2*nu));
    const mat3 sigma = lambda*eps.trace()*mat3::Identity() + 2*G*eps;

    // Assemble K (linear: K u = f_int(u)) densely
    matX K = matX::Zero(2*nn, 2*nn);
    const std::vector<materialState> s0(el->nQuadrature(), mat->initialState());
    for (const auto& nodes : mesh.elements)
    {
        std::vector<materialState> s1;
        vecX f;
        matX Ke;
        const matX Xe = test::gather(mesh.X, nodes);
        el->compute(Xe, matX::Zero(nodes.size(), 2), *mat, s0, s1, f, &Ke, 0);
        for (std::size_t p = 0; p < nodes.size(); ++p)
            for (std::size_t q = 0; q < nodes.size(); ++q)
                K.block<2, 2>(2*nodes[p], 2*nodes[q]) +=
                    Ke.block<2, 2>(2*p, 2*q);
    }

    // Partition: boundary dofs prescribed, interior solved
    std::vector<bool> isBoundary(nn, false);
    for (int b : mesh.boundaryNodes) isBoundary[b] = true;
    std::vector<int> freeDofs, fixedDofs;
    for (int i = 0; i < nn; ++i)
        for (int d = 0; d < 2; ++d)
            (isBoundary[i] ? fixedDofs : freeDofs).push_back(2*i + d);
    const vecX uAll = uExact.transpose().reshaped();
    const matX Kff = K(freeDofs, freeDofs);
    const vecX rhs = -K(freeDofs, fixedDofs)*uAll(fixedDofs);
    const vecX uFree = Kff.partialPivLu().solve(rhs);

    patchResult r{0, 0, 0, int(freeDofs.size())/2};
    vecX u = uAll;
    for (std::size_t k = 0; k < freeDofs.size(); ++k)
    {
        r.uError = std::max(r.uError, std::abs(uFree(k) - uAll(freeDofs[k])));
        u(freeDofs[k]) = uFree(k);
    }
    const matX uNodal = u.reshaped(2, nn).transpose();
    for (const auto& nodes : mesh.elements)
    {
        const elementResult res = el->result
        (
            test::gather(mesh.X, nodes), test::gather(uNodal, nodes), *mat, s0
        );
        r.stressError = std::max(r.stressError,
                                 (res.cauchy - sigma).norm()/sigma.norm());
        const double p = -sigma.trace()/3;
        r.pressureError = std::max(r.pressureError,
                                   std::abs(res.pressure - p)/std::abs(p));
    }
    return r;
}
}

TEST(upQuadPatch, linearFieldReproducedOnDistortedPatch)
{
    for (const std::string type : {"Q4", "Q9", "Q4P1", "Q9P3"})
    {
        for (const analysisType a :
             {analysisType::planeStrain, analysisType::axisymmetric})
        {
            // compressible and nearly incompressible
            for (const double nu : {0.3, 0.4999})
            {
                const patchResult r = runPatch(type, a, nu);
                ASSERT_GT(r.nInterior, 3);
                EXPECT_LT(r.uError, 1e-12) << type << " "
                    << analysisTypeName(a) << " nu=" << nu;
                EXPECT_LT(r.stressError, 1e-10) << type << " "
                    << analysisTypeName(a) << " nu=" << nu;
                EXPECT_LT(r.pressureError, 1e-10) << type << " "
                    << analysisTypeName(a) << " nu=" << nu;
            }
        }
    }
}
