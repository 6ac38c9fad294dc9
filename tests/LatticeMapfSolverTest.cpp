#include "TestProblems.h"

#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/subproblem/LatticeMapfSolver.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/util/Time.h>

using namespace ompl_parc;
using ompl_parc::test::validatePatch;
using ompl_parc::test::wholeProblem;
namespace ob = ompl::base;

TEST(LatticeMapfSolver, SolvesDenseCrossingsWhole)
{
    // 48 robots in a crossing of corridors two or three robots wide, 12 leaving and 12 entering each arm: what
    // prioritised planning and composite RRT-Connect both fail on (docs/results.md).
    for (std::uint32_t instance = 0; instance < 5; ++instance)
    {
        const auto problem = scenarios::generateFamilyInstance("crossing", 48, instance);
        const auto sub = wholeProblem(problem);
        Patch patch;
        ASSERT_TRUE(LatticeMapfSolver().solve(*problem.getSpaceInformation(), sub,
                                              ob::timedPlannerTerminationCondition(60.), instance + 1, patch))
            << "instance " << instance;
        ASSERT_EQ(patch.paths.size(), 48u);
        const auto report = validatePatch(problem, sub, patch);
        EXPECT_TRUE(report.valid) << "instance " << instance << ": " << report.message;
    }
}

TEST(LatticeMapfSolver, AWideSearchCutByItsTimeLeavesTheRestToTheTightLattice)
{
    // With no time for the wide lattice's search, the tight lattice plans the crossing of 48: valid, and slower
    // (its turns wait sub-steps), which shows the tight one made it.
    const auto problem = scenarios::generateFamilyInstance("crossing", 48, 0);
    const auto sub = wholeProblem(problem);
    const auto &si = *problem.getSpaceInformation();
    Patch wide, tight;
    ASSERT_TRUE(LatticeMapfSolver().solve(si, sub, ob::timedPlannerTerminationCondition(60.), 1, wide));
    ASSERT_TRUE(LatticeMapfSolver(std::size_t(1) << 18, 0.).solve(si, sub, ob::timedPlannerTerminationCondition(60.),
                                                                   1, tight));
    EXPECT_TRUE(validatePatch(problem, sub, tight).valid);
    EXPECT_GT(tight.getDuration(), wide.getDuration());
}

