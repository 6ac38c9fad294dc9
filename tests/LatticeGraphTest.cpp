#include "ompl_parc/mapf/LatticeGraph.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

using namespace ompl_parc;

namespace
{
    /** The lattice of step 1 on [0, 4] x [0, 2] without the point (2, 1): a 5 x 3 grid with a hole in the middle. */
    LatticeGraph gridWithHole(std::size_t maxPoints = 100)
    {
        return LatticeGraph(
            {0., 0.}, {4., 2.}, {0., 0.}, 1., [](const double *q) { return !(q[0] == 2. && q[1] == 1.); },
            [](const double *, const double *) { return true; }, maxPoints);
    }

    LatticeGraph::Vertex at(const LatticeGraph &graph, double x, double y)
    {
        const double q[2] = {x, y};
        const auto found = graph.near(q, 1e-9);
        return found.empty() ? LatticeGraph::NONE : found.front();
    }
}  // namespace

TEST(LatticeGraph, KeepsTheFreePointsAndTheirAxisMoves)
{
    const auto graph = gridWithHole();
    EXPECT_EQ(LatticeGraph::countPoints({0., 0.}, {4., 2.}, {0., 0.}, 1.), 15u);
    ASSERT_EQ(graph.size(), 14u);
    EXPECT_EQ(at(graph, 2., 1.), LatticeGraph::NONE);
    const auto v = at(graph, 1., 1.);
    ASSERT_NE(v, LatticeGraph::NONE);
    const auto [first, last] = graph.getNeighbours(v);
    std::vector<LatticeGraph::Vertex> neighbours(first, last);
    std::sort(neighbours.begin(), neighbours.end());
    std::vector<LatticeGraph::Vertex> expected = {at(graph, 0., 1.), at(graph, 1., 0.), at(graph, 1., 2.)};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(neighbours, expected);
    // A move the check refuses is no edge.
    const LatticeGraph walled(
        {0., 0.}, {2., 0.}, {0., 0.}, 1., [](const double *) { return true; },
        [](const double *a, const double *b) { return std::max(a[0], b[0]) < 1.5; }, 10);
    EXPECT_EQ(walled.getNeighbours(2).first, walled.getNeighbours(2).second);
}

TEST(LatticeGraph, NearFindsTheClosestPointsFirstAndHopsGoAroundTheHole)
{
    const auto graph = gridWithHole();
    const double q[2] = {1.2, 0.9};
    const auto found = graph.near(q, 1.01);
    ASSERT_GE(found.size(), 2u);
    EXPECT_EQ(found[0], at(graph, 1., 1.));
    for (const auto v : found)
        EXPECT_LE(std::hypot(graph.getPoint(v)[0] - q[0], graph.getPoint(v)[1] - q[1]), 1.01);
    std::vector<std::uint32_t> hops;
    graph.hopsTo(at(graph, 3., 1.), hops);
    EXPECT_EQ(hops[at(graph, 1., 1.)], 4u);  // around the hole, not 2 through it
    EXPECT_EQ(hops[at(graph, 4., 2.)], 2u);
    EXPECT_TRUE(graph.straight(at(graph, 0., 0.), at(graph, 1., 0.), at(graph, 2., 0.)));
    EXPECT_FALSE(graph.straight(at(graph, 0., 0.), at(graph, 1., 0.), at(graph, 1., 1.)));
}

TEST(LatticeGraph, RefusesBadStepsBoundsAndTooLargeBoxes)
{
    const auto yes = [](const double *) { return true; };
    const auto move = [](const double *, const double *) { return true; };
    EXPECT_THROW(LatticeGraph({0.}, {1.}, {0.}, 0., yes, move, 10), ompl::Exception);
    EXPECT_THROW(LatticeGraph({0.}, {1.}, {0.}, std::nan(""), yes, move, 10), ompl::Exception);
    EXPECT_THROW(LatticeGraph({0., 0.}, {1.}, {0., 0.}, 1., yes, move, 10), ompl::Exception);
    EXPECT_THROW(LatticeGraph({0., 0., 0., 0.}, {1., 1., 1., 1.}, {0., 0., 0., 0.}, 1., yes, move, 100),
                 ompl::Exception);
    EXPECT_THROW(gridWithHole(14), ompl::Exception);
    EXPECT_EQ(LatticeGraph::countPoints({0.}, {1e300}, {0.}, 1e-300), std::numeric_limits<std::size_t>::max());
}
