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
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

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
        /** \brief Makespan over its obstacle-aware bound (PlanQuality), for a valid solution. */
        double makespanPathRatio;
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
        instance.validator = std::make_shared<const SolutionValidator>(problem);
        for (const auto &entry : config.getPlanners())
        {
            auto planner = PlannerRegistry::create(entry.type, problem.getSpaceInformation(), entry.params);
            planner->setName(entry.name);
            if (const unsigned int budget = workerBudget(*planner); budget > config.getWorkers())
                throw std::invalid_argument(
                    "planner '" + entry.name + "' needs " + std::to_string(budget) +
                    " workers but [benchmark] workers = " + std::to_string(config.getWorkers()));
            instance.planners.push_back(planner);
        }
        return instance;
    }

    /** \brief Success rate, median time (failures counted at the time limit) and median makespan over its lower
        bounds, straight-line and obstacle-aware (solved runs), per planner, as a Markdown table: the robustness and
        quality view of an experiment over many instances. */
    void printSummary(const BenchmarkConfig &config, const Tally &tally, std::ostream &out)
    {
        out << "| planner | solved | median time (s, failures at " << config.getTimeLimit()
            << " s) | median makespan / lower bound (solved) | median makespan / path bound (solved) |\n"
            << "|---|---|---|---|---|\n";
        for (const auto &entry : config.getPlanners())
        {
            const auto it = tally.find(entry.name);
            if (it == tally.end())
                continue;
            std::vector<double> times, ratios, pathRatios;
            for (const RunOutcome &run : it->second)
            {
                times.push_back(run.success ? run.time : config.getTimeLimit());
                if (run.success)
                {
                    ratios.push_back(run.makespanRatio);
                    pathRatios.push_back(run.makespanPathRatio);
                }
            }
            out << "| " << entry.name << " | " << ratios.size() << "/" << times.size() << " | " << std::fixed
                << std::setprecision(3) << median(times) << " | ";
            if (ratios.empty())
                out << "- | - |\n";
            else
                out << std::setprecision(2) << median(ratios) << " | " << median(pathRatios) << " |\n";
        }
    }

    /** \brief The PlannerStatus a run's properties record (OMPL's "status ENUM"). */
    ob::PlannerStatus statusOf(const ompl::tools::Benchmark::RunProperties &properties)
    {
        return ob::PlannerStatus(static_cast<ob::PlannerStatus::StatusType>(std::stoi(properties.at("status ENUM"))));
    }

    /** \brief OMPL's Benchmark whose experiment is assembled from run records instead of run: its log is OMPL's own
        format, whichever process did the runs. */
    class MergedBenchmark : public ompl::tools::Benchmark
    {
      public:
        using ompl::tools::Benchmark::Benchmark;
        /** \brief The experiment the log is written from. */
        CompleteExperiment &getExperiment() { return exp_; }
    };

    /** \brief A SimpleSetup for \e problem's start and goal with \e planner (else SimpleSetup allocates a default
        planner it never runs). */
    std::unique_ptr<ompl::geometric::SimpleSetup> setupFor(const MultiRobotProblem &problem,
                                                           const ob::PlannerPtr &planner)
    {
        const auto &si = problem.getSpaceInformation();
        auto setup = std::make_unique<ompl::geometric::SimpleSetup>(si);
        ob::ScopedState<> start(si), goal(si);
        const auto pdef = problem.createProblemDefinition();
        start = pdef->getStartState(0);
        goal = pdef->getGoal()->as<ob::GoalState>()->getState();
        setup->setStartAndGoalStates(start, goal);
        setup->setPlanner(planner);
        return setup;
    }

    /** \brief Run \e run (seed [benchmark] seed + run) of planner \e p of \e instance with OMPL's Benchmark; the
        solution re-checked by the independent validator; a line on \e log. */
    tools::RunRecord runOnce(const BenchmarkConfig &config, const Instance &instance, std::size_t instanceIndex,
                             std::size_t p, std::size_t run, std::ostream &log, const std::string &counter)
    {
        const MultiRobotProblem &problem = instance.problem;
        const auto &si = problem.getSpaceInformation();
        const ob::PlannerPtr &planner = instance.planners.at(p);
        const auto setup = setupFor(problem, planner);
        ompl::tools::Benchmark benchmark(*setup, config.getProblemName());
        benchmark.addPlanner(planner);
        const unsigned int seed = config.getSeed() + static_cast<unsigned int>(run);
        benchmark.setPreRunEvent(
            [&](const ob::PlannerPtr &planner)
            {
                if (planner->params().hasParam("seed"))
                    planner->params().setParam("seed", std::to_string(seed));
            });

        tools::RunRecord record;
        record.instance = instanceIndex;
        record.planner = p;
        record.run = run;
        benchmark.setPostRunEvent(
            [&](const ob::PlannerPtr &planner, ompl::tools::Benchmark::RunProperties &properties)
            {
                // A run succeeds only with an exact solution that the independent validator accepts.
                bool success = false;
                std::string verdict = "no exact solution";
                if (planner->getProblemDefinition()->hasExactSolution())
                {
                    try
                    {
                        const MultiRobotPlan plan = PlannerRegistry::planOf(*planner, si, false);
                        const ValidationReport report = instance.validator->validate(plan);
                        success = report.valid;
                        verdict = report.valid ? "valid" : report.message;
                        // Every planner's plan against the same bounds (our planners report them too).
                        PlanQuality::measure(*si, plan).addProperties(properties);
                    }
                    catch (const std::exception &e)
                    {
                        verdict = std::string("validation failed: ") + e.what();
                    }
                    if (!success)
                    {
                        record.invalid = true;
                        log << "ompl_parc_benchmark: *** INVALID SOLUTION *** planner '" << planner->getName()
                            << "' run " << run << " (seed " << seed << "): " << verdict << std::endl;
                    }
                }
                properties["success BOOLEAN"] = success ? "1" : "0";
                properties["validation STRING"] = verdict;
                properties["seed INTEGER"] = std::to_string(seed);
                log << "[" << counter << "] " << config.getProblemName() << " " << planner->getName() << " seed "
                    << seed << ": " << (success ? "solved" : statusOf(properties).asString()) << " in "
                    << properties["time REAL"] << " s" << std::endl;
            });

        ompl::tools::Benchmark::Request request(config.getTimeLimit(), config.getMemLimit(), 1);
        request.displayProgress = false;    // our progress line goes to stderr instead
        request.saveConsoleOutput = false;  // no console log file next to the results
        request.simplify = false;           // the planners' own solutions are what is compared
        request.timeBetweenUpdates = PROGRESS_PERIOD;
        benchmark.benchmark(request);

        const auto &experiment = benchmark.getRecordedExperimentData();
        const auto &recorded = experiment.planners.at(0);
        record.plannerName = recorded.name;
        record.properties = recorded.runs.at(0);
        record.common = recorded.common;
        record.progressNames = recorded.progressPropertyNames;
        if (!recorded.runsProgressData.empty())
            record.progress = recorded.runsProgressData.front();
        record.host = experiment.host;
        record.cpuInfo = experiment.cpuInfo;
        record.setupInfo = experiment.setupInfo;
        record.programSeed = experiment.seed;
        record.started = std::chrono::duration<double>(experiment.startTime.time_since_epoch()).count();
        record.duration = experiment.totalDuration;
        return record;
    }

    /** \brief The CSV row of \e record, a run of \e instance; tallied. */
    void writeRow(const BenchmarkConfig &config, const Instance &instance, const tools::RunRecord &record,
                  tools::ResultsCsv &csv, Tally &tally)
    {
        const auto &planner = instance.planners.at(record.planner);
        const auto &properties = record.properties;
        const bool success = properties.at("success BOOLEAN") == "1";
        tally[planner->getName()].push_back({success, std::stod(properties.at("time REAL")),
                                             success ? std::stod(properties.at("makespan_ratio REAL")) : 0.,
                                             success ? std::stod(properties.at("makespan_path_ratio REAL")) : 0.});
        csv.write({instance.scenario, instance.problem.getSpaceInformation()->getRobotCount(), instance.task,
                   static_cast<unsigned int>(std::stoul(properties.at("seed INTEGER"))), workerBudget(*planner),
                   planner->getName(), config.getPlanners().at(record.planner).type, config.getTimeLimit(), success,
                   statusOf(properties).asString()},
                  properties);
    }

    /** \brief Writes the OMPL log of \e instance from its \e records (every run of it, sorted by planner, then run:
        OMPL's own order) to \e path. */
    void writeLog(const BenchmarkConfig &config, const Instance &instance, const std::vector<tools::RunRecord> &records,
                  const std::filesystem::path &path)
    {
        const MultiRobotProblem &problem = instance.problem;
        const auto &si = problem.getSpaceInformation();
        const auto setup = setupFor(problem, instance.planners.front());
        MergedBenchmark benchmark(*setup, config.getProblemName());
        benchmark.addExperimentParameter("robots", "INTEGER", std::to_string(si->getRobotCount()));
        benchmark.addExperimentParameter("resolution", "REAL", std::to_string(si->getResolution()));
        benchmark.addExperimentParameter("base_seed", "INTEGER", std::to_string(config.getSeed()));
        benchmark.addExperimentParameter("worker_budget", "INTEGER", std::to_string(config.getWorkers()));
        benchmark.addExperimentParameter("task", "INTEGER", std::to_string(instance.task));
        benchmark.addExperimentParameter("ompl_parc_version", "VARCHAR(32)", OMPL_PARC_VERSION);
        auto &experiment = benchmark.getExperiment();
        experiment.maxTime = config.getTimeLimit();
        experiment.maxMem = config.getMemLimit();
        experiment.runCount = config.getRunCount();
        experiment.planners.resize(instance.planners.size());
        double first = records.front().started, last = first;
        for (const tools::RunRecord &r : records)
        {
            auto &entry = experiment.planners.at(r.planner);
            if (entry.runs.empty())
            {
                entry.name = r.plannerName;
                entry.common = r.common;
                entry.progressPropertyNames = r.progressNames;
            }
            entry.runs.push_back(r.properties);
            if (!r.progressNames.empty())
                entry.runsProgressData.push_back(r.progress);
            first = std::min(first, r.started);
            last = std::max(last, r.started + r.duration);
        }
        experiment.startTime = ompl::time::point(
            std::chrono::duration_cast<ompl::time::point::duration>(std::chrono::duration<double>(first)));
        experiment.totalDuration = last - first;
        experiment.setupInfo = records.front().setupInfo;
        experiment.seed = static_cast<std::uint_fast32_t>(records.front().programSeed);
        experiment.host = records.front().host;
        experiment.cpuInfo = records.front().cpuInfo;
        // The log's first line names OMPL's version from its OMPL_VERSION macro, which Debian's OMPL leaves empty:
        // the database would show none. The version CMake found goes there instead.
        std::stringstream saved;
        benchmark.saveResultsToStream(saved);
        std::string text = saved.str();
        const std::string blank = "OMPL version \n";
        if (text.rfind(blank, 0) == 0)
            text.replace(0, blank.size(), std::string("OMPL version ") + OMPL_PARC_OMPL_VERSION + "\n");
        openForWriting(path) << text;
    }

    /** \brief Writes a benchmark's results as its runs come in: each run's CSV row at once (flushed: an interrupted
        benchmark keeps the rows of the runs it did), each problem's OMPL log when its last run is in; then the
        summary. The rows follow the order the runs come in (OMPL's, from one process or sorted after a sweep). */
    class ResultsWriter
    {
      public:
        /** \brief Opens the CSV at the last of \e paths (the logs before it, one per problem). */
        ResultsWriter(const BenchmarkConfig &config, const std::vector<Instance> &instances,
                      const std::vector<std::filesystem::path> &paths)
            : config_(config), instances_(instances), csvFile_(openForWriting(paths.back())), csv_(csvFile_)
        {
            logs_.assign(paths.begin(), paths.end() - 1);
            results_.csv = paths.back();
            pending_.resize(instances.size());
        }

        /** \brief Takes one run's record. */
        void add(tools::RunRecord record)
        {
            const std::size_t index = record.instance;
            const Instance &instance = instances_.at(index);
            writeRow(config_, instance, record, csv_, tally_);
            ++results_.runs;
            results_.invalid += record.invalid ? 1 : 0;
            auto &runs = pending_[index];
            runs.push_back(std::move(record));
            if (runs.size() < instance.planners.size() * config_.getRunCount())
                return;
            std::sort(runs.begin(), runs.end(),
                      [](const tools::RunRecord &a, const tools::RunRecord &b)
                      { return std::tie(a.planner, a.run) < std::tie(b.planner, b.run); });
            writeLog(config_, instance, runs, logs_.at(index));
            results_.logs.push_back(logs_.at(index));
            runs.clear();
        }

        /** \brief The results, with the summary table; a line on \e log. The logs of problems whose runs did not all
            end (the runs were stopped) are not written: their empty files, made by checkOutput(), are removed. */
        tools::BenchmarkResults finish(std::ostream &log)
        {
            for (const auto &path : logs_)
                if (std::find(results_.logs.begin(), results_.logs.end(), path) == results_.logs.end())
                    std::filesystem::remove(path);
            log << "ompl_parc_benchmark: wrote " << results_.csv.string() << " and " << results_.logs.size()
                << " log(s)"
                << (results_.invalid ? ", " + std::to_string(results_.invalid) + " INVALID solutions" : std::string())
                << std::endl;
            std::ostringstream summary;
            printSummary(config_, tally_, summary);
            results_.summary = summary.str();
            return results_;
        }

      private:
        const BenchmarkConfig &config_;
        const std::vector<Instance> &instances_;
        tools::BenchmarkResults results_;
        /** \brief Where each problem's log goes (results_.logs: those written). */
        std::vector<std::filesystem::path> logs_;
        std::ofstream csvFile_;
        tools::ResultsCsv csv_;
        Tally tally_;
        /** \brief Per problem, its runs in so far (until its log is written). */
        std::vector<std::vector<tools::RunRecord>> pending_;
    };
}  // namespace

