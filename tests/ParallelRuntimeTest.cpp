#include "ompl_parc/parallel/OrTaskRunner.h"
#include "ompl_parc/parallel/WorkerPool.h"
#include "ompl_parc/statespaces/CompositeStateSpace.h"
#include "ompl_parc/statespaces/SpaceRegistryLock.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

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

/* Stages back to back (workers still spinning from the last one), and after pauses longer than the spin (workers
   asleep): every stage runs each worker exactly once, the caller as worker 0, and none starts before the caller
   has asked for it. W = 2 spins wherever two cores are usable; one more worker than the machine has cores never
   spins. */
TEST(WorkerPool, EveryStageRunsEachWorkerOnceWhetherItsWorkersSpinOrSleep)
{
    for (unsigned int workers : {2u, std::thread::hardware_concurrency() + 1})
    {
        WorkerPool pool(workers);
        const auto caller = std::this_thread::get_id();
        std::vector<std::atomic<int>> runs(workers);
        for (int stage = 0; stage < 400; ++stage)
        {
            if (stage % 100 == 99)
                std::this_thread::sleep_for(std::chrono::duration<double>(3. * WorkerPool::SPIN_SECONDS));
            const auto cpu = pool.run(
                [&](unsigned int w)
                {
                    EXPECT_EQ(w == 0, std::this_thread::get_id() == caller);
                    ++runs[w];
                });
            ASSERT_EQ(cpu.size(), workers);
            for (unsigned int w = 0; w < workers; ++w)
                ASSERT_EQ(runs[w].load(), stage + 1) << "worker " << w << " in stage " << stage;
        }
    }
}

TEST(WorkerPool, AThrowingWorkerStopsTheOthersAndTheErrorReachesTheCaller)
{
    WorkerPool pool(2);
    // The thrower is the caller (worker 0), then a pool thread (worker 1).
    for (unsigned int thrower : {0u, 1u})
    {
        std::atomic<bool> otherStopped{false};
        EXPECT_THROW(pool.run(
                         [&](unsigned int w)
                         {
                             if (w == thrower)
                                 throw std::runtime_error("task failed");
                             while (!pool.aborted())
                                 std::this_thread::yield();
                             otherStopped = true;
                         }),
                     std::runtime_error);
        EXPECT_TRUE(otherStopped.load());
        // The pool is reusable after a failed stage, and the next stage starts unaborted.
        std::atomic<int> abortedSeen{0};
        EXPECT_NO_THROW(pool.run([&](unsigned int) { abortedSeen += pool.aborted() ? 1 : 0; }));
        EXPECT_EQ(abortedSeen.load(), 0);
    }
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

/* Threads building and dropping composite spaces at once, as P-ARC's workers do for every robot plan and repair: each
   gets whole, working spaces, and a composite that takes its robot spaces down with it nests the lock (a thread
   blocking on its own lock would hang this test). Mutual exclusion itself does not show here (OMPL's own mutex still
   guards its list); ThreadSanitizer checks the lock's memory order in the sanitizer pass. */
TEST(SpaceRegistryLock, ThreadsBuildAndDropSpacesAtOnce)
{
    std::vector<std::thread> threads;
    std::atomic<int> built{0};
    for (int t = 0; t < 4; ++t)
        threads.emplace_back(
            [&built]
            {
                for (int k = 0; k < 300; ++k)
                {
                    std::vector<ob::StateSpacePtr> robots{makeStateSpace<ob::RealVectorStateSpace>(2),
                                                          makeStateSpace<ob::RealVectorStateSpace>(3)};
                    for (auto &robot : robots)
                        robot->as<ob::RealVectorStateSpace>()->setBounds(-1., 1.);
                    auto team = makeStateSpace<CompositeStateSpace>(robots);
                    robots.clear();  // the composite now holds the last references
                    const auto second = team->createSubspace({1});
                    team.reset();
                    if (second->getDimension() == 3u)
                        ++built;
                }
            });
    for (auto &thread : threads)
        thread.join();
    EXPECT_EQ(built.load(), 4 * 300);
}
