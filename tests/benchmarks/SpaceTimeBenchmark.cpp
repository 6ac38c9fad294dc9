/* Space-time planning times. STRRTstar: robot 0 of Mobile Cross 2 crosses to the other end while robot 1
   comes head-on along the same line (a straight timestep path): time to the first solution, in the authors'
   settings (range 1, batch 4096, factors 2 and 2, no rewiring) and with k-nearest rewiring. PPSTRRT: the
   PrioritizedSTRRTSolver on the whole of Mobile Cross 4 and 8 (given order). Every iteration uses a new seed;
   counters report the success fraction and the mean arrival (s) or makespan (timesteps). */
#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <benchmark/benchmark.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** Robot 1's straight timestep path from its start to its goal. */
    std::vector<double> straightPath(const MultiRobotProblem &problem, std::size_t robot)
    {
        const auto &a = problem.getStart(robot), &b = problem.getGoal(robot);
        const double res = problem.getSpaceInformation()->getResolution();
        const auto steps = static_cast<std::size_t>(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) * res));
        std::vector<double> flat;
        for (std::size_t s = 0; s <= steps; ++s)
            for (std::size_t d = 0; d < 2; ++d)
                flat.push_back(a[d] + (b[d] - a[d]) * static_cast<double>(s) / static_cast<double>(steps));
        return flat;
    }

    void strrtstar(benchmark::State &state, const std::string &rewiring)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        const auto problem = scenarios::createMobileCross(2);
        const auto &team = *problem.getSpaceInformation();
        const auto moving = straightPath(problem, 1);
        std::uint_fast32_t seed = 1;
        double solved = 0., arrival = 0.;
        for (auto _ : state)
        {
            // Fresh seeded robot space per run, as PP-ST-RRT builds them.
            const MultiRobotSpaceInformation local({team.getRobot(0)}, team.getResolution(), {}, ++seed);
            auto obstacles = std::make_shared<DynamicObstacles>(team.getRobot(0), team.getResolution());
            obstacles->addPath(*team.getRobot(1), moving);
            const auto si = createSpaceTimeSpaceInformation(local.getCompositeSpace()->getRobotSpace(0), obstacles);
            auto pdef = std::make_shared<ob::ProblemDefinition>(si);
            ob::ScopedState<> start(si), goal(si);
            start = std::vector<double>{problem.getStart(0)[0], problem.getStart(0)[1], 0.};
            goal = std::vector<double>{problem.getGoal(0)[0], problem.getGoal(0)[1], 0.};
            pdef->setStartAndGoalStates(start, goal);
            STRRTstar planner(si);
            planner.setRange(1.);
            planner.setBatchSize(4096);
            planner.setRewiringState(rewiring);
            planner.setStopAtFirstSolution(true);
            planner.setLocalSeed(mixSeed(seed, 1));
            planner.setProblemDefinition(pdef);
            planner.setup();
            if (planner.solve(ob::timedPlannerTerminationCondition(30.)) == ob::PlannerStatus::EXACT_SOLUTION)
            {
                const auto &path = *pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
                solved += 1.;
                arrival += SpaceTimeStateSpace::getStateTime(path.getState(path.getStateCount() - 1));
            }
        }
        state.counters["success"] = solved / static_cast<double>(state.iterations());
        state.counters["arrival_s"] = solved > 0. ? arrival / solved : 0.;
    }

    void ppstrrt(benchmark::State &state, std::size_t robots)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        const auto problem = scenarios::createMobileCross(robots);
        Subproblem whole;
        for (std::size_t i = 0; i < robots; ++i)
        {
            whole.robots.push_back(i);
            whole.starts.push_back(problem.getStart(i));
            whole.goals.push_back(problem.getGoal(i));
        }
        const PrioritizedSTRRTSolver solver;
        std::uint_fast32_t seed = 1;
        double solved = 0., makespan = 0.;
        for (auto _ : state)
        {
            Patch patch;
            if (solver.solve(*problem.getSpaceInformation(), whole, ob::timedPlannerTerminationCondition(30.), ++seed,
                             patch))
            {
                solved += 1.;
                makespan += static_cast<double>(patch.getDuration(2));
            }
        }
        state.counters["success"] = solved / static_cast<double>(state.iterations());
        state.counters["makespan_steps"] = solved > 0. ? makespan / solved : 0.;
    }
}  // namespace

BENCHMARK_CAPTURE(strrtstar, MovingObstacle_RewiringOff, std::string("off"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(strrtstar, MovingObstacle_RewiringKNearest, std::string("knearest"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ppstrrt, MobileCross4, std::size_t{4})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ppstrrt, MobileCross8, std::size_t{8})->Unit(benchmark::kMillisecond);
