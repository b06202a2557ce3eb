/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The MITC4 shell element (mitc4.H).
\*---------------------------------------------------------------------------*/
#include "mitc4.H"
#include "quadShape.H"
#include "gaussLegendre.H"
#include "formError.H"
#include <cmath>
#include <vector>

namespace form
{

mitc4::mitc4
(
    const Eigen::Matrix<double, 4, 3>& X,
    const Eigen::Matrix<double, 4, 3>& V0,
    const Eigen::Vector4d& a,
    std::shared_ptr<const shellLaw> law,
    int nThickness,
    bool lobatto,
    bool plus
)
:
    X_(X),
    V0_(V0),
    a_(a),
    law_(std::move(law)),
    nThickness_(nThickness),
    plus_(plus),
    aTie_(Eigen::Matrix<double, 5, 1>::Zero())
{
    if (!law_)
    {
        throw numericalError("mitc4: no lamina law");
    }
    if (!(a.minCoeff() > 0))
    {
        throw numericalError("mitc4: thicknesses must be positive");
    }
    if (lobatto ? nThickness < 3 || nThickness > 10 : nThickness < 1 || nThickness > 10)
    {
        throw numericalError
        (
            lobatto
          ? "mitc4: 3 to 10 Gauss-Lobatto points through the thickness"
          : "mitc4: 1 to 10 Gauss points through the thickness"
        );
    }
    if (lobatto) gaussLobatto1D(nThickness, zt_, wt_);
    else gaussLegendre1D(nThickness, zt_, wt_);
    if (!plus_) return;

    // MITC4+ geometric coefficients (mitc4.H) from the initial mid-surface
    quadShape<4>::vecN N;
    quadShape<4>::matN2 dN;
    quadShape<4>::eval(0, 0, N, dN);
    const vec3 xr = X_.transpose()*dN.col(0);
    const vec3 xs = X_.transpose()*dN.col(1);
    quadShape<4>::eval(0, 1, N, dN);
    const vec3 xd = X_.transpose()*dN.col(0) - xr;     // dX/dr = x_r + s x_d
    Eigen::Matrix<double, 3, 2> M;
    M << xr, xs;
    const Eigen::Matrix2d G = M.transpose()*M;
    if (!(G.determinant() > 1e-12*G.trace()*G.trace()))
    {
        throw numericalError("mitc4: the element's initial geometry is degenerate");
    }
    // c = (m_r . x_d, m_s . x_d) with m_r, m_s the rows of G^-1 M^T
    const Eigen::Vector2d c = G.ldlt().solve(M.transpose()*xd);
    const double cr = c(0), cs = c(1);
    const double d = cr*cr + cs*cs - 1;
    if (!(std::abs(d) > 1e-3))
    {
        throw numericalError
        (
            "mitc4: the element is too distorted for MITC4+ (d = "
          + std::to_string(d) + ", Ko, Lee & Bathe 2017 eq. 24)"
        );
    }
    aTie_ << cr*(cr - 1)/(2*d), cr*(cr + 1)/(2*d),
             cs*(cs - 1)/(2*d), cs*(cs + 1)/(2*d), 2*cr*cs/d;
}


mitc4::mitc4
(
    const Eigen::Matrix<double, 4, 3>& X,
    const Eigen::Matrix<double, 4, 3>& V0,
    const Eigen::Vector4d& a,
    const shellElastic& law,
    int nThickness,
    bool lobatto,
    bool plus
)
:
    mitc4
    (
        X, V0, a, std::make_shared<shellElastic>(law), nThickness, lobatto,
        plus
    )
{}


mitc4::basis mitc4::at
(
    double r,
    double s,
    double t,
    const std::array<shellNodeState, 4>& nodes
) const
{
    quadShape<4>::vecN N;
    quadShape<4>::matN2 dN;
    quadShape<4>::eval(r, s, N, dN);
    basis b;
    for (int i = 0; i < 3; ++i)
    {
        b.G[i].setZero();
        b.dg[i].setZero();
        b.D[i].setZero();
    }
    for (int k = 0; k < 4; ++k)
    {
        const vec3 X0 = X_.row(k).transpose();
        const vec3 V0 = V0_.row(k).transpose();
        const vec3& u = nodes[k].u;
        const vec3& dV = nodes[k].dV;
        const double h = 0.5*t*a_(k);
        // coefficient of node k's director in g_r, g_s, g_t
        b.c[0][k] = dN(k, 0)*h;
        b.c[1][k] = dN(k, 1)*h;
        b.c[2][k] = 0.5*a_(k)*N(k);
        for (int i = 0; i < 2; ++i)
        {
            b.G[i] += dN(k, i)*X0 + b.c[i][k]*V0;
            b.dg[i] += dN(k, i)*u + b.c[i][k]*dV;
            b.D[i].block<3, 3>(0, 5*k) = dN(k, i)*mat3::Identity();
        }
        b.G[2] += b.c[2][k]*V0;
        b.dg[2] += b.c[2][k]*dV;
        for (int i = 0; i < 3; ++i)
        {
            b.D[i].block<3, 2>(0, 5*k + 3) = b.c[i][k]*nodes[k].director.dV;
        }
    }
    for (int i = 0; i < 3; ++i) b.g[i] = b.G[i] + b.dg[i];
    return b;
}


namespace
{

//- The rotation dofs of the four nodes
const std::array<int, 4> rotationDofs = {3, 8, 13, 18};

//- The nodes' director states
std::array<const directorState*, 4> directors
(
    const std::array<shellNodeState, 4>& nodes
)
{
    return {&nodes[0].director, &nodes[1].director, &nodes[2].director,
            &nodes[3].director};
}

} // anonymous namespace


void mitc4::addMembraneSecond
(
    double r,
    double s,
    const double (&moment)[3][3],
    const std::array<shellNodeState, 4>& nodes,
    matQ& K
) const
{
    // D_i(t) = D0_i + t D1_i (at: the translations' columns do not
    // depend on t, the rotations' are proportional to it), so with the
    // weights' moments W_n = sum_t w(t) t^n
    //   sum_t w (D_i^T D_j + D_j^T D_i)
    //     = S^T M S,  S = [D0_r; D1_r; D0_s; D1_s],
    // M of 3 x 3 blocks (scaled identities) from W_0, W_1, W_2
    const basis b0 = at(r, s, 0, nodes), b1 = at(r, s, 1, nodes);
    Eigen::Matrix<double, 12, nDofs> S;
    S << b0.D[0], b1.D[0] - b0.D[0], b0.D[1], b1.D[1] - b0.D[1];
    double M[4][4] = {};
    for (int k = 0; k < 2; ++k)         // rr (blocks 0, 1), ss (2, 3)
    {
        const int o = 2*k;
        M[o][o] += 2*moment[0][k];
        M[o][o + 1] += 2*moment[1][k];
        M[o + 1][o] += 2*moment[1][k];
        M[o + 1][o + 1] += 2*moment[2][k];
    }
    const double w[3] = {moment[0][2], moment[1][2], moment[2][2]};
    M[0][2] += w[0]; M[2][0] += w[0];   // rs
    M[0][3] += w[1]; M[3][0] += w[1];
    M[1][2] += w[1]; M[2][1] += w[1];
    M[1][3] += w[2]; M[3][1] += w[2];
    Eigen::Matrix<double, 12, nDofs> MS;
    for (int a = 0; a < 4; ++a)
    {
        MS.middleRows<3>(3*a) =
            M[a][0]*S.middleRows<3>(0) + M[a][1]*S.middleRows<3>(3)
          + M[a][2]*S.middleRows<3>(6) + M[a][3]*S.middleRows<3>(9);
    }
    K.noalias() += S.transpose().lazyProduct(MS);
}


void mitc4::addSecond
(
    const basis& b,
    int i,
    int j,
    double w,
    const std::array<shellNodeState, 4>& nodes,
    matQ& K
)
{
    addShellSecond<4, nDofs>
    (
        b, i, j, w,
        {&nodes[0].director, &nodes[1].director, &nodes[2].director,
         &nodes[3].director},
        {3, 8, 13, 18}, K
    );
}


namespace
{

//- P_ij and its derivative (shellBasis.H)
template<class Row>
double product(const shellBasis<4, mitc4::nDofs>& b, int i, int j, Row&& dP)
{
    return shellProduct(b, i, j, dP);
}

//- The tying points: A (0, 1), B (0, -1) for e_rt; C (1, 0), D (-1, 0)
//  for e_st
constexpr double tie[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};

//- MITC4+ membrane tying points A (0, 1), B (0, -1) (rr), C (1, 0),
//  D (-1, 0) (ss), E (0, 0) (rs), and the product each ties
constexpr double tieM[5][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}, {0, 0}};
constexpr int tieMij[5][2] = {{0, 0}, {0, 0}, {1, 1}, {1, 1}, {0, 1}};

} // anonymous namespace


