#include "ompl_parc/util/InnerPlannerLog.h"

#include <ompl/util/Console.h>

#include <atomic>
#include <mutex>

namespace
{
    std::atomic<bool> shown{false};
    /** How many Scopes the calling thread is inside. */
    thread_local unsigned int depth = 0;

    /** Forwards to the handler it replaced, except the inner planners' messages below warnings. OMPL calls it with
        its console lock held: it must not call back into OMPL's console functions. */
    class Filter : public ompl::msg::OutputHandler
    {
      public:
        void log(const std::string &text, ompl::msg::LogLevel level, const char *filename, int line) override
        {
            if (depth > 0 && level < ompl::msg::LOG_WARN && !shown.load(std::memory_order_relaxed))
                return;
            next_->log(text, level, filename, line);
        }

        ompl::msg::OutputHandler *next_{nullptr};
    };

    std::mutex sessionsMutex;
    unsigned int sessions = 0;
    Filter filter;
    /** Whether the first Session put the filter in place, and OMPL's "previous handler" (what
        restorePreviousOutputHandler() goes back to) at that moment, given back with the handler. */
    bool installed = false;
    ompl::msg::OutputHandler *previous = nullptr;
}  // namespace

void ompl_parc::InnerPlannerLog::setShown(bool show)
{
    shown = show;
}

bool ompl_parc::InnerPlannerLog::isShown()
{
    return shown;
}

ompl_parc::InnerPlannerLog::Session::Session()
{
    const std::lock_guard<std::mutex> lock(sessionsMutex);
    if (sessions++ > 0)
        return;
    ompl::msg::OutputHandler *current = ompl::msg::getOutputHandler();
    if (current == nullptr || current == &filter)
        return;  // nothing is printed, or the filter is in place already
    // OMPL keeps one "previous handler", which useOutputHandler() overwrites: read it (two swaps) to give it back.
    ompl::msg::restorePreviousOutputHandler();
    previous = ompl::msg::getOutputHandler();
    ompl::msg::restorePreviousOutputHandler();
    filter.next_ = current;
    ompl::msg::useOutputHandler(&filter);
    installed = true;
}

ompl_parc::InnerPlannerLog::Session::~Session()
{
    const std::lock_guard<std::mutex> lock(sessionsMutex);
    if (--sessions > 0 || !installed)
        return;
    installed = false;
    if (ompl::msg::getOutputHandler() != &filter)
        return;  // someone put a handler of their own meanwhile: it stays
    // As before the first Session: the handler it found, and OMPL's previous handler behind it.
    ompl::msg::useOutputHandler(previous);
    ompl::msg::useOutputHandler(filter.next_);
}

ompl_parc::InnerPlannerLog::Scope::Scope()
{
    ++depth;
}

ompl_parc::InnerPlannerLog::Scope::~Scope()
{
    --depth;
}
