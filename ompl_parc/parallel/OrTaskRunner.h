#ifndef OMPL_PARC_OR_TASK_RUNNER_
#define OMPL_PARC_OR_TASK_RUNNER_

#include "ompl_parc/parallel/WorkerPool.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace ompl_parc
{
    /** \brief Counters of one OrTaskRunner stage. */
    struct OrTaskStatistics
    {
        /** \brief Attempts started, and attempts that lost to another attempt of the same task. */
        unsigned int attempts{0}, cancelled{0};
        /** \brief Thread CPU seconds of each worker over the stage. */
        std::vector<double> workerCpu;
    };

    /** \brief P-ARC's way of spreading randomised tasks over workers (initial paths, conflict repairs).

        Workers take tasks as they free up (dynamic assignment, so the real load is balanced, not the task
        count). With local OR multi-start, a worker that finds no unstarted task starts another attempt
        (a new attempt index, hence a new seed) of the unsolved task with the fewest attempts running; the
        first attempt of a task to succeed wins and cancels the others through their termination
        condition (outer condition OR task solved OR stage aborted). run() returns when every task is solved
        or the outer condition fires, with all workers joined. */
    template <typename Result>
    class OrTaskRunner
    {
      public:
        /** \brief One attempt: task index, attempt index (0 for the first), its termination condition. */
        using Attempt = std::function<std::optional<Result>(std::size_t, unsigned int,
                                                            const ompl::base::PlannerTerminationCondition &)>;

        OrTaskRunner(WorkerPool &pool, bool localOr) : pool_(pool), localOr_(localOr) {}

        /** \brief Run tasks 0..tasks-1; an unsolved task (the outer condition fired) has no result. */
        std::vector<std::optional<Result>> run(std::size_t tasks, const ompl::base::PlannerTerminationCondition &ptc,
                                               const Attempt &attempt, OrTaskStatistics &statistics)
        {
            std::mutex mutex;
            std::vector<std::optional<Result>> results(tasks);
            std::unique_ptr<std::atomic<bool>[]> solved(new std::atomic<bool>[tasks]);
            for (std::size_t k = 0; k < tasks; ++k)
                solved[k] = false;
            std::vector<unsigned int> started(tasks, 0), running(tasks, 0);
            std::size_t next = 0;
            unsigned int attempts = 0, cancelled = 0;

            // Under the lock: the next task this worker should attempt, or none.
            const auto pick = [&]() -> std::optional<std::size_t>
            {
                if (next < tasks)
                    return next++;
                if (!localOr_)
                    return std::nullopt;
                std::optional<std::size_t> best;
                for (std::size_t k = 0; k < tasks; ++k)
                    if (!solved[k] && (!best || running[k] < running[*best]))
                        best = k;
                return best;
            };

            statistics.workerCpu = pool_.run(
                [&](unsigned int)
                {
                    while (!ptc && !pool_.aborted())
                    {
                        std::size_t task;
                        unsigned int index;
                        {
                            std::lock_guard<std::mutex> lock(mutex);
                            const auto chosen = pick();
                            if (!chosen)
                                return;
                            task = *chosen;
                            index = started[task]++;
                            ++running[task];
                            ++attempts;
                        }
                        const ompl::base::PlannerTerminationCondition stop(
                            [&ptc, &solved, task, this] { return solved[task].load() || pool_.aborted() || ptc(); });
                        std::optional<Result> result;
                        {
                            const StopSignal::Scope scope(stop);
                            result = attempt(task, index, stop);
                        }
                        std::lock_guard<std::mutex> lock(mutex);
                        --running[task];
                        if (result && !solved[task])
                        {
                            results[task] = std::move(result);
                            solved[task] = true;
                        }
                        else if (solved[task])
                            ++cancelled;
                    }
                });
            statistics.attempts += attempts;
            statistics.cancelled += cancelled;
            return results;
        }

      private:
        WorkerPool &pool_;
        bool localOr_;
    };
}  // namespace ompl_parc

#endif
