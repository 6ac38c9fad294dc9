#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfFclModel.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <regex>
#include <sstream>

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

namespace
{
    /** Our Panda with each collision primitive replaced by five spheres around its origin: a sphere model with
        several spheres per link, like the spherized Pandas users bring. */
    std::string spherePandaUrdf(bool withCylinders = false)
    {
        const std::string urdf = ompl_parc::models::pandaUrdf();
        const std::regex collision("<collision>[\\s\\S]*?</collision>"), origin("xyz=\"([^\"]*)\"");
        std::string out;
        auto last = urdf.cbegin();
        for (std::sregex_iterator it(urdf.begin(), urdf.end(), collision), end; it != end; ++it)
        {
            out.append(last, urdf.cbegin() + it->position());
            last = urdf.cbegin() + it->position() + it->length();
            std::smatch xyz;
            const std::string block = it->str();
            double x = 0., y = 0., z = 0.;
            if (std::regex_search(block, xyz, origin))
                std::istringstream(xyz[1].str()) >> x >> y >> z;
            for (int k = -2; k <= 2; ++k)
            {
                const std::string radius = std::to_string(0.04 + 0.005 * (k + 2));
                // withCylinders: one capsule per link among the spheres (a sphere model holding a rod)
                const std::string shape = withCylinders && k == 0
                                              ? "<cylinder radius=\"" + radius + "\" length=\"0.08\"/>"
                                              : "<sphere radius=\"" + radius + "\"/>";
                out += "<collision><origin xyz=\"" + std::to_string(x + 0.01 * k) + " " + std::to_string(y) + " " +
                       std::to_string(z + 0.04 * k) + "\"/><geometry>" + shape + "</geometry></collision>";
            }
        }
        out.append(last, urdf.cend());
        return out;
    }

    /** \e body's capsules in a body of its own without groups (boxes, as our Panda's). */
    ompl_parc::CollisionBody withoutGroups(const ompl_parc::CollisionBody &body)
    {
        ompl_parc::CollisionBody plain;
        for (std::size_t i = 0; i < body.size(); ++i)
            plain.addCapsule(body.ax_[i], body.ay_[i], body.az_[i], body.bx_[i], body.by_[i], body.bz_[i],
                             body.radius_[i]);
        plain.updateBound();
        return plain;
    }
}  // namespace

namespace
{
    /** Two Pandas of \e urdf in the facing layout above, their bodies with link groups and group bounds: every way
        of pairing them (groups, boxes, one of each, groups with boxes added) must answer as every capsule pair does.
        \e spheresOnly: whether the model's bodies are all spheres. */
    void expectGroupsGiveTheAnswersOfEveryPair(const std::string &urdf, bool spheresOnly)
    {
        const auto a = std::make_shared<UrdfArm>("panda", nullptr, urdf, "panda_link0", "panda_hand",
                                                 Eigen::Isometry3d::Identity());
        const auto b = std::make_shared<UrdfArm>("panda", nullptr, urdf, "panda_link0", "panda_hand",
                                                 UrdfArm::pose(0.6, 0., 1.2, M_PI, 0., M_PI));
        std::mt19937 rng(12);
        const auto sample = [&rng](const Robot &robot)
        {
            std::vector<double> q(robot.getDimension());
            for (unsigned int k = 0; k < robot.getDimension(); ++k)
                q[k] = std::uniform_real_distribution<double>(robot.getBounds().low[k], robot.getBounds().high[k])(rng);
            return q;
        };
        constexpr int PAIRS = 20000;
        int hits = 0, disagreements = 0;
        CollisionBody bodyA, bodyB;
        for (int k = 0; k < PAIRS; ++k)
        {
            a->computeBody(sample(*a).data(), bodyA);
            b->computeBody(sample(*b).data(), bodyB);
            ASSERT_TRUE(bodyA.hasGroupBounds());
            ASSERT_EQ(bodyA.spheresOnly_, spheresOnly);
            ASSERT_FALSE(bodyA.hasBoxes());
            ASSERT_GT(bodyA.size(), 2 * bodyA.groupCount());
            // The kinematics' group spheres (moved with their links) contain their capsules.
            std::size_t begin = 0;
            for (const CollisionBody::Group &group : bodyA.groups_)
            {
                for (std::size_t i = begin; i < group.end; ++i)
                {
                    const double dx = bodyA.ax_[i] - group.x, dy = bodyA.ay_[i] - group.y, dz = bodyA.az_[i] - group.z;
                    ASSERT_LE(std::sqrt(dx * dx + dy * dy + dz * dz) + bodyA.radius_[i], group.radius);
                }
                begin = group.end;
            }
            bool pairwise = false;
            for (std::size_t i = 0; i < bodyA.size() && !pairwise; ++i)
                for (std::size_t j = 0; j < bodyB.size() && !pairwise; ++j)
                    pairwise = capsulesCollide(bodyA, i, bodyB, j);
            hits += pairwise ? 1 : 0;
            const CollisionBody plainA = withoutGroups(bodyA), plainB = withoutGroups(bodyB);
            ASSERT_EQ(plainA.groupCount(), 0u);
            for (const bool answer :
                 {bodiesCollide(bodyA, bodyB), bodiesCollide(bodyB, bodyA), bodiesCollide(plainA, plainB),
                  bodiesCollide(bodyA, plainB), bodiesCollide(plainA, bodyB)})
                disagreements += answer != pairwise ? 1 : 0;
            bodyA.updateBoxes();  // as the environment test does: groups and boxes, either path
            disagreements += bodiesCollide(bodyA, plainB) != pairwise ? 1 : 0;
            disagreements += bodiesCollide(bodyA, bodyB) != pairwise ? 1 : 0;
        }
        EXPECT_EQ(disagreements, 0);
        EXPECT_GT(hits, PAIRS / 20);  // the test must exercise collisions, and pairs that do not collide
        EXPECT_LT(hits, PAIRS - PAIRS / 20);
    }
}  // namespace

TEST(PandaCollision, SphereModelGroupsGiveTheAnswersOfEveryPair)
{
    // A model of spheres only, and one with a capsule per link among its spheres (the segment distances' path).
    for (const bool withCylinders : {false, true})
        expectGroupsGiveTheAnswersOfEveryPair(spherePandaUrdf(withCylinders), !withCylinders);
}

TEST(PandaCollision, GroupsAreCheckedAndDroppedWithTheCapsules)
{
    CollisionBody body;
    body.addSphere(0., 0., 0., 0.1);
    body.addSphere(1., 0., 0., 0.1);
    body.addSphere(2., 0., 0., 0.1);
    const std::uint32_t repeated[] = {2, 2, 3}, shortEnds[] = {1, 2}, good[] = {2, 3};
    EXPECT_THROW(body.setGroups(repeated, 3), std::invalid_argument);
    EXPECT_THROW(body.setGroups(shortEnds, 2), std::invalid_argument);
    body.setGroups(good, 2);
    body.updateBound();
    EXPECT_TRUE(body.hasGroupBounds());
    EXPECT_GE(body.boundRadius_, 1.1);
    CollisionBody other;
    other.addSphere(2.15, 0., 0., 0.1);
    other.updateBound();
    EXPECT_TRUE(bodiesCollide(body, other));
    other.addSphere(5., 0., 0., 0.1);  // stale: refused, whichever path
    EXPECT_THROW(bodiesCollide(body, other), std::logic_error);
    body.resize(3, true);  // the kinematics write the capsules again: the groups go with them
    EXPECT_EQ(body.groupCount(), 0u);
    EXPECT_FALSE(body.hasGroupBounds());
}
