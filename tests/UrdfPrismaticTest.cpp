/* UrdfArm's prismatic and mimic joints: forward kinematics against transforms composed by hand, the validator's
   displacement bound against the motion of every capsule end, a gripper's second finger (a mimic joint off the
   chain) moving with the first, mimic limits narrowing the coordinate they follow, one-line errors for bad input,
   and two such arms planned by ARC and checked by the independent validator. */
#include "TestProblems.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/validation/DisplacementBound.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** Two revolute joints about y, links 0.4 long: "j1" (base to "upper", -1 .. 1) and "j2" ("upper" to "lower",
        -2 .. 2) with \e mimic2 in its element, then "tip" fixed 0.4 along "lower"; \e extra is spliced in before
        </robot>. */
    std::string benderUrdf(const std::string &mimic2 = "<mimic joint=\"j1\" multiplier=\"2\"/>",
                           const std::string &extra = "")
    {
        return R"(<robot name="bender">
  <link name="base"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.2"/><geometry><cylinder radius="0.05" length="0.3"/></geometry></collision></link>
  <link name="lower"><collision><origin xyz="0 0 0.2"/><geometry><cylinder radius="0.05" length="0.3"/></geometry></collision></link>
  <link name="tip"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="upper"/><child link="lower"/><origin xyz="0 0 0.4"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/>)" +
               mimic2 + R"(</joint>
  <joint name="j3" type="fixed"><parent link="lower"/><child link="tip"/><origin xyz="0 0 0.4"/></joint>
)" + extra + "</robot>";
    }

    /** A joint "side_joint" off the bender's chain, from "upper" to a link "side" (a sphere), turning about x,
        with \e mimic in its element. */
    std::string sideJoint(const std::string &mimic)
    {
        return R"(<link name="side"><collision><geometry><sphere radius="0.03"/></geometry></collision></link>
  <joint name="side_joint" type="revolute"><parent link="upper"/><child link="side"/><origin xyz="0.1 0 0.2"/>
    <axis xyz="1 0 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/>)" +
               mimic + "</joint>\n";
    }

    /** \e urdf with the first \e from replaced by \e to. */
    std::string replaced(std::string urdf, const std::string &from, const std::string &to)
    {
        const std::size_t at = urdf.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return at == std::string::npos ? urdf : urdf.replace(at, from.size(), to);
    }

    void expectJointError(const std::string &urdf, const std::string &needle, const std::string &baseLink = "base",
                          const std::string &tipLink = "finger1")
    {
        try
        {
            UrdfArm("arm", nullptr, urdf, baseLink, tipLink, Eigen::Isometry3d::Identity());
            ADD_FAILURE() << "no error, expected one mentioning '" << needle << "'";
        }
        catch (const ompl::Exception &e)
        {
            const std::string message = e.what();
            EXPECT_NE(message.find(needle), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }

    Eigen::Vector3d capsuleEnd(const CollisionBody &body, std::size_t c, bool b)
    {
        return b ? Eigen::Vector3d(body.bx_[c], body.by_[c], body.bz_[c])
                 : Eigen::Vector3d(body.ax_[c], body.ay_[c], body.az_[c]);
    }

    /** Index of the first primitive of link \e link. */
    std::size_t primitiveOf(const UrdfArm &arm, const std::string &link)
    {
        const auto &primitives = arm.getPrimitives();
        for (std::size_t k = 0; k < primitives.size(); ++k)
            if (primitives[k].shape.name == link)
                return k;
        ADD_FAILURE() << "no primitive of link " << link;
        return 0;
    }
}  // namespace

TEST(UrdfPrismatic, ForwardKinematicsMatchesTransformsComposedByHand)
{
    // Slide along x, everything else at zero: the carriage at (d, 0, 0.55), the first finger's origin 0.3 above the
    // forearm's joint (0.05 further along x), 0.01 + f along y and 0.015 up.
    const UrdfArm straight("arm", nullptr, test::gripperArmUrdf(), "base", "finger1", Eigen::Isometry3d::Identity());
    ASSERT_EQ(straight.getDimension(), 4u);
    const std::vector<double> q0 = {0., 0.25, 0., 0.02};
    std::vector<Eigen::Isometry3d> frames;
    straight.computeFrames(q0.data(), frames);
    ASSERT_EQ(frames.size(), 6u);
    EXPECT_LT((frames[2].translation() - Eigen::Vector3d(0.25, 0., 0.55)).norm(), 1e-12);
    EXPECT_LT((straight.computeTipPose(q0.data()).translation() - Eigen::Vector3d(0.3, 0.03, 0.865)).norm(), 1e-12);
    EXPECT_LT((frames[5].translation() - Eigen::Vector3d(0.3, -0.03, 0.865)).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(straight.getBounds().low[1], -0.2);
    EXPECT_DOUBLE_EQ(straight.getBounds().high[1], 0.3);

    // A skew slide axis, a turned and moved base, every joint away from zero: each frame against the URDF's
    // transforms (origin, then rotation about or translation along the axis) multiplied out.
    const Eigen::Vector3d slide = Eigen::Vector3d(1., 0.5, 0.2).normalized();
    const Eigen::Isometry3d base = UrdfArm::pose(1., 2., 0.5, 0.3, -0.1, 0.4);
    const UrdfArm arm("arm", nullptr, test::gripperArmUrdf("1 0.5 0.2"), "base", "finger1", base);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 100; ++trial)
    {
        const std::vector<double> q = test::randomConfig(arm, rng);
        const Eigen::Isometry3d column =
            base * Eigen::Translation3d(0., 0., 0.05) * Eigen::AngleAxisd(q[0], Eigen::Vector3d::UnitZ());
        const Eigen::Isometry3d carriage =
            column * Eigen::Translation3d(0., 0., 0.5) * Eigen::Translation3d(q[1] * slide);
        const Eigen::Isometry3d forearm =
            carriage * Eigen::Translation3d(0.05, 0., 0.) * Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitY());
        const Eigen::Isometry3d hand = forearm * Eigen::Translation3d(0., 0., 0.3);
        const Eigen::Isometry3d finger1 = hand * Eigen::Translation3d(0., 0.01 + q[3], 0.015);
        const Eigen::Isometry3d finger2 = hand * Eigen::Translation3d(0., -0.01 - q[3], 0.015);
        arm.computeFrames(q.data(), frames);
        ASSERT_EQ(frames.size(), 6u);
        const Eigen::Isometry3d expected[] = {base, column, carriage, forearm, finger1, finger2};
        for (std::size_t k = 0; k < 6; ++k)
            EXPECT_LT((frames[k].matrix() - expected[k].matrix()).norm(), 1e-12) << "frame " << k;
        EXPECT_LT((arm.computeTipPose(q.data()).matrix() - finger1.matrix()).norm(), 1e-12);
    }

    // Position IK through the Jacobian: a prismatic joint's column is its axis.
    const std::vector<double> goal = {0.4, 0.1, -0.8, 0.01};
    const Eigen::Vector3d target = arm.computeTipPose(goal.data()).translation();
    std::vector<double> solution;
    ASSERT_TRUE(arm.solvePositionIk(target, rng, solution));
    EXPECT_LT((arm.computeTipPose(solution.data()).translation() - target).norm(), 1e-4);
}

