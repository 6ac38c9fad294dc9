#include "TestProblems.h"

#include "ompl_parc/arc/RepairLoop.h"
#include "ompl_parc/arc/RepairWorkspace.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

/* reset() forgets a scanned plan: every frontier back to 0, every pair in play, so a second plan's detection finds its
   own earliest conflict, not one left from the first. */
TEST(RepairWorkspace, ResetForgetsTheLastPlan)
{
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    RepairWorkspace workspace(si, 2);
    workspace.configure(2, 50, 1, true);
    std::mt19937 rng(5);
    const RepairCache cache;
    for (int k = 0; k < 10; ++k)
    {
        const auto plan = test::randomWalkPlan(si, rng, 0.04);
        workspace.reset();
        for (std::size_t i = 0; i < 8; ++i)
            for (std::size_t j = i + 1; j < 8; ++j)
                ASSERT_EQ(workspace.getDetector().getFrontier(i, j), 0u);
        const auto all = test::allConflicts(si, plan);
        const auto batch =
            workspace.getBatchDetector().detect(plan, cache, 200, ob::plannerNonTerminatingCondition()).entries;
        ASSERT_EQ(batch.empty(), all.empty());
        if (!all.empty())
            EXPECT_EQ(batch.front().conflict, all.front());
    }
}

TEST(RepairWorkspace, ConfigureChangesTheWorkerCountAndRefusesZeros)
{
    const auto problem = scenarios::createMobileCross(4);
    RepairWorkspace workspace(*problem.getSpaceInformation(), 1);
    EXPECT_EQ(workspace.getPool().getWorkerCount(), 1u);
    workspace.configure(3, 10, 8, true);
    EXPECT_EQ(workspace.getPool().getWorkerCount(), 3u);
    EXPECT_THROW(workspace.configure(0, 10, 8, true), ompl::Exception);
    EXPECT_THROW(workspace.configure(3, 0, 8, true), ompl::Exception);
    EXPECT_THROW(workspace.configure(3, 10, 0, true), ompl::Exception);
    EXPECT_THROW(workspace.configure(2, 0, 8, true), ompl::Exception);
    EXPECT_EQ(workspace.getPool().getWorkerCount(), 3u);  // a refused configuration changes nothing
    EXPECT_THROW(RepairWorkspace(*problem.getSpaceInformation(), 0), ompl::Exception);
}

TEST(RepairWorkspace, ALoopRefusesTheWorkspaceOfAnotherTeam)
{
    const auto problem = scenarios::createMobileCross(4), other = scenarios::createMobileCross(4);
    RepairWorkspace workspace(*other.getSpaceInformation(), 1);
    EXPECT_THROW(RepairLoop(problem, 1, workspace), ompl::Exception);
    RepairWorkspace own(*problem.getSpaceInformation(), 1);
    EXPECT_NO_THROW(RepairLoop(problem, 1, own));
}

/* The planner keeps its workspace across clear(): a query after another query gives the plan a fresh planner gives. */
TEST(RepairWorkspace, APlannerReusedAfterClearPlansAsAFreshOne)
{
    const auto problem = scenarios::createMobileCross(16);
    const auto solve = [&](ARC &arc, unsigned int seed)
    {
        arc.setSeed(seed);
        arc.setProblemDefinition(problem.createProblemDefinition());
        EXPECT_EQ(arc.solve(ob::timedPlannerTerminationCondition(60.)), ob::PlannerStatus::EXACT_SOLUTION);
        const auto report = SolutionValidator(problem).validate(arc.getPlan());
        EXPECT_TRUE(report.valid) << report.message;
        return arc.getPlan();
    };
    ARC fresh(problem.getSpaceInformation()), reused(problem.getSpaceInformation());
    const MultiRobotPlan expected = solve(fresh, 3);
    ASSERT_GT(fresh.getStatistics().conflicts, 0u);
    solve(reused, 11);
    reused.clear();
    const MultiRobotPlan again = solve(reused, 3);
    for (std::size_t r = 0; r < 16; ++r)
        EXPECT_TRUE(again.getRobotPath(r) == expected.getRobotPath(r)) << "robot " << r;
}

/* P-ARC's worker count may change between queries: the workspace makes a new pool, and the plans stay valid. */
TEST(RepairWorkspace, PArcSolvesAgainWithAnotherWorkerCount)
{
    const auto problem = scenarios::createMobileCross(16);
    PARC parc(problem.getSpaceInformation());
    parc.setSeed(4);
    parc.params().setParam("workers", "2");
    parc.setProblemDefinition(problem.createProblemDefinition());
    parc.setup();
    for (const char *workers : {"2", "3", "1"})
    {
        parc.clear();
        parc.params().setParam("workers", workers);
        parc.setProblemDefinition(problem.createProblemDefinition());
        ASSERT_EQ(parc.solve(ob::timedPlannerTerminationCondition(60.)), ob::PlannerStatus::EXACT_SOLUTION)
            << workers << " workers";
        const auto report = SolutionValidator(problem).validate(parc.getPlan());
        EXPECT_TRUE(report.valid) << workers << " workers: " << report.message;
    }
}