ompl_parc::tools::BenchmarkRunner::BenchmarkRunner(BenchmarkConfig config) : config_(std::move(config))
{
    for (std::size_t k = 0; k < config_.getInstances(); ++k)
        instances_.push_back(makeInstance(config_, config_.getTask() + k));
    for (const auto &planner : instances_.front().planners)
        if (!planner->params().hasParam("seed"))
            seedless_.push_back(planner->getName());
}

ompl_parc::tools::BenchmarkRunner::~BenchmarkRunner() = default;

std::string ompl_parc::tools::BenchmarkRunner::describe() const
{
    return config_.getProblemName() + ": " + std::to_string(instances_.size()) + " problem(s) of " +
           std::to_string(instances_.front().problem.getSpaceInformation()->getRobotCount()) + " robots, " +
           std::to_string(instances_.front().planners.size()) + " planners, config ok";
}

std::size_t ompl_parc::tools::BenchmarkRunner::getRunCount() const
{
    return instances_.size() * config_.getPlanners().size() * config_.getRunCount();
}

std::vector<std::filesystem::path> ompl_parc::tools::BenchmarkRunner::checkOutput() const
{
    const std::filesystem::path folder = config_.getOutput();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw std::invalid_argument("cannot create output folder '" + folder.string() + "': " + error.message());
    std::vector<std::filesystem::path> paths;
    for (const auto &instance : instances_)
        paths.push_back(folder / (config_.getProblemName() +
                                  (instances_.size() > 1 ? "_" + std::to_string(instance.task) : "") + ".log"));
    paths.push_back(folder / (config_.getProblemName() + ".csv"));
    for (const auto &path : paths)
        openForWriting(path);  // fail now rather than after hours of runs
    return paths;
}

