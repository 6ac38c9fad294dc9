/* The analytic robot-environment test (Environment::collides, ObstacleSet) against FCL (collidesFcl), the exact
   reference: over many random configurations of each robot kind it never misses a collision FCL reports; the
   false-positive rate is printed and recorded. Also the segment-box distance against a dense scan, and the
   motion validator's sample set against OMPL's. */
#include "ompl_parc/collision/PrimitiveDistance.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/robots/RakeMotionValidator.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
#ifdef OMPL_PARC_SANITIZED
    constexpr std::size_t SAMPLES = 20000;  // FCL's share is not instrumented, ours is: keep the ASan run short
#else
    constexpr std::size_t SAMPLES = 100000;
#endif

    /** Boxes (rotated footprints), upright and lying cylinders and spheres around the plane z = 0. */
    EnvironmentPtr mixedWorld()
    {
        auto env = std::make_shared<Environment>();
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> position(-4., 4.), angle(-M_PI, M_PI);
        for (int k = 0; k < 8; ++k)
            env->addBox2D("box" + std::to_string(k), position(rng), position(rng),
                          std::uniform_real_distribution<double>(0.1, 1.5)(rng),
                          std::uniform_real_distribution<double>(0.1, 1.5)(rng), angle(rng));
        for (int k = 0; k < 8; ++k)
        {
            Obstacle o;
            o.name = "cylinder" + std::to_string(k);
            o.shape = Obstacle::Shape::CYLINDER;
            o.size = Eigen::Vector3d(std::uniform_real_distribution<double>(0.05, 0.5)(rng), 0.,
                                     std::uniform_real_distribution<double>(0.5, 3.)(rng));
            // Half upright (walls seen from above), half lying across the plane at a random height and heading.
            o.pose = Eigen::Translation3d(position(rng), position(rng),
                                          k % 2 == 0 ? 0. : std::uniform_real_distribution<double>(-0.4, 0.4)(rng)) *
                     Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(k % 2 == 0 ? 0. : M_PI / 2., Eigen::Vector3d::UnitX());
            env->addObstacle(o);
        }
        for (int k = 0; k < 4; ++k)
        {
            Obstacle o;
            o.name = "sphere" + std::to_string(k);
            o.shape = Obstacle::Shape::SPHERE;
            o.size.x() = std::uniform_real_distribution<double>(0.1, 0.8)(rng);
            o.pose.translation() =
                Eigen::Vector3d(position(rng), position(rng), std::uniform_real_distribution<double>(-0.3, 0.3)(rng));
            env->addObstacle(o);
        }
        return env;
    }

    /** Random configurations of \e robot in its bounds: no FCL collision missed; prints the rates. */
    void expectConservative(const Robot &robot, const std::string &label)
    {
        std::mt19937 rng(1);
        std::vector<double> q(robot.getDimension());
        CollisionBody body;
        std::size_t missed = 0, fclHits = 0, falsePositives = 0;
        for (std::size_t s = 0; s < SAMPLES; ++s)
        {
            for (unsigned int d = 0; d < q.size(); ++d)
                q[d] = std::uniform_real_distribution<double>(robot.getBounds().low[d], robot.getBounds().high[d])(rng);
            robot.computeBody(q.data(), body);
            const bool exact = robot.getEnvironment()->collidesFcl(body), ours = robot.getEnvironment()->collides(body);
            fclHits += exact ? 1 : 0;
            missed += exact && !ours ? 1 : 0;
            falsePositives += !exact && ours ? 1 : 0;
        }
        EXPECT_EQ(missed, 0u) << label;
        EXPECT_GT(fclHits, SAMPLES / 100) << label << ": too few collisions to test anything";
        EXPECT_LT(fclHits, SAMPLES - SAMPLES / 100) << label << ": too few free configurations";
        const double rate = double(falsePositives) / double(SAMPLES - fclHits);
        std::cout << "[          ] " << label << ": " << SAMPLES << " configurations, " << fclHits
                  << " in collision (FCL), missed " << missed << ", false positives " << falsePositives << " ("
                  << 100. * rate << " % of the free ones)\n";
        ::testing::Test::RecordProperty(label + "_false_positive_rate", std::to_string(rate));
    }
}  // namespace