TEST(UrdfPrismatic, DisplacementBoundHoldsForPrismaticAndMimicJoints)
{
    const auto arm = std::make_shared<UrdfArm>("arm", nullptr, test::gripperArmUrdf("1 0.5 0.2"), "base", "finger1",
                                               UrdfArm::pose(1., 2., 0.5, 0.3, -0.1, 0.4));
    const DisplacementBound bound(*arm);
    const unsigned int n = arm->getDimension();
    std::mt19937 rng(3);
    CollisionBody start, moved;
    std::size_t checked = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        // A short step (up to a tenth of each range, or a whole one every tenth trial) within the bounds.
        const std::vector<double> q0 = test::randomConfig(*arm, rng);
        std::vector<double> dq(n), qs(n), step(n);
        for (unsigned int k = 0; k < n; ++k)
        {
            const double range = arm->getBounds().high[k] - arm->getBounds().low[k];
            const double scale = trial % 10 == 0 ? 1. : 0.1;
            dq[k] = std::clamp(q0[k] + std::uniform_real_distribution<double>(-scale, scale)(rng) * range,
                               arm->getBounds().low[k], arm->getBounds().high[k]) -
                    q0[k];
        }
        arm->computeCapsules(q0.data(), start);
        for (double s : {0.25, 0.5, 1.})
        {
            for (unsigned int k = 0; k < n; ++k)
            {
                qs[k] = q0[k] + s * dq[k];
                step[k] = s * dq[k];
            }
            arm->computeCapsules(qs.data(), moved);
            const double whole = bound(step.data());
            for (std::size_t c = 0; c < start.size(); ++c)
            {
                const double capsule = bound.capsuleBound(c, step.data());
                EXPECT_LE(capsule, whole + 1e-15);
                for (bool b : {false, true})
                {
                    const double moves = (capsuleEnd(moved, c, b) - capsuleEnd(start, c, b)).norm();
                    EXPECT_LE(moves, capsule * (1. + 1e-9) + 1e-12) << "trial " << trial << " capsule " << c;
                    ++checked;
                }
            }
        }
    }
    EXPECT_EQ(checked, 3000u * 3u * 2u * start.size());

    // The fingers slide: opening them by df moves either finger's ends by exactly df, and the bound says so.
    std::vector<double> q = {0.3, 0.1, -0.5, 0.01}, open = q, dq(n, 0.);
    open[3] = 0.04;
    dq[3] = 0.03;
    arm->computeCapsules(q.data(), start);
    arm->computeCapsules(open.data(), moved);
    for (const char *finger : {"finger1", "finger2"})
    {
        const std::size_t c = primitiveOf(*arm, finger);
        EXPECT_NEAR((capsuleEnd(moved, c, true) - capsuleEnd(start, c, true)).norm(), 0.03, 1e-12) << finger;
        EXPECT_NEAR(bound.capsuleBound(c, dq.data()), 0.03, 1e-12) << finger;
    }
}

