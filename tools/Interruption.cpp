#include "Interruption.h"

#include "ToolSupport.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>

#include <unistd.h>

namespace
{
    // What the handler touches: lock-free atomics and text written before it is installed.
    static_assert(std::atomic<bool>::is_always_lock_free, "the SIGINT handler needs a lock-free flag");
    std::atomic<bool> interrupted{false};
    std::atomic<bool> exitAtFirst{false};

    /** \brief A line the handler writes as it is (write(2) is async-signal-safe, building a string is not). */
    struct Line
    {
        char text[256]{};
        std::size_t length{0};

        void set(const std::string &line)
        {
            length = std::min(line.size(), sizeof(text));
            std::memcpy(text, line.data(), length);
        }

        void write() const
        {
            // Nothing to do if stderr is gone: the signal is handled all the same.
            [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, text, length);
        }
    };
    Line stopLine, exitLine;

    struct sigaction previousAction;

    void onInterrupt(int)
    {
        const int savedErrno = errno;
        if (exitAtFirst.load() || interrupted.exchange(true))
        {
            exitLine.write();
            _exit(ompl_parc::tools::EXIT_INTERRUPTED);
        }
        stopLine.write();
        errno = savedErrno;
    }
}  // namespace

ompl_parc::tools::Interruption::Interruption(const std::string &tool, FirstSignal first, const std::string &stopping)
{
    struct sigaction current = {};
    sigaction(SIGINT, nullptr, &current);
    if (current.sa_handler == SIG_IGN)
        return;
    interrupted = false;
    exitAtFirst = first == FirstSignal::EXIT;
    // On a terminal the "^C" echo (and a live progress line) end without a line break: start a line of our own.
    const std::string start = isatty(STDERR_FILENO) != 0 ? "\n" + tool : tool;
    stopLine.set(start + ": interrupted, " + stopping + " (Ctrl-C again quits at once)\n");
    exitLine.set(start + ": interrupted\n");
    struct sigaction ours = {};
    ours.sa_handler = onInterrupt;
    ours.sa_flags = SA_RESTART;  // a read or write in progress goes on rather than failing with EINTR
    sigemptyset(&ours.sa_mask);
    sigaction(SIGINT, &ours, &previousAction);
    listens_ = true;
}

ompl_parc::tools::Interruption::~Interruption()
{
    if (listens_)
        sigaction(SIGINT, &previousAction, nullptr);
}

bool ompl_parc::tools::Interruption::raised()
{
    return interrupted;
}

ompl::base::PlannerTerminationCondition ompl_parc::tools::Interruption::condition()
{
    return ompl::base::PlannerTerminationCondition([] { return interrupted.load(); });
}
