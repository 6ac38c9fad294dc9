/* ompl_parc_mpi: OR-P-ARC over MPI ranks, and benchmark sweeps over them. Run under mpirun or srun.

   Race (default): the demo's problem and P-ARC options; rank k runs OR-P-ARC's instance k (seed mixSeed(race seed,
   k), --workers threads); the first exact solution wins and stops every other rank (MpiRace). The winner smooths its
   plan (--smooth) and sends it to rank 0, which validates it with the independent validator, writes it (--out) and
   prints which rank won and how every rank ended. What crosses the network: the set-up's agreement on errors, the
   scenario file once (rank 0 reads it; built-in scenarios are built on every rank), the race seed, two small messages
   per rank, and the plan once.

   --benchmark CONFIG.cfg: the runs of a benchmark configuration shared over the ranks (MpiSweep); rank 0 writes the
   same .log and CSV rows as ompl_parc_benchmark would. The configuration says everything: the race's options are
   refused beside it (exit 2), not ignored.

   Only rank 0 writes to stdout. Exit codes as the other tools: 0 solved and valid (benchmark: every solution valid);
   1 not solved in time, invalid, or a rank failed; 2 bad input (rank 0 names it; every rank exits 2). */
#include "MpiRace.h"
#include "MpiSession.h"
#include "MpiSweep.h"
#include "ToolSupport.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/util/ParseNumber.h"
#include "ompl_parc/util/PlannerSeed.h"
#include "ompl_parc/util/TextFile.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/util/RandomNumbers.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>

#include <unistd.h>

namespace ob = ompl::base;
namespace po = boost::program_options;
using json = nlohmann::json;
using namespace ompl_parc;
using tools::MpiSession;

namespace
{
    using Clock = std::chrono::steady_clock;

    double secondsSince(Clock::time_point start)
    {
        return std::chrono::duration<double>(Clock::now() - start).count();
    }

    /** \brief Throws unless a file can be written at \e path (its folder exists and is writable, and it is no folder):
        a bad --out shows before the race, not after it. */
    void checkWritable(const std::string &path)
    {
        const std::filesystem::path file(path);
        const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
        if (std::filesystem::is_directory(file) || !std::filesystem::is_directory(folder) ||
            access(folder.c_str(), W_OK) != 0)
            throw std::invalid_argument("cannot write --out '" + path + "' (is its folder there and writable?)");
    }

    /** \brief Throws if --benchmark comes with options of the race, which the sweep would ignore (its configuration
        names the problem, the planners, the seed and the limits): a run that looks set up is not quietly another. */
    void checkSweepOptions(const po::variables_map &vm)
    {
        std::string given;
        for (const char *name : {"scenario", "robots", "task", "scenario-file", "param", "seed", "time-limit",
                                 "workers", "smooth", "out", "no-validate", "fail-rank"})
            if (vm.count(name) != 0 && !vm[name].defaulted())
                given += (given.empty() ? "--" : ", --") + std::string(name);
        if (!given.empty())
            throw std::invalid_argument(
                "with --benchmark the configuration names the problem, the planners, the seed and the limits: drop " +
                given);
    }

    /** \brief The options of the race, read on every rank. */
    struct RaceOptions
    {
        double timeLimit{30.};
        std::uint32_t seed{1};
        int failRank{-1};
        bool validate{true};
        std::vector<std::string> params;
    };

    /** \brief Everything a rank races with. */
    struct Racer
    {
        std::optional<MultiRobotProblem> problem;
        std::shared_ptr<ORPARC> orparc;
        std::shared_ptr<PARC> instance;
        std::uint_fast32_t raceSeed{0};
        std::size_t problemBytes{0};
    };

