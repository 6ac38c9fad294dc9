#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <limits>
#include <random>

using namespace ompl_parc;

namespace
{
    ompl::base::RealVectorBounds box(unsigned int dim, double lo, double hi)
    {
        ompl::base::RealVectorBounds b(dim);
        b.setLow(lo);
        b.setHigh(hi);
        return b;
    }
}  // namespace

TEST(DiscRobot, ValidityAgainstBoundsAndEnvironment)
{
    auto env = std::make_shared<Environment>();
    env->addBox2D("block", 3., 0., 1., 1.);
    DiscRobot disc("d", env, 0.5, box(2, -5., 5.));
    const double free[2] = {0., 0.}, outside[2] = {6., 0.}, hit[2] = {2.1, 0.}, grazing[2] = {1.99, 0.};
    EXPECT_EQ(disc.checkValidity(free), Robot::Validity::VALID);
    EXPECT_EQ(disc.checkValidity(outside), Robot::Validity::OUT_OF_BOUNDS);
    EXPECT_EQ(disc.checkValidity(hit), Robot::Validity::ENVIRONMENT_COLLISION);
    EXPECT_EQ(disc.checkValidity(grazing), Robot::Validity::VALID);
    EXPECT_EQ(disc.getKind(), "disc");
}

TEST(DiscRobot, OwnSpaceInformationUsesTheValidityCheck)
{
    auto env = std::make_shared<Environment>();
    env->addBox2D("block", 0., 0., 1., 1.);
    DiscRobot disc("d", env, 0.5, box(2, -5., 5.));
    auto si = disc.getSpaceInformation();
    auto *s = si->allocState();
    const double inside[2] = {0.2, 0.};
    disc.configToState(inside, s);
    EXPECT_FALSE(si->isValid(s));
    const double away[2] = {-3., 3.};
    disc.configToState(away, s);
    EXPECT_TRUE(si->isValid(s));
    si->freeState(s);
}

TEST(DiscRobot, RejectsBadParameters)
{
    EXPECT_THROW(DiscRobot("d", nullptr, 0., box(2, -1., 1.)), ompl::Exception);
    EXPECT_THROW(DiscRobot("d", nullptr, 0.5, box(3, -1., 1.)), ompl::Exception);
    EXPECT_THROW(DiscRobot("d", nullptr, 0.5, box(2, 1., -1.)), ompl::Exception);
}

TEST(PlanarArm, ForwardKinematicsMatchesHandComputedPose)
{
    PlanarArm arm("a", nullptr, 1., 2., M_PI / 2., {1.0, 0.5, 0.25}, 0.1, box(3, -M_PI, M_PI));
    const double q[3] = {0., M_PI / 2., -M_PI / 2.};
    CollisionBody body;
    arm.computeBody(q, body);
    ASSERT_EQ(body.size(), 3u);
    // Link 0 points up from (1,2) to (1,3); link 1 turns left to (0.5,3); link 2 points up again to (0.5,3.25).
    EXPECT_NEAR(body.bx_[0], 1., 1e-12);
    EXPECT_NEAR(body.by_[0], 3., 1e-12);
    EXPECT_NEAR(body.bx_[1], 0.5, 1e-12);
    EXPECT_NEAR(body.by_[1], 3., 1e-12);
    EXPECT_NEAR(body.bx_[2], 0.5, 1e-12);
    EXPECT_NEAR(body.by_[2], 3.25, 1e-12);
    EXPECT_DOUBLE_EQ(body.radius_[2], 0.05);
}

TEST(PlanarArm, DetectsSelfCollisionOfNonAdjacentLinksOnly)
{
    PlanarArm arm("a", nullptr, 0., 0., 0., {1.0, 0.3, 1.0}, 0.1, box(3, -M_PI, M_PI));
    ASSERT_EQ(arm.getSelfCollisionPairs().size(), 1u);
    const double straight[3] = {0., 0., 0.}, folded[3] = {0., 2.9, 0.3};
    EXPECT_EQ(arm.checkValidity(straight), Robot::Validity::VALID);
    EXPECT_EQ(arm.checkValidity(folded), Robot::Validity::SELF_COLLISION);
}

TEST(PlanarArm, RejectsBadParameters)
{
    EXPECT_THROW(PlanarArm("a", nullptr, 0., 0., 0., {1.0, 1.0}, 0.1, box(3, -1., 1.)), ompl::Exception);
    EXPECT_THROW(PlanarArm("a", nullptr, 0., 0., 0., {1.0, -1.0, 1.0}, 0.1, box(3, -1., 1.)), ompl::Exception);
    EXPECT_THROW(PlanarArm("a", nullptr, 0., 0., 0., {1.0, 1.0, 1.0}, 0., box(3, -1., 1.)), ompl::Exception);
}

