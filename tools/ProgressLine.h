#ifndef OMPL_PARC_DEMOS_PROGRESS_LINE_
#define OMPL_PARC_DEMOS_PROGRESS_LINE_

#include "ompl_parc/arc/ArcProgress.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace ompl_parc::tools
{
    /** \brief A live "planning... 3.2 s, resolving: 12 of 15 conflicts resolved" line on stderr while a long solve
        runs, so an interactive user sees where the planner is; silent when stdout is not a terminal (scripts, logs,
        tests).

        With an ArcProgress (the ARC family's; its atomics may be read from this thread) it shows the stage and its
        counters; otherwise the elapsed time only (other planners' statistics are plain members written by the
        planning threads: reading them here would be a data race). The line appears after one second and is erased
        by stop(). */
    class ProgressLine
    {
      public:
        /** \brief Starts the display thread if stdout is a terminal; \e label starts the line; \e progress (may be
            null) is the planner's, \e robots the team size. */
        ProgressLine(std::string label, const ArcProgress *progress, std::size_t robots);
        ~ProgressLine();
        ProgressLine(const ProgressLine &) = delete;
        ProgressLine &operator=(const ProgressLine &) = delete;

        /** \brief Stops the thread and erases the line (idempotent). */
        void stop();

      private:
        void run();

        /** \brief The text after the elapsed time: the stage and its counters. */
        std::string describe() const;

        std::string label_;
        const ArcProgress *progress_;
        std::size_t robots_;
        std::chrono::steady_clock::time_point start_;
        std::mutex mutex_;
        std::condition_variable wake_;
        bool stopping_{false};
        std::thread thread_;
    };
}  // namespace ompl_parc::tools

#endif
