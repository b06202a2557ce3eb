/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Main of formFoamTests, the unit tests of the OpenFOAM layer (the ALE
    fluid's operators on small scratch cases). OpenFOAM errors throw
    (FatalError.throwExceptions) so that a failure is a test failure with
    its message, not an exit of the binary.
\*---------------------------------------------------------------------------*/
#include "error.H"
#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
