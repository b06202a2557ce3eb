/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The linearSolver auto: CHOLMOD until its first indefinite factorisation,
    UMFPACK from then on (autoSolver.H).
\*---------------------------------------------------------------------------*/
#include "autoSolver.H"
#include "formError.H"

form::autoSolver::autoSolver(std::ostream* log)
:
    solver_(linearSolver::New("cholmod")),
    log_(log)
{}


std::string form::autoSolver::type() const
{
    return "auto (" + solver_->type() + ")";
}


void form::autoSolver::analyzePattern(const sparseMatrix& K)
{
    solver_->analyzePattern(K);
}


void form::autoSolver::factorize(const sparseMatrix& K)
{
    if (switched_)
    {
        solver_->factorize(K);
        return;
    }
    try
    {
        solver_->factorize(K);
    }
    catch (const numericalError& err)
    {
        if (log_)
        {
            *log_ << "    linear solver: " << err.what()
                  << "\n    linear solver: switching from cholmod to umfpack"
                  << " for the rest of the run" << std::endl;
        }
        solver_ = linearSolver::New("umfpack");
        switched_ = true;
        solver_->analyzePattern(K);
        solver_->factorize(K);
    }
}


form::vecX form::autoSolver::solve(const vecX& r)
{
    return solver_->solve(r);
}


form::linearSolver::factorStats form::autoSolver::stats() const
{
    return solver_->stats();
}


double form::autoSolver::factorMemory() const
{
    return solver_->factorMemory();
}
