#include "InterruptScope.h"

#include <pybind11/pybind11.h>

#include <atomic>
#include <csignal>
#include <mutex>

namespace
{
    std::atomic<bool> interrupted{false};
    std::mutex scopesMutex;
    unsigned int scopes = 0;
    struct sigaction pythons;

    void onInterrupt(int)
    {
        interrupted = true;
    }

    bool onMainThread()
    {
        const pybind11::module_ threading = pybind11::module_::import("threading");
        return threading.attr("current_thread")().is(threading.attr("main_thread")());
    }
}  // namespace

ompl_parc::python::InterruptScope::InterruptScope()
{
    if (!onMainThread())
        return;
    {
        const std::lock_guard<std::mutex> lock(scopesMutex);
        struct sigaction current = {};
        sigaction(SIGINT, nullptr, &current);
        if (scopes == 0 && current.sa_handler == SIG_IGN)
            return;
        if (scopes++ == 0)
        {
            interrupted = false;
            struct sigaction ours = {};
            ours.sa_handler = onInterrupt;
            ours.sa_flags = SA_RESTART;
            sigemptyset(&ours.sa_mask);
            sigaction(SIGINT, &ours, &pythons);
        }
        counted_ = true;
    }
    // A Ctrl-C between the caller's last bytecode and our handler is pending in Python: raise it now.
    if (PyErr_CheckSignals() != 0)
    {
        release();  // a constructor that throws gets no destructor call
        throw pybind11::error_already_set();
    }
}

ompl_parc::python::InterruptScope::~InterruptScope()
{
    release();
}

void ompl_parc::python::InterruptScope::release()
{
    if (!counted_)
        return;
    counted_ = false;
    const std::lock_guard<std::mutex> lock(scopesMutex);
    if (--scopes == 0)
        sigaction(SIGINT, &pythons, nullptr);
}

bool ompl_parc::python::InterruptScope::fired()
{
    return interrupted;
}
