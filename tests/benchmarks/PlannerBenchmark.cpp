/* ARC-family planners on the paper's 2D scenarios and on Panda Cage 4, same seeds side by side in one run:
   ARC, P-ARC with 2 workers, OR-P-ARC 2x1 and P-ARC with 16 workers (oversubscribed on small machines: its
   wall time is measured, its 16-core time is a projection from per-worker CPU time, labelled as such).
   Each (planner, scenario) runs once per seed 1..5 (Panda Cage: each of its 5 tasks with seeds 1 and 2)
   (Google Benchmark repetitions, manual time = planning wall time); every result is re-checked by the
   SolutionValidator and an invalid or failed run aborts the benchmark. At the end a Markdown table gives the median
   time, the median per-stage wall times, the median projected W-core time (P-ARC) and the speedups of medians against
   ARC on the same scenario and seeds. Usage: ompl_parc_bench_planners [--benchmark_filter=REGEX] (the table covers what
   ran). */
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <benchmark/benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

using namespace ompl_parc;

namespace
{
    constexpr int SEEDS = 5;

    struct Case
    {
        std::string scenario;
        std::size_t robots;
        std::string profile;
        /** \brief Run k plans task k % tasks with seed k / tasks + 1, for seeds * tasks runs. */
        std::size_t tasks{1};
        int seeds{SEEDS};
    };

    struct Run
    {
        double total, initial, detection, resolution, projected;
    };

    /** \brief Allocates an ARC-family planner: an ArcPlannerBase or an ORPARC (which wraps P-ARC instances). */
    template <typename P>
    using PlannerFactory = std::function<std::shared_ptr<P>(const ompl::base::SpaceInformationPtr &)>;
    using Runner = std::function<void(benchmark::State &, const std::string &, const Case &)>;

    std::map<std::pair<std::string, std::string>, std::vector<Run>> &results()
    {
        static std::map<std::pair<std::string, std::string>, std::vector<Run>> table;
        return table;
    }

    std::string label(const Case &c)
    {
        return c.scenario + " " + std::to_string(c.robots);
    }

    template <typename P>
    void runPlanner(benchmark::State &state, const std::string &name, const PlannerFactory<P> &factory, const Case &c)
    {
        auto &runs = results()[{label(c), name}];
        for (auto _ : state)
        {
            const std::size_t run = runs.size() % (c.tasks * static_cast<std::size_t>(c.seeds));
            const auto problem = scenarios::createScenario(c.scenario, c.robots, 128., run % c.tasks);
            auto planner = factory(problem.getSpaceInformation());
            planner->params().setParam("profile", c.profile);
            planner->setSeed(static_cast<unsigned int>(run / c.tasks + 1));
            planner->setProblemDefinition(problem.createProblemDefinition());
            planner->setup();
            const auto start = ompl::time::now();
            const auto status = planner->solve(ompl::base::timedPlannerTerminationCondition(120.));
            const double seconds = ompl::time::seconds(ompl::time::now() - start);
            if (status != ompl::base::PlannerStatus::EXACT_SOLUTION)
                throw std::runtime_error(name + " failed on " + label(c) + ": " + planner->getStatusMessage());
            const auto report = SolutionValidator(problem).validate(planner->getPlan());
            if (!report.valid)
                throw std::runtime_error(name + " returned an invalid plan on " + label(c) + ": " + report.message);
            state.SetIterationTime(seconds);
            const auto &s = planner->getStatistics();
            const auto *parc = dynamic_cast<const PARC *>(planner.get());
            const double projected = parc != nullptr ? parc->getParallelStatistics().projectedInitial +
                                                           parc->getParallelStatistics().projectedDetection +
                                                           parc->getParallelStatistics().projectedResolution
                                                     : -1.;
            runs.push_back({seconds, s.initialWall, s.detectionWall, s.resolutionWall, projected});
            state.counters["conflicts"] = s.conflicts;
            state.counters["makespan"] = static_cast<double>(planner->getPlan().getMakespan());
        }
    }

    /** \brief runPlanner with the planners of \e factory. */
    template <typename P>
    Runner runnerOf(PlannerFactory<P> factory)
    {
        return [factory](benchmark::State &state, const std::string &name, const Case &c)
        { runPlanner(state, name, factory, c); };
    }

    double median(std::vector<double> v)
    {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }

    void printTable()
    {
        std::printf(
            "\n| scenario | planner | median wall (s) | initial | detection | resolution | "
            "projected W-core stages (s) | wall speedup vs ARC | projected speedup vs ARC |\n"
            "|---|---|---|---|---|---|---|---|---|\n");
        for (const auto &[key, runs] : results())
        {
            if (runs.empty())
                continue;
            auto column = [&runs](double Run::*field)
            {
                std::vector<double> v;
                for (const auto &r : runs)
                    v.push_back(r.*field);
                return median(v);
            };
            const double total = column(&Run::total), projected = column(&Run::projected);
            std::string speedup = "—", projectedSpeedup = "—", projectedText = "—";
            const auto arc = results().find({key.first, "ARC"});
            if (projected >= 0.)
                projectedText = std::to_string(projected);
            if (key.second != "ARC" && arc != results().end() && !arc->second.empty())
            {
                std::vector<double> wall, stages;
                for (const auto &r : arc->second)
                {
                    wall.push_back(r.total);
                    stages.push_back(r.initial + r.detection + r.resolution);
                }
                speedup = std::to_string(median(wall) / total) + "x";
                if (projected > 0.)
                    projectedSpeedup = std::to_string(median(stages) / projected) + "x (projection)";
            }
            std::printf("| %s | %s | %.3f | %.3f | %.3f | %.3f | %s | %s | %s |\n", key.first.c_str(),
                        key.second.c_str(), total, column(&Run::initial), column(&Run::detection),
                        column(&Run::resolution), projectedText.c_str(), speedup.c_str(), projectedSpeedup.c_str());
        }
    }
}  // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const std::vector<Case> cases = {{"mobile_cross", 16, "mobile"},
                                     {"mobile_cross", 64, "mobile"},
                                     {"planar_cross", 8, "planar"},
                                     {"planar_cross", 16, "planar"},
                                     {"panda_cage", 4, "panda", 5, 2}};
    const auto parc = [](unsigned int workers)
    {
        return runnerOf<ArcPlannerBase>(
            [workers](const ompl::base::SpaceInformationPtr &si)
            {
                auto p = std::make_shared<PARC>(si);
                p->setWorkers(workers);
                return p;
            });
    };
    const std::vector<std::pair<std::string, Runner>> planners = {
        {"ARC",
         runnerOf<ArcPlannerBase>([](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ARC>(si); })},
        {"P-ARC-2", parc(2)},
        {"OR-P-ARC-2x1", runnerOf<ORPARC>(
                             [](const ompl::base::SpaceInformationPtr &si)
                             {
                                 auto p = std::make_shared<ORPARC>(si);
                                 p->setInstances(2);
                                 p->setWorkers(1);
                                 return p;
                             })},
        {"P-ARC-16", parc(16)}};
    for (const auto &c : cases)
        for (const auto &[name, run] : planners)
            benchmark::RegisterBenchmark((name + "/" + c.scenario + "/" + std::to_string(c.robots)).c_str(),
                                         [name = name, run = run, c](benchmark::State &state) { run(state, name, c); })
                ->Iterations(1)
                ->Repetitions(static_cast<int>(c.tasks) * c.seeds)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->ReportAggregatesOnly(true);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    printTable();
    return 0;
}
