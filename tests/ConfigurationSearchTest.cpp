#include "ompl_parc/mapf/ConfigurationSearch.h"

#include <gtest/gtest.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_int_distribution.hpp>

#include <algorithm>
#include <cmath>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** A width x height grid of step 1 whose free points \e free says. */
    LatticeGraph grid(int width, int height, const std::function<bool(int, int)> &free)
    {
        return LatticeGraph(
            {0., 0.}, {width - 1., height - 1.}, {0., 0.}, 1.,
            [&](const double *q)
            { return free(static_cast<int>(std::lround(q[0])), static_cast<int>(std::lround(q[1]))); },
            [](const double *, const double *) { return true; }, 10000);
    }

    LatticeGraph::Vertex at(const LatticeGraph &graph, int x, int y)
    {
        const double q[2] = {static_cast<double>(x), static_cast<double>(y)};
        const auto found = graph.near(q, 1e-9);
        return found.empty() ? LatticeGraph::NONE : found.front();
    }

    /** Every step of \e steps keeps the rules, and the steps go from \e starts to \e goals. */
    void expectValidSolution(const LatticeGraph &graph, const std::vector<ConfigurationSearch::Configuration> &steps,
                             const ConfigurationSearch::Configuration &starts,
                             const ConfigurationSearch::Configuration &goals)
    {
        ASSERT_FALSE(steps.empty());
        EXPECT_EQ(steps.front(), starts);
        EXPECT_EQ(steps.back(), goals);
        std::vector<unsigned int> levels;
        for (std::size_t s = 1; s < steps.size(); ++s)
            EXPECT_TRUE(ConfigurationSearch::followLevels(graph, steps[s - 1], steps[s], levels)) << "step " << s;
    }
}  // namespace

TEST(ConfigurationSearch, FollowLevelsKeepsTheRulesOfAStep)
{
    const auto graph = grid(3, 3, [](int, int) { return true; });
    const auto v = [&](int x, int y) { return at(graph, x, y); };
    std::vector<unsigned int> levels;
    // A swap, two robots on one vertex, a jump and a rotation around a square are refused.
    EXPECT_FALSE(ConfigurationSearch::followLevels(graph, {v(0, 0), v(1, 0)}, {v(1, 0), v(0, 0)}, levels));
    EXPECT_FALSE(ConfigurationSearch::followLevels(graph, {v(0, 0), v(2, 0)}, {v(1, 0), v(1, 0)}, levels));
    EXPECT_FALSE(ConfigurationSearch::followLevels(graph, {v(0, 0)}, {v(2, 0)}, levels));
    EXPECT_FALSE(ConfigurationSearch::followLevels(graph, {v(0, 0), v(1, 0), v(1, 1), v(0, 1)},
                                                   {v(1, 0), v(1, 1), v(0, 1), v(0, 0)}, levels));
    // A straight train moves at once; a robot entering at right angles the vertex another leaves goes after it,
    // and one following it straight goes with it.
    ASSERT_TRUE(
        ConfigurationSearch::followLevels(graph, {v(0, 0), v(1, 0), v(2, 0)}, {v(1, 0), v(2, 0), v(2, 1)}, levels));
    EXPECT_EQ(levels, (std::vector<unsigned int>{1, 1, 0}));
    ASSERT_TRUE(
        ConfigurationSearch::followLevels(graph, {v(0, 0), v(1, 0), v(2, 2)}, {v(1, 0), v(2, 0), v(2, 2)}, levels));
    EXPECT_EQ(levels, (std::vector<unsigned int>{0, 0, 0}));
}

TEST(ConfigurationSearch, SwapsTwoRobotsInACorridorThroughItsOnlyPocket)
{
    // A corridor 7 long with one pocket above its middle: the robots at its ends swap, so one must wait in the pocket.
    const auto graph = grid(7, 2, [](int x, int y) { return y == 0 || x == 3; });
    const ConfigurationSearch::Configuration starts = {at(graph, 0, 0), at(graph, 6, 0)},
                                             goals = {at(graph, 6, 0), at(graph, 0, 0)};
    ConfigurationSearch search(graph);
    const auto steps = search.solve(starts, goals, ob::timedPlannerTerminationCondition(30.), 1);
    expectValidSolution(graph, steps, starts, goals);
    EXPECT_TRUE(std::any_of(steps.begin(), steps.end(),
                            [&](const auto &q) { return q[0] == at(graph, 3, 1) || q[1] == at(graph, 3, 1); }));
}

