/* ompl_parc_benchmark CONFIG.cfg: run an OMPL.app-style benchmark configuration (see BenchmarkConfig.h) with
   OMPL's own ompl::tools::Benchmark. Run j of every planner is seeded with [benchmark] seed + j; every solution
   is re-checked by the independent SolutionValidator. Writes <output>/<name>.log (OMPL's log format, for
   ompl_benchmark_statistics) and <output>/<name>.csv (one row per run, for scripts/plot_benchmarks.py); with
   [problem] instances = N, one log per task (<name>_<task>.log), one CSV, and a table of success rate and
   median time per planner on stdout.
   Exit 0: all runs done and every solution valid; 1: some solution failed validation; 2: bad input. */
#include "ResultsCsv.h"
#include "ToolSupport.h"

#include "ompl_parc/Version.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/setup/BenchmarkConfig.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace ob = ompl::base;
namespace po = boost::program_options;
using namespace ompl_parc;

namespace
{
    /** \brief Seconds between two samples of the planners' progress properties (OMPL's default, 0.05 s, misses
        most of a run that takes a tenth of a second). */
    constexpr double PROGRESS_PERIOD = 0.01;

    /** \brief Threads a planner uses at once: total_workers if it declares it, else instances x workers. */
    unsigned int workerBudget(const ob::Planner &planner)
    {
        const auto value = [&planner](const std::string &name)
        {
            std::string text;
            return planner.params().getParam(name, text) ? std::stoul(text) : 1ul;
        };
        if (planner.params().hasParam("total_workers"))
            return value("total_workers");
        return value("instances") * value("workers");
    }

    std::ofstream openForWriting(const std::filesystem::path &path)
    {
        std::ofstream out(path);
        if (!out)
            throw std::invalid_argument("cannot write '" + path.string() + "' (is the output folder writable?)");
        return out;
    }

    /** \brief One problem of the experiment, its CSV scenario label and the planners made for it. */
    struct Instance
    {
        MultiRobotProblem problem;
        std::string scenario;
        std::size_t task{0};
        std::vector<ob::PlannerPtr> planners;
    };

    /** \brief One run as the summary table counts it. */
    struct RunOutcome
    {
        bool success;
        double time;
        /** \brief Makespan over its straight-line bound (PlanQuality), for a valid solution. */
        double makespanRatio;
    };

    /** \brief Per planner name, each run's outcome. */
    using Tally = std::map<std::string, std::vector<RunOutcome>>;

    double median(std::vector<double> values)
    {
        std::sort(values.begin(), values.end());
        const std::size_t n = values.size();
        return n == 0 ? 0. : n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    }

    /** \brief The problem of \e task with its planners, checked: every input error shows before any run. */
    Instance makeInstance(const BenchmarkConfig &config, std::size_t task)
    {
        Instance instance{
            config.getScenarioFile().empty()
                ? scenarios::createScenario(config.getScenario(), config.getRobots(), config.getResolution(), task)
                : ScenarioFile::read(config.getScenarioFile()),
            config.getScenario(),
            task,
            {}};
        const MultiRobotProblem &problem = instance.problem;
        if (!config.getScenarioFile().empty())
            instance.scenario = problem.getName().empty()
                                    ? std::filesystem::path(config.getScenarioFile()).stem().string()
                                    : problem.getName();
        else if (config.getInstances() > 1 || task > 0)
            instance.scenario =
                problem.getName().empty() ? config.getScenario() + "_" + std::to_string(task) : problem.getName();
        for (const std::string &reason :
             {problem.checkEndpoints(), problem.getSpaceInformation()->checkPlanningResolution()})
            if (!reason.empty())
                throw std::invalid_argument(reason);
        for (const auto &entry : config.getPlanners())
        {
            auto planner = PlannerRegistry::create(entry.type, problem.getSpaceInformation(), entry.params);
            planner->setName(entry.name);
            if (const unsigned int budget = workerBudget(*planner); budget > config.getWorkers())
                throw std::invalid_argument(
                    "planner '" + entry.name + "' needs " + std::to_string(budget) +
                    " workers but [benchmark] workers = " + std::to_string(config.getWorkers()));
            if (!planner->params().hasParam("seed") && task == config.getTask())
                std::cerr << "ompl_parc_benchmark: planner '" << entry.name
                          << "' has no seed parameter: its runs use OMPL's global random sequence\n";
            instance.planners.push_back(planner);
        }
        return instance;
    }

