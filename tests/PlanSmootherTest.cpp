#include "TestProblems.h"

#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/planners/subproblem/LatticeMapfSolver.h"
#include "ompl_parc/planners/subproblem/WholeTeamSolver.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/quality/PlanSmoother.h"
#include "ompl_parc/quality/SmoothingStep.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/PlannerData.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <functional>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** The planner's PlannerData property \e name ("" if missing). */
    std::string property(const ob::Planner &planner, const std::string &name)
    {
        ob::PlannerData data(planner.getSpaceInformation());
        planner.getPlannerData(data);
        const auto found = data.properties.find(name);
        return found == data.properties.end() ? "" : found->second;
    }

    /** Record into \e reported the cost of every solution \e planner reports through its ProblemDefinition's
        intermediate-solution callback (checking that the report is its own and carries a path). */
    void recordReports(ob::Planner &planner, std::vector<double> &reported)
    {
        planner.getProblemDefinition()->setIntermediateSolutionCallback(
            [&planner, &reported](const ob::Planner *from, const std::vector<const ob::State *> &states,
                                  const ob::Cost cost)
            {
                EXPECT_EQ(from, &planner);
                EXPECT_GT(states.size(), 1u);
                reported.push_back(cost.value());
            });
    }

    /** The time limit of an anytime solve: long enough for several rounds, also under ThreadSanitizer. */
    constexpr double anytimeLimit()
    {
#ifdef OMPL_PARC_SANITIZED
        return 20.;
#else
        return 4.;
#endif
    }

    /** ARC's plan (seed 1) for \e problem; empty paths if it finds none. */
    MultiRobotPlan arcPlanOf(const MultiRobotProblem &problem)
    {
        ARC arc(problem.getSpaceInformation());
        arc.setSeed(1);
        EXPECT_EQ(test::solveWith(arc, problem), ob::PlannerStatus::EXACT_SOLUTION);
        return arc.getPlan();
    }

    /** Every robot starts and ends where it did in \e before. */
    void expectSameEndpoints(const MultiRobotPlan &before, const MultiRobotPlan &after);

    struct Smoothed
    {
        MultiRobotPlan before, plan;
        SmoothingReport report;
    };

    /** ARC's plan for \e problem smoothed for up to 5 s by a smoother (seed 7) that \e configure sets up; checks that
        the result is valid, starts and ends where the plan did, and that the report has its makespan. */
    Smoothed smoothArcPlan(const MultiRobotProblem &problem, const std::function<void(PlanSmoother &)> &configure)
    {
        MultiRobotPlan plan = arcPlanOf(problem);
        EXPECT_FALSE(plan.getPath(0).empty());
        Smoothed s{plan, plan, {}};
        PlanSmoother smoother(problem.getSpaceInformation(), 7);
        configure(smoother);
        s.report = smoother.smooth(s.plan, ob::timedPlannerTerminationCondition(5.));
        const auto check = SolutionValidator(problem).validate(s.plan);
        EXPECT_TRUE(check.valid) << check.message;
        expectSameEndpoints(s.before, s.plan);
        EXPECT_EQ(s.report.makespanAfter, s.plan.getMakespan());
        return s;
    }

    /** Every robot starts and ends where it did in \e before. */
    void expectSameEndpoints(const MultiRobotPlan &before, const MultiRobotPlan &after)
    {
        for (std::size_t i = 0; i < before.getRobotCount(); ++i)
        {
            EXPECT_EQ(test::config(after, i, 0), test::config(before, i, 0));
            EXPECT_EQ(test::config(after, i, after.getArrival(i)), test::config(before, i, before.getArrival(i)));
        }
    }
}  // namespace

TEST(PlanSmoother, RandomValidPlansStayValidAndNeverGetLonger)
{
    // Property test: jittery random walks of 8 discs (at most one timestep's motion per timestep), those the
    // independent validator accepts, smoothed with and without the replanner: still valid, same endpoints, never
    // a longer makespan or sum of costs; most get much shorter.
    std::mt19937 rng(23);
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = problem.getSpaceInformation();
    int smoothed = 0, shorter = 0;
    for (int k = 0; k < 400 && smoothed < 16; ++k)
    {
        MultiRobotPlan plan = test::randomWalkPlan(*si, rng, 0.7 / si->getResolution());
        const MultiRobotProblem own = test::problemOfPlan(si, plan);
        if (!SolutionValidator(own).validate(plan).valid)
            continue;
        const MultiRobotPlan before = plan;
        PlanSmoother smoother(si, static_cast<std::uint_fast32_t>(k + 1));
        if (k % 2 == 0)
            smoother.setReplanner(PrioritizedSTRRTSolver::makeReplanner());
        const SmoothingReport report = smoother.smooth(plan, ob::timedPlannerTerminationCondition(60.));
        ++smoothed;
        const auto check = SolutionValidator(own).validate(plan);
        EXPECT_TRUE(check.valid) << "plan " << k << ": " << check.message;
        expectSameEndpoints(before, plan);
        EXPECT_LE(plan.getMakespan(), before.getMakespan());
        EXPECT_LE(plan.getSumOfCosts(), before.getSumOfCosts());
        EXPECT_EQ(report.makespanBefore, before.getMakespan());
        EXPECT_EQ(report.makespanAfter, plan.getMakespan());
        shorter += plan.getSumOfCosts() * 2 < before.getSumOfCosts();
    }
    EXPECT_GE(smoothed, 16);
    EXPECT_GE(shorter, smoothed / 2);
}

