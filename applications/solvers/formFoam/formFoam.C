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
#include "IFstream.H"
#include "OSspecific.H"
#include <new>
#include <unistd.h>

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

//- Edit distance of two keywords (for "did you mean")
label distance(const std::string& a, const std::string& b)
{
    std::vector<label> d(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) d[j] = label(j);
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        label prev = d[0];
        d[0] = label(i);
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const label cur = d[j];
            d[j] = min(min(d[j] + 1, d[j - 1] + 1), prev + (a[i-1] != b[j-1]));
            prev = cur;
        }
    }
    return d[b.size()];
}


//- The entries of system/controlDict that OpenFOAM's Time needs, checked
//  before Time reads them, so that a missing or misspelt one is named as
//  the user wrote it (Time would report e.g. 'writeFrequency not found')
void checkControlDict(const fileName& caseDir)
{
    const fileName file = caseDir/"system"/"controlDict";
    if (!isFile(file))
    {
        FatalErrorInFunction
            << "No system/controlDict in the case directory " << caseDir
            << ": is this an OpenFOAM case? (run formFoam in the case"
            << " directory, or give it with -case)" << exit(FatalError);
    }
    IFstream is(file);
    const dictionary d(is);
    wordList required{"deltaT", "writeInterval"};
    if (d.getOrDefault<word>("startFrom", "startTime") == "startTime")
    {
        required.append("startTime");
    }
    if (d.getOrDefault<word>("stopAt", "endTime") == "endTime")
    {
        required.append("endTime");
    }
    // Entries OpenFOAM's Time takes with a warning or silently when wrong
    const auto oneOf = [&](const word& key, const wordList& valid)
    {
        if (!d.found(key)) return;
        const word v = d.get<word>(key);
        if (!valid.found(v))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "' in " << file << ": unknown '" << v
                << "'; valid: " << valid << exit(FatalIOError);
        }
    };
    oneOf("writeFormat", {"ascii", "binary"});
    oneOf("timeFormat", {"general", "fixed", "scientific"});
    oneOf("startFrom", {"firstTime", "startTime", "latestTime"});
    oneOf("stopAt", {"endTime", "writeNow", "noWriteNow", "nextWrite"});
    oneOf
    (
        "writeControl",
        // (formFoam writes by step count or simulated time; clockTime and
        // cpuTime are not implemented)
        {"timeStep", "runTime", "adjustableRunTime", "adjustable"}
    );
    if (d.found("writeInterval") && !(d.get<scalar>("writeInterval") > 0))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'writeInterval' in " << file << " must be positive"
            << " (steps for writeControl timeStep, a time otherwise)"
            << exit(FatalIOError);
    }
    for (const word key : {"writePrecision", "timePrecision"})
    {
        if (d.found(key) && !(d.get<label>(key) > 0 && d.get<label>(key) <= 30))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "' in " << file << " is out of range:"
                << " a number of digits from 1 to 30" << exit(FatalIOError);
        }
    }
    for (const word& key : required)
    {
        if (d.found(key)) continue;
        word near;
        for (const entry& e : d)
        {
            if (distance(e.keyword(), key) <= 2) near = e.keyword();
        }
        FatalIOErrorInFunction(d)
            << "Entry '" << key << "' missing in " << file
            << (
                   near.empty() ? std::string()
                 : " (is '" + near + "' meant to be '" + key + "'?)"
               ).c_str()
            << exit(FatalIOError);
    }
}


//- OpenFOAM case paths cannot hold white space (OpenFOAM strips it, and
//  then looks for another directory)
void checkCasePath(int argc, char* argv[])
{
    std::string path;
    for (int i = 1; i + 1 < argc; ++i)
    {
        if (std::string(argv[i]) == "-case") path = argv[i + 1];
    }
    if (path.empty() || path[0] != '/')
    {
        char cwd[4096];
        if (::getcwd(cwd, sizeof(cwd)))
        {
            path = path.empty() ? std::string(cwd) : std::string(cwd) + "/" + path;
        }
    }
    if (path.find_first_of(" \t\n") != std::string::npos)
    {
        FatalErrorInFunction
            << "The case directory '" << path.c_str() << "' contains a space:"
            << " OpenFOAM case paths cannot contain spaces. Move or rename"
            << " the case (or a directory above it)" << exit(FatalError);
    }
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
            "check the Newton matrix along every Newton update against"
            " central differences of the residual (logged per iteration,"
            " the largest error in the log's end and the summary's"
            " tangentCheckMax); with a fluid, also compare its block with"
            " finite differences after each converged step (dense: all"
            " columns up to 3000 fluid unknowns, above only those of its"
            " coupling with the solid)"
        );
        checkCasePath(argc, argv);
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

        checkControlDict(args.path());
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
