/* P-ARC's first conflict-detection call on Panda Cage 8 (the paper's Table "Impact of Synchronization
   Horizon": 9.85 ms wall at 16 workers, H = 200, averaged over ten seeds on each of the five tasks).
   For every task 0..4 and initial-plan seed 1..2, the robots' initial paths are planned once (InitialPlanner,
   as ARC's first stage); each benchmark iteration then runs BatchDetector::detect on them from scratch (fresh
   frontiers and swept bounds, the worker pool already started, as inside P-ARC) for all ten plan sets, and
   reports the mean per call: wall time (manual time), the process CPU time of all threads, and the projected
   W-core time (largest per-worker CPU per round plus the coordinator; a projection when W exceeds the cores).
   Rows: W = 1, 2 (and 16, oversubscribed on small machines) at H = 200, and a horizon sweep at W = 2. A call
   with more workers returns a larger batch (up to W conflicts, as in the paper), so the table at the end gives, side by
   side in this run, the wall time per call and per conflict found, against W = 1. Usage: ompl_parc_bench_detection
   [--benchmark_filter=REGEX] */
#include "ompl_parc/arc/BatchDetector.h"
#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <benchmark/benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/Time.h>

#include <cstdio>
#include <ctime>
#include <map>
#include <stdexcept>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    constexpr std::size_t ROBOTS = 8;
    constexpr unsigned int PLAN_SEEDS = 2;

    /** A Panda Cage 8 task with one set of initial paths. */
    struct PlanSet
    {
        MultiRobotProblem problem;
        MultiRobotPlan plan;
    };

    const std::vector<PlanSet> &planSets()
    {
        static const std::vector<PlanSet> sets = []
        {
            std::vector<PlanSet> out;
            for (std::size_t task = 0; task < scenarios::PANDA_CAGE_TASKS; ++task)
                for (unsigned int seed = 1; seed <= PLAN_SEEDS; ++seed)
                {
                    auto problem = scenarios::createPandaCage(ROBOTS, task);
                    MultiRobotPlan plan(*problem.getSpaceInformation());
                    const InitialPlanner planner(problem);
                    for (std::size_t r = 0; r < ROBOTS; ++r)
                    {
                        TimedPath path;
                        if (!planner.plan(r, ob::timedPlannerTerminationCondition(60.), mixSeed(seed, r), path))
                            throw std::runtime_error("no initial path for robot " + std::to_string(r));
                        plan.setPath(r, std::move(path));
                    }
                    out.push_back({std::move(problem), std::move(plan)});
                }
            return out;
        }();
        return sets;
    }

    double processCpuSeconds()
    {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }

    /** Mean wall seconds per call and mean batch size, per (workers, horizon), for the closing table. */
    struct Mean
    {
        double wall, batch;
    };
    std::map<std::pair<unsigned int, unsigned int>, Mean> &means()
    {
        static std::map<std::pair<unsigned int, unsigned int>, Mean> table;
        return table;
    }

    void firstDetection(benchmark::State &state, unsigned int workers, unsigned int horizon)
    {
        const auto &sets = planSets();
        WorkerPool pool(workers);
        const RepairCache cache;
        const std::size_t window = 20;  // the Panda profile's window (robot-set expansion only; the cache is empty)
        double wall = 0., cpu = 0., projected = 0., conflicts = 0.;
        for (auto _ : state)
        {
            double iterationWall = 0.;
            for (const PlanSet &set : sets)
            {
                ConflictDetector detector(*set.problem.getSpaceInformation());
                BatchDetector batches(detector, pool, horizon, workers, true);  // the paper's batch: up to W
                const double cpuStart = processCpuSeconds();
                const auto start = ompl::time::now();
                const auto detected = batches.detect(set.plan, cache, window, ob::plannerNonTerminatingCondition());
                const auto &batch = detected.entries;
                const double seconds = ompl::time::seconds(ompl::time::now() - start);
                cpu += processCpuSeconds() - cpuStart;
                if (batch.empty())
                    throw std::runtime_error("a Panda Cage 8 initial plan set has no conflict: nothing measured");
                iterationWall += seconds;
                projected += detected.projectedSeconds;
                conflicts += static_cast<double>(batch.size());
            }
            wall += iterationWall;
            state.SetIterationTime(iterationWall / static_cast<double>(sets.size()));
        }
        const double calls = static_cast<double>(state.iterations() * sets.size());
        state.counters["wall_ms"] = 1e3 * wall / calls;
        state.counters["cpu_all_threads_ms"] = 1e3 * cpu / calls;
        state.counters["projected_ms"] = 1e3 * projected / calls;
        state.counters["batch_size"] = conflicts / calls;
        state.counters["wall_ms_per_conflict"] = 1e3 * wall / conflicts;
        means()[{workers, horizon}] = {wall / calls, conflicts / calls};
    }

    void printTable()
    {
        const auto &table = means();
        const auto one = table.find({1, 200});
        if (one == table.end())
            return;
        const double perConflict = one->second.wall / one->second.batch;
        std::printf(
            "\nFirst detection call, Panda Cage 8, H = 200, mean over %zu plan sets, same run:\n"
            "| workers | wall per call (ms) | batch size | wall per conflict (ms) | per call vs W = 1 | "
            "per conflict vs W = 1 |\n|---|---|---|---|---|---|\n",
            planSets().size());
        for (const auto &[key, m] : table)
            if (key.second == 200)
                std::printf("| %u | %.3f | %.2f | %.3f | %.2fx | %.2fx |\n", key.first, 1e3 * m.wall, m.batch,
                            1e3 * m.wall / m.batch, one->second.wall / m.wall, perConflict / (m.wall / m.batch));
    }
}  // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const auto add = [](unsigned int workers, unsigned int horizon)
    {
        benchmark::RegisterBenchmark(
            ("FirstDetection/PandaCage8/W:" + std::to_string(workers) + "/H:" + std::to_string(horizon)).c_str(),
            [workers, horizon](benchmark::State &state) { firstDetection(state, workers, horizon); })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond)
            ->MinTime(1.0);
    };
    for (unsigned int workers : {1u, 2u, 16u})
        add(workers, 200);
    for (unsigned int horizon : {50u, 100u, 400u, 800u, 1600u, 3200u})
        add(2, horizon);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    printTable();
    return 0;
}
