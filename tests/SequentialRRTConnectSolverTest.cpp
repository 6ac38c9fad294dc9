#include "TestProblems.h"

#include "ompl_parc/planners/subproblem/CompositeRRTConnectSolver.h"
#include "ompl_parc/planners/subproblem/SequentialRRTConnectSolver.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"

#include <gtest/gtest.h>
#include <ompl/util/Time.h>

#include <memory>
#include <thread>

using namespace ompl_parc;
using ompl_parc::test::validatePatch;
using ompl_parc::test::wholeProblem;
namespace ob = ompl::base;

namespace
{
    /** Pandas 4 to 7 of the Panda cell of 16, instance 2: four arms half a metre apart on one side of the cage,
        whose workspaces overlap. ARC's composite RRT-Connect does not solve their global problem in 30 s, nor
        does PP-ST-RRT or coupled RRT-Connect on the four alone; 2 of the 24 orders of single-arm moves work. */
    Subproblem pandaRow(const MultiRobotProblem &problem)
    {
        Subproblem whole = wholeProblem(problem), sub;
        for (std::size_t r = 4; r < 8; ++r)
        {
            sub.robots.push_back(whole.robots[r]);
            sub.starts.push_back(whole.starts[r]);
            sub.goals.push_back(whole.goals[r]);
        }
        sub.global = true;
        return sub;
    }

    void expectEndsKept(const Subproblem &sub, const Patch &patch)
    {
        for (std::size_t k = 0; k < sub.robots.size(); ++k)
        {
            std::vector<double> q(sub.starts[k].size());
            patch.paths[k].getConfig(0, q.data());
            EXPECT_EQ(q, sub.starts[k]);
            patch.paths[k].getConfig(patch.getDuration(), q.data());
            EXPECT_EQ(q, sub.goals[k]);
        }
    }
}  // namespace

TEST(SequentialRRTConnectSolver, MovesFourOverlappingPandasOneAtATime)
{
    const auto problem = scenarios::generateFamilyInstance("panda_cell", 16, 2);
    const auto sub = pandaRow(problem);
    for (const std::uint_fast32_t seed : {1u, 2u})
    {
        Patch patch;
        ASSERT_TRUE(SequentialRRTConnectSolver().solve(*problem.getSpaceInformation(), sub,
                                                       ob::timedPlannerTerminationCondition(120.), seed, patch))
            << "seed " << seed;
        ASSERT_EQ(patch.paths.size(), 4u);
        expectEndsKept(sub, patch);
        const auto report = validatePatch(problem, sub, patch);
        EXPECT_TRUE(report.valid) << "seed " << seed << ": " << report.message;
    }
}