TEST(UrdfPrismatic, AGrippersMimicFingerOffTheChainMovesWithTheFirst)
{
    const UrdfArm arm("arm", nullptr, test::gripperArmUrdf(), "base", "finger1", Eigen::Isometry3d::Identity());
    EXPECT_EQ(arm.getCoordinateNames(), (std::vector<std::string>{"turn", "slide", "bend", "finger_joint1"}));
    ASSERT_EQ(arm.getJoints().size(), 5u);
    EXPECT_EQ(arm.getChainJointCount(), 4u);
    const UrdfArm::Joint &mimic = arm.getJoints()[4];
    EXPECT_EQ(mimic.name, "finger_joint2");
    EXPECT_TRUE(mimic.prismatic);
    EXPECT_EQ(mimic.parent, 3u);  // the forearm's frame, which the hand is fixed to
    EXPECT_EQ(mimic.coordinate, 3u);
    EXPECT_EQ(arm.getPrimitives()[primitiveOf(arm, "finger2")].frame, 5u);
    // One velocity limit per coordinate, the URDF's.
    const MotionLimits limits = arm.getMotionLimits();
    ASSERT_EQ(limits.groups.size(), 4u);
    const double velocities[] = {1.5, 0.5, 1., 0.2};
    for (std::size_t g = 0; g < 4; ++g)
        EXPECT_DOUBLE_EQ(limits.groups[g].velocity, velocities[g]) << g;
    // The fingers' centres are 0.02 apart when closed and 0.02 + 2 f when open by f, wherever the arm is.
    const std::size_t f1 = primitiveOf(arm, "finger1"), f2 = primitiveOf(arm, "finger2");
    CollisionBody body;
    for (double f : {0., 0.02, 0.05})
    {
        const std::vector<double> q = {0.7, -0.1, 1.2, f};
        arm.computeCapsules(q.data(), body);
        const Eigen::Vector3d c1 = 0.5 * (capsuleEnd(body, f1, false) + capsuleEnd(body, f1, true));
        const Eigen::Vector3d c2 = 0.5 * (capsuleEnd(body, f2, false) + capsuleEnd(body, f2, true));
        EXPECT_NEAR((c1 - c2).norm(), 0.02 + 2. * f, 1e-12) << f;
    }
}

