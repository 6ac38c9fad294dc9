#include "TestProblems.h"

#include "ompl_parc/planners/subproblem/MoveScheduler.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>

using namespace ompl_parc;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    using Configs = std::vector<std::vector<double>>;

    /** The two discs' straight moves, \e first's then the other's, given to a scheduler; \e path starts as the moves
        one after another. Returns whether the scheduler overlapped them. */
    bool scheduleMoves(const MultiRobotProblem &problem, std::size_t first, MoveScheduler &scheduler,
                       og::PathGeometric &path)
    {
        const auto &si = problem.getSpaceInformation();
        const Configs moveA{problem.getStart(0), problem.getGoal(0)}, moveB{problem.getStart(1), problem.getGoal(1)};
        std::vector<MoveScheduler::Move> moves{{0, &moveA}, {1, &moveB}};
        if (first == 1)
            std::swap(moves[0], moves[1]);
        ob::ScopedState<> at(si);
        for (std::size_t r = 0; r < 2; ++r)
            std::copy(problem.getStart(r).begin(), problem.getStart(r).end(), si->getRobotValues(at.get(), r));
        path = og::PathGeometric(si, at.get());
        for (const auto &[robot, states] : moves)
        {
            std::copy(states->back().begin(), states->back().end(), si->getRobotValues(at.get(), robot));
            path.append(at.get());
        }
        return scheduler.schedule(moves, path.getState(0), path);
    }

    /** The path laid on the grid as a plan of the problem's team (\e makespan: its makespan), checked by the
        independent validator. */
    ValidationReport validate(const MultiRobotProblem &problem, const og::PathGeometric &path, std::size_t &makespan)
    {
        const auto plan = MultiRobotPlan::fromPathGeometric(*problem.getSpaceInformation(), path);
        makespan = plan.getMakespan();
        return SolutionValidator(problem).validate(plan);
    }
}  // namespace

TEST(MoveScheduler, RunsTheMovesOfRobotsFarApartAtOnce)
{
    // Two discs on parallel lanes 10 apart, 16 long each: 128 timesteps per unit, so 2048 each.
    const auto problem = test::twoDiscs({-8., 5.}, {8., 5.}, {-8., -5.}, {8., -5.}, false, 128.);
    MoveScheduler scheduler(problem.getSpaceInformation());
    og::PathGeometric path(problem.getSpaceInformation());
    ASSERT_TRUE(scheduleMoves(problem, 0, scheduler, path));
    EXPECT_EQ(scheduler.getDuration(), 2048u);
    std::size_t makespan = 0;
    const auto report = validate(problem, path, makespan);
    EXPECT_TRUE(report.valid) << report.message;
    EXPECT_EQ(makespan, 2048u);
}

TEST(MoveScheduler, StartsACrossingMoveOnceTheWayIsClear)
{
    // Lanes that cross at the origin, 10 long each (1280 timesteps): started together the discs would meet there.
    // Either order: the second starts once the first is far enough past, before the first has arrived.
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {0., -5.}, {0., 5.}, false, 128.);
    for (std::size_t first : {0u, 1u})
    {
        MoveScheduler scheduler(problem.getSpaceInformation());
        og::PathGeometric path(problem.getSpaceInformation());
        ASSERT_TRUE(scheduleMoves(problem, first, scheduler, path)) << first;
        EXPECT_GT(scheduler.getDuration(), 1280u) << first;
        EXPECT_LT(scheduler.getDuration(), 2560u) << first;
        std::size_t makespan = 0;
        const auto report = validate(problem, path, makespan);
        EXPECT_TRUE(report.valid) << first << ": " << report.message;
        EXPECT_EQ(makespan, scheduler.getDuration()) << first;
    }
}

TEST(MoveScheduler, LeavesMovesThatCannotOverlapAsTheyAre)
{
    // The second disc's lane passes through the first's goal, where the first stays: no start of the second move
    // avoids it (before: they meet at the origin; after: the first stands there), and the path is left untouched.
    const auto problem = test::twoDiscs({-5., 0.}, {0., 0.}, {0., -5.}, {0., 5.}, false, 128.);
    MoveScheduler scheduler(problem.getSpaceInformation());
    og::PathGeometric path(problem.getSpaceInformation());
    EXPECT_FALSE(scheduleMoves(problem, 0, scheduler, path));
    EXPECT_EQ(path.getStateCount(), 3u);
    EXPECT_EQ(scheduler.getDuration(), 640u + 1280u);
}

TEST(MoveScheduler, LeavesMovesTooLongToKeepTheirBodiesAsTheyAre)
{
    // The parallel lanes of the first test at 20 000 timesteps per unit: 640 000 bodies, more than MAX_BODIES.
    const auto problem = test::twoDiscs({-8., 5.}, {8., 5.}, {-8., -5.}, {8., -5.}, false, 20000.);
    MoveScheduler scheduler(problem.getSpaceInformation());
    og::PathGeometric path(problem.getSpaceInformation());
    EXPECT_FALSE(scheduleMoves(problem, 0, scheduler, path));
    EXPECT_EQ(path.getStateCount(), 3u);
    EXPECT_GT(scheduler.getDuration(), MoveScheduler::MAX_BODIES);
}
