#include "TestProblems.h"

#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"
#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

using namespace ompl_parc;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    constexpr double RESOLUTION = 128.;

    /** Disc 'a' crosses from (-5, 0) to (5, 0) while disc 'b' comes head-on along the same line: the straight
        plan meets b half-way, so a must step aside in time. */
    struct MovingObstacle
    {
        MultiRobotProblem problem = test::twoDiscs({-5., 0.}, {5., 0.}, {5., 0.}, {-5., 0.});
        std::vector<double> obstaclePath = test::straightLine({5., 0.}, {-5., 0.}, RESOLUTION);
        ob::SpaceInformationPtr si;
        ob::ProblemDefinitionPtr pdef;

        explicit MovingObstacle(std::vector<double> goal = {5., 0.})
        {
            const auto &team = problem.getSpaceInformation();
            auto obstacles = std::make_shared<DynamicObstacles>(team->getRobot(0), RESOLUTION);
            obstacles->addPath(*team->getRobot(1), obstaclePath);
            si = createSpaceTimeSpaceInformation(team->getCompositeSpace()->getRobotSpace(0), obstacles);
            pdef = std::make_shared<ob::ProblemDefinition>(si);
            ob::ScopedState<> start(si), end(si);
            start = std::vector<double>{-5., 0., 0.};
            end = std::vector<double>{goal[0], goal[1], 0.};
            pdef->setStartAndGoalStates(start, end);
        }

        /** a's space-time path on the timestep grid, next to b's, checked by the independent validator. */
        ValidationReport validate(const og::PathGeometric &path) const
        {
            MultiRobotPlan plan(*problem.getSpaceInformation());
            plan.setRobotPath(
                0, std::static_pointer_cast<SpaceTimeMotionValidator>(si->getMotionValidator())->layOnGrid(path));
            plan.setRobotPath(1, obstaclePath);
            return SolutionValidator(problem).validate(plan);
        }
    };

    void expectTimedMotions(const SpaceTimeStateSpace &space, const og::PathGeometric &path)
    {
        for (std::size_t k = 1; k < path.getStateCount(); ++k)
        {
            const ob::State *from = path.getState(k - 1), *to = path.getState(k);
            const double dt = SpaceTimeStateSpace::getStateTime(to) - SpaceTimeStateSpace::getStateTime(from);
            EXPECT_GT(dt, 0.) << "time must increase strictly, state " << k;
            EXPECT_LE(space.distanceSpace(from, to), space.getVMax() * dt * (1. + 1e-9)) << "faster than vMax";
        }
    }
}  // namespace

TEST(STRRTstar, TheStraightPlanHitsTheMovingObstacle)
{
    const MovingObstacle setup;
    MultiRobotPlan plan(*setup.problem.getSpaceInformation());
    plan.setRobotPath(0, test::straightLine({-5., 0.}, {5., 0.}, RESOLUTION));
    plan.setRobotPath(1, setup.obstaclePath);
    EXPECT_FALSE(SolutionValidator(setup.problem).validate(plan).valid);
}

class STRRTstarRewiring : public testing::TestWithParam<std::string>
{
};

TEST_P(STRRTstarRewiring, FindsATimedPathAroundAMovingObstacle)
{
    const MovingObstacle setup;
    STRRTstar planner(setup.si);
    planner.params().setParam("rewiring", GetParam());
    planner.setRange(1.);
    planner.setStopAtFirstSolution(true);
    planner.setLocalSeed(5);
    planner.setProblemDefinition(setup.pdef);
    planner.setup();
    ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(30.)), ob::PlannerStatus::EXACT_SOLUTION);
    const auto &path = *setup.pdef->getSolutionPath()->as<og::PathGeometric>();
    expectTimedMotions(*setup.si->getStateSpace()->as<SpaceTimeStateSpace>(), path);
    const auto report = setup.validate(path);
    EXPECT_TRUE(report.valid) << report.message;
}

