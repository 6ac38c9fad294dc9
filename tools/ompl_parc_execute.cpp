/* ompl_parc_execute: turn a solution into trajectories robots can run, and try it with robots that run late.
   1. Time parameterization within each robot's velocity and acceleration limits, checked conflict-free
      (TimeParameterization); --trajectory writes it with the temporal plan graph (TrajectoryFile).
   2. The temporal plan graph (TemporalPlanGraph).
   3. --runs executions with random delays (each robot starts up to --max-delay s late and runs at --min-speed..1 of
      its speed), time-indexed and coordinated by the graph, every executed instant checked by the validator.
   Exit 0: the trajectory is conflict-free and no coordinated run collided; 1: otherwise (or the solution itself does
   not validate); 2: bad input (one-line reason); 130: interrupted. */
#include "Interruption.h"
#include "ToolSupport.h"

#include "ompl_parc/execution/ExecutionSimulator.h"
#include "ompl_parc/execution/TemporalPlanGraph.h"
#include "ompl_parc/execution/TimeParameterization.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/io/TrajectoryFile.h"
#include "ompl_parc/util/ParseNumber.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/util/Time.h>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace po = boost::program_options;
using namespace ompl_parc;

namespace
{
    double median(std::vector<double> values)
    {
        std::sort(values.begin(), values.end());
        const std::size_t n = values.size();
        return n == 0 ? 0. : (n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.);
    }
}  // namespace

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_execute",
        [&]
        {
            po::options_description options("Usage: ompl_parc_execute [options] SOLUTION.json\nOptions");
            tools::addProblemOptions(options);
            options.add_options()("trajectory", po::value<std::string>(),
                                  "write the trajectories (JointTrajectory fields) and the temporal plan graph here")(
                "runs", po::value<std::string>()->default_value("100"), "executions with random delays (0: none)")(
                "max-delay", po::value<std::string>()->default_value("1"), "latest start of a robot, seconds")(
                "min-speed", po::value<std::string>()->default_value("0.7"),
                "slowest speed factor of a robot (each draws one in [min-speed, 1])")(
                "seed", po::value<std::string>()->default_value("1"), "seed of the first run (run k uses seed + k)")(
                "max-deviation", po::value<std::string>()->default_value("0.1"),
                "how far rounding a corner may take a robot off the plan's path (its configuration units: rad for "
                "arms; 0: sharp corners, the team stopping at each)")(
                "phase-steps", po::value<std::string>()->default_value("4"),
                "longest phase of the temporal plan graph, timesteps (shorter: more nodes, less waiting)")(
                "solution", po::value<std::string>(), "solution file");
            po::positional_options_description positional;
            positional.add("solution", 1);
            const auto vm = tools::parse(argc, argv, options, positional);
            const tools::Interruption interruption("ompl_parc_execute", tools::Interruption::FirstSignal::EXIT);
            if (!vm.count("solution"))
                throw std::invalid_argument("no solution file given (see --help)");
            const auto runs = parseInteger(vm["runs"].as<std::string>(), "--runs", 0, 100000);
            const double maxDelay = parseReal(vm["max-delay"].as<std::string>(), "--max-delay", 0., 3600.);
            const double minSpeed = parseReal(vm["min-speed"].as<std::string>(), "--min-speed", 0.01, 1.);
            const auto seed = parseInteger(vm["seed"].as<std::string>(), "--seed", 0, 1ull << 62);
            const auto phaseSteps = parseInteger(vm["phase-steps"].as<std::string>(), "--phase-steps", 1, 1000000);
            const double maxDeviation = parseReal(vm["max-deviation"].as<std::string>(), "--max-deviation", 0., 1e6);
            const MultiRobotProblem problem = tools::problemFromOptions(vm);
            const MultiRobotPlan plan =
                SolutionFile::read(vm["solution"].as<std::string>(), *problem.getSpaceInformation());
            const auto &si = *problem.getSpaceInformation();

            if (const auto report = SolutionValidator(problem).validate(plan); !report.valid)
            {
                std::cout << "invalid solution: " << report.message << std::endl;
                return static_cast<int>(tools::EXIT_FAILED);
            }
            ompl::time::point start = ompl::time::now();
            const TimeParameterization timing(problem, maxDeviation);
            const auto result = timing.computeConflictFree(plan);
            const auto &trajectory = result.trajectory;
            double first = trajectory.getDuration(), last = 0.;
            for (std::size_t i = 0; i < si.getRobotCount(); ++i)
            {
                first = std::min(first, trajectory.getArrivalTime(i));
                last = std::max(last, trajectory.getArrivalTime(i));
            }
            double deviation = 0.;
            for (std::size_t i = 0; i < si.getRobotCount(); ++i)
                deviation = std::max(deviation, trajectory.getMaxDeviation(i));
            std::cout << std::fixed << std::setprecision(2) << "trajectory: " << trajectory.getDuration()
                      << " s, robots arrive after " << first << " to " << last << " s; " << result.sharpened
                      << " corners made sharp, " << result.checks << " validator checks, off the plan's path by "
                      << std::setprecision(3) << deviation << " at most (" << std::setprecision(2)
                      << ompl::time::seconds(ompl::time::now() - start) << " s)" << std::endl;
            if (!result.valid)
            {
                std::cout << "not conflict-free: " << result.message << std::endl;
                return static_cast<int>(tools::EXIT_FAILED);
            }

            start = ompl::time::now();
            const TemporalPlanGraph graph(problem, plan, phaseSteps);
            std::cout << "temporal plan graph: " << graph.getNodeCount() << " motions in " << graph.getPhaseCount()
                      << " phases, " << graph.getEdges().size() << " edges (" << graph.getUnreducedEdgeCount()
                      << " before reduction), " << graph.getSynchronisedPairCount() << " synchronised pairs ("
                      << ompl::time::seconds(ompl::time::now() - start) << " s)" << std::endl;
            if (vm.count("trajectory"))
            {
                TrajectoryFile::write(vm["trajectory"].as<std::string>(),
                                      TrajectoryFile::toJson(problem, trajectory, &graph));
                std::cout << "written: " << vm["trajectory"].as<std::string>() << std::endl;
            }
            if (runs == 0)
                return static_cast<int>(tools::EXIT_SOLVED);

            const ExecutionSimulator simulator(problem, plan, trajectory, graph, timing.getMaxSpeed());
            const double nominal = simulator.getNominalMakespan();
            std::cout << "executions: " << runs << " runs, each robot " << std::setprecision(2) << "up to " << maxDelay
                      << " s late and at " << minSpeed << "..1 of its speed, seeds " << seed << ".." << seed + runs - 1
                      << "; undelayed makespan " << nominal << " s" << std::endl;
            bool coordinatedCollided = false;
            for (const auto mode : {ExecutionSimulator::Mode::TIME_INDEXED, ExecutionSimulator::Mode::COORDINATED})
            {
                const bool coordinated = mode == ExecutionSimulator::Mode::COORDINATED;
                std::size_t collisions = 0;
                std::string example;
                std::vector<double> makespans;
                start = ompl::time::now();
                for (std::uint64_t k = 0; k < runs; ++k)
                {
                    const auto disturbance =
                        ExecutionSimulator::Disturbance::random(si.getRobotCount(), seed + k, maxDelay, minSpeed);
                    const auto outcome = simulator.run(mode, disturbance);
                    makespans.push_back(outcome.makespan);
                    if (!outcome.collisionFree)
                    {
                        if (collisions++ == 0)
                            example = "seed " + std::to_string(seed + k) + ": " + outcome.message;
                    }
                }
                const double m = median(makespans);
                std::cout << (coordinated ? "  coordinated:  " : "  time-indexed: ") << collisions << "/" << runs
                          << " runs collide; makespan median " << m << " s (+" << std::setprecision(1)
                          << 100. * (m / nominal - 1.) << "% over undelayed)" << std::setprecision(2) << " ("
                          << ompl::time::seconds(ompl::time::now() - start) << " s)" << std::endl;
                if (!example.empty())
                    std::cout << "    first collision, " << example << std::endl;
                coordinatedCollided = coordinatedCollided || (coordinated && collisions > 0);
            }
            return static_cast<int>(coordinatedCollided ? tools::EXIT_FAILED : tools::EXIT_SOLVED);
        });
}
