#ifndef OMPL_PARC_DEMOS_PROGRESS_LINE_
#define OMPL_PARC_DEMOS_PROGRESS_LINE_

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace ompl_parc::tools
{
    /** \brief A live "planning... 3.2 s" line on stderr while a long solve runs, so an interactive user
        sees the tool is alive; silent when stdout is not a terminal (scripts, logs, tests).

        It shows the elapsed time only: the planners' statistics (ArcStatistics) are plain members
        written by the planning threads without synchronisation, so reading them from this thread would
        be a data race. The line appears after one second and is erased by stop(). */
    class ProgressLine
    {
      public:
        /** \brief Starts the display thread if stdout is a terminal; \e label starts the line. */
        explicit ProgressLine(std::string label);
        ~ProgressLine();
        ProgressLine(const ProgressLine &) = delete;
        ProgressLine &operator=(const ProgressLine &) = delete;

        /** \brief Stops the thread and erases the line (idempotent). */
        void stop();

      private:
        void run();

        std::string label_;
        std::chrono::steady_clock::time_point start_;
        std::mutex mutex_;
        std::condition_variable wake_;
        bool stopping_{false};
        std::thread thread_;
    };
}  // namespace ompl_parc::tools

#endif