TEST(PlanSmoother, ATeamReplanUndoesTheWaitsOfARepairChainAndStaysValid)
{
    // Ring 24, instance 1 (a family the smoother was not tuned on): ARC's repairs leave robots waiting for chains
    // of other repairs, far beyond their straight-line bounds. Replanning the whole team prioritised (the lattice
    // for discs) from the plan's own starts and goals finds a plan of a fraction of that makespan; the smoother
    // keeps it, then shortcuts it. Every plan validated.
    const Smoothed s = smoothArcPlan(scenarios::generateFamilyInstance("ring", 24, 1),
                                     [](PlanSmoother &smoother)
                                     {
                                         smoother.setReplanner(PrioritizedSTRRTSolver::makeReplanner());
                                         smoother.setTeamReplanTime(5.);  // it takes well under 0.1 s here
                                     });
    EXPECT_TRUE(s.report.teamReplanned);
    EXPECT_TRUE(s.report.teamReplanKept);
    EXPECT_LT(s.plan.getMakespan() * 2, s.before.getMakespan());
}

TEST(PlanSmoother, AWholeTeamLatticePlanReplacesTheRepairsOfADenseCrossing)
{
    // Crossing 24, instance 3 (a generated family): ARC's repairs chain waits through the crossing, and the
    // prioritised team replan does not finish in the default half second. The team solver (LaCAM on a lattice) plans
    // the whole team in milliseconds; the smoother keeps its plan when it is shorter, then shortcuts it. Validated.
    const Smoothed s = smoothArcPlan(scenarios::generateFamilyInstance("crossing", 24, 3),
                                     [](PlanSmoother &smoother)
                                     {
                                         smoother.setTeamSolver(LatticeMapfSolver::makeTeamSolver());
                                         smoother.setTeamReplanTime(10.);  // some 20 ms a try here
                                     });
    EXPECT_TRUE(s.report.teamSolveTried);
    EXPECT_TRUE(s.report.teamSolved);
    EXPECT_TRUE(s.report.teamSolveKept);
    EXPECT_FALSE(s.report.teamReplanned);  // no replanner
    EXPECT_LT(s.plan.getMakespan() * 3, s.before.getMakespan());
}

TEST(PlanSmoother, TheTeamSolverIsNotTriedOnArmsAndTheSmootherGoesOn)
{
    // A lattice is for translating robots: on planar arms the team solve is not tried, and the shortcuts still run
    // (smoothArcPlan: the plan stays valid, with the same endpoints).
    const Smoothed s = smoothArcPlan(scenarios::createPlanarCross(4),
                                     [](PlanSmoother &smoother)
                                     {
                                         smoother.setTeamSolver(LatticeMapfSolver::makeTeamSolver());
                                         smoother.setTeamReplanTime(5.);
                                     });
    EXPECT_FALSE(s.report.teamSolveTried);
    EXPECT_FALSE(s.report.teamSolved);
    EXPECT_GT(s.report.attempts, 0u);
    EXPECT_LE(s.plan.getMakespan(), s.before.getMakespan());
}

TEST(PlanSmoother, AnArmTeamIsSolvedWholeByMovesOverlappedInTime)
{
    // Panda cell 4, instance 1: ARC's repairs leave a plan 1.6x its bound. The whole-team solver moves the four arms
    // one at a time and overlaps the moves wherever the arms stay apart (in about 0.1 s); its plan is kept when shorter
    // (the smoother then shortcuts it) and validated (smoothArcPlan).
    const Smoothed s = smoothArcPlan(scenarios::generateFamilyInstance("panda_cell", 4, 1),
                                     [](PlanSmoother &smoother)
                                     {
                                         smoother.setTeamSolver(WholeTeamSolver::make());
                                         smoother.setTeamReplanTime(10.);  // 0.1 s needed, sanitizers too
                                     });
    EXPECT_TRUE(s.report.teamSolveTried);
    EXPECT_TRUE(s.report.teamSolved);
    EXPECT_TRUE(s.report.teamSolveKept);
    EXPECT_LT(s.plan.getMakespan() * 5, s.before.getMakespan() * 4);  // 1512 timesteps before, 934 after here
}

