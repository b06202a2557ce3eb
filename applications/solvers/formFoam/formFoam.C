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

    Bad input ends in a message and exit code 1, never in an abort, a
    stack trace or a signal: OpenFOAM's fatal errors are thrown and caught
    here, a duplicate keyword in any dictionary read is an error
    (inputMode error), and the floating-point trap is off: formFoam checks
    numbers itself (every dictionary entry must be finite, every residual
    and update is checked), so an overflow in an entry such as 1e400 is
    reported with its file and entry instead of a SIGFPE.

Usage
    formFoam [-case dir] [-checkTangent]
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "sigFpe.H"
#include "formScene.H"
#include "formError.H"
#include <new>

using namespace Foam;

namespace
{

//- Report what stopped the run and exit with 1. std::exit, not a return:
//  the stack is not unwound, so argList's destructor (which ends the job
//  with exit code 0) never runs; OpenFOAM's own exit(FatalError) does the
//  same
[[noreturn]] void stop()
{
    try
    {
        throw;
    }
    catch (const Foam::IOerror& err)
    {
        Perr<< nl << err << nl;
        // OpenFOAM's reader stops on a number it cannot hold (1e400)
        // with a message that does not say so
        if (err.message().find("ill defined primitiveEntry") != std::string::npos)
        {
            Perr<< "    (a value that cannot be read: a number beyond the"
                << " range of a double, e.g. 1e400, or an unbalanced"
                << " bracket)" << nl;
        }
        Perr<< "\nformFoam: stopped on input error\n" << endl;
    }
    catch (const Foam::error& err)
    {
        Perr<< nl << err << nl << "\nformFoam: stopped\n" << endl;
    }
    catch (const form::inputError& err)
    {
        Perr<< nl << "--> formFoam: entry '" << err.entry().c_str()
            << "': " << err.what() << nl << "\nformFoam: stopped on input"
            << " error\n" << endl;
    }
    catch (const std::bad_alloc&)
    {
        Perr<< nl << "--> formFoam: out of memory" << nl << endl;
    }
    catch (const std::exception& err)
    {
        Perr<< nl << "--> formFoam: " << err.what() << nl
            << "\nformFoam: stopped\n" << endl;
    }
    catch (...)
    {
        Perr<< nl << "--> formFoam: stopped by an unknown exception" << nl
            << endl;
    }
    std::exit(1);
}

} // namespace


int main(int argc, char *argv[])
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    // On the heap: an error must not unwind it, since argList's destructor
    // ends the job with exit code 0
    argList* argsPtr = nullptr;
    try
    {
        argList::addNote("Implicit FE forming solver (formFoam)");
        argList::noParallel();
        argList::addBoolOption
        (
            "checkTangent",
            "after each converged step, compare the fluid block's Newton"
            " matrix with finite differences of its residuals (dense: all"
            " columns up to 3000 fluid unknowns, above only those of its"
            " coupling with the solid)"
        );
        argsPtr = new argList(argc, argv);
        argList& args = *argsPtr;
        if (!args.checkRootCase())
        {
            FatalError.exit();
        }

        // Numbers are checked by formFoam (see Description), not trapped
        sigFpe::unset(false);
        // A keyword given twice is an error in every dictionary read
        // from now on
        entry::globalInputMode = entry::inputMode::ERROR;

        #include "createTime.H"

        formScene scene(runTime);
        scene.checkTangents(args.found("checkTangent"));
        scene.run();
    }
    catch (...)
    {
        stop();
    }
    delete argsPtr;     // ends the job (exit code 0)
    return 0;
}
