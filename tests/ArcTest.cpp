#include "TestProblems.h"

#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <map>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    struct Solved
    {
        ob::PlannerStatus status;
        MultiRobotPlan plan;
        ArcStatistics statistics;
    };

    Solved runArc(const MultiRobotProblem &problem, const std::string &profile, unsigned int seed, double limit = 60.)
    {
        ARC arc(problem.getSpaceInformation());
        arc.setProfile(profile);
        arc.setSeed(seed);
        arc.setProblemDefinition(problem.createProblemDefinition());
        arc.setup();
        const auto status = arc.solve(ob::timedPlannerTerminationCondition(limit));
        return {status, arc.getPlan(), arc.getStatistics()};
    }
}  // namespace

class ArcSolves : public testing::TestWithParam<std::tuple<std::string, std::size_t, std::string>>
{
};

TEST_P(ArcSolves, AndTheIndependentValidatorAgrees)
{
    const auto [scenario, robots, profile] = GetParam();
    const auto problem = scenarios::createScenario(scenario, robots);
    const auto solved = runArc(problem, profile, 1);
    ASSERT_EQ(solved.status, ob::PlannerStatus::EXACT_SOLUTION);
    const auto report = SolutionValidator(problem).validate(solved.plan);
    EXPECT_TRUE(report.valid) << report.message;
    EXPECT_GT(solved.statistics.conflicts, 0u);
    EXPECT_EQ(solved.statistics.repairs, solved.statistics.conflicts);
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, ArcSolves,
    testing::Values(std::make_tuple("mobile_cross", 4, "mobile"), std::make_tuple("mobile_cross", 16, "mobile"),
                    std::make_tuple("mobile_circle", 4, "mobile"), std::make_tuple("mobile_circle", 8, "mobile"),
                    std::make_tuple("planar_cross", 4, "planar"), std::make_tuple("planar_cross", 8, "planar")),
    [](const auto &info) { return std::get<0>(info.param) + std::to_string(std::get<1>(info.param)); });