void ompl_parc::tools::BenchmarkRunner::runRuns(std::size_t rank, std::size_t ranks, std::ostream &log,
                                                const std::function<void(RunRecord)> &take,
                                                const std::function<bool()> &stopped)
{
    if (rank == 0)
        for (const std::string &name : seedless_)
            log << "ompl_parc_benchmark: planner '" << name
                << "' has no seed parameter: its runs use OMPL's global random sequence" << std::endl;
    const std::size_t planners = config_.getPlanners().size(), runs = config_.getRunCount();
    const std::size_t share = getRunCount() / ranks + (rank < getRunCount() % ranks ? 1 : 0);
    std::size_t done = 0;
    for (std::size_t k = rank; k < getRunCount() && !(stopped && stopped()); k += ranks)
    {
        const std::size_t instance = k / (planners * runs), planner = k / runs % planners, run = k % runs;
        ++done;
        if (ranks == 1 && k % (planners * runs) == 0)
            log << "ompl_parc_benchmark: problem " << instance + 1 << "/" << instances_.size() << ": "
                << instances_[instance].scenario << std::endl;
        // One process counts per problem, as it goes through them; a rank counts its share.
        const std::string counter =
            ranks == 1 ? std::to_string(k % (planners * runs) + 1) + "/" + std::to_string(planners * runs)
                       : std::to_string(done) + "/" + std::to_string(share) + " on rank " + std::to_string(rank);
        take(runOnce(config_, instances_[instance], instance, planner, run, log, counter));
    }
}