TEST(UrdfPrismatic, JointsOffTheChainThatFollowNoneOfItsJointsAreHeldStill)
{
    // The chain ends at the hand: both fingers hang off it, the first mimicking nothing (held at 0 clamped into
    // its limits, 0 .. 0.05), the second mimicking the first (held where the first is). And a finger that mimics
    // nothing with limits 0.01 .. 0.05 is held at 0.01.
    const UrdfArm arm("arm", nullptr, test::gripperArmUrdf(), "base", "hand", Eigen::Isometry3d::Identity());
    EXPECT_EQ(arm.getCoordinateNames(), (std::vector<std::string>{"turn", "slide", "bend"}));
    EXPECT_EQ(arm.getJoints().size(), 3u);
    const UrdfArm held("arm", nullptr,
                       replaced(test::gripperArmUrdf("1 0 0", ""), "<limit lower=\"0\" upper=\"0.05\"",
                                "<limit lower=\"0.01\" upper=\"0.05\""),
                       "base", "hand", Eigen::Isometry3d::Identity());
    const std::size_t f1 = primitiveOf(arm, "finger1"), f2 = primitiveOf(arm, "finger2");
    CollisionBody body, heldBody;
    for (const std::vector<double> &q : {std::vector<double>{0.7, -0.1, 1.2}, std::vector<double>{-2., 0.2, 0.3}})
    {
        arm.computeCapsules(q.data(), body);
        held.computeCapsules(q.data(), heldBody);
        const auto centre = [](const CollisionBody &b, std::size_t k)
        { return Eigen::Vector3d(0.5 * (capsuleEnd(b, k, false) + capsuleEnd(b, k, true))); };
        EXPECT_NEAR((centre(body, f1) - centre(body, f2)).norm(), 0.02, 1e-12);
        // Held open by 0.01 (finger 1) and closed (finger 2 mimics nothing there).
        EXPECT_NEAR((centre(heldBody, f1) - centre(heldBody, f2)).norm(), 0.03, 1e-12);
    }
}

TEST(UrdfPrismatic, MimicJointsOnTheChainAndMimicsOfMimics)
{
    // j2 = 2 j1 on the chain: one coordinate, the lower link at three times j1's angle from vertical.
    const UrdfArm bender("arm", nullptr, benderUrdf(), "base", "tip", Eigen::Isometry3d::Identity());
    ASSERT_EQ(bender.getDimension(), 1u);
    EXPECT_EQ(bender.getCoordinateNames(), std::vector<std::string>{"j1"});
    // j2's limit (-2 .. 2) narrows j1 (-1 .. 1) to -1 .. 1 divided by the multiplier.
    EXPECT_DOUBLE_EQ(bender.getBounds().low[0], -1.);
    EXPECT_DOUBLE_EQ(bender.getBounds().high[0], 1.);
    const double a = 0.3;
    const Eigen::Vector3d tip = 0.4 * Eigen::Vector3d(std::sin(a), 0., std::cos(a)) +
                                0.4 * Eigen::Vector3d(std::sin(3. * a), 0., std::cos(3. * a));
    EXPECT_LT((bender.computeTipPose(&a).translation() - tip).norm(), 1e-12);
    std::mt19937 rng(2);
    std::vector<double> solution;
    ASSERT_TRUE(bender.solvePositionIk(tip, rng, solution));
    EXPECT_NEAR(solution[0], a, 1e-3);

    // A joint off the chain mimicking j2 (0.5 j2 + 0.1) follows j1 + 0.1, and j2 = 3 j1 narrows j1 to -2/3 .. 2/3.
    const UrdfArm side("arm", nullptr,
                       benderUrdf("<mimic joint=\"j1\" multiplier=\"3\"/>",
                                  sideJoint("<mimic joint=\"j2\" multiplier=\"0.5\" offset=\"0.1\"/>")),
                       "base", "tip", Eigen::Isometry3d::Identity());
    ASSERT_EQ(side.getJoints().size(), 3u);
    const UrdfArm::Joint &follower = side.getJoints()[2];
    EXPECT_EQ(follower.coordinate, 0u);
    EXPECT_EQ(follower.parent, 1u);
    EXPECT_DOUBLE_EQ(follower.multiplier, 1.5);
    EXPECT_DOUBLE_EQ(follower.offset, 0.1);
    EXPECT_DOUBLE_EQ(side.getBounds().high[0], 2. / 3.);
    std::vector<Eigen::Isometry3d> frames;
    side.computeFrames(&a, frames);
    ASSERT_EQ(frames.size(), 4u);
    const Eigen::Isometry3d expected = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()) *
                                       Eigen::Translation3d(0.1, 0., 0.2) *
                                       Eigen::AngleAxisd(1.5 * a + 0.1, Eigen::Vector3d::UnitX());
    EXPECT_LT((frames[3].matrix() - expected.matrix()).norm(), 1e-12);
}

