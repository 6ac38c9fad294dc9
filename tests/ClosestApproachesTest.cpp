#include "TestProblems.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/ClosestApproaches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>
#include <random>

using namespace ompl_parc;

/* Two discs of radius 0.5 pass each other on parallel lines 1.5 apart: their closest approach is 0.5, where their
   x coordinates meet, and its points lie on their surfaces, facing each other. */
TEST(ClosestApproaches, TwoDiscsPassingFindTheirGapAndWhereItIs)
{
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {5., 1.5}, {-5., 1.5});
    const auto plan = test::straightLinePlan(problem);
    std::vector<std::size_t> all(plan.getMakespan() + 1);
    std::iota(all.begin(), all.end(), 0);
    const auto closest = ClosestApproaches::find(*problem.getSpaceInformation(), plan, all, 3);
    ASSERT_EQ(closest.size(), 1u);  // one pair
    EXPECT_EQ(closest[0].first, 0u);
    EXPECT_EQ(closest[0].second, 1u);
    EXPECT_NEAR(closest[0].clearance, 0.5, 1e-6);
    const auto q0 = test::config(plan, 0, closest[0].timestep), q1 = test::config(plan, 1, closest[0].timestep);
    EXPECT_NEAR(q0[0], q1[0], 2. / plan.getResolution());
    EXPECT_NEAR(closest[0].points[0][1], 0.5, 1e-6);  // disc a's top
    EXPECT_NEAR(closest[0].points[1][1], 1.0, 1e-6);  // disc b's bottom
    EXPECT_TRUE(ClosestApproaches::find(*problem.getSpaceInformation(), plan, all, 0).empty());
}

/* The pruned search returns exactly what checking every pair at every timestep gives: random walks of 12 discs. */
TEST(ClosestApproaches, PruningChangesNothing)
{
    std::mt19937 rng(7);
    const auto problem = scenarios::createMobileCircle(12);
    const auto &team = problem.getSpaceInformation();
    for (int round = 0; round < 3; ++round)
    {
        const auto plan = test::randomWalkPlan(*team, rng, 5. / 128.);
        std::vector<std::size_t> times;
        for (std::size_t t = 0; t <= plan.getMakespan(); t += 3)
            times.push_back(t);
        std::map<std::pair<std::size_t, std::size_t>, double> best;
        CollisionBody a, b;
        for (std::size_t t : times)
            for (std::size_t i = 0; i < 12; ++i)
                for (std::size_t j = i + 1; j < 12; ++j)
                {
                    team->getRobot(i)->computeBody(test::config(plan, i, t).data(), a);
                    team->getRobot(j)->computeBody(test::config(plan, j, t).data(), b);
                    const double c = std::sqrt(segmentDistanceSquared(a, 0, b, 0)) - a.radius_[0] - b.radius_[0];
                    auto &entry = best.try_emplace({i, j}, c).first->second;
                    entry = std::min(entry, c);
                }
        std::vector<double> sorted;
        for (const auto &[pair, c] : best)
            sorted.push_back(c);
        std::sort(sorted.begin(), sorted.end());
        const auto closest = ClosestApproaches::find(*team, plan, times, 5);
        ASSERT_EQ(closest.size(), 5u);
        for (std::size_t k = 0; k < 5; ++k)
        {
            EXPECT_NEAR(closest[k].clearance, sorted[k], 1e-9) << "round " << round << ", pair " << k;
            EXPECT_NEAR(closest[k].clearance, best.at({closest[k].first, closest[k].second}), 1e-9);
        }
    }
}

/* Closest points of segments: crossing skew lines, parallel overlapping ones, and a point against a segment. */
TEST(ClosestApproaches, ClosestPointsOfSegments)
{
    auto p = ClosestApproaches::closestPoints({-1., 0., 0.}, {1., 0., 0.}, {0., -1., 1.}, {0., 1., 1.});
    EXPECT_NEAR(p[0][0], 0., 1e-12);
    EXPECT_NEAR(p[1][2], 1., 1e-12);
    EXPECT_NEAR(p[1][1], 0., 1e-12);
    p = ClosestApproaches::closestPoints({0., 0., 0.}, {0., 0., 0.}, {2., -1., 0.}, {2., 1., 0.});
    EXPECT_NEAR(p[1][0], 2., 1e-12);
    EXPECT_NEAR(p[1][1], 0., 1e-12);
    p = ClosestApproaches::closestPoints({0., 0., 0.}, {1., 0., 0.}, {3., 1., 0.}, {5., 1., 0.});
    EXPECT_NEAR(p[0][0], 1., 1e-12);
    EXPECT_NEAR(p[1][0], 3., 1e-12);
}