INSTANTIATE_TEST_SUITE_P(AllModes, STRRTstarRewiring, testing::Values("off", "radius", "knearest"));

TEST(STRRTstar, ImprovesUntilTheTerminationConditionUnlessToldToStop)
{
    const MovingObstacle setup;
    STRRTstar first(setup.si);
    first.setStopAtFirstSolution(true);
    first.setLocalSeed(9);
    first.setProblemDefinition(setup.pdef);
    ASSERT_EQ(first.solve(ob::timedPlannerTerminationCondition(30.)), ob::PlannerStatus::EXACT_SOLUTION);
    const double firstArrival =
        SpaceTimeStateSpace::getStateTime(setup.pdef->getSolutionPath()->as<og::PathGeometric>()->getStates().back());

    const MovingObstacle again;
    STRRTstar improving(again.si);
    improving.setLocalSeed(9);
    improving.setProblemDefinition(again.pdef);
    ASSERT_EQ(improving.solve(ob::timedPlannerTerminationCondition(0.5)), ob::PlannerStatus::EXACT_SOLUTION);
    const auto &path = *again.pdef->getSolutionPath()->as<og::PathGeometric>();
    EXPECT_LE(SpaceTimeStateSpace::getStateTime(path.getState(path.getStateCount() - 1)), firstArrival);
    EXPECT_GE(SpaceTimeStateSpace::getStateTime(path.getState(path.getStateCount() - 1)),
              10.);  // at least the straight-line time
    EXPECT_TRUE(again.validate(path).valid);
}

TEST(STRRTstar, HonoursTheMinimumGoalTime)
{
    const MovingObstacle setup;
    STRRTstar planner(setup.si);
    planner.setMinimumGoalTime(25.);
    planner.setStopAtFirstSolution(true);
    planner.setLocalSeed(3);
    planner.setProblemDefinition(setup.pdef);
    ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(30.)), ob::PlannerStatus::EXACT_SOLUTION);
    const auto &path = *setup.pdef->getSolutionPath()->as<og::PathGeometric>();
    EXPECT_GE(SpaceTimeStateSpace::getStateTime(path.getState(path.getStateCount() - 1)), 25.);
    EXPECT_TRUE(setup.validate(path).valid);
}

TEST(STRRTstar, ReturnsWithinItsTerminationCondition)
{
    // The obstacle ends at (-5, 0) for good: after 20 s the goal next to it is unreachable, so only the
    // 10 ms limit stops the search.
    const MovingObstacle setup({-5.2, 0.});
    STRRTstar planner(setup.si);
    planner.setMinimumGoalTime(20.);
    planner.setProblemDefinition(setup.pdef);
    planner.setup();
    const auto start = ompl::time::now();
    EXPECT_EQ(planner.solve(ob::timedPlannerTerminationCondition(0.01)), ob::PlannerStatus::TIMEOUT);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.2);
}

TEST(STRRTstar, RejectsANonSpaceTimeStateSpaceAndBadSettings)
{
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {5., 0.}, {-5., 0.});
    EXPECT_THROW(STRRTstar{problem.getSpaceInformation()}, ompl::Exception);
    EXPECT_THROW(STRRTstar{problem.getSpaceInformation()->getRobot(0)->getSpaceInformation()}, ompl::Exception);

    const MovingObstacle setup;
    STRRTstar planner(setup.si);
    EXPECT_THROW(planner.setRewiringState("sometimes"), ompl::Exception);
    EXPECT_THROW(planner.setTimeBoundFactorIncrease(1.), ompl::Exception);
    EXPECT_THROW(planner.setBatchSize(0), ompl::Exception);
    for (const char *name : {"range", "rewiring", "batch_size", "initial_time_bound_factor",
                             "time_bound_factor_increase", "sample_uniform_for_unbounded_time", "minimum_goal_time"})
        EXPECT_TRUE(planner.params().hasParam(name)) << name;
    EXPECT_TRUE(planner.params().setParam("rewiring", "radius"));
    EXPECT_EQ(planner.getRewiringState(), "radius");
}