TEST(UrdfPrismatic, AMimicJointsLimitsNarrowTheRangeAndVelocityOfTheCoordinateItFollows)
{
    // A second finger that opens only to 0.04 keeps the first within 0.04.
    const UrdfArm narrow("arm", nullptr, test::gripperArmUrdf("1 0 0", "<mimic joint=\"finger_joint1\"/>", "0.04"),
                         "base", "finger1", Eigen::Isometry3d::Identity());
    EXPECT_DOUBLE_EQ(narrow.getBounds().low[3], 0.);
    EXPECT_DOUBLE_EQ(narrow.getBounds().high[3], 0.04);
    // 2 q - 0.01 within 0 .. 0.05: q within 0.005 .. 0.03; twice as fast, so half the velocity limit.
    const UrdfArm twice(
        "arm", nullptr,
        test::gripperArmUrdf("1 0 0", "<mimic joint=\"finger_joint1\" multiplier=\"2\" offset=\"-0.01\"/>"), "base",
        "finger1", Eigen::Isometry3d::Identity());
    EXPECT_NEAR(twice.getBounds().low[3], 0.005, 1e-15);
    EXPECT_NEAR(twice.getBounds().high[3], 0.03, 1e-15);
    EXPECT_DOUBLE_EQ(twice.getMotionLimits().groups[3].velocity, 0.1);
    // -q within 0 .. 0.05 leaves q (0 .. 0.05) only 0: refused.
    expectJointError(test::gripperArmUrdf("1 0 0", "<mimic joint=\"finger_joint1\" multiplier=\"-1\"/>"),
                     "mimic joint 'finger_joint2' leaves joint 'finger_joint1' no range within both joints' <limit>s");
}

