/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    caseLock: one run per case directory (caseLock.H)
\*---------------------------------------------------------------------------*/
#include "caseLock.H"
#include "error.H"
#include "OSspecific.H"
#include "messageStream.H"
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{

//- The lock of this process, released at exit: an error ends the run with
//  std::exit, which does not unwind to the lock's destructor
Foam::caseLock* held = nullptr;

void releaseAtExit()
{
    if (held) held->release();
}

std::string thisHost()
{
    char buf[256] = {0};
    ::gethostname(buf, sizeof(buf) - 1);
    return buf;
}

} // namespace


bool Foam::caseLock::create() const
{
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) return false;
    const std::string owner =
        thisHost() + " " + std::to_string(::getpid()) + "\n";
    const bool ok =
        ::write(fd, owner.data(), owner.size()) == ssize_t(owner.size());
    ::close(fd);
    return ok;
}


Foam::caseLock::caseLock(const fileName& caseDir)
:
    path_(caseDir/".formFoam.lock")
{
    for (int attempt = 0; attempt < 2 && !held_; ++attempt)
    {
        if (create())
        {
            held_ = true;
            break;
        }
        if (errno != EEXIST)
        {
            FatalErrorInFunction
                << "Cannot create " << path_ << " (" << std::strerror(errno)
                << "): is the case directory writable?" << exit(FatalError);
        }
        // Who holds it? A lock of a run that no longer exists is stale
        std::ifstream is(path_);
        std::string host;
        long pid = 0;
        is >> host >> pid;
        const bool alive =
            pid > 0 && host == thisHost()
         && (::kill(pid_t(pid), 0) == 0 || errno == EPERM);
        if (alive || (pid > 0 && host != thisHost()))
        {
            FatalErrorInFunction
                << "Another formFoam run (PID " << label(pid) << " on "
                << host.c_str() << ") is running in this case directory ("
                << path_ << "): two runs in one case would mix their"
                << " results. Wait for it to end, or run this one in a copy"
                << " of the case. If no such run exists, remove the lock"
                << " file." << exit(FatalError);
        }
        Info<< "Removing the stale lock " << path_ << " of a run (PID "
            << label(pid) << ") that ended without removing it" << endl;
        std::remove(path_.c_str());
    }
    if (!held_)
    {
        FatalErrorInFunction
            << "Cannot take the lock " << path_ << exit(FatalError);
    }
    static const bool registered = (std::atexit(releaseAtExit) == 0);
    (void)registered;
    held = this;
}


void Foam::caseLock::release()
{
    if (held_)
    {
        std::remove(path_.c_str());
        held_ = false;
    }
    if (held == this) held = nullptr;
}
