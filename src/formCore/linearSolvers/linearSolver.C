/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Run-time selection of the sparse direct solvers (see linearSolver.H).
\*---------------------------------------------------------------------------*/
#include "linearSolver.H"
#include "cholmodSolver.H"
#include "umfpackSolver.H"
#include "sparseLUSolver.H"
#include "formError.H"

std::string form::linearSolver::validTypes()
{
    return "cholmod umfpack sparseLU";
}


std::unique_ptr<form::linearSolver> form::linearSolver::New
(
    const std::string& name
)
{
    if (name == "cholmod") return std::make_unique<cholmodSolver>();
    if (name == "umfpack") return std::make_unique<umfpackSolver>();
    if (name == "sparseLU") return std::make_unique<sparseLUSolver>();
    throw inputError
    (
        "linearSolver",
        "unknown linearSolver '" + name + "'; valid: " + validTypes()
    );
}