TEST(SequentialRRTConnectSolver, SameSeedSamePatchAndShortenedPatchesValid)
{
    const auto problem = scenarios::generateFamilyInstance("panda_cell", 16, 2);
    const auto sub = pandaRow(problem);
    const auto &si = *problem.getSpaceInformation();
    Patch a, b, shortened;
    ASSERT_TRUE(SequentialRRTConnectSolver().solve(si, sub, ob::timedPlannerTerminationCondition(120.), 3, a));
    ASSERT_TRUE(SequentialRRTConnectSolver().solve(si, sub, ob::timedPlannerTerminationCondition(120.), 3, b));
    EXPECT_EQ(a.paths, b.paths);
    ASSERT_TRUE(
        SequentialRRTConnectSolver(true).solve(si, sub, ob::timedPlannerTerminationCondition(120.), 3, shortened));
    // The same moves, shortened on the team's space: robots move together again, the patch is shorter.
    EXPECT_LT(shortened.getDuration(), a.getDuration());
    expectEndsKept(sub, shortened);
    const auto report = validatePatch(problem, sub, shortened);
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(SequentialRRTConnectSolver, ResumesWhereACutCallStopped)
{
    // Calls of 3000 condition checks each (a few hundred iterations of one move): the search goes on with its
    // moves' trees, its round and the sets found dead, and ends solved, as ARC's global rounds would.
    const auto problem = scenarios::generateFamilyInstance("panda_cell", 16, 2);
    const auto sub = pandaRow(problem);
    const SequentialRRTConnectSolver solver;
    const auto memory = solver.makeMemory();
    ASSERT_NE(memory, nullptr);
    Patch patch;
    unsigned int calls = 0;
    bool solved = false;
    while (!solved && calls < 10000)
    {
        auto checks = std::make_shared<unsigned int>(0);
        ++calls;
        solved = solver.resume(*problem.getSpaceInformation(), sub,
                               ob::PlannerTerminationCondition([checks] { return ++*checks > 3000; }), 7, patch,
                               memory.get());
    }
    ASSERT_TRUE(solved);
    EXPECT_GT(calls, 2u);
    expectEndsKept(sub, patch);
    const auto report = validatePatch(problem, sub, patch);
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(SequentialRRTConnectSolver, HonoursSampleCapAndStopAndDeclinesLargeTeams)
{
    const auto problem = scenarios::generateFamilyInstance("panda_cell", 16, 2);
    auto sub = pandaRow(problem);
    const auto &si = *problem.getSpaceInformation();
    for (const double limit : {0., 0.05, 0.3})
    {
        Patch patch;
        const auto start = ompl::time::now();
        SequentialRRTConnectSolver().solve(si, sub, ob::timedPlannerTerminationCondition(limit), 1, patch);
        EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), limit + test::promptReturn()) << limit;
    }
    // 300 iterations in all: the first round (256 per move) cannot finish the hard moves, and the search stops.
    sub.sampleCap = 300;
    Patch patch;
    EXPECT_FALSE(SequentialRRTConnectSolver().solve(si, sub, ob::timedPlannerTerminationCondition(120.), 1, patch));

    const auto everyone = wholeProblem(problem);  // 16 robots: the largest team it takes
    ASSERT_EQ(everyone.robots.size(), SequentialRRTConnectSolver::MAX_TEAM);
    const auto crowd = scenarios::generateFamilyInstance("field", 24, 0);
    const auto start = ompl::time::now();
    EXPECT_FALSE(SequentialRRTConnectSolver().solve(*crowd.getSpaceInformation(), wholeProblem(crowd),
                                                    ob::timedPlannerTerminationCondition(60.), 1, patch));
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.1);
}

TEST(ParcSequentialRRTConnect, TwoThreadsSolveOnOneTeamAsOneWould)
{
    // P-ARC's workers call the solver at once on one team's SpaceInformation and robots (run under TSan): each
    // thread's patch is the one a lone call with its seed gives. Pandas 5 and 6 of the same cell: a few milliseconds.
    const auto problem = scenarios::generateFamilyInstance("panda_cell", 16, 2);
    Subproblem sub = pandaRow(problem);
    sub.robots = {sub.robots[1], sub.robots[2]};
    sub.starts = {sub.starts[1], sub.starts[2]};
    sub.goals = {sub.goals[1], sub.goals[2]};
    const auto &si = *problem.getSpaceInformation();
    const SequentialRRTConnectSolver solver;
    Patch alone[2], together[2];
    bool solved[2] = {false, false};
    for (std::size_t k = 0; k < 2; ++k)
        ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(120.), 11 + k, alone[k]));
    std::thread other(
        [&] { solved[1] = solver.solve(si, sub, ob::timedPlannerTerminationCondition(120.), 12, together[1]); });
    solved[0] = solver.solve(si, sub, ob::timedPlannerTerminationCondition(120.), 11, together[0]);
    other.join();
    for (std::size_t k = 0; k < 2; ++k)
    {
        ASSERT_TRUE(solved[k]);
        EXPECT_EQ(together[k].paths, alone[k].paths);
        const auto report = validatePatch(problem, sub, together[k]);
        EXPECT_TRUE(report.valid) << report.message;
    }
}
