#include "ompl_parc/planners/subproblem/BlockingOrder.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

using namespace ompl_parc;

namespace
{
    using Point = std::array<double, 2>;

    /** Unit discs in an empty 20 x 20 square; robot k goes straight from starts[k] to goals[k] (one timestep per
        half unit), as if planned alone. */
    class Team
    {
      public:
        Team(std::vector<Point> starts, std::vector<Point> goals)
        {
            ompl::base::RealVectorBounds bounds(2);
            bounds.setLow(-10.);
            bounds.setHigh(10.);
            robot_ = std::make_shared<DiscRobot>("disc", std::make_shared<Environment>(), 0.5, bounds);
            for (std::size_t k = 0; k < starts.size(); ++k)
            {
                const Point s = starts[k], g = goals[k];
                const auto steps = static_cast<std::size_t>(std::ceil(2. * std::hypot(g[0] - s[0], g[1] - s[1])));
                std::vector<double> flat;
                for (std::size_t t = 0; t <= steps; ++t)
                {
                    const double f = steps == 0 ? 1. : static_cast<double>(t) / static_cast<double>(steps);
                    flat.push_back(s[0] + f * (g[0] - s[0]));
                    flat.push_back(s[1] + f * (g[1] - s[1]));
                }
                tracks.push_back(DynamicObstacles::computeTrack(*robot_, TimedPath::fromDense(2, flat)));
                startBodies.push_back(bodyAt(s));
                goalBodies.push_back(bodyAt(g));
            }
        }

        BlockingOrder order() const { return BlockingOrder(tracks, startBodies, goalBodies); }

        std::vector<std::shared_ptr<const BodyTrack>> tracks;
        std::vector<CollisionBody> startBodies, goalBodies;

      private:
        CollisionBody bodyAt(const Point &q) const
        {
            CollisionBody body;
            robot_->computeBody(q.data(), body);
            return body;
        }

        RobotPtr robot_;
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

TEST(BlockingOrder, ARobotWithoutAPathConstrainsNobody)
{
    Team team({{0., -3.}, {-5., 0.}}, {{0., 0.}, {5., 0.}});
    team.tracks[1] = nullptr;  // robot 1 could not be planned alone
    const auto order = team.order();
    EXPECT_FALSE(order.before(1, 0));
    EXPECT_EQ(order.order({0, 1}), (Order{0, 1}));
}

TEST(BlockingOrder, RejectsMismatchedInputs)
{
    const Team team({{0., -3.}, {-5., 0.}}, {{0., 0.}, {5., 0.}});
    EXPECT_THROW(BlockingOrder(team.tracks, {team.startBodies[0]}, team.goalBodies), ompl::Exception);
    EXPECT_THROW(team.order().order({0}), ompl::Exception);
    EXPECT_THROW(team.order().order({0, 0}), ompl::Exception);
    EXPECT_THROW(team.order().order({0, 2}), ompl::Exception);
    EXPECT_THROW(team.order().order({}), ompl::Exception);
}