    /** \brief Success rate, median time (failures counted at the time limit) and median makespan over its lower
        bound (solved runs) per planner, as a Markdown table: the robustness and quality view of an experiment
        over many instances. */
    void printSummary(const BenchmarkConfig &config, const Tally &tally, std::ostream &out)
    {
        out << "| planner | solved | median time (s, failures at " << config.getTimeLimit()
            << " s) | median makespan / lower bound (solved) |\n"
            << "|---|---|---|---|\n";
        for (const auto &entry : config.getPlanners())
        {
            const auto it = tally.find(entry.name);
            if (it == tally.end())
                continue;
            std::vector<double> times, ratios;
            for (const RunOutcome &run : it->second)
            {
                times.push_back(run.success ? run.time : config.getTimeLimit());
                if (run.success)
                    ratios.push_back(run.makespanRatio);
            }
            out << "| " << entry.name << " | " << ratios.size() << "/" << times.size() << " | " << std::fixed
                << std::setprecision(3) << median(times) << " | ";
            if (ratios.empty())
                out << "- |\n";
            else
                out << std::setprecision(2) << median(ratios) << " |\n";
        }
    }

    /** \brief Run every planner of \e instance run_count times with OMPL's Benchmark, write its log to \e logPath
        and one CSV row per run, and tally the runs; returns the number of invalid solutions. */
    std::size_t runInstance(const BenchmarkConfig &config, const Instance &instance,
                            const std::filesystem::path &logPath, tools::ResultsCsv &csv, Tally &tally)
    {
        const MultiRobotProblem &problem = instance.problem;
        const auto &si = problem.getSpaceInformation();
        const auto &planners = instance.planners;
        ompl::geometric::SimpleSetup setup(si);
        ob::ScopedState<> start(si), goal(si);
        const auto pdef = problem.createProblemDefinition();
        start = pdef->getStartState(0);
        goal = pdef->getGoal()->as<ob::GoalState>()->getState();
        setup.setStartAndGoalStates(start, goal);
        setup.setPlanner(planners.front());  // else SimpleSetup allocates a default planner it never runs

        ompl::tools::Benchmark benchmark(setup, config.getProblemName());
        benchmark.addExperimentParameter("robots", "INTEGER", std::to_string(si->getRobotCount()));
        benchmark.addExperimentParameter("resolution", "REAL", std::to_string(si->getResolution()));
        benchmark.addExperimentParameter("base_seed", "INTEGER", std::to_string(config.getSeed()));
        benchmark.addExperimentParameter("worker_budget", "INTEGER", std::to_string(config.getWorkers()));
        benchmark.addExperimentParameter("task", "INTEGER", std::to_string(instance.task));
        benchmark.addExperimentParameter("ompl_parc_version", "VARCHAR(32)", OMPL_PARC_VERSION);
        for (const auto &planner : planners)
            benchmark.addPlanner(planner);

        const auto seedOf = [&] { return config.getSeed() + benchmark.getStatus().activeRun; };
        benchmark.setPreRunEvent(
            [&](const ob::PlannerPtr &planner)
            {
                if (planner->params().hasParam("seed"))
                    planner->params().setParam("seed", std::to_string(seedOf()));
            });

        const SolutionValidator validator(problem);
        const std::size_t total = planners.size() * config.getRunCount();
        std::size_t done = 0, invalid = 0;
        std::map<std::string, std::string> typeOf;
        for (const auto &entry : config.getPlanners())
            typeOf[entry.name] = entry.type;
        benchmark.setPostRunEvent(
            [&](const ob::PlannerPtr &planner, ompl::tools::Benchmark::RunProperties &run)
            {
                // A run succeeds only with an exact solution that the independent validator accepts.
                bool success = false;
                std::string verdict = "no exact solution";
                if (planner->getProblemDefinition()->hasExactSolution())
                {
                    try
                    {
                        const MultiRobotPlan plan = PlannerRegistry::planOf(*planner, si, false);
                        const ValidationReport report = validator.validate(plan);
                        success = report.valid;
                        verdict = report.valid ? "valid" : report.message;
                        // Every planner's plan against the same bounds (our planners report them too).
                        PlanQuality::measure(*si, plan).addProperties(run);
                    }
                    catch (const std::exception &e)
                    {
                        verdict = std::string("validation failed: ") + e.what();
                    }
                    if (!success)
                    {
                        ++invalid;
                        std::cerr << "ompl_parc_benchmark: *** INVALID SOLUTION *** planner '" << planner->getName()
                                  << "' run " << benchmark.getStatus().activeRun << " (seed " << seedOf()
                                  << "): " << verdict << std::endl;
                    }
                }
                run["success BOOLEAN"] = success ? "1" : "0";
                run["validation STRING"] = verdict;
                run["seed INTEGER"] = std::to_string(seedOf());
                tally[planner->getName()].push_back(
                    {success, std::stod(run["time REAL"]), success ? std::stod(run["makespan_ratio REAL"]) : 0.});

                const auto status =
                    ob::PlannerStatus(static_cast<ob::PlannerStatus::StatusType>(std::stoi(run["status ENUM"])));
                csv.write(
                    {instance.scenario, si->getRobotCount(), instance.task, seedOf(), workerBudget(*planner),
                     planner->getName(), typeOf[planner->getName()], config.getTimeLimit(), success, status.asString()},
                    run);
                std::cerr << "[" << ++done << "/" << total << "] " << config.getProblemName() << " "
                          << planner->getName() << " seed " << seedOf() << ": "
                          << (success ? "solved" : status.asString()) << " in " << run["time REAL"] << " s"
                          << std::endl;
            });

        ompl::tools::Benchmark::Request request(config.getTimeLimit(), config.getMemLimit(), config.getRunCount());
        request.displayProgress = false;    // our progress line goes to stderr instead
        request.saveConsoleOutput = false;  // no console log file next to the results
        request.simplify = false;           // the planners' own solutions are what is compared
        request.timeBetweenUpdates = PROGRESS_PERIOD;
        benchmark.benchmark(request);
        // The log's first line names OMPL's version from its OMPL_VERSION macro, which Debian's OMPL leaves empty:
        // the database would show none. The version CMake found goes there instead.
        std::stringstream log;
        benchmark.saveResultsToStream(log);
        std::string text = log.str();
        const std::string blank = "OMPL version \n";
        if (text.rfind(blank, 0) == 0)
            text.replace(0, blank.size(), std::string("OMPL version ") + OMPL_PARC_OMPL_VERSION + "\n");
        openForWriting(logPath) << text;
        return invalid;
    }
}  // namespace

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_benchmark",
        [&]
        {
            po::options_description options("Usage: ompl_parc_benchmark [options] CONFIG.cfg\nOptions");
            options.add_options()("config", po::value<std::string>(), "benchmark configuration (OMPL.app INI)")(
                "check", "only check the config: load the problem, create every planner, then exit");
            po::positional_options_description positional;
            positional.add("config", 1);
            const auto vm = tools::parse(argc, argv, options, positional);
            if (!vm.count("config"))
                throw std::invalid_argument("no configuration file given (see --help)");

            // Everything that can be wrong with the input is checked before the first run.
            const auto config = BenchmarkConfig::read(vm["config"].as<std::string>());
            std::vector<Instance> instances;
            for (std::size_t k = 0; k < config.getInstances(); ++k)
                instances.push_back(makeInstance(config, config.getTask() + k));
            if (vm.count("check"))
            {
                std::cout << config.getProblemName() << ": " << instances.size() << " problem(s) of "
                          << instances.front().problem.getSpaceInformation()->getRobotCount() << " robots, "
                          << instances.front().planners.size() << " planners, config ok\n";
                return static_cast<int>(tools::EXIT_SOLVED);
            }

            const std::filesystem::path folder = config.getOutput();
            std::error_code error;
            std::filesystem::create_directories(folder, error);
            if (error)
                throw std::invalid_argument("cannot create output folder '" + folder.string() +
                                            "': " + error.message());
            const auto logPath = [&](const Instance &instance)
            {
                return folder / (config.getProblemName() +
                                 (instances.size() > 1 ? "_" + std::to_string(instance.task) : "") + ".log");
            };
            for (const auto &instance : instances)
                openForWriting(logPath(instance));  // fail now rather than after hours of runs
            const std::filesystem::path csvPath = folder / (config.getProblemName() + ".csv");
            std::ofstream csvFile = openForWriting(csvPath);
            tools::ResultsCsv csv(csvFile);

            Tally tally;
            std::size_t invalid = 0;
            for (std::size_t k = 0; k < instances.size(); ++k)
            {
                std::cerr << "ompl_parc_benchmark: problem " << k + 1 << "/" << instances.size() << ": "
                          << instances[k].scenario << std::endl;
                invalid += runInstance(config, instances[k], logPath(instances[k]), csv, tally);
            }
            std::cerr << "ompl_parc_benchmark: wrote " << csvPath.string() << " and " << instances.size() << " log(s)"
                      << (invalid ? ", " + std::to_string(invalid) + " INVALID solutions" : std::string()) << std::endl;
            printSummary(config, tally, std::cout);
            return static_cast<int>(invalid ? tools::EXIT_FAILED : tools::EXIT_SOLVED);
        });
}