TEST(LatticeMapfSolver, SameSeedSamePatchAndAWindowKeepsToItsEnds)
{
    const auto problem = scenarios::generateFamilyInstance("rooms", 8, 2);
    auto sub = wholeProblem(problem);
    sub.robots.resize(4);
    sub.starts.resize(4);
    sub.goals.resize(4);
    const auto &si = *problem.getSpaceInformation();
    Patch a, b;
    ASSERT_TRUE(LatticeMapfSolver().solve(si, sub, ob::timedPlannerTerminationCondition(60.), 5, a));
    ASSERT_TRUE(LatticeMapfSolver().solve(si, sub, ob::timedPlannerTerminationCondition(60.), 5, b));
    EXPECT_EQ(a.paths, b.paths);
    for (std::size_t k = 0; k < 4; ++k)
    {
        std::vector<double> q(2);
        a.paths[k].getConfig(0, q.data());
        EXPECT_EQ(q, sub.starts[k]);
        a.paths[k].getConfig(a.getDuration(), q.data());
        EXPECT_EQ(q, sub.goals[k]);
    }
    const auto report = validatePatch(problem, sub, a);
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(LatticeMapfSolver, DeclinesArmsAndLatticesTooLarge)
{
    const auto arms = scenarios::generateFamilyInstance("planar_cell", 4, 0);
    EXPECT_FALSE(LatticeMapfSolver().appliesTo(*arms.getSpaceInformation(), {0, 1, 2, 3}));
    Patch patch;
    EXPECT_FALSE(LatticeMapfSolver().solve(*arms.getSpaceInformation(), wholeProblem(arms),
                                           ob::timedPlannerTerminationCondition(60.), 1, patch));
    const auto discs = scenarios::generateFamilyInstance("crossing", 8, 0);
    EXPECT_TRUE(LatticeMapfSolver().appliesTo(*discs.getSpaceInformation(), {0, 1}));
    EXPECT_FALSE(LatticeMapfSolver(10).solve(*discs.getSpaceInformation(), wholeProblem(discs),
                                             ob::timedPlannerTerminationCondition(60.), 1, patch));
}

TEST(LatticeMapfSolver, ArcSolvesTheCrossingOf48Robots)
{
    // ARC with its default solvers (composite RRT-Connect, this solver, prioritised ST-RRT): 3 of the family suite's
    // 20 instances solved in 30 s without this solver, all 20 with it (median 1.9 s; this one 0.6 s,
    // docs/results.md); the limit is far above that.
    const auto problem = scenarios::generateFamilyInstance("crossing", 48, 2);
    ARC planner(problem.getSpaceInformation());
    planner.setSeed(1);
    ASSERT_EQ(test::solveWith(planner, problem, 120.), ob::PlannerStatus::EXACT_SOLUTION);
    const auto report = SolutionValidator(problem).validate(planner.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(ParcLatticeMapf, TwoWorkersRepairWithTheSolverConcurrently)
{
    // P-ARC-2 on a crossing of 24 robots: 30 of its repairs come from this solver (seed 1), two at a time in a batch;
    // named for the ThreadSanitizer pass (scripts/test.sh runs the "Parc" tests under it).
    const auto problem = scenarios::generateFamilyInstance("crossing", 24, 1);
    PARC planner(problem.getSpaceInformation());
    planner.setWorkers(2);
    planner.setSeed(1);
    ASSERT_EQ(test::solveWith(planner, problem, 120.), ob::PlannerStatus::EXACT_SOLUTION);
    const auto report = SolutionValidator(problem).validate(planner.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
    const auto wins = planner.getStatistics().solverWins;
    ASSERT_EQ(wins.count("lattice-mapf"), 1u);
    EXPECT_GT(wins.at("lattice-mapf"), 0u);
}

TEST(LatticeMapfSolver, ReturnsPromptlyWhenStopped)
{
    // Mobile Cross 128 as one subproblem, which the solver takes some 9 s to solve: its lattice of 200 000 points
    // (built in 0.13 s), 128 hop tables, the search, the checks and the shortening of a long team path (6 s of OMPL's
    // simplifier, which takes no stop). Stopped in each of these, it returns within the project's prompt-return bound
    // (before the lattice polled the stop it returned 0.12 s late, before the hop tables did 0.4 s, before the
    // simplifier ran under a StopSignal scope 6 s).
    const auto problem = scenarios::createMobileCross(128);
    const auto sub = wholeProblem(problem);
    for (const double limit : {0., 0.01, 0.3, 1., 3.})
    {
        Patch patch;
        const auto start = ompl::time::now();
        const bool solved = LatticeMapfSolver().solve(*problem.getSpaceInformation(), sub,
                                                      ob::timedPlannerTerminationCondition(limit), 1, patch);
        const double seconds = ompl::time::seconds(ompl::time::now() - start);
        EXPECT_FALSE(solved);
        EXPECT_LT(seconds, limit + test::promptReturn()) << seconds;
    }
}

TEST(LatticeMapfSolver, OffLeavesCompositeAndPrioritizedAlone)
{
    // P-ARC-2 on a crossing of 16 robots, whose run with the solver takes 17 of its repairs from it (seed 1), without
    // it (lattice_mapf=0): solved by composite RRT-Connect and PP-ST-RRT alone (0.8 s), none of its repairs this
    // solver's.
    const auto problem = scenarios::generateFamilyInstance("crossing", 16, 1);
    PARC planner(problem.getSpaceInformation());
    planner.setWorkers(2);
    planner.setSeed(1);
    planner.setLatticeMapf(false);
    ASSERT_EQ(test::solveWith(planner, problem, 120.), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(SolutionValidator(problem).validate(planner.getPlan()).valid);
    EXPECT_EQ(planner.getStatistics().solverWins.count("lattice-mapf"), 0u);
    EXPECT_GT(planner.getStatistics().solverWins.count("composite-rrtc"), 0u);
}
