#include "InterruptScope.h"

#include <atomic>

namespace
{
    std::atomic<bool> interrupted{false};

    void onInterrupt(int)
    {
        interrupted = true;
    }
}  // namespace

ompl_parc::python::InterruptScope::InterruptScope()
{
    interrupted = false;
    struct sigaction action = {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
}

ompl_parc::python::InterruptScope::~InterruptScope()
{
    sigaction(SIGINT, &previous_, nullptr);
}

bool ompl_parc::python::InterruptScope::fired()
{
    return interrupted;
}