TEST(ConfigurationSearch, SolvesDenseRandomPermutations)
{
    // 20 robots on a 5 x 5 grid to a random permutation of their places, for several seeds: dense enough that
    // most robots must be pushed aside on the way.
    const auto graph = grid(5, 5, [](int, int) { return true; });
    for (std::uint32_t seed = 1; seed <= 10; ++seed)
    {
        boost::random::mt19937 rng(seed);
        std::vector<LatticeGraph::Vertex> cells(graph.size());
        std::iota(cells.begin(), cells.end(), 0);
        for (std::size_t i = cells.size(); i > 1; --i)
            std::swap(cells[i - 1], cells[boost::random::uniform_int_distribution<std::size_t>(0, i - 1)(rng)]);
        const ConfigurationSearch::Configuration starts(cells.begin(), cells.begin() + 20);
        ConfigurationSearch::Configuration goals = starts;
        for (std::size_t i = goals.size(); i > 1; --i)
            std::swap(goals[i - 1], goals[boost::random::uniform_int_distribution<std::size_t>(0, i - 1)(rng)]);
        ConfigurationSearch search(graph);
        const auto steps = search.solve(starts, goals, ob::timedPlannerTerminationCondition(30.), seed);
        expectValidSolution(graph, steps, starts, goals);
    }
}

TEST(ConfigurationSearch, ReturnsNothingForAnUnreachableGoalOrOnceStopped)
{
    // Two separate rooms: a robot cannot reach the other one.
    const auto graph = grid(5, 1, [](int x, int) { return x != 2; });
    ConfigurationSearch search(graph);
    EXPECT_TRUE(
        search.solve({at(graph, 0, 0)}, {at(graph, 4, 0)}, ob::timedPlannerTerminationCondition(30.), 1).empty());
    // A corridor where two robots can never pass each other: the search runs out of configurations and says so.
    const auto corridor = grid(5, 1, [](int, int) { return true; });
    ConfigurationSearch closed(corridor);
    EXPECT_TRUE(closed
                    .solve({at(corridor, 0, 0), at(corridor, 4, 0)}, {at(corridor, 4, 0), at(corridor, 0, 0)},
                           ob::timedPlannerTerminationCondition(30.), 1)
                    .empty());
    EXPECT_GT(closed.getNodeCount(), 0u);
    // Stopped before it starts.
    const auto open = grid(5, 5, [](int, int) { return true; });
    ConfigurationSearch stopped(open);
    EXPECT_TRUE(
        stopped.solve({at(open, 0, 0)}, {at(open, 4, 4)}, ob::PlannerTerminationCondition([] { return true; }), 1)
            .empty());
}

TEST(ConfigurationSearch, GivesUpAtItsMemoryCap)
{
    // The corridor two robots can never pass each other in, so the search would try every configuration: with room
    // for a handful of entries it stops at once, and says so by its node count.
    const auto corridor = grid(9, 1, [](int, int) { return true; });
    ConfigurationSearch search(corridor);
    search.setMaxEntries(16);
    EXPECT_TRUE(search
                    .solve({at(corridor, 0, 0), at(corridor, 8, 0)}, {at(corridor, 8, 0), at(corridor, 0, 0)},
                           ob::timedPlannerTerminationCondition(30.), 1)
                    .empty());
    EXPECT_LE(search.getNodeCount(), 8u);
    ConfigurationSearch unbounded(corridor);
    EXPECT_TRUE(unbounded
                    .solve({at(corridor, 0, 0), at(corridor, 8, 0)}, {at(corridor, 8, 0), at(corridor, 0, 0)},
                           ob::timedPlannerTerminationCondition(30.), 1)
                    .empty());
    EXPECT_GT(unbounded.getNodeCount(), search.getNodeCount());
}