    /** \brief The race's options on every rank (each parses the same command line). */
    void readOptions(const MpiSession &mpi, const po::variables_map &vm, RaceOptions &options)
    {
        options.timeLimit = parseReal(vm["time-limit"].as<std::string>(), "--time-limit", 0., 1e7);
        if (!(options.timeLimit > 0.))
            throw std::invalid_argument("--time-limit must be positive");
        options.seed = static_cast<std::uint32_t>(parseInteger(vm["seed"].as<std::string>(), "--seed", 0, UINT32_MAX));
        if (vm.count("fail-rank"))
            options.failRank =
                static_cast<int>(parseInteger(vm["fail-rank"].as<std::string>(), "--fail-rank", 0, mpi.getSize() - 1));
        options.validate = vm.count("no-validate") == 0;
        if (vm.count("param"))
            options.params = vm["param"].as<std::vector<std::string>>();
        for (const std::string &param : options.params)
        {
            for (const char *rankSet : {"instances=", "total_workers="})
                if (param.rfind(rankSet, 0) == 0)
                    throw std::invalid_argument("--param " + param +
                                                ": the ranks are the instances (mpirun -np K), --workers the threads "
                                                "of each");
            if (param.rfind("objective=", 0) == 0 && param != "objective=first")
                throw std::invalid_argument("--param " + param +
                                            ": over MPI the first solution wins (the anytime objectives race in "
                                            "threads: ompl_parc_demo --planner orparc)");
        }
        if (vm.count("out") && mpi.isRoot())
            checkWritable(vm["out"].as<std::string>());
        ompl::RNG::setSeed(options.seed);
    }

    /** \brief The problem on every rank: a scenario file read by rank 0 only and broadcast (its text, then its
        folder, for the files it names), a built-in scenario built by every rank. Returns the agreed error (empty:
        every rank has it). */
    std::string shareProblem(const MpiSession &mpi, const po::variables_map &vm, Racer &racer)
    {
        if (!vm.count("scenario-file"))
            return mpi.agree(MpiSession::errorOf([&] { racer.problem.emplace(tools::problemFromOptions(vm)); }));
        std::string text, folder;
        std::string error = mpi.agree(MpiSession::errorOf(
            [&]
            {
                tools::checkProblemSource(vm);
                if (!mpi.isRoot())
                    return;
                const std::string path = vm["scenario-file"].as<std::string>();
                text = TextFile::read(path, "ScenarioFile");
                folder = std::filesystem::path(path).parent_path().string();
            }));
        if (!error.empty())
            return error;
        mpi.broadcast(text);
        mpi.broadcast(folder);
        racer.problemBytes = text.size() + folder.size();
        return mpi.agree(MpiSession::errorOf([&] { racer.problem.emplace(ScenarioFile::fromJson(text, folder)); }));
    }

    /** \brief The OR-P-ARC whose instances the ranks are, made from the options as ompl_parc_demo makes orparc; on
        rank 0 the race seed. */
    void makePlanner(const MpiSession &mpi, const po::variables_map &vm, const RaceOptions &options, Racer &racer)
    {
        const auto &si = racer.problem->getSpaceInformation();
        if (const std::string coarse = si->checkPlanningResolution(); !coarse.empty())
            throw std::invalid_argument(coarse);
        racer.orparc = std::static_pointer_cast<ORPARC>(PlannerRegistry::create("orparc", si, options.params));
        if (vm.count("workers"))
            PlannerRegistry::setParameter(*racer.orparc, "workers", vm["workers"].as<std::string>());
        PlannerRegistry::setParameter(*racer.orparc, "smooth", vm["smooth"].as<std::string>());
        racer.orparc->setProblemDefinition(racer.problem->createProblemDefinition());
        // Seed 0 draws one race seed from OMPL's sequence (--seed), on rank 0, for all.
        racer.raceSeed = mpi.isRoot() ? seedOrDraw(racer.orparc->getSeed()) : 0;
    }

    /** \brief The JSON a rank reports after its solve: its seed, stage times and counters. */
    std::string describe(const PARC &instance)
    {
        const ArcStatistics &s = instance.getStatistics();
        return json{
            {"name", instance.getName()},     {"seed", instance.getSeed()},
            {"initial", s.initialWall},       {"detection", s.detectionWall},
            {"resolution", s.resolutionWall}, {"conflicts", s.conflicts},
            {"solver_calls", s.solverCalls},  {"repair_attempts", instance.getParallelStatistics().repairAttempts}}
            .dump();
    }