mitc4::membraneTies mitc4::tieMembrane
(
    const std::array<shellNodeState, 4>& nodes
) const
{
    membraneTies m;
    Eigen::Matrix<double, 1, nDofs> dP;
    for (int p = 0; p < 5; ++p)
    {
        m.b[p] = at(tieM[p][0], tieM[p][1], 0, nodes);
        m.p(p) = product(m.b[p], tieMij[p][0], tieMij[p][1], dP);
        m.dP.row(p) = dP;
    }
    return m;
}


Eigen::Matrix<double, 3, 5> mitc4::plusWeights(double r, double s) const
{
    // Rows: E_rr, E_ss, 2E_rs; columns: the products A, B, C, D, E
    // (E_ij = P_ij/2 at the ties; mitc4.H)
    const Eigen::Matrix<double, 5, 1>& a = aTie_;
    Eigen::Matrix<double, 3, 5> W;
    W.row(0) = 0.5*(s*s - 1)*a.transpose();
    W(0, 0) += 0.25*(1 + s);
    W(0, 1) += 0.25*(1 - s);
    W.row(1) = 0.5*(r*r - 1)*a.transpose();
    W(1, 2) += 0.25*(1 + r);
    W(1, 3) += 0.25*(1 - r);
    W.row(2) = r*s*a.transpose();
    W(2, 0) += 0.25*r;
    W(2, 1) -= 0.25*r;
    W(2, 2) += 0.25*s;
    W(2, 3) -= 0.25*s;
    W(2, 4) += 1;
    return W;
}


