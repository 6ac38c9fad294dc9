#ifndef OMPL_PARC_STAGE_CLOCK_
#define OMPL_PARC_STAGE_CLOCK_

#include <chrono>
#include <ctime>

namespace ompl_parc
{
    /** \brief Wall-clock and calling-thread CPU time of one stage, added to accumulators when it ends.

        CPU time is what a worker really computed: on a machine with fewer cores than workers, wall time
        includes waiting for a core, thread CPU time does not. That is what lets a 16-worker run on 2 cores
        report a (labelled) projection of its 16-core time. */
    class StageClock
    {
      public:
        /** \brief Start timing; stop() (or destruction) adds the elapsed times to \e wall and \e cpu. */
        StageClock(double &wall, double &cpu) : wall_(wall), cpu_(cpu), wallStart_(now()), cpuStart_(threadCpu()) {}
        ~StageClock() { stop(); }
        StageClock(const StageClock &) = delete;
        StageClock &operator=(const StageClock &) = delete;

        void stop()
        {
            if (stopped_)
                return;
            stopped_ = true;
            wall_ += std::chrono::duration<double>(now() - wallStart_).count();
            cpu_ += threadCpu() - cpuStart_;
        }

        /** \brief CPU seconds used by the calling thread so far. */
        static double threadCpu()
        {
            timespec ts{};
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
            return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
        }

      private:
        static std::chrono::steady_clock::time_point now() { return std::chrono::steady_clock::now(); }

        double &wall_, &cpu_;
        std::chrono::steady_clock::time_point wallStart_;
        double cpuStart_;
        bool stopped_{false};
    };
}  // namespace ompl_parc

#endif
