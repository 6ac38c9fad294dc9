#include "TestProblems.h"

#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/planners/SpaceTime.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"
#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <array>
#include <string>

/* ST-RRT*: the tests of the standard behaviour run on the planner in use (spacetime::STRRTstar: ours against
   OMPL < 1.6, OMPL's own from OMPL 1.6 on) and on ours, which PP-ST-RRT always uses; our extensions (minimum
   goal time, stopping at the first solution, local seed, parameters) are tested on ours. */

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
            obstacles->addPath(*team->getRobot(1), TimedPath::fromDense(2, obstaclePath));
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
            plan.setPath(
                0, std::static_pointer_cast<SpaceTimeMotionValidator>(si->getMotionValidator())->layOnGrid(path));
            plan.setRobotPath(1, obstaclePath);
            return SolutionValidator(problem).validate(plan);
        }

        const og::PathGeometric &solution() const { return *pdef->getSolutionPath()->as<og::PathGeometric>(); }
    };

    double arrivalOf(const og::PathGeometric &path)
    {
        return spacetime::SpaceTimeStateSpace::getStateTime(path.getState(path.getStateCount() - 1));
    }

    void expectTimedMotions(const spacetime::SpaceTimeStateSpace &space, const og::PathGeometric &path)
    {
        for (std::size_t k = 1; k < path.getStateCount(); ++k)
        {
            const ob::State *from = path.getState(k - 1), *to = path.getState(k);
            const double dt =
                spacetime::SpaceTimeStateSpace::getStateTime(to) - spacetime::SpaceTimeStateSpace::getStateTime(from);
            EXPECT_GT(dt, 0.) << "time must increase strictly, state " << k;
            EXPECT_LE(space.distanceSpace(from, to), space.getVMax() * dt * (1. + 1e-9)) << "faster than vMax";
        }
    }

    /** Solve until the first solution (both planners report each solution to the intermediate solution
        callback) or 30 s. */
    ob::PlannerStatus solveToFirstSolution(ob::Planner &planner, const ob::ProblemDefinitionPtr &pdef)
    {
        auto found = std::make_shared<bool>(false);
        pdef->setIntermediateSolutionCallback(
            [found](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost) { *found = true; });
        return planner.solve(ob::plannerOrTerminationCondition(
            ob::timedPlannerTerminationCondition(30.), ob::PlannerTerminationCondition([found] { return *found; })));
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

template <typename Planner>
class STRRTstarInUse : public testing::Test
{
  protected:
    /** A first solution around the moving obstacle with the rewiring \e mode; a valid timed path. */
    void findsATimedPath(void (Planner::*mode)())
    {
        const MovingObstacle setup;
        Planner planner(setup.si);
        (planner.*mode)();
        planner.setRange(1.);
        planner.setProblemDefinition(setup.pdef);
        planner.setup();
        ASSERT_EQ(solveToFirstSolution(planner, setup.pdef), ob::PlannerStatus::EXACT_SOLUTION);
        expectTimedMotions(*setup.si->getStateSpace()->as<spacetime::SpaceTimeStateSpace>(), setup.solution());
        const auto report = setup.validate(setup.solution());
        EXPECT_TRUE(report.valid) << report.message;
    }
};

/** The planner in use, and ours where that is OMPL's. */
#if OMPL_PARC_OMPL_HAS_SPACE_TIME
using STRRTstarPlanners = testing::Types<spacetime::STRRTstar, ompl_parc::STRRTstar>;
#else
using STRRTstarPlanners = testing::Types<spacetime::STRRTstar>;
#endif

struct STRRTstarPlannerName
{
    template <typename Planner>
    static std::string GetName(int)
    {
        return std::is_same_v<Planner, ompl_parc::STRRTstar> ? "ompl_parc" : "OMPL";
    }
};

TYPED_TEST_SUITE(STRRTstarInUse, STRRTstarPlanners, STRRTstarPlannerName);

TYPED_TEST(STRRTstarInUse, FindsATimedPathWithoutRewiring)
{
    this->findsATimedPath(&TypeParam::setRewiringToOff);
}

TYPED_TEST(STRRTstarInUse, FindsATimedPathWithRadiusRewiring)
{
    this->findsATimedPath(&TypeParam::setRewiringToRadius);
}

TYPED_TEST(STRRTstarInUse, FindsATimedPathWithKNearestRewiring)
{
    this->findsATimedPath(&TypeParam::setRewiringToKNearest);
}

TYPED_TEST(STRRTstarInUse, ImprovesTheArrivalUntilTheTerminationCondition)
{
    const MovingObstacle setup;
    TypeParam planner(setup.si);
    planner.setRewiringToKNearest();
    planner.setProblemDefinition(setup.pdef);
    std::vector<double> reported;
    setup.pdef->setIntermediateSolutionCallback([&reported](const ob::Planner *, const std::vector<const ob::State *> &,
                                                            const ob::Cost cost) { reported.push_back(cost.value()); });
    ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(0.5)), ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_FALSE(reported.empty());
    for (std::size_t k = 1; k < reported.size(); ++k)
        EXPECT_LE(reported[k], reported[k - 1]) << "solution " << k << " arrives later";
    EXPECT_DOUBLE_EQ(arrivalOf(setup.solution()), reported.back());
    EXPECT_GE(arrivalOf(setup.solution()), 10. - 1e-6);  // at least the straight-line time
    EXPECT_TRUE(setup.validate(setup.solution()).valid);
}

TYPED_TEST(STRRTstarInUse, RejectsANonSpaceTimeStateSpace)
{
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {5., 0.}, {-5., 0.});
    EXPECT_THROW(TypeParam{problem.getSpaceInformation()}, ompl::Exception);
    EXPECT_THROW(TypeParam{problem.getSpaceInformation()->getRobot(0)->getSpaceInformation()}, ompl::Exception);
}

TEST(STRRTstar, ImprovesUntilTheTerminationConditionUnlessToldToStop)
{
    const MovingObstacle setup;
    STRRTstar first(setup.si);
    first.setStopAtFirstSolution(true);
    first.setLocalSeed(9);
    first.setProblemDefinition(setup.pdef);
    ASSERT_EQ(first.solve(ob::timedPlannerTerminationCondition(30.)), ob::PlannerStatus::EXACT_SOLUTION);
    const double firstArrival = arrivalOf(setup.solution());

    // The same seed finds the same first solution, then only earlier arrivals.
    const MovingObstacle again;
    STRRTstar improving(again.si);
    improving.setLocalSeed(9);
    improving.setProblemDefinition(again.pdef);
    ASSERT_EQ(improving.solve(ob::timedPlannerTerminationCondition(0.5)), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_LE(arrivalOf(again.solution()), firstArrival);
    EXPECT_TRUE(again.validate(again.solution()).valid);
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
    EXPECT_GE(arrivalOf(setup.solution()), 25.);
    EXPECT_TRUE(setup.validate(setup.solution()).valid);
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

TEST(STRRTstar, RejectsBadSettings)
{
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
