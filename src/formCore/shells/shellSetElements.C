/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    shellSet (shellSet.H): the evaluation of its elements, quadrilaterals
    (MITC4, MITC4+) and triangles (MITC3+): the node states they see,
    forces and tangents, results per element, mass matrices, initial
    states.
\*---------------------------------------------------------------------------*/
#include "shellSet.H"
#include "surfaceStrain.H"
#include "quadShape.H"
#include "planeStressMaterial.H"
#include <algorithm>
#include <cmath>

namespace form
{

template<int N>
std::array<shellNodeState, N> shellSet::nodeStates
(
    int block,
    int element,
    const dofMap& dofs,
    const vecX& U
) const
{
    const int* nodes = connectivity_[block].data() + N*element;
    std::array<shellNodeState, N> states;
    for (int k = 0; k < N; ++k)
    {
        const int n = nodes[k];
        const int s = shellNode_[n];
        states[k].u = dofs.vector3(U, n);
        const Eigen::Vector2d d = increment(s, dofs, U);
        states[k].director = frames_[s].at(d(0), d(1));
        // the committed director's change (zero until the first fold)
        // and the increment's, each without cancellation
        states[k].dV = (frames_[s].V - V0_[s]) + states[k].director.dVc;
    }
    return states;
}


std::vector<materialState> shellSet::initialStates(int block) const
{
    if (!tris_[block].empty()) return tris_[block].front().initialStates();
    const mitc4& el = quads_[block].front();
    return std::vector<materialState>(el.nQuadrature(), el.law().initialState());
}


namespace
{

//- Forces and tangent of an element of either type into fe, Ke
template<class Element, std::size_t N>
bool computeElement
(
    const Element& el,
    const std::array<shellNodeState, N>& nodes,
    const std::vector<materialState>& committed,
    std::vector<materialState>& trial,
    vecX& fe,
    matX* Ke
)
{
    typename Element::vecQ f;
    typename Element::matQ K;
    const bool ok = el.compute(nodes, committed, trial, f, Ke ? &K : nullptr);
    fe = f;
    if (Ke) *Ke = K;
    return ok;
}

} // anonymous namespace


bool shellSet::compute
(
    int block,
    int element,
    const dofMap& dofs,
    const vecX& U,
    const std::vector<materialState>& committed,
    std::vector<materialState>& trial,
    vecX& fe,
    matX* Ke
) const
{
    return
        npe_[block] == 3
      ? computeElement
        (
            tris_[block][element], nodeStates<3>(block, element, dofs, U),
            committed, trial, fe, Ke
        )
      : computeElement
        (
            quads_[block][element], nodeStates<4>(block, element, dofs, U),
            committed, trial, fe, Ke
        );
}


double shellSet::plasticDissipation
(
    int block,
    int element,
    const std::vector<materialState>& states
) const
{
    const std::vector<double> v = npe_[block] == 3
      ? tris_[block][element].pointVolumes()
      : quads_[block][element].pointVolumes();
    const shellLaw& lamina = law(block);
    double D = 0;
    for (std::size_t q = 0; q < v.size(); ++q)
    {
        D += v[q]*lamina.plasticDissipation(states[q]);
    }
    return D;
}


elementResult shellSet::result
(
    int block,
    int element,
    const dofMap& dofs,
    const vecX& U,
    const std::vector<materialState>& states
) const
{
    std::vector<mat3> Q;
    std::vector<vec5> eps;
    const shellLaw* lamina = nullptr;
    const std::vector<double>* points = nullptr;
    if (npe_[block] == 3)
    {
        const mitc3& el = tris_[block][element];
        el.pointStrains(nodeStates<3>(block, element, dofs, U), states, Q, eps);
        lamina = &el.law();
        points = &el.thicknessPoints();
    }
    else
    {
        const mitc4& el = quads_[block][element];
        el.pointStrains(nodeStates<4>(block, element, dofs, U), Q, eps);
        lamina = &el.law();
        points = &el.thicknessPoints();
    }
    const auto* law = dynamic_cast<const planeStressMaterial*>(lamina);
    elementResult r;
    if (!law) return r;
    const int nq = int(Q.size());
    // The bottom, middle and top points through the thickness: weights
    // of point it in each layer
    const std::vector<double>& zt = *points;
    const int nT = int(zt.size());
    std::vector<std::array<double, 3>> layer(nT, {0, 0, 0});
    const int bottom = int(std::min_element(zt.begin(), zt.end()) - zt.begin());
    const int top = int(std::max_element(zt.begin(), zt.end()) - zt.begin());
    // the in-plane points' share: 1/4 (quadrilaterals), 1/7 (triangles)
    const double share = 1.0/(nq/nT);
    layer[bottom][0] = layer[top][2] = share;
    std::vector<int> order(nT);
    for (int i = 0; i < nT; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return zt[a] < zt[b]; });
    if (nT % 2) layer[order[nT/2]][1] = share;
    else layer[order[nT/2 - 1]][1] = layer[order[nT/2]][1] = 0.5*share;
    for (int q = 0; q < nq; ++q)
    {
        const planeStressMaterial::pointOutput o =
            law->output(Q[q], eps[q], states[q]);
        for (int l = 0; l < 3; ++l) r.shellLayers[l] += layer[q % nT][l]*o.cauchy;
        r.cauchy += o.cauchy/nq;
        r.equivalentStrain += o.equivalentStrain/nq;
        r.thicknessStretch = q
          ? std::min(r.thicknessStretch, o.thicknessStretch)
          : o.thicknessStretch;
        r.meanThicknessStretch += (o.thicknessStretch - 1)/nq;
    }
    r.pressure = -r.cauchy.trace()/3;
    // The mid-surface's principal strains, from the corners' reference
    // and current positions
    const int npe = npe_[block];
    matX X0(npe, 3), x(npe, 3);
    for (int k = 0; k < npe; ++k)
    {
        const vec3 Xk = npe == 3
          ? tris_[block][element].referencePoint(k)
          : quads_[block][element].referencePoint(k);
        X0.row(k) = Xk.transpose();
        x.row(k) = (Xk + dofs.vector3(U, connectivity_[block][npe*element + k]))
            .transpose();
    }
    const surfaceStrain ss = surfaceStrains(X0, x);
    r.majorStrain = ss.major;
    r.minorStrain = ss.minor;
    return r;
}


