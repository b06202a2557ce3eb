/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Trapezoidal rule and Bathe composite scheme as acceleration laws for
    the Newton solver (timeIntegrator.H).
\*---------------------------------------------------------------------------*/
#include "timeIntegrator.H"
#include "solidModel.H"
#include "contactModel.H"
#include "formError.H"
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace form
{

timeIntegrator::timeIntegrator(const std::string& type, double gamma)
:
    type_(type),
    gamma_(gamma)
{
    if (type_ != "trapezoidal" && type_ != "bathe")
    {
        throw inputError
        (
            "integrator",
            "unknown integrator '" + type_ + "'; valid: trapezoidal bathe"
        );
    }
    if (type_ == "bathe" && !(gamma_ > 0 && gamma_ < 1))
    {
        throw inputError
        (
            "gamma",
            "the Bathe splitting parameter gamma must lie in (0, 1), got "
          + std::to_string(gamma_)
        );
    }
}


int timeIntegrator::nStages() const
{
    return type_ == "bathe" ? 2 : 1;
}


double timeIntegrator::stageEnd(int stage, double t0, double t1) const
{
    if (type_ == "bathe" && stage == 0) return t0 + gamma_*(t1 - t0);
    return t1;
}




void timeIntegrator::initialise(solidModel& model, double t0, const vecX& V0)
{
    const int n = model.nDofs();
    if (!model.hasInertia())
    {
        throw numericalError
        (
            "timeIntegrator::initialise: the model has no inertia"
            " (solidModel::setInertia)"
        );
    }
    U_ = model.U();
    V_ = V0.size() ? V0 : vecX(vecX::Zero(n));
    if (V_.size() != n)
    {
        throw numericalError
        (
            "timeIntegrator::initialise: initial velocity has "
          + std::to_string(V_.size()) + " entries for " + std::to_string(n)
          + " dofs"
        );
    }
    A_ = vecX::Zero(n);

    // Static residual at the initial state (no inertia forces)
    model.setAccelerationLaw(0, vecX::Zero(n));
    vecX r;
    if (!model.evaluate(t0, r, false))
    {
        throw numericalError
        (
            "timeIntegrator::initialise: material update failed at the"
            " initial state"
        );
    }
    const int nFree = model.nFreeDofs();
    const vecX rf = r.head(nFree);
    const double level = std::max
    (
        model.externalForce().norm(), model.internalForce().norm()
    );
    if (nFree > 0 && rf.norm() > 1e-12*std::max(level, 1e-300))
    {
        // M_ff A_f = r_f
        const std::vector<int>& free = model.freeDofs();
        std::vector<int> freeIndex(n, -1);
        for (int k = 0; k < nFree; ++k) freeIndex[free[k]] = k;
        const sparseMatrix& M = model.massMatrix();
        std::vector<Eigen::Triplet<double>> entries;
        for (int j = 0; j < M.outerSize(); ++j)
        {
            for (sparseMatrix::InnerIterator it(M, j); it; ++it)
            {
                const int i = freeIndex[it.row()], k = freeIndex[it.col()];
                if (i >= 0 && k >= 0) entries.emplace_back(i, k, it.value());
            }
        }
        Eigen::SparseMatrix<double> Mff(nFree, nFree);
        Mff.setFromTriplets(entries.begin(), entries.end());
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Mff);
        vecX Af;
        if (ldlt.info() == Eigen::Success) Af = ldlt.solve(rf);
        if (ldlt.info() != Eigen::Success || !Af.allFinite())
        {
            throw numericalError
            (
                "timeIntegrator::initialise: the mass matrix is singular on"
                " the free dofs (a free dof without mass); the initial"
                " acceleration cannot be computed"
            );
        }
        for (int k = 0; k < nFree; ++k) A_(free[k]) = Af(k);
    }
    work_.start(model);
    energy_ = energyBalance();
    energy_.kinetic = 0.5*V_.dot(model.massMatrix()*V_);
    energy_.initialKinetic = energy_.kinetic;
    Um_ = U_;
    Vm_ = V_;
}


void timeIntegrator::trapezoidalLaw(double h, solidModel& model) const
{
    const double alpha = 4/(h*h);
    model.setAccelerationLaw(alpha, -alpha*U_ - (4/h)*V_ - A_);
    // v = (2/h)(U - U_n) - V_n
    model.setVelocityLaw(2/h, -(2/h)*U_ - V_);
}


