#include "TestProblems.h"

#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace ompl_parc;

namespace
{
    const auto NEVER = ompl::base::plannerNonTerminatingCondition();

    /** Robot \e robot's configuration is valid at every timestep of \e path, through its arrival. */
    void expectValidThroughout(const MultiRobotProblem &problem, std::size_t robot, const TimedPath &path)
    {
        const Robot &body = *problem.getSpaceInformation()->getRobot(robot);
        std::vector<double> q(body.getDimension());
        for (std::size_t t = 0; t <= path.getArrival(); ++t)
        {
            path.getConfig(t, q.data());
            ASSERT_TRUE(body.isValid(q.data())) << "robot " << robot << " at timestep " << t;
        }
        path.getConfig(path.getArrival(), q.data());
        EXPECT_EQ(q, problem.getGoal(robot));
    }

    std::vector<std::size_t> breakpoints(const TimedPath &path)
    {
        std::vector<std::size_t> times;
        path.appendBreakpoints(times);
        return times;
    }
}  // namespace

TEST(InitialPlanner, AValidStraightMotionIsTakenAsIs)
{
    // Discs (checked by their swept capsule) and planar arms (checked at every timestep): each robot alone can
    // move straight, so each path is the straight line laid on the grid, timestep for timestep.
    for (const auto &problem :
         {test::twoDiscs({-5., -5.}, {5., -4.}, {-5., 5.}, {5., 5.}), scenarios::createPlanarCross(4)})
    {
        const auto &si = *problem.getSpaceInformation();
        const InitialPlanner planner(problem, true, {}, true);
        const MultiRobotPlan straight = test::straightLinePlan(problem);
        for (std::size_t r = 0; r < si.getRobotCount(); ++r)
        {
            TimedPath path;
            ASSERT_TRUE(planner.plan(r, NEVER, 7, path));
            EXPECT_EQ(breakpoints(path), (std::vector<std::size_t>{0, 0, path.getArrival()}));  // one straight piece
            ASSERT_EQ(path.getArrival(), straight.getArrival(r)) << problem.getName() << " robot " << r;
            std::vector<double> q(si.getRobot(r)->getDimension());
            for (std::size_t t = 0; t <= path.getArrival(); ++t)
            {
                path.getConfig(t, q.data());
                const auto expected = test::config(straight, r, t);
                for (std::size_t k = 0; k < q.size(); ++k)
                    ASSERT_NEAR(q[k], expected[k], 1e-12) << "robot " << r << " timestep " << t;
            }
            expectValidThroughout(problem, r, path);
        }
    }
}

TEST(InitialPlanner, ABlockedStraightMotionIsPlannedAround)
{
    // A wall at the origin blocks the straight motions through it: the planner's path goes around, valid at every
    // timestep, with or without trying the straight motion first (random starts and goals on either side).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> y(-6., 6.);
    for (int trial = 0; trial < 20; ++trial)
    {
        const auto problem = test::twoDiscs({-5., y(rng)}, {5., y(rng)}, {-5., -8.}, {5., -8.}, true);
        for (const bool straightFirst : {false, true})
        {
            const InitialPlanner planner(problem, true, {}, straightFirst);
            TimedPath path;
            ASSERT_TRUE(planner.plan(0, NEVER, 3 + trial, path));
            expectValidThroughout(problem, 0, path);
        }
    }
    const auto blocked = test::twoDiscs({-5., 0.}, {5., 0.}, {-5., -8.}, {5., -8.}, true);
    TimedPath around;
    ASSERT_TRUE(InitialPlanner(blocked, true, {}, true).plan(0, NEVER, 5, around));
    // Not the straight line, which the wall blocks: a straight path's breakpoints are 0 (twice) and its arrival.
    EXPECT_GT(breakpoints(around).size(), 3u);
}