TEST(PlanSmoother, RefusesAPlanWithAConflict)
{
    // Two discs swapping through each other on straight lines.
    const MultiRobotProblem problem = test::twoDiscs({-2, 0}, {2, 0}, {2, 0}, {-2, 0});
    MultiRobotPlan plan = test::straightLinePlan(problem);
    PlanSmoother smoother(problem.getSpaceInformation(), 1);
    EXPECT_THROW(smoother.smooth(plan, ob::timedPlannerTerminationCondition(10.)), ompl::Exception);
}

TEST(PlanSmoother, PlanQualityBoundsAreStraightLines)
{
    const MultiRobotProblem problem = test::twoDiscs({-2, 0}, {2, 0}, {0, -1}, {0, 3});
    const MultiRobotPlan plan = test::straightLinePlan(problem);
    const PlanQuality quality = PlanQuality::measure(*problem.getSpaceInformation(), plan);
    EXPECT_EQ(quality.makespanBound, 512u);  // 4 units at 128 timesteps per unit
    EXPECT_EQ(quality.sumOfCostsBound, 1024u);
    EXPECT_EQ(quality.makespan, plan.getMakespan());
    EXPECT_DOUBLE_EQ(quality.makespanRatio(), static_cast<double>(plan.getMakespan()) / 512.);
}

class SmoothedSolve : public testing::TestWithParam<std::tuple<std::string, std::size_t>>
{
};

