#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollidingPairSweep.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>

using namespace ompl_parc;

namespace
{
    /** The first colliding pair in (i, j) order by testing every pair: what the sweep must find. */
    std::optional<std::pair<std::size_t, std::size_t>> firstByEveryPair(const std::vector<CollisionBody> &bodies)
    {
        for (std::size_t i = 0; i < bodies.size(); ++i)
            for (std::size_t j = i + 1; j < bodies.size(); ++j)
                if (bodiesCollide(bodies[i], bodies[j]))
                    return std::make_pair(i, j);
        return std::nullopt;
    }
}  // namespace

/* Crowds of discs (2D), planar arms and Pandas (3D) at random places in a shrinking room, from sparse to crowded:
   the sweep finds the first colliding pair, and whether any, exactly as testing every pair does. One sweep object
   serves all rounds and all teams (its buffers are reused). */
TEST(CollidingPairSweep, FindsWhatTestingEveryPairFinds)
{
    std::mt19937 rng(11);
    CollidingPairSweep sweep;
    for (const auto &[scenario, robots] : std::vector<std::pair<const char *, std::size_t>>{
             {"mobile_circle", 300}, {"mobile_cross", 64}, {"planar_cross", 32}, {"panda_cage", 16}})
    {
        const auto problem = scenarios::createScenario(scenario, robots);
        const auto &si = *problem.getSpaceInformation();
        std::vector<CollisionBody> bodies(si.getRobotCount());
        int collided = 0;
        for (int k = 0; k < 40; ++k)
        {
            for (std::size_t i = 0; i < si.getRobotCount(); ++i)
            {
                const auto &bounds = si.getRobot(i)->getBounds();
                std::vector<double> q;
                for (std::size_t d = 0; d < bounds.low.size(); ++d)
                {
                    const double middle = 0.5 * (bounds.low[d] + bounds.high[d]),
                                 half = 0.5 * (bounds.high[d] - bounds.low[d]) * (1. - k / 50.);
                    q.push_back(std::uniform_real_distribution<double>(middle - half, middle + half)(rng));
                }
                si.getRobot(i)->computeBody(q.data(), bodies[i]);
            }
            const auto expected = firstByEveryPair(bodies);
            EXPECT_EQ(sweep.first(bodies), expected) << scenario << " round " << k;
            EXPECT_EQ(sweep.any(bodies), expected.has_value()) << scenario << " round " << k;
            collided += expected ? 1 : 0;
        }
        EXPECT_GE(collided, 3) << scenario;
    }
}

/* Discs touching (2 radii apart along an axis, at random coordinates, so that the boxes' ends round either way):
   whatever bodiesCollide says of such a pair, the sweep's box comparison must not round it away; a hair further
   apart, none collides. */
TEST(CollidingPairSweep, TouchingDiscsAreNotRoundedAway)
{
    const auto problem = scenarios::createScenario("mobile_circle", 4);
    const auto &si = *problem.getSpaceInformation();
    const double diameter = 2. * dynamic_cast<const DiscRobot &>(*si.getRobot(0)).getRadius();
    CollidingPairSweep sweep;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> coordinate(-50., 50.);
    for (int round = 0; round < 2000; ++round)
        for (int axis = 0; axis < 2; ++axis)
        {
            const double base = coordinate(rng);
            std::vector<CollisionBody> bodies(3);
            const double far[2] = {base + 40., base - 40.};
            si.getRobot(0)->computeBody(far, bodies[0]);
            for (const double gap : {0., 1e-6})
            {
                double a[2] = {base, base}, b[2] = {base, base};
                b[axis] += diameter + gap;
                si.getRobot(1)->computeBody(a, bodies[1]);
                si.getRobot(2)->computeBody(b, bodies[2]);
                const auto expected = firstByEveryPair(bodies);
                EXPECT_EQ(sweep.first(bodies), expected) << base << " " << axis << " " << gap;
                EXPECT_EQ(sweep.any(bodies), expected.has_value()) << base << " " << axis << " " << gap;
                if (gap > 0.)
                    EXPECT_FALSE(expected.has_value());
            }
        }
}
