#include "TestProblems.h"

#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"
#include "ompl_parc/spacetime/LatticeSearch.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <limits>
#include <random>

using namespace ompl_parc;

namespace
{
    constexpr double RESOLUTION = 128.;

    /** A wall across x = 0 with a door 1.6 wide at y = 0 (discs of radius 0.5 pass one at a time). Robot b
        goes through the door from the right to (-4, 3); robot a must cross it the other way, after b. */
    MultiRobotProblem doorCrossing(bool closed = false)
    {
        auto env = std::make_shared<Environment>();
        env->addBox2D("low", 0., closed ? -5. : -5.4, 0.4, closed ? 10. : 9.2);
        env->addBox2D("high", 0., 5.4, 0.4, 9.2);
        return test::discPair(env, {{-4., -3.}, {4., 0.}}, {{4., -3.}, {-4., 3.}}, RESOLUTION, "door");
    }

    /** b's path: straight through the door, then up to its goal. */
    TimedPath doorPath()
    {
        TimedPath path(2, std::vector<double>{4., 0.}.data());
        const std::vector<double> a{4., 0.}, b{-4., 0.}, c{-4., 3.};
        path.appendMotion(a.data(), b.data(), MultiRobotPlan::stepsFor(8., RESOLUTION));
        path.appendMotion(b.data(), c.data(), MultiRobotPlan::stepsFor(3., RESOLUTION));
        return path;
    }

    std::shared_ptr<DynamicObstacles> obstaclesFor(const MultiRobotProblem &problem, const TimedPath &other)
    {
        const auto &si = problem.getSpaceInformation();
        auto obstacles = std::make_shared<DynamicObstacles>(si->getRobot(0), RESOLUTION);
        obstacles->addPath(*si->getRobot(1), other);
        return obstacles;
    }

    LatticeSearch searchIn(const std::shared_ptr<DynamicObstacles> &obstacles)
    {
        return LatticeSearch(obstacles, {-9.5, -9.5}, {9.5, 9.5}, 0.25);
    }
}  // namespace

TEST(LatticeSearch, MotionCheckMatchesEveryTimestep)
{
    // Random motions among random walks, in an empty box: the blockwise check must say what checking every
    // timestep says (the sweep of a disc in an empty box only checks the bounds, convex, so it agrees).
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(-5.);
    bounds.setHigh(5.);
    auto env = std::make_shared<Environment>();
    std::vector<RobotPtr> team;
    for (int r = 0; r < 6; ++r)
        team.push_back(std::make_shared<DiscRobot>("r" + std::to_string(r), env, 0.4, bounds));
    const MultiRobotSpaceInformation si(team, RESOLUTION);
    std::mt19937 rng(7);
    const MultiRobotPlan plan = test::randomWalkPlan(si, rng, 0.05);
    DynamicObstacles obstacles(team[0], RESOLUTION);
    for (std::size_t r = 1; r < team.size(); ++r)
        obstacles.addPath(*team[r], plan.getPath(r));
    std::uniform_real_distribution<double> where(-4.5, 4.5);
    std::uniform_int_distribution<std::size_t> first(0, 450), steps(1, 150);
    int clear = 0, blocked = 0;
    for (int k = 0; k < 3000; ++k)
    {
        const std::vector<double> a{where(rng), where(rng)};
        std::vector<double> b = a;
        if (k % 5 != 0)  // and some waits
            b = {std::clamp(a[0] + 0.3 * where(rng), -4.5, 4.5), std::clamp(a[1] + 0.3 * where(rng), -4.5, 4.5)};
        const std::size_t t0 = first(rng), n = steps(rng);
        bool expected = true;
        std::vector<double> q(2);
        for (std::size_t s = 1; s <= n && expected; ++s)
        {
            TimedPath::interpolate(a.data(), b.data(), s, n, 2, q.data());
            expected = obstacles.isClear(q.data(), t0 + s);
        }
        ASSERT_EQ(obstacles.isMotionClear(a.data(), b.data(), t0, n), expected) << "motion " << k;
        ++(expected ? clear : blocked);
    }
    EXPECT_GT(clear, 300);
    EXPECT_GT(blocked, 300);
}

TEST(LatticeSearch, WaitsForARobotInTheDoorAndValidates)
{
    const auto problem = doorCrossing();
    const auto obstacles = obstaclesFor(problem, doorPath());
    const auto &start = problem.getStart(0), &goal = problem.getGoal(0);
    const auto hold = obstacles->earliestHold(goal.data());
    ASSERT_TRUE(hold.has_value());
    auto search = searchIn(obstacles);
    const TimedPath path = search.plan(start, goal, *hold, ompl::base::plannerNonTerminatingCondition());
    ASSERT_FALSE(path.empty());
    EXPECT_GE(path.getArrival(), *hold);

    MultiRobotPlan plan(*problem.getSpaceInformation());
    plan.setPath(0, path);
    plan.setPath(1, doorPath());
    const auto report = SolutionValidator(problem).validate(plan);
    EXPECT_TRUE(report.valid) << report.message;
    std::vector<double> end(2);
    plan.getConfig(0, plan.getMakespan(), end.data());
    EXPECT_EQ(end, goal);
    // b is in the door around its timestep 4 x 128: a, which could pass it alone in ~5 x 128, is later.
    EXPECT_GT(path.getArrival(), MultiRobotPlan::stepsFor(8. + 2., RESOLUTION));

    // Unweighted (weight 1, a little slower to find), valid too.
    search.setHeuristicWeight(1.);
    const TimedPath unweighted = search.plan(start, goal, *hold, ompl::base::plannerNonTerminatingCondition());
    ASSERT_FALSE(unweighted.empty());
    plan.setPath(0, unweighted);
    const auto second = SolutionValidator(problem).validate(plan);
    EXPECT_TRUE(second.valid) << second.message;
}

