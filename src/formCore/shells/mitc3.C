/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The MITC3+ shell element (mitc3.H).
\*---------------------------------------------------------------------------*/
#include "mitc3.H"
#include "gaussLegendre.H"
#include "formError.H"
#include <cmath>

namespace form
{

namespace
{

//- The bubble's state: 11 numbers (frame V, V1, V2; increments)
constexpr int bubbleSize = 11;

//- Rotation dofs of the director nodes (corners, bubble)
constexpr std::array<int, 4> rotationDofs{3, 8, 13, 15};

//- Tying points of the assumed shear (mitc3.H): A, B, C, D, E, F
std::array<std::array<double, 2>, 6> tyingPoints(double d)
{
    return
    {{
        {1.0/6, 2.0/3}, {2.0/3, 1.0/6}, {1.0/6, 1.0/6},
        {1.0/3 + d, 1.0/3 - 2*d}, {1.0/3 - 2*d, 1.0/3 + d},
        {1.0/3 + d, 1.0/3 + d}
    }};
}

} // anonymous namespace


mitc3::mitc3
(
    const Eigen::Matrix3d& X,
    const Eigen::Matrix3d& V0,
    const Eigen::Vector3d& a,
    std::shared_ptr<const shellLaw> law,
    int nThickness,
    bool lobatto,
    double d
)
:
    X_(X),
    V0_(V0),
    a_(a),
    law_(std::move(law)),
    nThickness_(nThickness),
    tie_(tyingPoints(d))
{
    if (!law_)
    {
        throw numericalError("mitc3: no lamina law");
    }
    if (!(a.minCoeff() > 0))
    {
        throw numericalError("mitc3: thicknesses must be positive");
    }
    if (!(d > 0 && d < 1.0/6))
    {
        throw numericalError("mitc3: the tying distance d must be in (0, 1/6)");
    }
    if (lobatto ? nThickness < 3 || nThickness > 10 : nThickness < 1 || nThickness > 10)
    {
        throw numericalError
        (
            lobatto
          ? "mitc3: 3 to 10 Gauss-Lobatto points through the thickness"
          : "mitc3: 1 to 10 Gauss points through the thickness"
        );
    }
    if (lobatto) gaussLobatto1D(nThickness, zt_, wt_);
    else gaussLegendre1D(nThickness, zt_, wt_);
    // The bubble's director: a_4 V0_4 = the mean of a_k V0_k
    const vec3 m = (V0_.transpose()*a_)/3;
    a4_ = m.norm();
    if (!(a4_ > 0.5*a_.minCoeff()))
    {
        throw numericalError
        (
            "mitc3: the corner directors are more than 120 degrees apart"
        );
    }
    V04_ = m/a4_;
}


mitc3::mitc3
(
    const Eigen::Matrix3d& X,
    const Eigen::Matrix3d& V0,
    const Eigen::Vector3d& a,
    const shellElastic& law,
    int nThickness,
    bool lobatto,
    double d
)
:
    mitc3(X, V0, a, std::make_shared<shellElastic>(law), nThickness, lobatto, d)
{}


std::vector<materialState> mitc3::initialStates() const
{
    std::vector<materialState> s(nStates(), law_->initialState());
    s.back().history.resize(0);
    return s;
}


shellDirector mitc3::bubbleFrame(const std::vector<materialState>& s) const
{
    const vecX& h = s[nQuadrature()].history;
    if (h.size() != bubbleSize) return shellDirector::of(V04_);
    shellDirector C;
    C.V = h.segment<3>(0);
    C.V1 = h.segment<3>(3);
    C.V2 = h.segment<3>(6);
    C.commit(h(9), h(10));
    return C;
}


mitc3::bubbleState mitc3::bubbleAt
(
    const shellDirector& C,
    const Eigen::Vector2d& phi
) const
{
    bubbleState b;
    b.director = C.at(phi(0), phi(1));
    b.dV = (C.V - V04_) + b.director.dVc;
    return b;
}


vec3 mitc3::bubbleDirector(const std::vector<materialState>& states) const
{
    return bubbleFrame(states).V;
}


mitc3::basis mitc3::at
(
    double r,
    double s,
    double t,
    const std::array<shellNodeState, 3>& nodes,
    const bubbleState& bubble
) const
{
    // h_1 = 1 - r - s, h_2 = r, h_3 = s; f_k = h_k - f_4/3 on the
    // directors, f_4 = 27 r s (1 - r - s)
    const double h[3] = {1 - r - s, r, s};
    const double dh[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
    const double f4 = 27*r*s*(1 - r - s);
    const double df4[2] = {27*s*(1 - 2*r - s), 27*r*(1 - r - 2*s)};
    basis b;
    for (int i = 0; i < 3; ++i)
    {
        b.G[i].setZero();
        b.dg[i].setZero();
        b.D[i].setZero();
    }
    for (int k = 0; k < 3; ++k)
    {
        const vec3 X0 = X_.row(k).transpose();
        const vec3 V0 = V0_.row(k).transpose();
        const double ht = 0.5*t*a_(k);
        b.c[0][k] = ht*(dh[k][0] - df4[0]/3);
        b.c[1][k] = ht*(dh[k][1] - df4[1]/3);
        b.c[2][k] = 0.5*a_(k)*(h[k] - f4/3);
        for (int i = 0; i < 2; ++i)
        {
            b.G[i] += dh[k][i]*X0 + b.c[i][k]*V0;
            b.dg[i] += dh[k][i]*nodes[k].u + b.c[i][k]*nodes[k].dV;
            b.D[i].block<3, 3>(0, 5*k) = dh[k][i]*mat3::Identity();
        }
        b.G[2] += b.c[2][k]*V0;
        b.dg[2] += b.c[2][k]*nodes[k].dV;
        for (int i = 0; i < 3; ++i)
        {
            b.D[i].block<3, 2>(0, 5*k + 3) = b.c[i][k]*nodes[k].director.dV;
        }
    }
    // The bubble node: a director only
    b.c[0][3] = 0.5*t*a4_*df4[0];
    b.c[1][3] = 0.5*t*a4_*df4[1];
    b.c[2][3] = 0.5*a4_*f4;
    for (int i = 0; i < 3; ++i)
    {
        b.G[i] += b.c[i][3]*V04_;
        b.dg[i] += b.c[i][3]*bubble.dV;
        b.D[i].block<3, 2>(0, 15) = b.c[i][3]*bubble.director.dV;
        b.g[i] = b.G[i] + b.dg[i];
    }
    return b;
}


Eigen::Matrix<double, 2, 12> mitc3::shearWeights(double r, double s) const
{
    // Columns 2p (P_rt at tie p), 2p + 1 (P_st), p = A..F (mitc3.H)
    enum { A, B, C, D, E, F };
    Eigen::Matrix<double, 2, 12> W = Eigen::Matrix<double, 2, 12>::Zero();
    W(0, 2*B) = 2.0/3;
    W(0, 2*B + 1) = -1.0/3;
    W(1, 2*A + 1) = 2.0/3;
    W(1, 2*A) = -1.0/3;
    for (int row = 0; row < 2; ++row)
    {
        W(row, 2*C) += 1.0/3;
        W(row, 2*C + 1) += 1.0/3;
        // c = P_rt^F - P_rt^D - P_st^F + P_st^E, times (3s - 1)/3 in
        // e_rt and (1 - 3r)/3 in e_st
        const double g = row == 0 ? (3*s - 1)/3 : (1 - 3*r)/3;
        W(row, 2*F) += g;
        W(row, 2*D) -= g;
        W(row, 2*F + 1) -= g;
        W(row, 2*E + 1) += g;
    }
    return W;
}


void mitc3::strains
(
    double r,
    double s,
    const basis& b,
    const std::array<basis, 6>& tb,
    Eigen::Matrix<double, 5, 1>& E,
    Eigen::Matrix<double, 5, nDofsB>* B
) const
{
    Eigen::Matrix<double, 1, nDofsB> dP;
    E(0) = 0.5*shellProduct(b, 0, 0, dP);
    if (B) B->row(0) = 0.5*dP;
    E(1) = 0.5*shellProduct(b, 1, 1, dP);
    if (B) B->row(1) = 0.5*dP;
    E(2) = shellProduct(b, 0, 1, dP);
    if (B) B->row(2) = dP;
    const Eigen::Matrix<double, 2, 12> W = shearWeights(r, s);
    E(3) = E(4) = 0;
    if (B) B->bottomRows<2>().setZero();
    for (int p = 0; p < 6; ++p)
    for (int j = 0; j < 2; ++j)         // P_rt, P_st
    {
        const double v = shellProduct(tb[p], j, 2, dP);
        const int col = 2*p + j;
        E(3) += W(0, col)*v;
        E(4) += W(1, col)*v;
        if (B)
        {
            B->row(3) += W(0, col)*dP;
            B->row(4) += W(1, col)*dP;
        }
    }
}


void mitc3::localFrame
(
    const std::array<vec3, 3>& G,
    Eigen::Matrix<double, 5, 5>& T,
    mat3& Q,
    double& detJ
)
{
    mat3 J;
    J << G[0], G[1], G[2];
    shellLocalFrame(J, "mitc3", T, Q, detJ);
}


void mitc3::addSecond
(
    const basis& b,
    int i,
    int j,
    double w,
    const std::array<shellNodeState, 3>& nodes,
    const bubbleState& bubble,
    matB& K
) const
{
    addShellSecond<4, nDofsB>
    (
        b, i, j, w,
        {&nodes[0].director, &nodes[1].director, &nodes[2].director,
         &bubble.director},
        rotationDofs, K
    );
}


bool mitc3::integrate
(
    const std::array<shellNodeState, 3>& nodes,
    const bubbleState& bubble,
    const std::vector<materialState>* committed,
    std::vector<materialState>* trial,
    vecB* f,
    matB* K,
    double* W
) const
{
    if (f) f->setZero();
    if (K) K->setZero();
    if (W) *W = 0;
    static const std::vector<quadraturePoint2D> plane = gaussTriangle7();
    const materialState none;
    materialState scratch;
    vec5 E;
    mat5 T;
    mat3 Q;
    Eigen::Matrix<double, 5, nDofsB> B;
    // The shear tying bases of each point through the thickness
    std::vector<std::array<basis, 6>> tieB(nThickness_);
    for (int it = 0; it < nThickness_; ++it)
    {
        for (int p = 0; p < 6; ++p)
        {
            tieB[it][p] = at(tie_[p][0], tie_[p][1], zt_[it], nodes, bubble);
        }
    }
    // The transverse shear strains' second derivatives live at the tying
    // bases (one set per point through the thickness): their weights are
    // summed over the in-plane points and added once per tying point
    // (d2P is linear in its weight), 60 products instead of 420
    std::vector<Eigen::Matrix<double, 2, 6>> tieWeight
    (
        K ? nThickness_ : 0, Eigen::Matrix<double, 2, 6>::Zero()
    );
    int q = 0;
    for (const quadraturePoint2D& pt : plane)
    {
        const Eigen::Matrix<double, 2, 12> Wsh = shearWeights(pt.r, pt.s);
        for (int it = 0; it < nThickness_; ++it, ++q)
        {
            const basis b = at(pt.r, pt.s, zt_[it], nodes, bubble);
            double detJ;
            localFrame(b.G, T, Q, detJ);
            const double w = detJ*pt.w*wt_[it];
            strains(pt.r, pt.s, b, tieB[it], E, f || K ? &B : nullptr);
            const vec5 eps = T*E;
            if (W)
            {
                *W += w*law_->energy(eps);
                if (!f && !K) continue;
            }
            vec5 m;
            if
            (
                !addShellPoint<nDofsB>
                (
                    *law_, Q, eps, committed ? (*committed)[q] : none,
                    trial ? (*trial)[q] : scratch, T, B, w, f, K, m
                )
            )
            {
                return false;
            }
            if (!K) continue;
            // Geometric part: the covariant resultants T^T S times the
            // second derivatives of the covariant strains
            addSecond(b, 0, 0, 0.5*m(0), nodes, bubble, *K);
            addSecond(b, 1, 1, 0.5*m(1), nodes, bubble, *K);
            addSecond(b, 0, 1, m(2), nodes, bubble, *K);
            for (int p = 0; p < 6; ++p)
            for (int j = 0; j < 2; ++j)
            {
                const int col = 2*p + j;
                tieWeight[it](j, p) += Wsh(0, col)*m(3) + Wsh(1, col)*m(4);
            }
        }
    }
    if (K)
    {
        for (int it = 0; it < nThickness_; ++it)
        for (int p = 0; p < 6; ++p)
        for (int j = 0; j < 2; ++j)
        {
            addSecond(tieB[it][p], j, 2, tieWeight[it](j, p), nodes, bubble, *K);
        }
    }
    return true;
}


bool mitc3::condense
(
    const std::array<shellNodeState, 3>& nodes,
    const shellDirector& C,
    Eigen::Vector2d& phi,
    const std::vector<materialState>* committed,
    std::vector<materialState>* trial,
    vecQ& f,
    matQ* K
) const
{
    // Newton on the bubble's equations f_b(phi) = 0, damped by halving
    // the step until |f_b| falls (a large plastic increment can overshoot);
    // the last evaluation's forces corrected to first order in its update
    vecB fB, fT;
    matB KB, KT;
    if (!integrate(nodes, bubbleAt(C, phi), committed, trial, &fB, &KB, nullptr))
    {
        return false;
    }
    for (int iter = 0; iter < 30; ++iter)
    {
        const Eigen::Matrix2d Kbb = KB.bottomRightCorner<2, 2>();
        if (!(Kbb(0, 0) > 0 && Kbb.determinant() > 0))
        {
            return false;       // no minimum in the bubble: cut back
        }
        const Eigen::Matrix2d Kinv = Kbb.inverse();
        const Eigen::Vector2d dphi = -Kinv*fB.tail<2>();
        if (dphi.norm() < 1e-10*(1 + phi.norm()))
        {
            const Eigen::Matrix<double, nDofs, 2> Kub =
                KB.topRightCorner<nDofs, 2>();
            f = fB.head<nDofs>() - Kub*(Kinv*fB.tail<2>());
            if (K)
            {
                *K = KB.topLeftCorner<nDofs, nDofs>()
                   - Kub*Kinv*KB.bottomLeftCorner<2, nDofs>();
            }
            return true;
        }
        const double r0 = fB.tail<2>().norm();
        bool accepted = false;
        for (double lambda = 1; lambda > 1e-3; lambda *= 0.5)
        {
            const Eigen::Vector2d p = phi + lambda*dphi;
            if
            (
                integrate(nodes, bubbleAt(C, p), committed, trial, &fT, &KT, nullptr)
             && fT.tail<2>().norm() < (1 - 1e-4*lambda)*r0
            )
            {
                phi = p;
                fB = fT;
                KB = KT;
                accepted = true;
                break;
            }
        }
        if (!accepted) return false;
    }
    return false;
}


bool mitc3::compute
(
    const std::array<shellNodeState, 3>& nodes,
    const std::vector<materialState>& committed,
    std::vector<materialState>& trial,
    vecQ& f,
    matQ* K
) const
{
    if
    (
        int(committed.size()) != nStates()
     || int(trial.size()) != nStates()
    )
    {
        throw numericalError
        (
            "mitc3: " + std::to_string(committed.size()) + " states for "
          + std::to_string(nStates()) + " (integration points and bubble)"
        );
    }
    const shellDirector C = bubbleFrame(committed);
    // Start from the trial's bubble if it belongs to the same frame (the
    // last solution of this step), else from the committed bubble
    Eigen::Vector2d phi = Eigen::Vector2d::Zero();
    const vecX& th = trial.back().history;
    if
    (
        th.size() == bubbleSize && th.segment<3>(0) == C.V
     && th.segment<3>(3) == C.V1 && th.segment<3>(6) == C.V2
    )
    {
        phi = th.segment<2>(9);
    }
    if (!condense(nodes, C, phi, &committed, &trial, f, K)) return false;
    vecX& h = trial.back().history;
    h.resize(bubbleSize);
    h << C.V, C.V1, C.V2, phi;
    return true;
}


void mitc3::compute
(
    const std::array<shellNodeState, 3>& nodes,
    vecQ& f,
    matQ* K
) const
{
    if (law_->initialState().history.size())
    {
        throw numericalError
        (
            "mitc3::compute: a law with history needs the states"
        );
    }
    Eigen::Vector2d phi = Eigen::Vector2d::Zero();
    if (!condense(nodes, shellDirector::of(V04_), phi, nullptr, nullptr, f, K))
    {
        throw numericalError("mitc3::compute: the lamina law or the bubble failed");
    }
}


bool mitc3::computeFull
(
    const std::array<shellNodeState, 3>& nodes,
    const Eigen::Vector2d& phi,
    const std::vector<materialState>& committed,
    std::vector<materialState>& trial,
    vecB& f,
    matB* K
) const
{
    return integrate
    (
        nodes, bubbleAt(bubbleFrame(committed), phi), &committed, &trial,
        &f, K, nullptr
    );
}


void mitc3::pointStrains
(
    const std::array<shellNodeState, 3>& nodes,
    const std::vector<materialState>& states,
    std::vector<mat3>& Q,
    std::vector<vec5>& eps
) const
{
    // The bubble of the states: their frame and increments
    const vecX& h = states.back().history;
    shellDirector C = shellDirector::of(V04_);
    Eigen::Vector2d phi = Eigen::Vector2d::Zero();
    if (h.size() == bubbleSize)
    {
        C.V = h.segment<3>(0);
        C.V1 = h.segment<3>(3);
        C.V2 = h.segment<3>(6);
        phi = h.segment<2>(9);
    }
    const bubbleState bubble = bubbleAt(C, phi);
    Q.resize(nQuadrature());
    eps.resize(nQuadrature());
    mat5 T;
    vec5 E;
    std::vector<std::array<basis, 6>> tieB(nThickness_);
    for (int it = 0; it < nThickness_; ++it)
    {
        for (int p = 0; p < 6; ++p)
        {
            tieB[it][p] = at(tie_[p][0], tie_[p][1], zt_[it], nodes, bubble);
        }
    }
    int q = 0;
    for (const quadraturePoint2D& pt : gaussTriangle7())
    {
        for (int it = 0; it < nThickness_; ++it, ++q)
        {
            const basis b = at(pt.r, pt.s, zt_[it], nodes, bubble);
            double detJ;
            localFrame(b.G, T, Q[q], detJ);
            strains(pt.r, pt.s, b, tieB[it], E, nullptr);
            eps[q] = T*E;
        }
    }
}


double mitc3::energy(const std::array<shellNodeState, 3>& nodes) const
{
    vecQ f;
    Eigen::Vector2d phi = Eigen::Vector2d::Zero();
    const shellDirector C = shellDirector::of(V04_);
    if (!condense(nodes, C, phi, nullptr, nullptr, f, nullptr))
    {
        throw numericalError("mitc3::energy: the bubble did not converge");
    }
    double W = 0;
    integrate(nodes, bubbleAt(C, phi), nullptr, nullptr, nullptr, nullptr, &W);
    return W;
}



std::vector<double> mitc3::pointVolumes() const
{
    // The points of integrate(), q = nThickness i_p + i_t; the initial
    // base vectors G do not depend on the node states
    const std::array<shellNodeState, 3> rest{};
    const bubbleState restBubble{};
    std::vector<double> v;
    Eigen::Matrix<double, 5, 5> T;
    mat3 Q;
    for (const quadraturePoint2D& pt : gaussTriangle7())
    {
        for (int it = 0; it < nThickness_; ++it)
        {
            double detJ;
            localFrame(at(pt.r, pt.s, zt_[it], rest, restBubble).G, T, Q, detJ);
            v.push_back(detJ*pt.w*wt_[it]);
        }
    }
    return v;
}

} // namespace form