std::vector<ompl_parc::tools::RunRecord> ompl_parc::tools::BenchmarkRunner::runShare(std::size_t rank,
                                                                                     std::size_t ranks,
                                                                                     std::ostream &log)
{
    std::vector<RunRecord> records;
    runRuns(rank, ranks, log, [&records](RunRecord record) { records.push_back(std::move(record)); });
    return records;
}

ompl_parc::tools::BenchmarkResults ompl_parc::tools::BenchmarkRunner::write(std::vector<RunRecord> records,
                                                                            std::ostream &log) const
{
    std::sort(records.begin(), records.end(),
              [](const RunRecord &a, const RunRecord &b)
              { return std::tie(a.instance, a.planner, a.run) < std::tie(b.instance, b.planner, b.run); });
    ResultsWriter writer(config_, instances_, checkOutput());
    for (RunRecord &record : records)
        writer.add(std::move(record));
    return writer.finish(log);
}

ompl_parc::tools::BenchmarkResults ompl_parc::tools::BenchmarkRunner::run(std::ostream &log,
                                                                          const std::function<bool()> &stopped)
{
    ResultsWriter writer(config_, instances_, checkOutput());
    const auto take = [&writer](RunRecord record) { writer.add(std::move(record)); };
    runRuns(0, 1, log, take, stopped);
    return writer.finish(log);
}
