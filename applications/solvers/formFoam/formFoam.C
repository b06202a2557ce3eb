/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Application
    formFoam

Description
    Implicit finite-element solver for metal forming (Kawka & Bathe): mixed
    u/p solid elements, static Newton-Raphson with the consistent tangent.
    The case is a scene: only the effects it declares are built (see
    src/formFoam/formScene/formScene.H for the dictionaries).

Usage
    formFoam [-case dir] [-checkTangent]
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "formScene.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote("Implicit FE forming solver (formFoam)");
    argList::noParallel();
    argList::addBoolOption
    (
        "checkTangent",
        "after each converged step, compare the fluid block's Newton matrix"
        " with finite differences of its residuals (dense: all columns up"
        " to 3000 fluid unknowns, above only those of its coupling with the"
        " solid)"
    );
    #include "setRootCase.H"
    #include "createTime.H"

    formScene scene(runTime);
    scene.checkTangents(args.found("checkTangent"));
    scene.run();

    return 0;
}