void timeIntegrator::beginStage
(
    int stage,
    double t0,
    double t1,
    solidModel& model
)
{
    if (U_.size() != model.nDofs())
    {
        throw numericalError
        (
            "timeIntegrator::beginStage: not initialised"
        );
    }
    const double h = t1 - t0;
    contactModel* contact = model.contact();
    if (stage == 0)
    {
        trapezoidalLaw(stageEnd(0, t0, t1) - t0, model);
        // Slip rates: the mean velocity over the (sub-)step, the one the
        // trapezoidal displacement update uses (contactModel.H)
        if (contact) contact->setSlipRateLaw(1, 0);
        return;
    }
    // Bathe, three-point Euler backward over the whole step
    const double g = gamma_;
    const double c1 = (1 - g)/(g*h);
    const double c2 = -1/((1 - g)*g*h);
    const double c3 = (2 - g)/((1 - g)*h);
    model.setAccelerationLaw
    (
        c3*c3,
        c1*V_ + c2*Vm_ + c3*(c1*U_ + c2*Um_)
    );
    // v = c1 U_n + c2 U_m + c3 U (as endStage)
    model.setVelocityLaw(c3, c1*U_ + c2*Um_);
    // Slip rates by the same formula, c3 (xi - xi_m) - c1 (xi_m - xi_t),
    // scaled by the stage length (1 - gamma) h (contactModel.H)
    if (contact) contact->setSlipRateLaw(2 - g, -(1 - g)*(1 - g)/g);
}


void timeIntegrator::endStage
(
    int stage,
    double t0,
    double t1,
    const solidModel& model
)
{
    const vecX& U = model.U();
    const vecX a = model.acceleration();
    vecX v;
    if (stage == 0)
    {
        const double h = stageEnd(0, t0, t1) - t0;
        v = (2/h)*(U - U_) - V_;
    }
    else
    {
        const double h = t1 - t0;
        const double g = gamma_;
        const double c1 = (1 - g)/(g*h);
        const double c2 = -1/((1 - g)*g*h);
        const double c3 = (2 - g)/((1 - g)*h);
        v = c1*U_ + c2*Um_ + c3*U;
    }

    // Work over the stage (trapezoidal quadrature from the previous
    // stage's end, or the step's start), as the step's increments: they
    // are summed over the stages first and then added to the integrals
    if (stage == 0)
    {
        pendingWork_ = work_;
        pendingWork_.internalWork = 0;
        pendingWork_.externalWork = 0;
        pendingWork_.contactWork = 0;
        pendingWork_.frictionWork = 0;
    }
    pendingWork_.add(model);

    Unew_ = U;
    Vnew_ = v;
    Anew_ = a;
    if (stage == 0)
    {
        Um_ = U;
        Vm_ = v;
    }
    pendingKinetic_ = 0.5*v.dot(model.massMatrix()*v);
}


void timeIntegrator::commitStep()
{
    U_ = Unew_;
    V_ = Vnew_;
    A_ = Anew_;
    energy_.kinetic = pendingKinetic_;
    energy_.internalWork += pendingWork_.internalWork;
    energy_.externalWork += pendingWork_.externalWork;
    energy_.contactWork += pendingWork_.contactWork;
    energy_.frictionWork += pendingWork_.frictionWork;
    work_ = pendingWork_;
    Um_ = U_;
    Vm_ = V_;
}


void timeIntegrator::revertStep()
{
    Um_ = U_;
    Vm_ = V_;
}


std::vector<double> timeIntegrator::state() const
{
    std::vector<double> s;
    for
    (
        const vecX* v
      : {&U_, &V_, &A_, &work_.fint, &work_.fext, &work_.fcon, &work_.ffri}
    )
    {
        s.insert(s.end(), v->data(), v->data() + v->size());
    }
    s.insert
    (
        s.end(),
        {
            energy_.kinetic, energy_.internalWork, energy_.externalWork,
            energy_.contactWork, energy_.frictionWork,
            energy_.initialKinetic
        }
    );
    return s;
}


void timeIntegrator::setState(const std::vector<double>& s)
{
    // 7 nodal vectors and 6 energies (5 in restart files written before
    // the initial kinetic energy was kept: the two sizes differ mod 7)
    constexpr int nVectors = 7;
    const int nEnergies =
        s.size() >= 6 && (s.size() - 6) % nVectors == 0 ? 6 : 5;
    if (s.size() < std::size_t(nEnergies) || (s.size() - nEnergies) % nVectors)
    {
        throw numericalError
        (
            "timeIntegrator::setState: " + std::to_string(s.size())
          + " values, not 7 nodal vectors and 6 energies"
        );
    }
    const int n = int((s.size() - nEnergies)/nVectors);
    int i = 0;
    for
    (
        vecX* v
      : {&U_, &V_, &A_, &work_.fint, &work_.fext, &work_.fcon, &work_.ffri}
    )
    {
        *v = Eigen::Map<const vecX>(s.data() + i, n);
        i += n;
    }
    work_.U = U_;
    energy_.kinetic = s[i];
    energy_.internalWork = s[i + 1];
    energy_.externalWork = s[i + 2];
    energy_.contactWork = s[i + 3];
    energy_.frictionWork = s[i + 4];
    energy_.initialKinetic = nEnergies == 6 ? s[i + 5] : 0.0;
    Um_ = U_;
    Vm_ = V_;
}

} // namespace form