matX shellSet::massMatrix
(
    int block,
    int element,
    double rho,
    bool lumped
) const
{
    const int npe = npe_[block];
    const double t = thickness_[shellNode_[connectivity_[block][npe*element]]];
    // m_ab = int N_a N_b dA on the initial mid-surface
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(npe, npe);
    if (npe == 3)
    {
        const mitc3& el = tris_[block][element];
        const double area = 0.5*
        (
            (el.referencePoint(1) - el.referencePoint(0)).cross
            (
                el.referencePoint(2) - el.referencePoint(0)
            )
        ).norm();
        m.setConstant(area/12);
        m.diagonal().setConstant(area/6);
    }
    else
    {
        const mitc4& el = quads_[block][element];
        Eigen::Matrix<double, 4, 3> X;
        for (int k = 0; k < 4; ++k) X.row(k) = el.referencePoint(k).transpose();
        const double g = 1/std::sqrt(3.0);
        for (const double r : {-g, g})
        {
            for (const double s : {-g, g})
            {
                quadShape<4>::vecN N;
                quadShape<4>::matN2 dN;
                quadShape<4>::eval(r, s, N, dN);
                const vec3 Xr = X.transpose()*dN.col(0);
                const vec3 Xs = X.transpose()*dN.col(1);
                m += N*N.transpose()*Xr.cross(Xs).norm();
            }
        }
    }
    matX M = matX::Zero(5*npe, 5*npe);
    for (int a = 0; a < npe; ++a)
    {
        const double area = m.row(a).sum();      // int N_a dA
        for (int b = 0; b < npe; ++b)
        {
            const double mab = lumped ? (a == b ? area : 0.0) : m(a, b);
            for (int i = 0; i < 3; ++i) M(5*a + i, 5*b + i) = rho*t*mab;
        }
        M(5*a + 3, 5*a + 3) = M(5*a + 4, 5*a + 4) = rho*t*t*t/12*area;
    }
    return M;
}

} // namespace form