TEST(Environment, RejectsNonPositiveSizes)
{
    Environment env;
    EXPECT_THROW(env.addBox2D("flat", 0., 0., 0., 1.), ompl::Exception);
    Obstacle sphere;
    sphere.shape = Obstacle::Shape::SPHERE;
    EXPECT_THROW(env.addObstacle(sphere), ompl::Exception);
}

TEST(Environment, AHugeRotatedSlabAnswersExactlyAndInfiniteSizesAreRefused)
{
    // A thin slab 1e300 wide, tilted: its world box spans all of space in single precision. Bodies of 3 capsules
    // (one NaN padding lane in their boxes) must still get the slab's exact answer: clear 5 away from its plane,
    // in collision across it.
    Environment env;
    Obstacle slab;
    slab.name = "slab";
    slab.shape = Obstacle::Shape::BOX;
    slab.size = Eigen::Vector3d(1e300, 1e300, 0.1);
    slab.pose = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX());
    env.addObstacle(slab);
    const Eigen::Vector3d normal = slab.pose.linear() * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d along = slab.pose.linear() * Eigen::Vector3d::UnitX();
    for (const double height : {5., 0., -5.})
    {
        CollisionBody body;
        for (int c = 0; c < 3; ++c)
        {
            const Eigen::Vector3d p = height * normal + (c - 1.) * along, q = p + 0.3 * along;
            body.addCapsule(p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), 0.05);
        }
        body.updateBound();
        EXPECT_EQ(env.collides(body), height == 0.) << "at height " << height;
    }
    Obstacle infinite = slab;
    infinite.size.x() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(env.addObstacle(infinite), ompl::Exception);
    Obstacle nowhere = slab;
    nowhere.pose.translation().x() = std::nan("");
    EXPECT_THROW(env.addObstacle(nowhere), ompl::Exception);
}

TEST(Environment, CapsulesAgainstRotatedBoxAndSphere)
{
    Environment env;
    env.addBox2D("diamond", 0., 0., 1., 1., M_PI / 4.);
    Obstacle ball;
    ball.name = "ball";
    ball.shape = Obstacle::Shape::SPHERE;
    ball.size.x() = 0.5;
    ball.pose.translation() = Eigen::Vector3d(5., 0., 0.);
    env.addObstacle(ball);
    CollisionBody body;
    // The diamond's corner is at x = sqrt(0.5) = 0.707; a thin capsule at x = 0.75 misses it, at 0.65 hits.
    body.addCapsule(0.75, -1., 0., 0.75, 1., 0., 0.01);
    EXPECT_FALSE(env.collides(body));
    body.clear();
    body.addCapsule(0.65, -1., 0., 0.65, 1., 0., 0.01);
    EXPECT_TRUE(env.collides(body));
    body.clear();
    body.addSphere(5.9, 0., 0., 0.41);
    EXPECT_TRUE(env.collides(body));
    body.clear();
    body.addSphere(5.9, 0., 0., 0.39);
    EXPECT_FALSE(env.collides(body));
}

TEST(DiscRobot, BoxOverConfigurationsIsTheUnionOfTheBodiesBoxes)
{
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(-5.);
    bounds.setHigh(5.);
    DiscRobot robot("disc", nullptr, 0.3, bounds);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-5., 5.);
    for (int trial = 0; trial < 200; ++trial)
    {
        double lo[2] = {u(rng), u(rng)}, hi[2];
        for (int d = 0; d < 2; ++d)
            hi[d] = lo[d] + std::uniform_real_distribution<double>(0., 2.)(rng);
        std::array<double, 3> boxLo{1e9, 1e9, 1e9}, boxHi{-1e9, -1e9, -1e9}, unionLo = boxLo, unionHi = boxHi;
        ASSERT_TRUE(robot.expandBoxOver(lo, hi, boxLo, boxHi));
        CollisionBody body;
        for (const double x : {lo[0], hi[0]})  // the corners reach the extremes; the box is their union
            for (const double y : {lo[1], hi[1]})
            {
                const double q[2] = {x, y};
                robot.computeBody(q, body);
                body.expandBox(unionLo, unionHi);
            }
        for (int d = 0; d < 3; ++d)
        {
            EXPECT_DOUBLE_EQ(boxLo[d], unionLo[d]);
            EXPECT_DOUBLE_EQ(boxHi[d], unionHi[d]);
        }
    }
}
