#include "BenchmarkRunner.h"

#include "ResultsCsv.h"

#include "ompl_parc/Version.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace ob = ompl::base;
using namespace ompl_parc;
using ompl_parc::tools::Instance;

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
        and one CSV row per run, and tally the runs (a line per run on \e log); returns the number of invalid
        solutions. */
    std::size_t runInstance(const BenchmarkConfig &config, const Instance &instance,
                            const std::filesystem::path &logPath, tools::ResultsCsv &csv, Tally &tally,
                            std::ostream &log)
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
                        log << "ompl_parc_benchmark: *** INVALID SOLUTION *** planner '" << planner->getName()
                            << "' run " << benchmark.getStatus().activeRun << " (seed " << seedOf() << "): " << verdict
                            << std::endl;
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
                log << "[" << ++done << "/" << total << "] " << config.getProblemName() << " " << planner->getName()
                    << " seed " << seedOf() << ": " << (success ? "solved" : status.asString()) << " in "
                    << run["time REAL"] << " s" << std::endl;
            });

        ompl::tools::Benchmark::Request request(config.getTimeLimit(), config.getMemLimit(), config.getRunCount());
        request.displayProgress = false;    // our progress line goes to stderr instead
        request.saveConsoleOutput = false;  // no console log file next to the results
        request.simplify = false;           // the planners' own solutions are what is compared
        request.timeBetweenUpdates = PROGRESS_PERIOD;
        benchmark.benchmark(request);
        // The log's first line names OMPL's version from its OMPL_VERSION macro, which Debian's OMPL leaves empty:
        // the database would show none. The version CMake found goes there instead.
        std::stringstream saved;
        benchmark.saveResultsToStream(saved);
        std::string text = saved.str();
        const std::string blank = "OMPL version \n";
        if (text.rfind(blank, 0) == 0)
            text.replace(0, blank.size(), std::string("OMPL version ") + OMPL_PARC_OMPL_VERSION + "\n");
        openForWriting(logPath) << text;
        return invalid;
    }
}  // namespace

ompl_parc::tools::BenchmarkRunner::BenchmarkRunner(BenchmarkConfig config) : config_(std::move(config))
{
    for (std::size_t k = 0; k < config_.getInstances(); ++k)
        instances_.push_back(makeInstance(config_, config_.getTask() + k));
}

ompl_parc::tools::BenchmarkRunner::~BenchmarkRunner() = default;

std::string ompl_parc::tools::BenchmarkRunner::describe() const
{
    return config_.getProblemName() + ": " + std::to_string(instances_.size()) + " problem(s) of " +
           std::to_string(instances_.front().problem.getSpaceInformation()->getRobotCount()) + " robots, " +
           std::to_string(instances_.front().planners.size()) + " planners, config ok";
}

ompl_parc::tools::BenchmarkResults ompl_parc::tools::BenchmarkRunner::run(std::ostream &log)
{
    const std::filesystem::path folder = config_.getOutput();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw std::invalid_argument("cannot create output folder '" + folder.string() + "': " + error.message());
    BenchmarkResults results;
    for (const auto &instance : instances_)
    {
        results.logs.push_back(folder / (config_.getProblemName() +
                                         (instances_.size() > 1 ? "_" + std::to_string(instance.task) : "") + ".log"));
        openForWriting(results.logs.back());  // fail now rather than after hours of runs
    }
    results.csv = folder / (config_.getProblemName() + ".csv");
    std::ofstream csvFile = openForWriting(results.csv);
    ResultsCsv csv(csvFile);

    Tally tally;
    for (std::size_t k = 0; k < instances_.size(); ++k)
    {
        log << "ompl_parc_benchmark: problem " << k + 1 << "/" << instances_.size() << ": " << instances_[k].scenario
            << std::endl;
        results.invalid += runInstance(config_, instances_[k], results.logs[k], csv, tally, log);
    }
    log << "ompl_parc_benchmark: wrote " << results.csv.string() << " and " << instances_.size() << " log(s)"
        << (results.invalid ? ", " + std::to_string(results.invalid) + " INVALID solutions" : std::string())
        << std::endl;
    std::ostringstream summary;
    printSummary(config_, tally, summary);
    results.summary = summary.str();
    return results;
}