TEST(Arc, SameSeedGivesTheSamePlan)
{
    const auto problem = scenarios::createMobileCross(8);
    const auto a = runArc(problem, "mobile", 17), b = runArc(problem, "mobile", 17), c = runArc(problem, "mobile", 18);
    ASSERT_EQ(a.status, ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_EQ(b.status, ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_EQ(c.status, ob::PlannerStatus::EXACT_SOLUTION);
    for (std::size_t r = 0; r < 8; ++r)
        EXPECT_EQ(a.plan.getRobotPath(r), b.plan.getRobotPath(r)) << "robot " << r;
    bool differs = false;
    for (std::size_t r = 0; r < 8; ++r)
        differs = differs || a.plan.getRobotPath(r) != c.plan.getRobotPath(r);
    EXPECT_TRUE(differs);
    EXPECT_TRUE(SolutionValidator(problem).validate(a.plan).valid);
    EXPECT_TRUE(SolutionValidator(problem).validate(c.plan).valid);
}

TEST(Arc, InvalidStartAndGoalAreReportedNamingTheRobot)
{
    const auto problem = scenarios::createMobileCross(4);
    auto starts = std::vector<std::vector<double>>{problem.getStart(0), problem.getStart(1), problem.getStart(2),
                                                   problem.getStart(3)};
    auto goals = std::vector<std::vector<double>>{problem.getGoal(0), problem.getGoal(1), problem.getGoal(2),
                                                  problem.getGoal(3)};
    auto badStart = starts;
    badStart[2] = {50., 0.};  // out of bounds
    ARC arc(problem.getSpaceInformation());
    arc.setProblemDefinition(
        MultiRobotProblem(problem.getSpaceInformation(), badStart, goals).createProblemDefinition());
    EXPECT_EQ(arc.solve(1.0), ob::PlannerStatus::INVALID_START);
    EXPECT_EQ(arc.getStatusMessage(), "start of robot 'r2' is out of bounds");

    auto badGoal = goals;
    badGoal[3] = goals[1];  // two robots share a goal
    arc.clear();
    arc.setProblemDefinition(
        MultiRobotProblem(problem.getSpaceInformation(), starts, badGoal).createProblemDefinition());
    EXPECT_EQ(arc.solve(1.0), ob::PlannerStatus::INVALID_GOAL);
    EXPECT_EQ(arc.getStatusMessage(), "goals of robots 'r1' and 'r3' collide");
}

TEST(Arc, PlainSpaceInformationIsAClearError)
{
    auto plain = std::make_shared<ob::SpaceInformation>(std::make_shared<ob::RealVectorStateSpace>(2));
    EXPECT_THROW(ARC arc(plain), ompl::Exception);
}

TEST(Arc, HonoursTerminationPromptlyAndContinuesOnTheNextSolve)
{
    // Mobile Circle 12 takes ARC about 100 ms: stop it after 20 ms, then let it finish.
    const auto problem = scenarios::createMobileCircle(12);
    ARC arc(problem.getSpaceInformation());
    arc.setSeed(3);
    arc.setProblemDefinition(problem.createProblemDefinition());
    const auto start = ompl::time::now();
    EXPECT_EQ(arc.solve(ob::timedPlannerTerminationCondition(0.02)), ob::PlannerStatus::TIMEOUT);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.02 + test::promptReturn());
    EXPECT_FALSE(arc.getStatusMessage().empty());
    ASSERT_EQ(arc.solve(ob::timedPlannerTerminationCondition(120.)), ob::PlannerStatus::EXACT_SOLUTION);
    const auto report = SolutionValidator(problem).validate(arc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
    // The solution is in the ProblemDefinition too, one composite state per breakpoint.
    auto *path = arc.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    EXPECT_TRUE(test::pathFollowsPlan(*problem.getSpaceInformation(), *path, arc.getPlan()));
}

TEST(Arc, ParametersAreDeclaredAndStatisticsReported)
{
    const auto problem = scenarios::createPlanarCross(4);
    ARC arc(problem.getSpaceInformation());
    auto &params = arc.params();
    for (const char *name : {"profile", "window", "growth", "growth_step", "min_window_growth", "endpoint_step",
                             "bound_margin", "min_bound_range", "sample_cap", "solvers", "simplify_initial",
                             "straight_initial", "shorten_patches", "lattice_mapf", "sequential", "smooth", "seed"})
        EXPECT_TRUE(params.hasParam(name)) << name;
    EXPECT_TRUE(arc.getLatticeMapf());
    EXPECT_TRUE(params.setParam("lattice_mapf", "0"));
    EXPECT_FALSE(arc.getLatticeMapf());
    EXPECT_TRUE(params.setParam("profile", "mobile"));  // a profile keeps what was set one by one
    EXPECT_FALSE(arc.getLatticeMapf());
    EXPECT_TRUE(params.setParam("lattice_mapf", "1"));
    EXPECT_TRUE(params.setParam("profile", "planar"));
    EXPECT_EQ(arc.getWindow(), 100u);
    EXPECT_EQ(arc.getGrowth(), "exponential");
    EXPECT_EQ(arc.getMinWindowGrowth(), 1.);
    EXPECT_TRUE(params.setParam("min_window_growth", "1.25"));
    EXPECT_EQ(arc.getMinWindowGrowth(), 1.25);
    EXPECT_THROW(params.setParam("min_window_growth", "0.5"), ompl::Exception);  // below 1: windows could shrink
    EXPECT_EQ(arc.getMinWindowGrowth(), 1.25);
    EXPECT_TRUE(params.setParam("window", "80"));
    EXPECT_EQ(arc.getWindow(), 80u);
    EXPECT_TRUE(params.setParam("seed", "5"));
    arc.setProblemDefinition(problem.createProblemDefinition());
    ASSERT_EQ(arc.solve(ob::timedPlannerTerminationCondition(60.)), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(SolutionValidator(problem).validate(arc.getPlan()).valid);
    ob::PlannerData data(problem.getSpaceInformation());
    arc.getPlannerData(data);
    EXPECT_EQ(data.properties["conflicts INTEGER"], std::to_string(arc.getStatistics().conflicts));
    EXPECT_EQ(data.properties["makespan INTEGER"], std::to_string(arc.getPlan().getMakespan()));
    EXPECT_TRUE(data.properties.count("resolution_cpu_time REAL"));
    EXPECT_THROW(arc.setProfile("humanoid"), ompl::Exception);
    EXPECT_THROW(arc.setWindow(0), ompl::Exception);
    EXPECT_THROW(arc.setMinWindowGrowth(std::nan("")), ompl::Exception);
}

TEST(Arc, ProfileFollowsTheRobotsUnlessOneIsNamed)
{
    // No profile named: the team's robots choose it (discs: mobile, planar arms: planar, URDF arms: panda), so a
    // Panda team is not repaired with 2D windows; a named profile (also for ORPARC's racers) overrides it.
    const std::vector<std::pair<MultiRobotProblem, unsigned int>> teams = {{scenarios::createMobileCross(4), 200u},
                                                                           {scenarios::createPlanarCross(4), 100u},
                                                                           {scenarios::createPandaCage(4), 20u}};
    for (const auto &[problem, window] : teams)
    {
        ARC arc(problem.getSpaceInformation());
        EXPECT_EQ(arc.getProfile(), "auto");
        EXPECT_EQ(arc.getWindow(), window) << problem.getName();
        EXPECT_EQ(arc.getSequential(), window == 20u) << problem.getName();
    }
    ARC named(scenarios::createPandaCage(4).getSpaceInformation());
    ASSERT_TRUE(named.params().setParam("profile", "mobile"));
    EXPECT_EQ(named.getWindow(), 200u);
    EXPECT_FALSE(named.getSequential());
    ASSERT_TRUE(named.params().setParam("profile", "auto"));
    EXPECT_EQ(named.getWindow(), 20u);
    ORPARC orparc(scenarios::createPlanarCross(4).getSpaceInformation());
    EXPECT_EQ(orparc.params().getParam("profile")->getValue(), "auto");
}

TEST(Arc, ProfileAndExplicitParametersInAnyOrder)
{
    // OMPL's ParamSet::setParams applies a map alphabetically: "bound_margin" before "profile". A profile must
    // never undo a parameter set one by one, whichever comes first.
    const auto problem = scenarios::createPlanarCross(4);
    const std::map<std::string, std::string> values = {
        {"profile", "panda"}, {"bound_margin", "0.25"}, {"growth_step", "7"}, {"solvers", "hierarchy"}};
    ARC mapped(problem.getSpaceInformation());
    ASSERT_TRUE(mapped.params().setParams(values, true));
    ARC profileLast(problem.getSpaceInformation());
    for (const char *name : {"bound_margin", "growth_step", "solvers", "profile"})
        ASSERT_TRUE(profileLast.params().setParam(name, values.at(name)));
    ARC profileFirst(problem.getSpaceInformation());
    for (const char *name : {"profile", "bound_margin", "growth_step", "solvers"})
        ASSERT_TRUE(profileFirst.params().setParam(name, values.at(name)));
    for (const ARC *arc : {&mapped, &profileLast, &profileFirst})
    {
        EXPECT_DOUBLE_EQ(arc->getBoundMargin(), 0.25);
        EXPECT_DOUBLE_EQ(arc->getGrowthStep(), 7.);
        EXPECT_EQ(arc->getSolvers(), "hierarchy");
        EXPECT_EQ(arc->getWindow(), 20u);  // the panda profile's, not set explicitly
        EXPECT_EQ(arc->getGrowth(), "exponential");
        EXPECT_DOUBLE_EQ(arc->getMinBoundRange(), 0.5);
    }
}

TEST(Arc, LengthBreakdownAddsUpToThePlan)
{
    // Where the length comes from: the initial plan plus what each solver's repairs added is the plan, for ARC and for
    // P-ARC's batches (every splice counted once), on a dense generated crossing with several solvers winning.
    const MultiRobotProblem problem = scenarios::generateFamilyInstance("crossing", 12, 1);
    for (const unsigned int workers : {1u, 2u})
    {
        SCOPED_TRACE(workers);
        PARC planner(problem.getSpaceInformation());
        planner.setSeed(2);
        planner.params().setParam("workers", std::to_string(workers));
        ASSERT_EQ(test::solveWith(planner, problem, 60.), ompl::base::PlannerStatus::EXACT_SOLUTION);
        const auto &s = planner.getStatistics();
        const MultiRobotPlan &plan = planner.getPlan();
        ASSERT_GT(s.repairs, 0u);
        long long makespan = static_cast<long long>(s.initialMakespan);
        long long sum = static_cast<long long>(s.initialSumOfCosts);
        unsigned int wins = 0;
        for (const auto &[solver, count] : s.solverWins)
        {
            makespan += s.solverMakespanAdded.at(solver);
            sum += s.solverDelays.at(solver);
            wins += count;
        }
        EXPECT_EQ(wins, s.repairs);
        EXPECT_EQ(makespan, static_cast<long long>(plan.getMakespan()));
        EXPECT_EQ(sum, static_cast<long long>(plan.getSumOfCosts()));
        EXPECT_GT(plan.getMakespan(), s.initialMakespan);  // the repairs of this crossing do cost time
        const auto check = SolutionValidator(problem).validate(plan);
        EXPECT_TRUE(check.valid) << check.message;
    }
}
