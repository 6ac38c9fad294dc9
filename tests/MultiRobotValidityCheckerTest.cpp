/* MultiRobotValidityChecker::allValid() on teams of arms, whose robot pairs are compared a lane batch at a time in
   single precision (UrdfArmLanes::nearLanes()) and tested exactly only where the lanes cannot rule a pair out: its
   answer must be the one of the exact test of every configuration (each robot alone as Robot::allValid() decides,
   then every pair with bodiesCollide() in double precision), on random batches of overlapping arms, and a hair on
   either side of the configurations where two arms start to touch, where single-precision rounding matters. Two
   teams: Pandas of the cage (capsules), and arms of spheres (test::sphereArmUrdf()), as VAMP models arms. */
#include "TestProblems.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/model/MultiRobotValidityChecker.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/robots/UrdfArmLanes.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <gtest/gtest.h>

#include <random>

using namespace ompl_parc;

namespace
{
    /** Four neighbouring Pandas of the cage (sixteen arms, task 0), whose workspaces overlap pairwise. */
    std::vector<RobotPtr> cagedTeam()
    {
        static const MultiRobotProblem problem = scenarios::createPandaCage(16, 0);
        std::vector<RobotPtr> team;
        for (std::size_t i = 0; i < 4; ++i)
            team.push_back(problem.getSpaceInformation()->getRobot(i));
        return team;
    }

    /** Three arms of spheres in a row, their bases 0.8 m apart (each reaches about 1.7 m), among no obstacles. */
    std::vector<RobotPtr> sphereTeam()
    {
        const auto environment = std::make_shared<Environment>();
        std::vector<RobotPtr> team;
        for (int i = 0; i < 3; ++i)
            team.push_back(std::make_shared<UrdfArm>("spheres" + std::to_string(i), environment, test::sphereArmUrdf(),
                                                     "link0", "link6",
                                                     UrdfArm::pose(0.8 * i, 0., 0., 0., 0., 1.3 * i)));
        return team;
    }

    /** The answer of testing every configuration exactly: each robot alone (its own allValid(), lanes included),
        then every pair of bodies in double precision. */
    bool exactlyValid(const std::vector<RobotPtr> &team, const std::vector<double> &flat, std::size_t count)
    {
        std::size_t total = 0;
        for (const RobotPtr &robot : team)
            total += robot->getDimension();
        for (std::size_t k = 0; k < count; ++k)
        {
            std::vector<CollisionBody> bodies(team.size());
            for (std::size_t i = 0, offset = 0; i < team.size(); offset += team[i]->getDimension(), ++i)
            {
                const double *q = flat.data() + k * total + offset;
                if (!team[i]->allValid(q, 1))
                    return false;
                team[i]->computeBody(q, bodies[i]);
            }
            for (std::size_t i = 0; i < team.size(); ++i)
                for (std::size_t j = i + 1; j < team.size(); ++j)
                    if (bodiesCollide(bodies[i], bodies[j]))
                        return false;
        }
        return true;
    }

    /** A team configuration whose robots are each valid alone. */
    std::vector<double> aloneValidConfig(const std::vector<RobotPtr> &team, std::mt19937 &rng)
    {
        std::vector<double> flat;
        for (const RobotPtr &robot : team)
        {
            std::vector<double> q = test::randomConfig(*robot, rng);
            while (!robot->allValid(q.data(), 1))
                q = test::randomConfig(*robot, rng);
            flat.insert(flat.end(), q.begin(), q.end());
        }
        return flat;
    }
}  // namespace