    /** \brief The winner's plan, smoothed like OR-P-ARC's winner, on rank 0 (sent there if the winner is another
        rank); with the transfer's size and time. */
    struct Delivered
    {
        MultiRobotPlan plan;
        std::size_t bytes{0};
        double transfer{0.}, smoothing{0.};
    };

    std::optional<Delivered> deliverPlan(const MpiSession &mpi, const tools::MpiRace &race, const Racer &racer,
                                         double timeLimit)
    {
        const int winner = race.getWinner();
        if (winner < 0 || (mpi.getRank() != winner && !mpi.isRoot()))
            return std::nullopt;
        const auto si = MultiRobotSpaceInformation::get(racer.problem->getSpaceInformation(), "ompl_parc_mpi");
        if (mpi.getRank() == winner)
        {
            Delivered delivered{racer.instance->getPlan(), 0, 0., 0.};
            const auto report = racer.orparc->smoothWinner(
                delivered.plan, racer.instance->getSeed(),
                ob::timedPlannerTerminationCondition(std::max(0., timeLimit - race.getElapsed())));
            delivered.smoothing = report ? report->seconds : 0.;
            if (mpi.isRoot())
                return delivered;
            const auto sent = Clock::now();
            const std::string text = SolutionFile::toJson(delivered.plan, *si);
            mpi.send(json{{"smoothing", delivered.smoothing}, {"serialise", secondsSince(sent)}}.dump(), 0,
                     tools::TAG_PLAN_INFO);
            mpi.send(text, 0, tools::TAG_PLAN);
            return std::nullopt;
        }
        const json info = json::parse(mpi.receive(winner, tools::TAG_PLAN_INFO).second);
        const auto received = Clock::now();
        const std::string text = mpi.receive(winner, tools::TAG_PLAN).second;
        Delivered delivered{SolutionFile::fromJson(text, *si), text.size(), 0., info.at("smoothing").get<double>()};
        // Serialising on the winner, the message, parsing here (the smoothing before it is not transfer).
        delivered.transfer = info.at("serialise").get<double>() + secondsSince(received);
        return delivered;
    }

    void printClaims(const tools::MpiRace &race)
    {
        const auto &claims = race.getClaims();
        for (std::size_t r = 0; r < claims.size(); ++r)
        {
            const auto &c = claims[r];
            // A planner stopped because another rank won reports a timeout: say what happened instead.
            const bool stopped = race.getWinner() >= 0 && static_cast<int>(r) != race.getWinner() &&
                                 c.status == ob::PlannerStatus::TIMEOUT;
            std::cout << "rank " << std::left << std::setw(6) << r << std::right
                      << (stopped ? "stopped: rank " + std::to_string(race.getWinner()) + " won" : c.reason)
                      << ", returned after " << c.returnedAfter << " s";
            const json report = json::parse(c.report);
            if (report.contains("name"))
                std::cout << ", " << report["name"].get<std::string>() << " seed " << report["seed"]
                          << ", stages initial " << report["initial"].get<double>() << " s, detection "
                          << report["detection"].get<double>() << " s, resolution "
                          << report["resolution"].get<double>() << " s, " << report["conflicts"]
                          << " conflicts resolved, " << report["repair_attempts"] << " repair attempts";
            std::cout << (static_cast<int>(r) == race.getWinner() ? "  <- winner" : "") << "\n";
        }
    }