TEST(EnvironmentCheck, SegmentBoxDistanceMatchesADenseScan)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-2., 2.), h(0.05, 1.);
    constexpr int STEPS = 20000;
    for (int trial = 0; trial < 500; ++trial)
    {
        double p[3], d[3], half[3];
        for (int k = 0; k < 3; ++k)
        {
            p[k] = u(rng);
            d[k] = trial % 10 == 0 && k == 1 ? 0. : u(rng);  // some axis-parallel segments
            half[k] = h(rng);
        }
        const double exact = std::sqrt(segmentBoxDistanceSquared(p, d, half));
        double scanned = INFINITY;
        for (int s = 0; s <= STEPS; ++s)
        {
            const double t = double(s) / STEPS;
            double d2 = 0.;
            for (int k = 0; k < 3; ++k)
            {
                const double x = p[k] + t * d[k], e = x - std::min(std::max(x, -half[k]), half[k]);
                d2 += e * e;
            }
            scanned = std::min(scanned, std::sqrt(d2));
        }
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        EXPECT_LE(exact, scanned + 1e-12);
        EXPECT_LE(scanned, exact + 0.5 * length / STEPS + 1e-12);
    }
}

TEST(EnvironmentCheck, DiscNeverMissesAnFclCollision)
{
    ob::RealVectorBounds bounds(2);
    bounds.setLow(-5.);
    bounds.setHigh(5.);
    DiscRobot robot("disc", mixedWorld(), 0.3, bounds);
    expectConservative(robot, "disc");
}

TEST(EnvironmentCheck, PlanarArmNeverMissesAnFclCollision)
{
    ob::RealVectorBounds limits(3);
    limits.setLow(-M_PI);
    limits.setHigh(M_PI);
    PlanarArm robot("arm", mixedWorld(), 0.5, -0.5, 0., {1.2, 1., 0.8}, 0.2, limits);
    expectConservative(robot, "planar_arm");
}

TEST(EnvironmentCheck, PandaInTheCageNeverMissesAnFclCollision)
{
    const MultiRobotProblem problem = scenarios::createPandaCage(8, 0);
    expectConservative(*problem.getSpaceInformation()->getRobot(0), "panda_cage");
}

TEST(EnvironmentCheck, RakeChecksDiscreteMotionValidatorsSamplesFarApartFirst)
{
    auto space = std::make_shared<ob::RealVectorStateSpace>(1);
    space->setBounds(0., 1.);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    std::vector<double> checked;
    si->setStateValidityChecker(
        [&checked](const ob::State *state)
        {
            checked.push_back(state->as<ob::RealVectorStateSpace::StateType>()->values[0]);
            return true;
        });
    si->setStateValidityCheckingResolution(1. / 36.5);  // 37 segments over the whole extent
    si->setup();
    ob::ScopedState<ob::RealVectorStateSpace> from(space), to(space);
    from[0] = 0.;
    to[0] = 1.;
    ob::DiscreteMotionValidator discrete(si.get());
    RakeMotionValidator rake(si.get());
    ASSERT_TRUE(discrete.checkMotion(from.get(), to.get()));
    std::vector<double> reference = checked;
    checked.clear();
    ASSERT_TRUE(rake.checkMotion(from.get(), to.get()));
    ASSERT_EQ(checked.size(), 37u);  // the end state and 36 inner samples
    EXPECT_EQ(checked[0], 1.);
    EXPECT_DOUBLE_EQ(checked[1], 32. / 37.);  // the largest power-of-two stride below 37 first
    EXPECT_DOUBLE_EQ(checked[2], 16. / 37.);
    std::sort(reference.begin(), reference.end());
    std::sort(checked.begin(), checked.end());
    EXPECT_EQ(checked, reference);  // the same sample set, bit for bit

    // A wall in the middle: the rake rejects the motion after a few samples.
    checked.clear();
    si->setStateValidityChecker(
        [&checked](const ob::State *state)
        {
            const double x = state->as<ob::RealVectorStateSpace::StateType>()->values[0];
            checked.push_back(x);
            return std::abs(x - 0.45) > 0.02;
        });
    EXPECT_FALSE(rake.checkMotion(from.get(), to.get()));
    EXPECT_LT(checked.size(), 10u);
    std::pair<ob::State *, double> lastValid{si->allocState(), 0.};
    EXPECT_FALSE(rake.checkMotion(from.get(), to.get(), lastValid));  // OMPL's sequential contract
    EXPECT_DOUBLE_EQ(lastValid.second, 15. / 37.);
    EXPECT_DOUBLE_EQ(lastValid.first->as<ob::RealVectorStateSpace::StateType>()->values[0], 15. / 37.);
    si->freeState(lastValid.first);
}

