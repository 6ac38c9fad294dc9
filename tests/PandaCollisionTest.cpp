#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfFclModel.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace ompl_parc;

TEST(PandaCollision, CapsuleModelFlagsEveryPairFclFindsInCollision)
{
    // Two Pandas facing each other 0.6 apart, the second one hanging from a ceiling 1.2 up: random
    // configurations give a mix of far, near and deeply interpenetrating pairs.
    const auto load = [](const Eigen::Isometry3d &base)
    { return std::make_shared<UrdfArm>("panda", nullptr, models::pandaUrdf(), "panda_link0", "panda_link8", base); };
    const auto a = load(Eigen::Isometry3d::Identity());
    const auto b = load(UrdfArm::pose(0.6, 0., 1.2, M_PI, 0., M_PI));
    UrdfFclModel exactA(a), exactB(b);
    std::mt19937 rng(11);
    const auto sample = [&rng](const Robot &robot)
    {
        std::vector<double> q(robot.getDimension());
        for (unsigned int k = 0; k < robot.getDimension(); ++k)
            q[k] = std::uniform_real_distribution<double>(robot.getBounds().low[k], robot.getBounds().high[k])(rng);
        return q;
    };
    constexpr int PAIRS = 100000;
    int exactHits = 0, ourHits = 0, missed = 0, disagreements = 0;
    CollisionBody bodyA, bodyB;
    for (int k = 0; k < PAIRS; ++k)
    {
        const auto qa = sample(*a), qb = sample(*b);
        exactA.setConfig(qa.data());
        exactB.setConfig(qb.data());
        a->computeBody(qa.data(), bodyA);
        b->computeBody(qb.data(), bodyB);
        const bool exact = exactA.collides(exactB), ours = bodiesCollide(bodyA, bodyB);
        exactHits += exact ? 1 : 0;
        ourHits += ours ? 1 : 0;
        missed += exact && !ours ? 1 : 0;
        // The pair kernel (boxes, then exact distances) against the plain test of every capsule pair.
        bool pairwise = false;
        for (std::size_t i = 0; i < bodyA.size() && !pairwise; ++i)
            for (std::size_t j = 0; j < bodyB.size() && !pairwise; ++j)
                pairwise = capsulesCollide(bodyA, i, bodyB, j);
        disagreements += pairwise != ours ? 1 : 0;
    }
    EXPECT_EQ(missed, 0);
    EXPECT_EQ(disagreements, 0);
    EXPECT_GT(exactHits, PAIRS / 20);  // the test must exercise collisions
    std::printf(
        "[ info ] %d pairs: FCL %d in collision, capsules %d; false positives %.2f%% of all pairs, "
        "%.2f%% of flagged ones\n",
        PAIRS, exactHits, ourHits, 100. * (ourHits - exactHits) / PAIRS,
        100. * (ourHits - exactHits) / std::max(ourHits, 1));
}