    /** \brief Rank 0 after the race: the summary, the validation and the solution file; returns the exit code. */
    int report(const MpiSession &mpi, const po::variables_map &vm, const RaceOptions &options, const Racer &racer,
               const tools::MpiRace &race, const std::optional<Delivered> &delivered, double startup)
    {
        std::cout << std::fixed << std::setprecision(3) << "start-up   " << startup
                  << " s on rank 0 (MPI, problem on every rank: " << racer.problemBytes << " bytes broadcast)\n";
        if (race.getFailedRank() >= 0)
        {
            printClaims(race);
            tools::printError("ompl_parc_mpi", "rank " + std::to_string(race.getFailedRank()) +
                                                   " failed: " + race.getClaims()[race.getFailedRank()].reason);
            return tools::EXIT_FAILED;
        }
        std::cout << "status     "
                  << (race.getWinner() >= 0 ? "Exact solution from rank " + std::to_string(race.getWinner())
                                            : "no rank solved it: " + race.getClaims()[0].reason)
                  << " after " << race.getClaims()[std::max(race.getWinner(), 0)].returnedAfter << " s (all "
                  << mpi.getSize() << " ranks stopped and joined after "
                  << std::max_element(race.getClaims().begin(), race.getClaims().end(),
                                      [](const auto &a, const auto &b) { return a.returnedAfter < b.returnedAfter; })
                         ->returnedAfter
                  << " s)\n";
        printClaims(race);
        if (!delivered)
            return tools::EXIT_FAILED;
        const MultiRobotPlan &plan = delivered->plan;
        std::cout << "plan       from rank " << race.getWinner() << ": "
                  << (race.getWinner() == 0 ? std::string("local")
                                            : std::to_string(delivered->bytes) + " bytes in " +
                                                  std::to_string(delivered->transfer) + " s")
                  << ", smoothed " << delivered->smoothing << " s\n";
        const auto checkStart = Clock::now();
        const ValidationReport check =
            options.validate ? SolutionValidator(*racer.problem).validate(plan) : ValidationReport{};
        std::cout << "makespan   " << plan.getMakespan() << " timesteps, sum of costs " << plan.getSumOfCosts() << "\n"
                  << "validated  "
                  << (!options.validate ? std::string("skipped (--no-validate)")
                      : check.valid     ? "yes (" + std::to_string(secondsSince(checkStart)) + " s)"
                                        : "NO: " + check.message)
                  << std::endl;
        if (vm.count("out"))
        {
            SolutionFile::write(
                vm["out"].as<std::string>(), plan,
                *MultiRobotSpaceInformation::get(racer.problem->getSpaceInformation(), "ompl_parc_mpi"));
            std::cout << "solution   " << vm["out"].as<std::string>() << std::endl;
        }
        return check.valid || !options.validate ? tools::EXIT_SOLVED : tools::EXIT_FAILED;
    }

    /** \brief The race: returns the tool's exit code on this rank (the others' is 0 unless the input is bad). */
    int race(const MpiSession &mpi, const po::variables_map &vm, Clock::time_point processStart)
    {
        RaceOptions options;
        Racer racer;
        std::string error = mpi.agree(MpiSession::errorOf([&] { readOptions(mpi, vm, options); }));
        if (error.empty())
            error = shareProblem(mpi, vm, racer);
        if (error.empty())
            error = mpi.agree(MpiSession::errorOf([&] { makePlanner(mpi, vm, options, racer); }));
        if (error.empty())
        {
            std::string raceSeed = std::to_string(racer.raceSeed);
            mpi.broadcast(raceSeed);
            racer.raceSeed = std::stoul(raceSeed);
            // Instance k = rank k, as OR-P-ARC's instance k in threads.
            error = mpi.agree(MpiSession::errorOf(
                [&] { racer.instance = racer.orparc->createInstance(mpi.getRank(), racer.raceSeed); }));
        }
        if (!error.empty())
        {
            if (mpi.isRoot())
                tools::printError("ompl_parc_mpi", error);
            return tools::EXIT_BAD_INPUT;
        }
        const auto &si = racer.problem->getSpaceInformation();
        std::cout << "scenario   " << racer.problem->getName() << ", " << si->getRobotCount() << " robots\n"
                  << "planner    OR-P-ARC over MPI: " << mpi.getSize()
                  << (mpi.getSize() == 1 ? " rank x " : " ranks x ") << racer.instance->getWorkers()
                  << " worker(s), race seed " << racer.raceSeed
                  << " (the same instances race in threads with ompl_parc_demo --planner orparc --param instances="
                  << mpi.getSize() << " --workers " << racer.instance->getWorkers()
                  << " --param seed=" << racer.raceSeed;
        for (const std::string &param : options.params)
            if (param.rfind("seed=", 0) != 0)
                std::cout << " --param " << param;
        std::cout << ")\n";

        tools::MpiRace race(mpi);
        const double startup = secondsSince(processStart);
        race.run(
            [&](const ob::PlannerTerminationCondition &ptc)
            {
                if (mpi.getRank() == options.failRank)
                    throw std::runtime_error("failure injected by --fail-rank " + std::to_string(options.failRank));
                return racer.instance->solve(ptc);
            },
            [&] { return describe(*racer.instance); }, options.timeLimit);
        const auto delivered = deliverPlan(mpi, race, racer, options.timeLimit);
        if (!mpi.isRoot())
            return tools::EXIT_SOLVED;  // rank 0 speaks for the run
        // Every other rank is done with MPI: what fails from here is rank 0's alone (an exit code, no abort).
        try
        {
            return report(mpi, vm, options, racer, race, delivered, startup);
        }
        catch (const std::exception &e)
        {
            tools::printError("ompl_parc_mpi", e.what());
            return tools::EXIT_BAD_INPUT;
        }
    }
}  // namespace