void mitc4::localFrame
(
    double r,
    double s,
    double t,
    Eigen::Matrix<double, 5, 5>& T,
    mat3& Q,
    double& detJ
) const
{
    quadShape<4>::vecN N;
    quadShape<4>::matN2 dN;
    quadShape<4>::eval(r, s, N, dN);
    mat3 J = mat3::Zero();      // columns G_r, G_s, G_t
    for (int k = 0; k < 4; ++k)
    {
        const vec3 X0 = X_.row(k).transpose();
        const vec3 V0 = V0_.row(k).transpose();
        const double h = 0.5*t*a_(k);
        J.col(0) += dN(k, 0)*(X0 + h*V0);
        J.col(1) += dN(k, 1)*(X0 + h*V0);
        J.col(2) += 0.5*a_(k)*N(k)*V0;
    }
    shellLocalFrame(J, "mitc4", T, Q, detJ);
}


std::array<mitc4::basis, 4> mitc4::tieShear
(
    double t,
    const std::array<shellNodeState, 4>& nodes
) const
{
    std::array<basis, 4> tb;
    for (int p = 0; p < 4; ++p) tb[p] = at(tie[p][0], tie[p][1], t, nodes);
    return tb;
}


void mitc4::strains
(
    double r,
    double s,
    const basis& b,
    const std::array<basis, 4>& tb,
    const basis* bm,
    const membraneTies* ties,
    Eigen::Matrix<double, 5, 1>& E,
    Eigen::Matrix<double, 5, nDofs>* B
) const
{
    Eigen::Matrix<double, 1, nDofs> dP;
    E(0) = 0.5*product(b, 0, 0, dP);
    if (B) B->row(0) = 0.5*dP;
    E(1) = 0.5*product(b, 1, 1, dP);
    if (B) B->row(1) = 0.5*dP;
    E(2) = product(b, 0, 1, dP);
    if (B) B->row(2) = dP;
    // Tied transverse shears
    E(3) = E(4) = 0;
    if (B) B->bottomRows<2>().setZero();
    for (int p = 0; p < 4; ++p)
    {
        const bool rt = p < 2;
        const double w = rt
          ? 0.5*(1 + tie[p][1]*s)
          : 0.5*(1 + tie[p][0]*r);
        const double v = product(tb[p], rt ? 0 : 1, 2, dP);
        E(rt ? 3 : 4) += w*v;
        if (B) B->row(rt ? 3 : 4) += w*dP;
    }
    if (!ties) return;
    // MITC4+: the mid-surface membrane strains replaced by the assumed ones
    E(0) -= 0.5*product(*bm, 0, 0, dP);
    if (B) B->row(0) -= 0.5*dP;
    E(1) -= 0.5*product(*bm, 1, 1, dP);
    if (B) B->row(1) -= 0.5*dP;
    E(2) -= product(*bm, 0, 1, dP);
    if (B) B->row(2) -= dP;
    const Eigen::Matrix<double, 3, 5> W = plusWeights(r, s);
    E.head<3>() += W*ties->p;
    if (B) B->topRows<3>() += W*ties->dP;
}