TEST(EnvironmentCheck, RobotSpacesUseTheRake)
{
    const MultiRobotProblem problem = scenarios::createPandaCage(8, 0);
    const auto &si = problem.getSpaceInformation();
    EXPECT_NE(std::dynamic_pointer_cast<RakeMotionValidator>(si->getMotionValidator()), nullptr);
    EXPECT_NE(
        std::dynamic_pointer_cast<RakeMotionValidator>(si->getRobot(0)->getSpaceInformation()->getMotionValidator()),
        nullptr);
}

TEST(EnvironmentCheck, DiscSweepNeverAcceptsWhatTheSamplesRejectAndCatchesTunnelling)
{
    ob::RealVectorBounds bounds(2);
    bounds.setLow(-5.);
    bounds.setHigh(5.);
    const auto robot = std::make_shared<DiscRobot>("disc", mixedWorld(), 0.05, bounds);
    const auto &si = robot->getSpaceInformation();
    ob::DiscreteMotionValidator samples(si.get());
    ob::ScopedState<> a(si), b(si);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-5., 5.);
    std::size_t rejected = 0, motions = 0;
    while (motions < 20000)
    {
        const double from[2] = {u(rng), u(rng)}, to[2] = {u(rng), u(rng)};
        if (!robot->isValid(from))
            continue;
        robot->configToState(from, a.get());
        robot->configToState(to, b.get());
        const bool sampled = samples.checkMotion(a.get(), b.get()), swept = si->checkMotion(a.get(), b.get());
        EXPECT_FALSE(swept && !sampled) << "motion " << motions;
        EXPECT_EQ(swept, *robot->sweepValid(from, to));
        rejected += swept ? 0 : 1;
        ++motions;
    }
    EXPECT_GT(rejected, 2000u);
    EXPECT_LT(rejected, 18000u);

    // A disc hopping over a wall thinner than a timestep's motion: the samples miss it, the sweep does not.
    auto world = std::make_shared<Environment>();
    world->addBox2D("wall", 0., 0., 1e-4, 2.);
    const auto small = std::make_shared<DiscRobot>("small", world, 1e-3, bounds);
    small->setResolution(128.);
    const double left[2] = {-0.003, 0.}, right[2] = {0.003, 0.};
    ASSERT_TRUE(small->isValid(left) && small->isValid(right));
    EXPECT_EQ(small->sweepValid(left, right), std::optional<bool>(false));
    robot->configToState(left, a.get());
    robot->configToState(right, b.get());
    EXPECT_TRUE(ob::DiscreteMotionValidator(small->getSpaceInformation().get()).checkMotion(a.get(), b.get()));
    EXPECT_FALSE(small->getSpaceInformation()->checkMotion(a.get(), b.get()));
}
