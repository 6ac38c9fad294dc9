/* Space-time planning times. STRRTstar: robot 0 of Mobile Cross 2 or 8 crosses to the other end while the
   others follow their straight timestep paths (robot 1 head-on along the same line). First: time to the first
   solution, in the authors' settings (range 1, batch 4096, factors 2 and 2) without and with k-nearest
   rewiring. Anytime: the arrival (s) reached within a 1 s budget with k-nearest rewiring. Both for our
   ompl_parc::STRRTstar and, built against OMPL >= 1.6, OMPL's ompl::geometric::STRRTstar on the same problems
   (both report their solutions to the same intermediate solution callback; both draw from OMPL's global seed).
   PPSTRRT: the PrioritizedSTRRTSolver on the whole of Mobile Cross 4 and 8 and of generated rooms 8 instances 0 and
   1 (given order). Counters report the success fraction and the mean arrival (s) or makespan (timesteps).
   Nearest: one nearest-neighbour query in a tree of N space-time states (2D discs' space, times in [0, 50], drawn
   uniformly) by OMPL's NearestNeighborsLinear through the space's distance (what ST-RRT* used) and by
   SpaceTimeNearestNeighbors (what it uses now); same answers, side by side. */
#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/planners/SpaceTimeNearestNeighbors.h"
#include "ompl_parc/planners/SpaceTime.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <benchmark/benchmark.h>
#include <ompl/base/ScopedState.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <type_traits>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** A robot's straight timestep path from its start to its goal. */
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

    /** Robot 0 of Mobile Cross \e robots among the others' straight paths: a fresh problem definition per run. */
    class CrossingProblem
    {
      public:
        explicit CrossingProblem(std::size_t robots) : problem_(scenarios::createMobileCross(robots))
        {
            const auto &team = *problem_.getSpaceInformation();
            auto obstacles = std::make_shared<DynamicObstacles>(team.getRobot(0), team.getResolution());
            for (std::size_t r = 1; r < robots; ++r)
                obstacles->addPath(*team.getRobot(r), TimedPath::fromDense(2, straightPath(problem_, r)));
            si_ = createSpaceTimeSpaceInformation(team.getCompositeSpace()->getRobotSpace(0), obstacles);
        }

        const ob::SpaceInformationPtr &getSpaceInformation() const { return si_; }

        ob::ProblemDefinitionPtr createProblemDefinition() const
        {
            auto pdef = std::make_shared<ob::ProblemDefinition>(si_);
            ob::ScopedState<> start(si_), goal(si_);
            start = std::vector<double>{problem_.getStart(0)[0], problem_.getStart(0)[1], 0.};
            goal = std::vector<double>{problem_.getGoal(0)[0], problem_.getGoal(0)[1], 0.};
            pdef->setStartAndGoalStates(start, goal);
            return pdef;
        }

      private:
        MultiRobotProblem problem_;
        ob::SpaceInformationPtr si_;
    };

    /** Run \e Planner (ours or OMPL's, same settings) once per iteration; \e firstOnly stops at the first
        solution, else the planner improves it for \e budget seconds. */
    template <typename Planner>
    void strrtstar(benchmark::State &state, std::size_t robots, bool rewire, bool firstOnly, double budget)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        const CrossingProblem crossing(robots);
        double solved = 0., arrival = 0.;
        for (auto _ : state)
        {
            const auto pdef = crossing.createProblemDefinition();
            Planner planner(crossing.getSpaceInformation());
            planner.setRange(1.);
            planner.setBatchSize(4096);
            planner.setInitialTimeBoundFactor(2.);
            planner.setTimeBoundFactorIncrease(2.);
            if (rewire)
                planner.setRewiringToKNearest();
            else
                planner.setRewiringToOff();
            planner.setProblemDefinition(pdef);
            planner.setup();
            auto found = std::make_shared<bool>(false);
            pdef->setIntermediateSolutionCallback([found](const ob::Planner *, const std::vector<const ob::State *> &,
                                                          const ob::Cost) { *found = true; });
            const auto stop = firstOnly ? ob::plannerOrTerminationCondition(
                                              ob::timedPlannerTerminationCondition(budget),
                                              ob::PlannerTerminationCondition([found] { return *found; }))
                                        : ob::timedPlannerTerminationCondition(budget);
            if (planner.solve(stop) == ob::PlannerStatus::EXACT_SOLUTION)
            {
                const auto &path = *pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
                solved += 1.;
                arrival += spacetime::SpaceTimeStateSpace::getStateTime(path.getState(path.getStateCount() - 1));
            }
        }
        state.counters["success"] = solved / static_cast<double>(state.iterations());
        state.counters["arrival_s"] = solved > 0. ? arrival / solved : 0.;
    }

    /** Registers the first-solution and anytime runs of \e Planner, named by \e name. */
    template <typename Planner>
    void registerSTRRTstar(const std::string &name)
    {
        for (const std::size_t robots : {std::size_t{2}, std::size_t{8}})
        {
            const std::string problem = "MobileCross" + std::to_string(robots);
            benchmark::RegisterBenchmark((name + "/First/" + problem + "/RewiringOff").c_str(), strrtstar<Planner>,
                                         robots, false, true, 30.)
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark((name + "/First/" + problem + "/RewiringKNearest").c_str(), strrtstar<Planner>,
                                         robots, true, true, 30.)
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark((name + "/Anytime1s/" + problem + "/RewiringKNearest").c_str(),
                                         strrtstar<Planner>, robots, true, false, 1.)
                ->Unit(benchmark::kMillisecond)
                ->Iterations(5);
        }
    }

    void ppstrrt(benchmark::State &state, const std::string &scenario, std::size_t robots, unsigned int task)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        const auto problem = scenarios::createScenario(scenario, robots, 128., task);
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
                makespan += static_cast<double>(patch.getDuration());
            }
        }
        state.counters["success"] = solved / static_cast<double>(state.iterations());
        state.counters["makespan_steps"] = solved > 0. ? makespan / solved : 0.;
    }

    /** A tree element of the nearest-neighbour benchmarks: a space-time state. */
    struct NearestElement
    {
        ob::State *state;
    };

    /** One nearest query per iteration in a tree of state.range(0) uniform space-time states (discs' 2D space). */
    template <typename Structure>
    void nearest(benchmark::State &state)
    {
        auto component = std::make_shared<ob::RealVectorStateSpace>(2);
        component->setBounds(-10., 10.);
        const auto space = std::make_shared<spacetime::SpaceTimeStateSpace>(component);
        space->setTimeBounds(0., 50.);
        space->updateEpsilon();
        ompl::RNG rng(1);
        const auto draw = [&]
        {
            auto *s = space->allocState()->as<ob::CompoundState>();
            for (int k = 0; k < 2; ++k)
                s->as<ob::RealVectorStateSpace::StateType>(0)->values[k] = rng.uniformReal(-10., 10.);
            s->as<ob::TimeStateSpace::StateType>(1)->position = rng.uniformReal(0., 50.);
            return NearestElement{s};
        };
        std::vector<NearestElement> elements(static_cast<std::size_t>(state.range(0))), queries(1024);
        std::generate(elements.begin(), elements.end(), draw);
        std::generate(queries.begin(), queries.end(), draw);
        std::unique_ptr<ompl::NearestNeighbors<const NearestElement *>> tree;
        if constexpr (std::is_same_v<Structure, SpaceTimeNearestNeighbors<const NearestElement *>>)
            tree = std::make_unique<Structure>(*space, [](const NearestElement *const &e) { return e->state; });
        else
            tree = std::make_unique<Structure>();
        tree->setDistanceFunction([&](const NearestElement *a, const NearestElement *b)
                                  { return space->distance(a->state, b->state); });
        for (const auto &e : elements)
            tree->add(&e);
        std::size_t q = 0;
        for (auto _ : state)
            benchmark::DoNotOptimize(tree->nearest(&queries[q++ % queries.size()]));
        for (auto &e : elements)
            space->freeState(e.state);
        for (auto &e : queries)
            space->freeState(e.state);
    }

    /** Our ST-RRT*, and OMPL's where this OMPL has one. */
    const bool registered = []
    {
        registerSTRRTstar<ompl_parc::STRRTstar>("STRRTstar_ompl_parc");
        if constexpr (spacetime::USES_OMPL_SPACE_TIME)
            registerSTRRTstar<spacetime::STRRTstar>("STRRTstar_OMPL");
        return true;
    }();
}  // namespace

BENCHMARK_CAPTURE(ppstrrt, MobileCross4, "mobile_cross", std::size_t{4}, 0u)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ppstrrt, MobileCross8, "mobile_cross", std::size_t{8}, 0u)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ppstrrt, Rooms8_0, "rooms", std::size_t{8}, 0u)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ppstrrt, Rooms8_1, "rooms", std::size_t{8}, 1u)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(nearest, ompl::NearestNeighborsLinear<const NearestElement *>)->Arg(1000)->Arg(10000);
BENCHMARK_TEMPLATE(nearest, SpaceTimeNearestNeighbors<const NearestElement *>)->Arg(1000)->Arg(10000);