namespace
{
    void expectExactAnswers(const std::vector<RobotPtr> &team)
    {
        ASSERT_NE(team[0]->getLanes(), nullptr);
        MultiRobotSpaceInformation si(team);
        const MultiRobotValidityChecker checker(&si, team);
        std::mt19937 rng(21);
        std::size_t rejected = 0;
        for (int trial = 0; trial < 2000; ++trial)
        {
            // Even trials: independent configurations; odd ones: the samples of a motion from a valid configuration a
            // fifth of the way to another (what the motion checks ask).
            const std::size_t count = std::uniform_int_distribution<std::size_t>(1, trial % 2 == 0 ? 3 : 13)(rng);
            std::vector<double> flat, from = aloneValidConfig(team, rng);
            while (trial % 2 == 1 && !exactlyValid(team, from, 1))
                from = aloneValidConfig(team, rng);
            const std::vector<double> to = aloneValidConfig(team, rng);
            for (std::size_t k = 0; k < count; ++k)
            {
                std::vector<double> q = aloneValidConfig(team, rng);
                if (trial % 2 == 1)
                    for (std::size_t d = 0; d < q.size(); ++d)
                        q[d] =
                            from[d] + 0.2 * static_cast<double>(k + 1) / static_cast<double>(count) * (to[d] - from[d]);
                flat.insert(flat.end(), q.begin(), q.end());
            }
            const bool exact = exactlyValid(team, flat, count);
            EXPECT_EQ(checker.allValid(flat.data(), count), exact) << "trial " << trial;
            rejected += exact ? 0 : 1;
        }
        // Both answers are common (the independent configurations are valid alone: their rejections are pairs').
        EXPECT_GT(rejected, 200u);
        EXPECT_LT(rejected, 1800u);
    }

    void expectBoundariesToldApart(const std::vector<RobotPtr> &team)
    {
        MultiRobotSpaceInformation si(team);
        const MultiRobotValidityChecker checker(&si, team);
        std::mt19937 rng(22);
        int boundaries = 0;
        for (int trial = 0; trial < 4000 && boundaries < 200; ++trial)
        {
            // Between a team configuration whose pairs touch and one whose do not, bisect to where they start to.
            std::vector<double> clear = aloneValidConfig(team, rng), touching = aloneValidConfig(team, rng);
            if (!exactlyValid(team, clear, 1) || exactlyValid(team, touching, 1))
                continue;
            std::vector<double> mid(clear.size());
            bool aloneValid = true;
            for (int step = 0; step < 60 && aloneValid; ++step)
            {
                for (std::size_t d = 0; d < mid.size(); ++d)
                    mid[d] = 0.5 * (clear[d] + touching[d]);
                std::size_t offset = 0;
                for (const RobotPtr &robot : team)
                {
                    aloneValid = aloneValid && robot->allValid(mid.data() + offset, 1);
                    offset += robot->getDimension();
                }
                if (aloneValid)
                    (exactlyValid(team, mid, 1) ? clear : touching) = mid;
            }
            if (!aloneValid)
                continue;  // a robot alone became invalid on the way: not a pair's boundary
            ++boundaries;
            EXPECT_TRUE(checker.allValid(clear.data(), 1)) << "trial " << trial;
            EXPECT_FALSE(checker.allValid(touching.data(), 1)) << "trial " << trial;
            // Both in one batch, among valid configurations, in every lane position.
            std::vector<double> batch;
            for (int k = 0; k < 7; ++k)
                batch.insert(batch.end(), clear.begin(), clear.end());
            for (std::size_t lane = 0; lane < 7; ++lane)
            {
                std::vector<double> withTouch = batch;
                std::copy(touching.begin(), touching.end(), withTouch.begin() + lane * touching.size());
                EXPECT_FALSE(checker.allValid(withTouch.data(), 7)) << "trial " << trial << ", lane " << lane;
            }
            EXPECT_TRUE(checker.allValid(batch.data(), 7)) << "trial " << trial;
        }
        EXPECT_GE(boundaries, 100);
    }
}  // namespace

TEST(MultiRobotValidityChecker, ArmTeamsComparedInLanesAnswerAsTheExactTestOfEveryConfiguration)
{
    expectExactAnswers(cagedTeam());
}

TEST(MultiRobotValidityChecker, ArmPairsAHairApartOrTouchingAreToldApart)
{
    expectBoundariesToldApart(cagedTeam());
}

TEST(MultiRobotValidityChecker, SphereArmTeamsComparedInLanesAnswerAsTheExactTestOfEveryConfiguration)
{
    expectExactAnswers(sphereTeam());
}

TEST(MultiRobotValidityChecker, SphereArmPairsAHairApartOrTouchingAreToldApart)
{
    expectBoundariesToldApart(sphereTeam());
}
