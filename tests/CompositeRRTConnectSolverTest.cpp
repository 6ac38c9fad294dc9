#include "TestProblems.h"

#include "ompl_parc/planners/subproblem/CompositeRRTConnectSolver.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/util/Time.h>

using namespace ompl_parc;
using ompl_parc::test::validatePatch;
namespace ob = ompl::base;

namespace
{
    /** The head-on swap of robots 0 and 1 of Mobile Cross 4, as a subproblem on their whole lines. */
    Subproblem headOnSwap(const MultiRobotProblem &problem)
    {
        Subproblem sub;
        sub.robots = {0, 1};
        sub.starts = {problem.getStart(0), problem.getStart(1)};
        sub.goals = {problem.getGoal(0), problem.getGoal(1)};
        sub.windowStart = 0;
        sub.windowEnd = 2560;
        return sub;
    }
}  // namespace

TEST(CompositeRRTConnectSolver, SolvesAHeadOnSwapWithASynchronisedValidPatch)
{
    const auto problem = scenarios::createMobileCross(4);
    const auto sub = headOnSwap(problem);
    Patch patch;
    ASSERT_TRUE(CompositeRRTConnectSolver().solve(*problem.getSpaceInformation(), sub,
                                                  ob::timedPlannerTerminationCondition(30.), 7, patch));
    ASSERT_EQ(patch.paths.size(), 2u);
    EXPECT_EQ(patch.paths[0].getArrival(), patch.paths[1].getArrival());
    const auto report = validatePatch(problem, sub, patch);
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(CompositeRRTConnectSolver, SameSeedGivesTheSamePatch)
{
    const auto problem = scenarios::createMobileCross(4);
    const auto sub = headOnSwap(problem);
    Patch a, b, c;
    const CompositeRRTConnectSolver solver(0., true);
    const auto &si = *problem.getSpaceInformation();
    ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(30.), 11, a));
    ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(30.), 11, b));
    ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(30.), 12, c));
    EXPECT_EQ(a.paths, b.paths);
    EXPECT_NE(a.paths, c.paths);
    const auto report = validatePatch(problem, sub, a);
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(CompositeRRTConnectSolver, LocalBoundsConfineTheSearch)
{
    const auto problem = scenarios::createMobileCross(4);
    auto sub = headOnSwap(problem);
    // A corridor 2 units tall around y = -2.5 is enough to pass; the patch must stay in it.
    for (std::size_t k = 0; k < 2; ++k)
    {
        ob::RealVectorBounds b(2);
        b.setLow(0, -10.);
        b.setHigh(0, 10.);
        b.setLow(1, -3.5);
        b.setHigh(1, -1.5);
        sub.bounds.push_back(b);
    }
    Patch patch;
    ASSERT_TRUE(CompositeRRTConnectSolver().solve(*problem.getSpaceInformation(), sub,
                                                  ob::timedPlannerTerminationCondition(30.), 3, patch));
    for (const auto &timed : patch.paths)
    {
        const auto path = timed.toDense();
        for (std::size_t k = 1; k < path.size(); k += 2)
        {
            EXPECT_GE(path[k], -3.5);
            EXPECT_LE(path[k], -1.5);
        }
    }
    EXPECT_TRUE(validatePatch(problem, sub, patch).valid);
}

TEST(CompositeRRTConnectSolver, FailsCleanlyOnInvalidEndpointsSampleCapAndTimeout)
{
    const auto problem = scenarios::createMobileCross(4);
    const auto &si = *problem.getSpaceInformation();
    Patch patch;
    auto clash = headOnSwap(problem);
    clash.starts[1] = {clash.starts[0][0] - 0.5, clash.starts[0][1]};  // local starts overlap
    EXPECT_FALSE(CompositeRRTConnectSolver().solve(si, clash, ob::timedPlannerTerminationCondition(5.), 1, patch));

    auto capped = headOnSwap(problem);
    capped.sampleCap = 1;  // one iteration cannot connect a blocked head-on swap
    EXPECT_FALSE(CompositeRRTConnectSolver().solve(si, capped, ob::timedPlannerTerminationCondition(5.), 1, patch));

    // An impossible subproblem (robot 1 boxed into a strip that robot 0 blocks) within a 10 ms limit.
    auto boxed = headOnSwap(problem);
    for (std::size_t k = 0; k < 2; ++k)
    {
        ob::RealVectorBounds b(2);
        b.setLow(0, -10.);
        b.setHigh(0, 10.);
        b.setLow(1, -2.6);
        b.setHigh(1, -2.4);
        boxed.bounds.push_back(b);
    }
    const auto start = ompl::time::now();
    EXPECT_FALSE(CompositeRRTConnectSolver().solve(si, boxed, ob::timedPlannerTerminationCondition(0.01), 1, patch));
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.01 + test::promptReturn());

    auto malformed = headOnSwap(problem);
    malformed.robots = {1, 0};
    EXPECT_FALSE(CompositeRRTConnectSolver().solve(si, malformed, ob::timedPlannerTerminationCondition(1.), 1, patch));
}
