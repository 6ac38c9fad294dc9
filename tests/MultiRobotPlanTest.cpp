#include "TestProblems.h"

#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

using namespace ompl_parc;
namespace ob = ompl::base;
namespace og = ompl::geometric;

TEST(MultiRobotPlan, RobotsHoldTheirGoalAfterArriving)
{
    MultiRobotPlan plan({2, 2}, 10.);
    plan.setRobotPath(0, test::straightLine({0, 0}, {1, 0}, 10.));  // 10 steps
    plan.setRobotPath(1, test::straightLine({0, 5}, {0, 8}, 10.));  // 30 steps
    EXPECT_EQ(plan.getArrival(0), 10u);
    EXPECT_EQ(plan.getArrival(1), 30u);
    EXPECT_EQ(plan.getMakespan(), 30u);
    EXPECT_EQ(plan.getSumOfCosts(), 40u);
    EXPECT_DOUBLE_EQ(test::config(plan, 0, 25)[0], 1.);
    EXPECT_DOUBLE_EQ(test::config(plan, 0, 1000)[0], 1.);
    EXPECT_DOUBLE_EQ(test::config(plan, 1, 15)[1], 6.5);
    EXPECT_THROW(plan.setRobotPath(0, {1., 2., 3.}), ompl::Exception);
    EXPECT_THROW(MultiRobotPlan({2}, 0.), ompl::Exception);
}

TEST(MultiRobotPlan, CompositePathIsLaidOnTheGridSynchronisedAndArrivalsTrimmed)
{
    const auto problem = test::twoDiscs({-5, 0}, {5, 0}, {5, 5}, {5, 3}, false, 16.);
    const auto &si = problem.getSpaceInformation();
    og::PathGeometric path(si);
    ob::ScopedState<> s(si);
    s[0] = -5;
    s[1] = 0;
    s[2] = 5;
    s[3] = 5;
    path.append(s.get());
    s[0] = 0;
    s[2] = 5;
    s[3] = 3;  // robot b finishes in the first segment
    path.append(s.get());
    s[0] = 5;
    path.append(s.get());
    const auto plan = MultiRobotPlan::fromPathGeometric(*si, path);
    // Segment 1 lasts 5 * 16 = 80 steps (the largest move), segment 2 another 80.
    EXPECT_EQ(plan.getArrival(0), 160u);
    EXPECT_EQ(plan.getArrival(1), 80u);
    EXPECT_DOUBLE_EQ(test::config(plan, 1, 40)[1], 4.);  // b moves 2 in 80 steps
    for (std::size_t t = 0; t < plan.getMakespan(); ++t)
        for (std::size_t r = 0; r < 2; ++r)
        {
            const auto a = test::config(plan, r, t), b = test::config(plan, r, t + 1);
            EXPECT_LE(std::hypot(b[0] - a[0], b[1] - a[1]), 1. / 16. + 1e-12);
        }
    EXPECT_DOUBLE_EQ(test::config(plan, 0, 160)[0], 5.);
    // Robot a moves in two straight segments (breakpoints 0, 80, 160), robot b in one (0, 80): three waypoints.
    EXPECT_EQ(plan.getBreakpoints(), (std::vector<std::size_t>{0, 80, 160}));
}

TEST(MultiRobotPlan, PathGeometricRoundTrip)
{
    const auto problem = scenarios::createMobileCross(4, 8.);
    const auto &si = problem.getSpaceInformation();
    MultiRobotPlan plan(*si);
    for (std::size_t i = 0; i < 4; ++i)
        plan.setRobotPath(i, test::straightLine(problem.getStart(i), {problem.getStart(i)[0], 0.}, 8.));
    const auto path = plan.toPathGeometric(si);
    EXPECT_TRUE(test::pathFollowsPlan(*si, *path, plan));
    const auto back = MultiRobotPlan::fromPathGeometric(*si, *path);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_EQ(back.getRobotPath(i), plan.getRobotPath(i));
}

TEST(MultiRobotPlan, DiscretizeSingleRobotPath)
{
    const auto problem = scenarios::createMobileCross(4, 4.);
    const auto &robot = *problem.getSpaceInformation()->getRobot(0);
    og::PathGeometric path(robot.getSpaceInformation());
    ob::ScopedState<> s(robot.getSpaceInformation());
    s[0] = 0;
    s[1] = 0;
    path.append(s.get());
    s[0] = 1.1;
    path.append(s.get());
    s[1] = 0.5;
    path.append(s.get());
    const auto flat = MultiRobotPlan::discretize(robot, path, 4.).toDense();
    // ceil(1.1 * 4) = 5 steps, then ceil(0.5 * 4) = 2 steps; the waypoints are exact.
    ASSERT_EQ(flat.size(), 2u * 8u);
    EXPECT_DOUBLE_EQ(flat[10], 1.1);
    EXPECT_DOUBLE_EQ(flat[11], 0.);
    EXPECT_DOUBLE_EQ(flat[15], 0.5);
    EXPECT_THROW(MultiRobotPlan::discretize(robot, og::PathGeometric(robot.getSpaceInformation()), 4.),
                 ompl::Exception);
}
