/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Trapezoidal work integrals of a solid's motion (workLedger.H).
\*---------------------------------------------------------------------------*/
#include "workLedger.H"
#include "solidModel.H"
#include "formError.H"
#include <string>

namespace form
{

namespace
{

// The external force g of the work integrals: applied loads on the free
// dofs, the support forces f_int + M a on the prescribed ones (the work
// of the prescribed motion)
vecX workForce(const solidModel& model)
{
    vecX g = model.externalForce();
    const vecX& fi = model.internalForce();
    const vecX& fm = model.inertiaForce();
    for (int d : model.prescribedDofs())
    {
        g(d) = fi(d) + (fm.size() ? fm(d) : 0.0);
    }
    return g;
}

// A force of the model, or zero before its first evaluate()
vecX orZero(const vecX& f, int n)
{
    return f.size() == n ? f : vecX(vecX::Zero(n));
}

} // namespace


void workLedger::start(const solidModel& model)
{
    const int n = model.nDofs();
    *this = workLedger();
    U = model.U();
    const bool evaluated = model.internalForce().size() == n;
    fint = orZero(model.internalForce(), n);
    fext = evaluated ? workForce(model) : vecX(vecX::Zero(n));
    fcon = orZero(model.contactForce(), n);
    ffri = orZero(model.frictionForce(), n);
}


void workLedger::add(const solidModel& model)
{
    const vecX& fi = model.internalForce();
    const vecX g = workForce(model);
    const vecX fc = model.contactForce();
    const vecX ft = model.frictionForce();
    const vecX dU = model.U() - U;
    internalWork += 0.5*(fint + fi).dot(dU);
    externalWork += 0.5*(fext + g).dot(dU);
    contactWork += 0.5*(fcon + fc).dot(dU);
    frictionWork += 0.5*(ffri + ft).dot(dU);
    U = model.U();
    fint = fi;
    fext = g;
    fcon = fc;
    ffri = ft;
}


std::vector<double> workLedger::state() const
{
    std::vector<double> s
    {
        internalWork, externalWork, contactWork, frictionWork
    };
    for (const vecX* v : {&U, &fint, &fext, &fcon, &ffri})
    {
        s.insert(s.end(), v->data(), v->data() + v->size());
    }
    return s;
}


void workLedger::setState(const std::vector<double>& s, int nDofs)
{
    if (s.size() != 4 + 5*std::size_t(nDofs))
    {
        throw numericalError
        (
            "workLedger::setState: " + std::to_string(s.size())
          + " values, not 4 integrals and 5 vectors of "
          + std::to_string(nDofs) + " dofs"
        );
    }
    internalWork = s[0];
    externalWork = s[1];
    contactWork = s[2];
    frictionWork = s[3];
    std::size_t i = 4;
    for (vecX* v : {&U, &fint, &fext, &fcon, &ffri})
    {
        *v = Eigen::Map<const vecX>(s.data() + i, nDofs);
        i += nDofs;
    }
}

} // namespace form