void mitc4::addPlusSecond
(
    double r,
    double s,
    const basis& bm,
    const vec3& mSum,
    const std::array<shellNodeState, 4>& nodes,
    Eigen::Matrix<double, 5, 1>& omega,
    matQ& K
) const
{
    // The displacement-based mid-surface strains out, the tied ones in
    addSecond(bm, 0, 0, -0.5*mSum(0), nodes, K);
    addSecond(bm, 1, 1, -0.5*mSum(1), nodes, K);
    addSecond(bm, 0, 1, -mSum(2), nodes, K);
    omega += plusWeights(r, s).transpose()*mSum;
}


bool mitc4::integrate
(
    const std::array<shellNodeState, 4>& nodes,
    const std::vector<materialState>* committed,
    std::vector<materialState>* trial,
    vecQ* f,
    matQ* K,
    double* W
) const
{
    if (f) f->setZero();
    if (K) K->setZero();
    if (W) *W = 0;
    const std::vector<double>& zt = zt_;
    const std::vector<double>& wt = wt_;
    const double g = 1/std::sqrt(3.0);
    const double pts[2] = {-g, g};
    const materialState none;
    materialState scratch;
    vec5 E;
    mat5 T;
    mat3 Q;
    Eigen::Matrix<double, 5, nDofs> B;
    membraneTies ties;
    if (plus_) ties = tieMembrane(nodes);
    const membraneTies* tp = plus_ ? &ties : nullptr;
    // The shear tying bases of each point through the thickness, and the
    // weights of their second derivatives summed over the in-plane points
    // (the bases do not depend on r, s: one product per tying point and
    // layer instead of one per integration point)
    std::vector<std::array<basis, 4>> tieB(nThickness_);
    for (int it = 0; it < nThickness_; ++it) tieB[it] = tieShear(zt[it], nodes);
    std::vector<std::array<double, 4>> tieW(nThickness_, {0, 0, 0, 0});
    Eigen::Matrix<double, 5, 1> omega = Eigen::Matrix<double, 5, 1>::Zero();
    int q = 0;
    for (double r : pts)
    for (double s : pts)
    {
        // MITC4+: the mid-surface basis; the membrane resultants summed
        // through the thickness
        basis bm;
        if (plus_) bm = at(r, s, 0, nodes);
        vec3 mSum = vec3::Zero();
        double moment[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (int it = 0; it < nThickness_; ++it, ++q)
        {
            const double t = zt[it];
            double detJ;
            localFrame(r, s, t, T, Q, detJ);
            const double w = detJ*wt[it];       // 2 x 2 Gauss weights are 1
            const basis b = at(r, s, t, nodes);
            strains(r, s, b, tieB[it], &bm, tp, E, f || K ? &B : nullptr);
            const vec5 eps = T*E;
            if (W)
            {
                *W += w*law_->energy(eps);
                if (!f && !K) continue;
            }
            vec5 m;
            if
            (
                !addShellPoint<nDofs>
                (
                    *law_, Q, eps, committed ? (*committed)[q] : none,
                    trial ? (*trial)[q] : scratch, T, B, w, f, K, m
                )
            )
            {
                return false;
            }
            if (!K) continue;
            // Geometric part: the covariant stress resultants T^T S
            // times the second derivatives of the covariant strains
            // (the D_i^T D_j terms through the thickness at once below:
            // their weights' moments in t)
            const double wm[3] = {0.5*m(0), 0.5*m(1), m(2)};
            const int ij[3][2] = {{0, 0}, {1, 1}, {0, 1}};
            for (int k = 0; k < 3; ++k)
            {
                addShellDirectorSecond<4, nDofs>
                (
                    b, ij[k][0], ij[k][1], wm[k], directors(nodes),
                    rotationDofs, *K
                );
                moment[0][k] += wm[k];
                moment[1][k] += wm[k]*t;
                moment[2][k] += wm[k]*t*t;
            }
            for (int p = 0; p < 4; ++p)
            {
                const bool rt = p < 2;
                const double wp = rt
                  ? 0.5*(1 + tie[p][1]*s)
                  : 0.5*(1 + tie[p][0]*r);
                tieW[it][p] += wp*m(rt ? 3 : 4);
            }
            mSum += m.head<3>();
        }
        if (K) addMembraneSecond(r, s, moment, nodes, *K);
        if (plus_ && K) addPlusSecond(r, s, bm, mSum, nodes, omega, *K);
    }
    if (K)
    {
        for (int p = 0; plus_ && p < 5; ++p)
        {
            addSecond(ties.b[p], tieMij[p][0], tieMij[p][1], omega(p), nodes, *K);
        }
        // The shear ties: D_t does not depend on t, so the sum through
        // the thickness of w (D_i^T D_t + D_t^T D_i) is one product with
        // the weighted sum of D_i
        for (int p = 0; p < 4; ++p)
        {
            const int i = p < 2 ? 0 : 1;
            Eigen::Matrix<double, 3, nDofs> Dsum =
                Eigen::Matrix<double, 3, nDofs>::Zero();
            for (int it = 0; it < nThickness_; ++it)
            {
                Dsum += tieW[it][p]*tieB[it][p].D[i];
                addShellDirectorSecond<4, nDofs>
                (
                    tieB[it][p], i, 2, tieW[it][p], directors(nodes),
                    rotationDofs, *K
                );
            }
            const matQ DD = Dsum.transpose().lazyProduct(tieB[0][p].D[2]);
            *K += DD + DD.transpose();
        }
    }
    return true;
}


bool mitc4::compute
(
    const std::array<shellNodeState, 4>& nodes,
    const std::vector<materialState>& committed,
    std::vector<materialState>& trial,
    vecQ& f,
    matQ* K
) const
{
    if
    (
        int(committed.size()) != nQuadrature()
     || int(trial.size()) != nQuadrature()
    )
    {
        throw numericalError
        (
            "mitc4: " + std::to_string(committed.size()) + " states for "
          + std::to_string(nQuadrature()) + " integration points"
        );
    }
    return integrate(nodes, &committed, &trial, &f, K, nullptr);
}


void mitc4::compute
(
    const std::array<shellNodeState, 4>& nodes,
    vecQ& f,
    matQ* K
) const
{
    if (law_->initialState().history.size())
    {
        throw numericalError
        (
            "mitc4::compute: a law with history needs the states"
        );
    }
    if (!integrate(nodes, nullptr, nullptr, &f, K, nullptr))
    {
        throw numericalError("mitc4::compute: the lamina law failed");
    }
}


void mitc4::pointStrains
(
    const std::array<shellNodeState, 4>& nodes,
    std::vector<mat3>& Q,
    std::vector<vec5>& eps
) const
{
    Q.resize(nQuadrature());
    eps.resize(nQuadrature());
    const std::vector<double>& zt = zt_;
    const std::vector<double>& wt = wt_;
    const double g = 1/std::sqrt(3.0);
    const double pts[2] = {-g, g};
    mat5 T;
    vec5 E;
    membraneTies ties;
    if (plus_) ties = tieMembrane(nodes);
    int q = 0;
    for (double r : pts)
    for (double s : pts)
    {
        basis bm;
        if (plus_) bm = at(r, s, 0, nodes);
        for (int it = 0; it < nThickness_; ++it, ++q)
        {
            double detJ;
            localFrame(r, s, zt[it], T, Q[q], detJ);
            strains
            (
                r, s, at(r, s, zt[it], nodes), tieShear(zt[it], nodes), &bm,
                plus_ ? &ties : nullptr, E, nullptr
            );
            eps[q] = T*E;
        }
    }
}


double mitc4::energy(const std::array<shellNodeState, 4>& nodes) const
{
    double W = 0;
    integrate(nodes, nullptr, nullptr, nullptr, nullptr, &W);
    return W;
}



std::vector<double> mitc4::pointVolumes() const
{
    // The points of integrate(): 2 x 2 Gauss (weights 1) in the lamina,
    // nThickness through it, q = (2 i_r + i_s) nThickness + i_t
    const double g = 1/std::sqrt(3.0);
    std::vector<double> v;
    mat5 T;
    mat3 Q;
    for (double r : {-g, g})
    for (double s : {-g, g})
    {
        for (int it = 0; it < nThickness_; ++it)
        {
            double detJ;
            localFrame(r, s, zt_[it], T, Q, detJ);
            v.push_back(detJ*wt_[it]);
        }
    }
    return v;
}

} // namespace form