TEST_P(SmoothedSolve, ArcWithSmoothingReturnsAValidatedPlanNoLongerThanItsOwn)
{
    // Families the smoother was not tuned on: the smoothed plan is validated and no longer than the plan ARC had
    // before smoothing; a run without smoothing reports none. (Two runs are not compared plan for plan: solver
    // calls capped in time may end differently on a loaded machine.)
    const auto &[family, robots] = GetParam();
    const MultiRobotProblem problem = scenarios::generateFamilyInstance(family, robots, 0);
    const std::string profile = family == "planar_cell" ? "planar" : "mobile";
    ARC plain(problem.getSpaceInformation()), smoothing(problem.getSpaceInformation());
    for (ARC *arc : {&plain, &smoothing})
    {
        arc->setProfile(profile);
        arc->setSeed(3);
    }
    smoothing.params().setParam("smooth", "0.5");
    ASSERT_EQ(test::solveWith(plain, problem), ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_EQ(test::solveWith(smoothing, problem), ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_TRUE(smoothing.getSmoothingReport().has_value());
    const SmoothingReport &report = *smoothing.getSmoothingReport();
    EXPECT_EQ(property(smoothing, "makespan_unsmoothed INTEGER"), std::to_string(report.makespanBefore));
    // What a tool reads back from the properties is the planner's own report.
    ob::PlannerData data(smoothing.getSpaceInformation());
    smoothing.getPlannerData(data);
    const auto read = SmoothingStep::reportOf(data.properties);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(read->makespanBefore, report.makespanBefore);
    EXPECT_EQ(read->sumOfCostsBefore, report.sumOfCostsBefore);
    EXPECT_EQ(read->attempts, report.attempts);
    EXPECT_EQ(read->kept(), report.kept());
    EXPECT_EQ(read->teamReplanned, report.teamReplanned);
    EXPECT_EQ(read->teamReplanKept, report.teamReplanKept);
    EXPECT_EQ(read->teamSolveTried, report.teamSolveTried);
    EXPECT_EQ(read->teamSolved, report.teamSolved);
    EXPECT_EQ(read->teamSolveKept, report.teamSolveKept);
    ob::PlannerData none(plain.getSpaceInformation());
    plain.getPlannerData(none);
    EXPECT_FALSE(SmoothingStep::reportOf(none.properties).has_value());
    const MultiRobotPlan &plan = smoothing.getPlan();
    const auto check = SolutionValidator(problem).validate(plan);
    EXPECT_TRUE(check.valid) << check.message;
    expectSameEndpoints(plain.getPlan(), plan);
    EXPECT_EQ(plan.getMakespan(), report.makespanAfter);
    EXPECT_LE(report.makespanAfter, report.makespanBefore);
    EXPECT_LE(report.sumOfCostsAfter, report.sumOfCostsBefore);
    EXPECT_EQ(property(smoothing, "makespan INTEGER"), std::to_string(plan.getMakespan()));
    EXPECT_NE(property(smoothing, "makespan_ratio REAL"), "");
    EXPECT_EQ(property(plain, "smoothing_time REAL"), "");
    // The solution path handed to OMPL is the smoothed plan.
    const auto &path = *smoothing.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    EXPECT_TRUE(test::pathFollowsPlan(*problem.getSpaceInformation(), path, plan));
}

INSTANTIATE_TEST_SUITE_P(Families, SmoothedSolve,
                         testing::Values(std::make_tuple("ring", 8), std::make_tuple("crossing", 8),
                                         std::make_tuple("field", 8), std::make_tuple("planar_cell", 4)));

TEST(PlanSmoother, EveryPlannerOfOursSmoothsWhenAsked)
{
    const MultiRobotProblem problem = scenarios::createMobileCircle(8);
    const auto si = problem.getSpaceInformation();
    std::vector<ob::PlannerPtr> planners{std::make_shared<ORPARC>(si), std::make_shared<PrioritizedSTRRT>(si)};
    for (const auto &planner : planners)
    {
        SCOPED_TRACE(planner->getName());
        planner->params().setParam("seed", "2");
        planner->params().setParam("smooth", "0.3");
        ASSERT_EQ(test::solveWith(*planner, problem), ob::PlannerStatus::EXACT_SOLUTION);
        const MultiRobotPlan &plan = dynamic_cast<ORPARC *>(planner.get())
                                         ? static_cast<ORPARC &>(*planner).getPlan()
                                         : static_cast<PrioritizedSTRRT &>(*planner).getPlan();
        const auto check = SolutionValidator(problem).validate(plan);
        EXPECT_TRUE(check.valid) << check.message;
        EXPECT_NE(property(*planner, "smoothing_time REAL"), "");
        EXPECT_EQ(property(*planner, "makespan INTEGER"), std::to_string(plan.getMakespan()));
        EXPECT_LE(plan.getMakespan(), std::stoul(property(*planner, "makespan_unsmoothed INTEGER")));
        const auto &path = *planner->getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
        EXPECT_TRUE(test::pathFollowsPlan(*si, path, plan));
    }
}

TEST(PlanSmoother, BadBudgetsAreRefused)
{
    ARC arc(scenarios::createMobileCircle(2).getSpaceInformation());
    EXPECT_THROW(arc.setSmoothing(-1.), ompl::Exception);
    EXPECT_THROW(arc.setSmoothing(std::numeric_limits<double>::infinity()), ompl::Exception);
    EXPECT_THROW(arc.params().setParam("smooth", "-2"), ompl::Exception);
    EXPECT_EQ(arc.getSmoothing(), 0.);
}

TEST(PlanSmoother, AnytimeOrParcKeepsTheBestPlanAndReportsEachImprovement)
{
    const MultiRobotProblem problem = scenarios::createMobileCircle(8);
    const auto si = problem.getSpaceInformation();
    ORPARC orparc(si);
    orparc.setSeed(4);
    orparc.params().setParam("objective", "makespan");
    orparc.params().setParam("smooth", "0.2");
    orparc.setProblemDefinition(problem.createProblemDefinition());
    std::vector<double> reported;
    recordReports(orparc, reported);
    orparc.setup();
    // Races until the limit: long enough for several races (one takes ~0.2 s, seconds under ThreadSanitizer).
    const double limit = anytimeLimit();
    const auto started = ompl::time::now();
    ASSERT_EQ(orparc.solve(ob::timedPlannerTerminationCondition(limit)), ob::PlannerStatus::EXACT_SOLUTION);
    const double took = ompl::time::seconds(ompl::time::now() - started);
    const PlanQuality quality = PlanQuality::measure(*si, orparc.getPlan());
    if (quality.makespan > quality.makespanBound)
        EXPECT_GE(took, limit);  // anytime: it races until the end (or until a plan meets the bound)
    EXPECT_LT(took, limit + test::promptReturn());
    ASSERT_FALSE(reported.empty());
    EXPECT_TRUE(std::is_sorted(reported.rbegin(), reported.rend()));  // each report better than the last
    EXPECT_EQ(static_cast<std::size_t>(reported.back()), orparc.getPlan().getMakespan());
    EXPECT_GE(std::stoul(property(orparc, "anytime_rounds INTEGER")), 2u);
    EXPECT_EQ(property(orparc, "improvements INTEGER"), std::to_string(reported.size()));
    const auto check = SolutionValidator(problem).validate(orparc.getPlan());
    EXPECT_TRUE(check.valid) << check.message;
    const auto &path = *orparc.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    EXPECT_TRUE(test::pathFollowsPlan(*si, path, orparc.getPlan()));
    EXPECT_EQ(orparc.getProblemDefinition()->getSolutionCount(), 1u);
    EXPECT_THROW(orparc.setObjective("fastest"), ompl::Exception);

    // A problem no race can solve ends the anytime solve at once, not at the limit.
    const MultiRobotProblem blocked = test::twoDiscs({0, 0}, {2, 0}, {0.3, 0}, {-2, 0});
    ORPARC again(blocked.getSpaceInformation());
    again.params().setParam("objective", "sum_of_costs");
    const auto start = ompl::time::now();
    EXPECT_EQ(test::solveWith(again, blocked, 30.), ob::PlannerStatus::INVALID_START);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 5.);
}

TEST(PlanSmoother, AnytimeArcAndParcImproveTheirPlanAndReportEachImprovement)
{
    // A dense crossing (not designed with the planners): the first plan is several times its bound, and the anytime
    // phase (one worker for ARC, two for P-ARC) keeps finding better ones until the limit.
    const MultiRobotProblem problem = scenarios::generateFamilyInstance("crossing", 12, 1);
    const auto si = problem.getSpaceInformation();
    for (const unsigned int workers : {1u, 2u})
    {
        SCOPED_TRACE(workers);
        PARC planner(si);
        planner.setSeed(3);
        planner.params().setParam("workers", std::to_string(workers));
        planner.params().setParam("objective", workers == 1 ? "makespan" : "sum_of_costs");
        planner.setProblemDefinition(problem.createProblemDefinition());
        std::vector<double> reported;
        recordReports(planner, reported);
        planner.setup();
        const double limit = anytimeLimit();
        const auto started = ompl::time::now();
        ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(limit)), ob::PlannerStatus::EXACT_SOLUTION);
        const double took = ompl::time::seconds(ompl::time::now() - started);
        EXPECT_LT(took, limit + test::promptReturn());
        ASSERT_TRUE(planner.getImprovementReport().has_value());
        const auto &plan = planner.getPlan();
        const std::size_t value = workers == 1 ? plan.getMakespan() : plan.getSumOfCosts();
        // The first solution, then each better plan (lower by the objective, or as low and lower by the other
        // measure); the last is the solution.
        ASSERT_GE(reported.size(), 2u);
        EXPECT_TRUE(std::is_sorted(reported.rbegin(), reported.rend()));
        EXPECT_LT(reported.back(), reported.front());
        EXPECT_EQ(static_cast<std::size_t>(reported.back()), value);
        EXPECT_EQ(property(planner, "improvements INTEGER"), std::to_string(reported.size() - 1));
        EXPECT_GE(std::stoul(property(planner, "anytime_rounds INTEGER")), 2u);
        EXPECT_LT(std::stod(property(planner, "first_solution_time REAL")), took);
        const auto check = SolutionValidator(problem).validate(plan);
        EXPECT_TRUE(check.valid) << check.message;
        const auto &path = *planner.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
        EXPECT_TRUE(test::pathFollowsPlan(*si, path, plan));
        EXPECT_EQ(planner.getProblemDefinition()->getSolutionCount(), 1u);
    }
    ARC arc(si);
    EXPECT_THROW(arc.setObjective("fastest"), ompl::Exception);
    EXPECT_EQ(arc.getObjective(), "first");
}

TEST(PlanSmoother, SmoothingNeverOutlastsTheSolvesTerminationCondition)
{
    // A budget far past the limit: smoothing stops with the solve's termination condition, the plan it has by then
    // is the solution, and it is valid.
    const MultiRobotProblem problem = scenarios::createMobileCircle(16);
    ARC arc(problem.getSpaceInformation());
    arc.setSeed(1);
    arc.setSmoothing(1000.);
    // ARC takes ~0.25 s here; under ASan on a loaded machine a run took 2.7 s (its repairs' time caps follow the
    // machine's speed), so the limit leaves ample room: smoothing then runs until it.
    const double limit = 10.;
    const auto started = ompl::time::now();
    ASSERT_EQ(test::solveWith(arc, problem, limit), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - started), limit + test::promptReturn());
    ASSERT_TRUE(arc.getSmoothingReport().has_value());
    EXPECT_GT(arc.getSmoothingReport()->attempts, 0u);
    EXPECT_LE(arc.getPlan().getMakespan(), arc.getSmoothingReport()->makespanBefore);
    const auto check = SolutionValidator(problem).validate(arc.getPlan());
    EXPECT_TRUE(check.valid) << check.message;
}
