/* UrdfArmLanes, the single-precision SIMD check of several arm configurations at once, against the
   double-precision check (Robot::checkValidity, itself checked against FCL in EnvironmentCheckTest): it never
   calls a configuration valid that the double check rejects, also a hair inside a collision, where rounding
   matters most; it rarely rejects more (its inflation); batches answer like single configurations; and the
   robot's batched motion validator never accepts a motion OMPL's DiscreteMotionValidator rejects. Four worlds:
   the Panda cage, a Panda far from the origin (larger coordinates, larger rounding) among random obstacles, an
   arm with prismatic joints and a mimic finger off the chain among random obstacles, and an arm of spheres among
   random obstacles. */
#include "TestProblems.h"

#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/ScopedState.h>

#include <gtest/gtest.h>

#include <iostream>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
#ifdef OMPL_PARC_SANITIZED
    constexpr std::size_t SAMPLES = 10000;
#else
    constexpr std::size_t SAMPLES = 100000;
#endif

    bool exactlyValid(const Robot &robot, const std::vector<double> &q)
    {
        return robot.checkValidity(q.data()) == Robot::Validity::VALID;
    }

    /** The first Panda of the cage scenario (eight arms, task 0). */
    std::shared_ptr<const Robot> cagedPanda()
    {
        static const MultiRobotProblem problem = scenarios::createPandaCage(8, 0);
        return problem.getSpaceInformation()->getRobot(0);
    }

    /** 40 random boxes, cylinders and spheres with centres within \e spread of \e centre (per coordinate), none
        within half that of its vertical axis (where an arm's base link stands). */
    std::shared_ptr<Environment> obstaclesAround(const Eigen::Vector3d &centre, double spread)
    {
        auto env = std::make_shared<Environment>();
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> unit(-1., 1.), size(0.03, 0.25);
        for (int k = 0; k < 40; ++k)
        {
            Obstacle o;
            o.name = "obstacle" + std::to_string(k);
            o.shape = static_cast<Obstacle::Shape>(k % 3);
            o.size = Eigen::Vector3d(size(rng), size(rng), size(rng));
            Eigen::Vector3d offset = spread * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
            if (offset.head<2>().norm() < 0.5 * spread)  // keep clear of the base link
                offset.head<2>() *= 0.5 * spread / std::max(offset.head<2>().norm(), 1e-3);
            o.pose = Eigen::Translation3d(centre + offset) *
                     Eigen::AngleAxisd(unit(rng) * M_PI, Eigen::Vector3d(unit(rng), unit(rng), 1.).normalized());
            env->addObstacle(o);
        }
        return env;
    }

    /** A Panda based at (40, -25, 3), pitched, among obstacles around its base (within its reach, none touching
        its base). */
    std::shared_ptr<const Robot> farPanda()
    {
        const Eigen::Vector3d base(40., -25., 3.);
        return std::make_shared<UrdfArm>("far", obstaclesAround(base, 1.), models::pandaUrdf(), "panda_link0",
                                         "panda_link8", UrdfArm::pose(base.x(), base.y(), base.z(), 0.3, -0.2, 1.));
    }

    /** test::gripperArmUrdf() (prismatic joints, one sliding along a skew axis, and a mimic finger off the chain)
        based at (-7, 12, 1), rolled, among obstacles within its smaller reach. */
    std::shared_ptr<const Robot> gripperArm()
    {
        const Eigen::Vector3d base(-7., 12., 1.);
        return std::make_shared<UrdfArm>("gripper", obstaclesAround(base + Eigen::Vector3d(0., 0., 0.5), 0.6),
                                         test::gripperArmUrdf("1 0.5 0.2"), "base", "finger1",
                                         UrdfArm::pose(base.x(), base.y(), base.z(), 0.2, 0., -0.7));
    }

    /** test::sphereArmUrdf() based at (3, 2, 0.5) among obstacles around it. */
    std::shared_ptr<const Robot> sphereArm()
    {
        const std::string urdf = test::sphereArmUrdf();
        const Eigen::Vector3d base(3., 2., 0.5);
        return std::make_shared<UrdfArm>("spheres", obstaclesAround(base + Eigen::Vector3d(0., 0., 0.6), 1.), urdf,
                                         "link0", "link6", UrdfArm::pose(base.x(), base.y(), base.z(), 0., 0., 0.4));
    }

    /** Random configurations: no collision of the double check missed, few extra rejections. */
    void expectConservative(const Robot &robot, const std::string &label)
    {
        std::mt19937 rng(2);
        std::size_t invalid = 0, missed = 0, extra = 0;
        for (std::size_t s = 0; s < SAMPLES; ++s)
        {
            const std::vector<double> q = test::randomConfig(robot, rng);
            const bool exact = exactlyValid(robot, q), lanes = robot.allValid(q.data(), 1);
            invalid += exact ? 0 : 1;
            missed += !exact && lanes ? 1 : 0;
            extra += exact && !lanes ? 1 : 0;
        }
        EXPECT_EQ(missed, 0u) << label;
        EXPECT_GT(invalid, SAMPLES / 100) << label << ": too few collisions to test anything";
        EXPECT_LT(invalid, SAMPLES - SAMPLES / 100) << label << ": too few free configurations";
        EXPECT_LE(extra, (SAMPLES - invalid) / 200) << label << ": more than 0.5 % of the valid ones rejected";
        std::cout << "[          ] " << label << ": " << SAMPLES << " configurations, " << invalid
                  << " invalid (double check), missed " << missed << ", extra rejections " << extra << "\n";
    }

    /** Configurations within 1e-9 (joint space) inside the boundary of the invalid set, found by bisection
        between a valid and an invalid one: the lanes reject every one. */
    void expectBoundaryRejected(const Robot &robot, const std::string &label)
    {
        std::mt19937 rng(3);
        std::size_t tested = 0;
        const unsigned int d = robot.getDimension();
        while (tested < 2000)
        {
            std::vector<double> valid = test::randomConfig(robot, rng), invalid = test::randomConfig(robot, rng);
            if (!exactlyValid(robot, valid) || exactlyValid(robot, invalid))
                continue;
            std::vector<double> mid(d);
            for (int it = 0; it < 60; ++it)
            {
                for (unsigned int k = 0; k < d; ++k)
                    mid[k] = 0.5 * (valid[k] + invalid[k]);
                (exactlyValid(robot, mid) ? valid : invalid) = mid;
            }
            ASSERT_FALSE(exactlyValid(robot, invalid));
            EXPECT_FALSE(robot.allValid(invalid.data(), 1)) << label << ": boundary configuration " << tested;
            ++tested;
        }
    }
}  // namespace

