#include "ompl_parc/parallel/OrTaskRunner.h"
#include "ompl_parc/parallel/WorkerPool.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <atomic>
#include <stdexcept>
#include <thread>

using namespace ompl_parc;
namespace ob = ompl::base;

TEST(WorkerPool, RunsEveryWorkerOnceAndReportsCpu)
{
    WorkerPool pool(3);
    std::atomic<int> mask{0};
    const auto cpu = pool.run(
        [&](unsigned int w)
        {
            mask |= 1 << w;
            volatile double x = 0.;
            for (int k = 0; k < 2000000; ++k)
                x = x + 1.;
        });
    EXPECT_EQ(mask.load(), 7);
    ASSERT_EQ(cpu.size(), 3u);
    for (double c : cpu)
        EXPECT_GT(c, 0.);
    EXPECT_THROW(WorkerPool(0), ompl::Exception);
}

TEST(WorkerPool, AThrowingWorkerStopsTheOthersAndTheErrorReachesTheCaller)
{
    WorkerPool pool(2);
    std::atomic<bool> otherStopped{false};
    EXPECT_THROW(pool.run(
                     [&](unsigned int w)
                     {
                         if (w == 0)
                             throw std::runtime_error("task failed");
                         while (!pool.aborted())
                             std::this_thread::yield();
                         otherStopped = true;
                     }),
                 std::runtime_error);
    EXPECT_TRUE(otherStopped.load());
    // The pool is reusable after a failed stage.
    EXPECT_NO_THROW(pool.run([](unsigned int) {}));
}

TEST(OrTaskRunner, EveryTaskSolvedOnceAndLosersAreCancelled)
{
    WorkerPool pool(4);
    OrTaskStatistics stats;
    std::atomic<int> calls{0};
    // Two tasks, four workers: with local OR the idle workers start extra attempts. Attempt 0 of task 1 never
    // succeeds on its own (it waits for cancellation), so an extra attempt must solve it.
    const auto results = OrTaskRunner<int>(pool, true)
                             .run(
                                 2, ob::timedPlannerTerminationCondition(30.),
                                 [&](std::size_t task, unsigned int attempt,
                                     const ob::PlannerTerminationCondition &stop) -> std::optional<int>
                                 {
                                     ++calls;
                                     if (task == 1 && attempt == 0)
                                     {
                                         while (!stop)
                                             std::this_thread::yield();
                                         return std::nullopt;
                                     }
                                     return static_cast<int>(10 * task + attempt);
                                 },
                                 stats);
    ASSERT_TRUE(results[0] && results[1]);
    EXPECT_EQ(*results[0] / 10, 0);
    EXPECT_EQ(*results[1] / 10, 1);
    EXPECT_GE(*results[1] % 10, 1);  // won by an extra attempt
    EXPECT_GE(stats.attempts, 3u);
    EXPECT_GE(stats.cancelled, 1u);
    EXPECT_EQ(stats.workerCpu.size(), 4u);
}

TEST(OrTaskRunner, WithoutLocalOrEachTaskIsAttemptedOnceAndTheOuterConditionStopsAll)
{
    WorkerPool pool(2);
    OrTaskStatistics stats;
    std::atomic<bool> stop{false};
    const ob::PlannerTerminationCondition outer([&stop] { return stop.load(); });
    const auto results =
        OrTaskRunner<int>(pool, false)
            .run(
                3, outer,
                [&](std::size_t task, unsigned int, const ob::PlannerTerminationCondition &ptc) -> std::optional<int>
                {
                    if (task == 2)
                    {
                        stop = true;  // the outer condition fires while task 2 runs
                        while (!ptc)
                            std::this_thread::yield();
                        return std::nullopt;
                    }
                    return static_cast<int>(task);
                },
                stats);
    EXPECT_FALSE(results[2].has_value());
    EXPECT_LE(stats.attempts, 3u);
}
