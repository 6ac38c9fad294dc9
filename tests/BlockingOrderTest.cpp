#include "TestProblems.h"

#include "ompl_parc/planners/subproblem/BlockingOrder.h"
#include "ompl_parc/robots/DiscRobot.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <algorithm>

using namespace ompl_parc;

namespace
{
    /** Unit discs in an empty 20 x 20 square; robot k goes straight from starts[k] to goals[k] (one timestep per
        half unit), as if planned alone. */
    struct Team
    {
        Team(std::vector<std::vector<double>> s, std::vector<std::vector<double>> g)
            : starts(std::move(s)), goals(std::move(g))
        {
            ompl::base::RealVectorBounds bounds(2);
            bounds.setLow(-10.);
            bounds.setHigh(10.);
            const auto disc = std::make_shared<DiscRobot>("disc", std::make_shared<Environment>(), 0.5, bounds);
            for (std::size_t k = 0; k < starts.size(); ++k)
            {
                robots.push_back(disc);
                alone.push_back(TimedPath::fromDense(2, test::straightLine(starts[k], goals[k], 2.)));
            }
        }

        BlockingOrder order() const { return BlockingOrder(robots, alone, starts, goals); }

        std::vector<std::vector<double>> starts, goals;
        std::vector<RobotPtr> robots;
        std::vector<TimedPath> alone;
    };

    using Order = std::vector<std::size_t>;
}  // namespace

TEST(BlockingOrder, ARobotParksAfterThoseWhoseWayItsGoalIsOn)
{
    // Robot 0 parks at (0, 0), on robot 1's way from (-5, 0) to (5, 0): robot 1 goes first, whatever the base.
    const Team team({{0., -3.}, {-5., 0.}}, {{0., 0.}, {5., 0.}});
    const auto order = team.order();
    EXPECT_TRUE(order.before(1, 0));
    EXPECT_FALSE(order.before(0, 1));
    EXPECT_EQ(order.order({0, 1}), (Order{1, 0}));
    EXPECT_EQ(order.order({1, 0}), (Order{1, 0}));
}

TEST(BlockingOrder, ARobotLeavesBeforeThoseWhoseWayItsStartIsOn)
{
    // Robot 0 starts at (0, 0), on robot 1's way: robot 0 goes first and leaves.
    const Team team({{0., 0.}, {-5., 0.}}, {{0., 3.}, {5., 0.}});
    const auto order = team.order();
    EXPECT_TRUE(order.before(0, 1));
    EXPECT_FALSE(order.before(1, 0));
    EXPECT_EQ(order.order({1, 0}), (Order{0, 1}));
}

TEST(BlockingOrder, FollowsChainsAndKeepsTheBaseOrderAmongFreeRobots)
{
    // Robot 2 parks on robot 1's way, robot 1 on robot 0's: 0, 1, 2. Robot 3, far away, keeps its base place.
    const Team team({{-8., 0.}, {2., -6.}, {6., -3.}, {-8., 8.}}, {{8., 0.}, {2., 0.}, {2., -3.}, {-8., 6.}});
    const auto order = team.order();
    EXPECT_TRUE(order.before(0, 1));
    EXPECT_TRUE(order.before(1, 2));
    EXPECT_EQ(order.order({3, 2, 1, 0}), (Order{3, 0, 1, 2}));
    EXPECT_EQ(order.order({2, 1, 0, 3}), (Order{0, 1, 2, 3}));
}

TEST(BlockingOrder, BreaksACycleByTheBaseOrder)
{
    // Robot 0 starts and ends on robot 1's way: it must both leave first and park after. The base order decides.
    const Team team({{-2., 0.}, {-5., 0.}}, {{2., 0.}, {5., 0.}});
    const auto order = team.order();
    EXPECT_TRUE(order.before(0, 1));
    EXPECT_TRUE(order.before(1, 0));
    EXPECT_EQ(order.order({0, 1}), (Order{0, 1}));
    EXPECT_EQ(order.order({1, 0}), (Order{1, 0}));
}

TEST(BlockingOrder, InACycleTheRobotWithFewestPredecessorsLeftGoesFirst)
{
    // Robots 0 and 1 make a cycle (0 starts and ends on 1's way); robot 2 parks at (0, 0), on both their ways.
    const Team team({{-2., 0.}, {-5., 0.}, {0., -5.}}, {{2., 0.}, {5., 0.}, {0., 0.}});
    const auto order = team.order();
    EXPECT_TRUE(order.before(0, 2));
    EXPECT_TRUE(order.before(1, 2));
    // Nobody is free; robot 0 waits for one robot, robot 2 for two: 0 goes first though 2 comes first in the base.
    EXPECT_EQ(order.order({2, 0, 1}), (Order{0, 1, 2}));
}

TEST(BlockingOrder, LongPathsAreTestedBlockByBlock)
{
    // Robot 1 crosses robot 0's goal late in a path of many blocks, and passes far from robot 0's start.
    Team team({{0., -3.}, {-9., 0.}}, {{0., 0.}, {9., 0.}});
    std::vector<double> flat;
    for (std::size_t t = 0; t <= 10 * BlockingOrder::BLOCK; ++t)  // waits at (-9, 0), then goes at unit speed
    {
        const double x = std::min(9., -9. + std::max(0., static_cast<double>(t) - 9. * BlockingOrder::BLOCK));
        flat.insert(flat.end(), {x, 0.});
    }
    team.alone[1] = TimedPath::fromDense(2, flat);
    const auto order = team.order();
    EXPECT_TRUE(order.before(1, 0));
    EXPECT_FALSE(order.before(0, 1));
}

TEST(BlockingOrder, ARobotWithoutAPathConstrainsNobody)
{
    Team team({{0., -3.}, {-5., 0.}}, {{0., 0.}, {5., 0.}});
    team.alone[1] = TimedPath();  // robot 1 could not be planned alone
    const auto order = team.order();
    EXPECT_FALSE(order.before(1, 0));
    EXPECT_EQ(order.order({0, 1}), (Order{0, 1}));
}

TEST(BlockingOrder, RejectsMismatchedInputs)
{
    const Team team({{0., -3.}, {-5., 0.}}, {{0., 0.}, {5., 0.}});
    EXPECT_THROW(BlockingOrder(team.robots, team.alone, {team.starts[0]}, team.goals), ompl::Exception);
    EXPECT_THROW(BlockingOrder(team.robots, team.alone, team.starts, {{0., 0.}, {5., 0., 1.}}), ompl::Exception);
    EXPECT_THROW(team.order().order({0}), ompl::Exception);
    EXPECT_THROW(team.order().order({0, 0}), ompl::Exception);
    EXPECT_THROW(team.order().order({0, 2}), ompl::Exception);
    EXPECT_THROW(team.order().order({}), ompl::Exception);
}