TEST(UrdfPrismatic, BadJointsAndMimicsAreRefusedInOneLineNamingTheJoint)
{
    const std::string gripper = test::gripperArmUrdf();
    const std::string slideLimit = "<limit lower=\"-0.2\" upper=\"0.3\" effort=\"1\" velocity=\"0.5\"/>";
    // A prismatic joint needs a <limit> (urdfdom's error), a non-empty and a finite one (ours).
    expectJointError(replaced(gripper, slideLimit, ""), "malformed URDF: Joint [slide] is of type PRISMATIC");
    expectJointError(replaced(gripper, slideLimit, "<limit lower=\"0.1\" upper=\"0.1\" effort=\"1\" velocity=\"1\"/>"),
                     "prismatic joint 'slide' has an empty <limit>");
    expectJointError(replaced(gripper, slideLimit, "<limit lower=\"0\" upper=\"1e999\" effort=\"1\" velocity=\"1\"/>"),
                     "malformed URDF: upper value (1e999) is not a valid float");
    expectJointError(replaced(gripper, "<axis xyz=\"1 0 0\"/>", "<axis xyz=\"0 0 0\"/>"),
                     "joint 'slide' has a zero or non-finite <axis>");
    // Mimics of an unknown joint, of a fixed joint, of a joint off the chain, of itself and in a loop of two.
    expectJointError(benderUrdf("<mimic joint=\"nowhere\"/>"),
                     "joint 'j2' mimics joint 'nowhere', which leads to unknown joint 'nowhere'", "base", "tip");
    expectJointError(benderUrdf("<mimic joint=\"j3\"/>"),
                     "joint 'j2' mimics joint 'j3', which leads to joint 'j3', not a movable joint", "base", "tip");
    expectJointError(benderUrdf(),
                     "joint 'j2' mimics joint 'j1', which leads to joint 'j1', not a movable joint of chain 'upper' .. "
                     "'tip'",
                     "upper", "tip");
    expectJointError(benderUrdf("<mimic joint=\"j2\"/>"),
                     "joint 'j2' mimics joint 'j2': the mimics form a loop through joint 'j2'", "base", "tip");
    expectJointError(benderUrdf("<mimic joint=\"side_joint\"/>", sideJoint("<mimic joint=\"j2\"/>")),
                     "joint 'j2' mimics joint 'side_joint': the mimics form a loop through joint 'j2'", "base", "tip");
}

TEST(UrdfPrismatic, TwoGripperArmsArePlannedAndTheValidatorAgrees)
{
    // Facing each other 0.9 apart, forearms level and carriages slid out: the left arm turns out of the middle
    // while the right one turns into it, so going straight at once their hands meet half way.
    auto environment = std::make_shared<Environment>();
    const std::string urdf = test::gripperArmUrdf();
    std::vector<RobotPtr> team = {std::make_shared<UrdfArm>("left", environment, urdf, "base", "finger1",
                                                            UrdfArm::pose(-0.45, 0., 0., 0., 0., 0.)),
                                  std::make_shared<UrdfArm>("right", environment, urdf, "base", "finger1",
                                                            UrdfArm::pose(0.45, 0., 0., 0., 0., M_PI))};
    const std::vector<double> reaching = {0., 0.3, 1.5, 0.04}, rightAside = {1.5, 0.3, 1.5, 0.},
                              leftAside = {-1.5, 0.3, 1.5, 0.};
    const MultiRobotProblem problem(std::make_shared<MultiRobotSpaceInformation>(team), {reaching, rightAside},
                                    {leftAside, reaching}, "gripper_pair");
    ASSERT_EQ(problem.checkEndpoints(), "");
    ASSERT_EQ(problem.getSpaceInformation()->checkPlanningResolution(), "");
    ASSERT_FALSE(test::allConflicts(*problem.getSpaceInformation(), test::straightLinePlan(problem)).empty());
    ARC planner(problem.getSpaceInformation());
    planner.setSeed(1);
    ASSERT_EQ(test::solveWith(planner, problem, 60.), ob::PlannerStatus::EXACT_SOLUTION) << planner.getStatusMessage();
    EXPECT_GT(planner.getStatistics().repairs, 0u);
    const auto report = SolutionValidator(problem).validate(planner.getPlan());
    EXPECT_TRUE(report.valid) << report.message;

    // Through a scenario file and back: the same coordinates, the mimic finger included, and the plan still valid.
    const MultiRobotProblem again = ScenarioFile::fromJson(ScenarioFile::toJson(problem));
    const auto arm = std::dynamic_pointer_cast<const UrdfArm>(again.getSpaceInformation()->getRobot(1));
    ASSERT_NE(arm, nullptr);
    EXPECT_EQ(arm->getCoordinateNames(), team[1]->getCoordinateNames());
    EXPECT_EQ(arm->getJoints().size(), 5u);
    EXPECT_TRUE(SolutionValidator(again).validate(planner.getPlan()).valid);
}