TEST(UrdfArmLanes, CagedPandaNeverMissesACollisionOfTheDoubleCheck)
{
    expectConservative(*cagedPanda(), "panda_cage");
    expectBoundaryRejected(*cagedPanda(), "panda_cage");
}

TEST(UrdfArmLanes, FarPandaAmongRandomObstaclesNeverMissesACollisionOfTheDoubleCheck)
{
    expectConservative(*farPanda(), "far_panda");
    expectBoundaryRejected(*farPanda(), "far_panda");
}

TEST(UrdfArmLanes, PrismaticAndMimicJointsNeverMissACollisionOfTheDoubleCheck)
{
    expectConservative(*gripperArm(), "gripper_arm");
    expectBoundaryRejected(*gripperArm(), "gripper_arm");
}

TEST(UrdfArmLanes, ArmOfSpheresNeverMissesACollisionOfTheDoubleCheck)
{
    expectConservative(*sphereArm(), "sphere_arm");
    expectBoundaryRejected(*sphereArm(), "sphere_arm");
}

TEST(UrdfArmLanes, BatchesAnswerLikeTheirConfigurationsOneByOne)
{
    const auto robot = cagedPanda();
    const unsigned int d = robot->getDimension();
    std::mt19937 rng(4);
    std::size_t rejected = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const std::size_t count = std::uniform_int_distribution<std::size_t>(1, 17)(rng);
        std::vector<double> flat;
        bool all = true;
        for (std::size_t k = 0; k < count; ++k)
        {
            // mostly valid configurations, so that batches are often all valid
            std::vector<double> q = test::randomConfig(*robot, rng);
            for (int retry = 0; retry < 4 && trial % 3 != 0 && !robot->allValid(q.data(), 1); ++retry)
                q = test::randomConfig(*robot, rng);
            all = all && robot->allValid(q.data(), 1);
            flat.insert(flat.end(), q.begin(), q.end());
        }
        EXPECT_EQ(robot->allValid(flat.data(), count), all) << "trial " << trial;
        rejected += all ? 0 : 1;
    }
    EXPECT_GT(rejected, 300u);
    EXPECT_LT(rejected, 2700u);
}

TEST(UrdfArmLanes, BatchedMotionValidatorNeverAcceptsWhatTheDiscreteOneRejects)
{
    for (const auto &robot : {cagedPanda(), farPanda(), gripperArm()})
    {
        const auto &si = robot->getSpaceInformation();
        ob::DiscreteMotionValidator discrete(si.get());
        ob::ScopedState<> a(si), b(si);
        std::mt19937 rng(5);
        std::size_t discreteRejects = 0, extra = 0, motions = 0;
        while (motions < 3000)
        {
            const std::vector<double> qa = test::randomConfig(*robot, rng), step = test::randomConfig(*robot, rng);
            if (!robot->isValid(qa.data()))
                continue;
            std::vector<double> qb(qa);
            for (unsigned int k = 0; k < qb.size(); ++k)  // a short motion, a tenth of the way to a random one
                qb[k] += 0.1 * (step[k] - qa[k]);
            robot->configToState(qa.data(), a.get());
            robot->configToState(qb.data(), b.get());
            const bool exact = discrete.checkMotion(a.get(), b.get());
            const bool rake = si->checkMotion(a.get(), b.get());
            EXPECT_FALSE(rake && !exact) << robot->getName() << ": motion " << motions;
            discreteRejects += exact ? 0 : 1;
            extra += exact && !rake ? 1 : 0;
            ++motions;
        }
        EXPECT_GT(discreteRejects, 100u) << robot->getName();
        EXPECT_LE(extra, 30u) << robot->getName()
                              << ": more than 1 % of the motions rejected beyond the discrete check";
    }
}