int main(int argc, char **argv)
{
    const auto processStart = Clock::now();
    std::optional<MpiSession> session;
    try
    {
        session.emplace(argc, argv);
    }
    catch (const std::exception &e)
    {
        tools::printError("ompl_parc_mpi", e.what());
        return tools::EXIT_BAD_INPUT;
    }
    const MpiSession &mpi = *session;
    if (!mpi.isRoot())
        std::cout.rdbuf(nullptr);  // rank 0 speaks for the run
    return tools::runTool(
        "ompl_parc_mpi",
        [&]
        {
            po::options_description options("Usage: mpirun -np K ompl_parc_mpi [options]\nOptions");
            tools::addProblemOptions(options);
            options.add_options()("param", po::value<std::vector<std::string>>()->composing(),
                                  "P-ARC parameter key=value (repeatable, as ompl_parc_demo --planner orparc; not "
                                  "instances or total_workers: the ranks are the instances)")(
                "seed", po::value<std::string>()->default_value("1"),
                "OMPL's random seed (the race seed is drawn from it unless --param seed=S gives one)")(
                "time-limit", po::value<std::string>()->default_value("30"), "planning time limit in seconds")(
                "workers", po::value<std::string>(), "worker threads of each rank's P-ARC (W_k; default 1)")(
                "smooth", po::value<std::string>()->default_value("1"),
                "seconds of time-aware shortcutting of the winner's plan; 0: off")(
                "out", po::value<std::string>(), "write the solution to this JSON file (rank 0)")(
                "no-validate", "skip the independent validation of the solution")(
                "benchmark", po::value<std::string>(),
                "run this benchmark configuration's runs spread over the ranks instead (see ompl_parc_benchmark; "
                "the race's options are refused beside it)")(
                "fail-rank", po::value<std::string>(),
                "for testing the failure path: this rank's solve throws (the run ends with exit 1 and its message)");
            // Every rank parses the same command line: an error is the same everywhere, and rank 0 alone says it.
            po::variables_map vm;
            if (const std::string error = mpi.agree(MpiSession::errorOf(
                    [&]
                    {
                        vm = tools::parse(argc, argv, options);
                        if (vm.count("benchmark"))
                            checkSweepOptions(vm);
                    }));
                !error.empty())
            {
                if (mpi.isRoot())
                    throw std::invalid_argument(error);
                return static_cast<int>(tools::EXIT_BAD_INPUT);
            }
            try
            {
                return vm.count("benchmark") ? tools::MpiSweep(mpi).run(vm["benchmark"].as<std::string>())
                                             : race(mpi, vm, processStart);
            }
            catch (const std::exception &e)
            {
                // Past the agreed set-up the other ranks may be waiting for this one: end them all.
                tools::printError("ompl_parc_mpi", "rank " + std::to_string(mpi.getRank()) + ": " + e.what());
                mpi.abort(tools::EXIT_FAILED);
            }
        });
}