TEST(LatticeSearch, EndsWhenTheLatticeHasNoPath)
{
    const auto problem = doorCrossing();
    const auto &start = problem.getStart(0), &goal = problem.getGoal(0);
    // b goes into the door and stays there: the search must exhaust the lattice (every point is one state once
    // b has stopped), not run to its cap.
    TimedPath blocking(2, problem.getStart(1).data());
    const std::vector<double> door{0., 0.};
    blocking.appendMotion(problem.getStart(1).data(), door.data(), MultiRobotPlan::stepsFor(4., RESOLUTION));
    auto search = searchIn(obstaclesFor(problem, blocking));
    search.setMaxExpansions(10000000);
    EXPECT_TRUE(search.plan(start, goal, 0, ompl::base::plannerNonTerminatingCondition()).empty());
    EXPECT_LT(search.getExpansions(), std::size_t{2000000});
    EXPECT_GT(search.getExpansions(), std::size_t{1000});

    search.setMaxExpansions(50);
    EXPECT_TRUE(search.plan(start, goal, 0, ompl::base::plannerNonTerminatingCondition()).empty());
    EXPECT_EQ(search.getExpansions(), std::size_t{50});

    // A stop that has already come: no expansion at all.
    search.setMaxExpansions(10000000);
    EXPECT_TRUE(search.plan(start, goal, 0, ompl::base::PlannerTerminationCondition([] { return true; })).empty());
    EXPECT_EQ(search.getExpansions(), std::size_t{0});

    // A closed door: the static distances already say there is no way, before any expansion.
    const auto closed = doorCrossing(true);
    auto none = searchIn(obstaclesFor(closed, TimedPath(2, closed.getStart(1).data())));
    EXPECT_TRUE(none.plan(start, goal, 0, ompl::base::plannerNonTerminatingCondition()).empty());
    EXPECT_EQ(none.getExpansions(), std::size_t{0});
}

TEST(LatticeSearch, BadSettingsAreRefused)
{
    const auto problem = doorCrossing();
    const auto obstacles = obstaclesFor(problem, doorPath());
    EXPECT_THROW(LatticeSearch(obstacles, {-1., -1.}, {1., 1.}, 0.), ompl::Exception);
    EXPECT_THROW(LatticeSearch(obstacles, {-1., -1.}, {1., 1.}, -1.), ompl::Exception);
    EXPECT_THROW(LatticeSearch(obstacles, {-1.}, {1.}, 0.25), ompl::Exception);
    EXPECT_THROW(LatticeSearch(nullptr, {-1., -1.}, {1., 1.}, 0.25), ompl::Exception);
    auto search = searchIn(obstacles);
    // Bounds too wide for the lattice's coordinates: no path (the caller falls back to ST-RRT), no crash.
    LatticeSearch wide(obstacles, {-1e300, -1e300}, {1e300, 1e300}, 0.25);
    EXPECT_TRUE(
        wide.plan(problem.getStart(0), problem.getGoal(0), 0, ompl::base::plannerNonTerminatingCondition()).empty());
    EXPECT_THROW(search.setHeuristicWeight(0.5), ompl::Exception);
    EXPECT_THROW(search.setHeuristicWeight(std::numeric_limits<double>::infinity()), ompl::Exception);
    EXPECT_THROW(search.setHeuristicWeight(2000.), ompl::Exception);
    EXPECT_TRUE(LatticeSearch::applies(*problem.getSpaceInformation()->getRobot(0)));
    const auto arms = scenarios::createScenario("planar_cross", 4);
    EXPECT_FALSE(LatticeSearch::applies(*arms.getSpaceInformation()->getRobot(0)));
    PrioritizedSTRRT planner(problem.getSpaceInformation());
    EXPECT_THROW(planner.setLatticeStep(-0.5), ompl::Exception);
}

TEST(LatticeSearch, PrioritizedPlanningSolvesAGeneratedRoomsInstance)
{
    // 24 robots in rooms joined by doors, the lattice on (the default): the plan re-checked by the independent
    // validator.
    const auto problem = scenarios::generateFamilyInstance("rooms", 24, 1, RESOLUTION);
    PrioritizedSTRRT planner(problem.getSpaceInformation());
    planner.setSeed(3);
    ASSERT_EQ(test::solveWith(planner, problem, 120.), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const auto report = SolutionValidator(problem).validate(planner.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}
