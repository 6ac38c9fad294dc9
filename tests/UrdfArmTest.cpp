#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_parc;

namespace
{
    std::shared_ptr<UrdfArm> panda(const Eigen::Isometry3d &base = Eigen::Isometry3d::Identity())
    {
        return std::make_shared<UrdfArm>("panda", nullptr, models::pandaUrdf(), "panda_link0", "panda_link8", base);
    }

    /** A two-joint arm with one box, one cylinder and one sphere; \e extra is spliced in before </robot>. */
    std::string smallArm(const std::string &joint2Type = "revolute",
                         const std::string &limit2 = "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         const std::string &geometry = "<box size=\"0.1 0.1 0.4\"/>", const std::string &extra = "")
    {
        return R"(<robot name="small">
  <link name="base"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.2"/><geometry>)" +
               geometry + R"(</geometry></collision></link>
  <link name="lower"><collision><origin xyz="0 0 0.2"/><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision></link>
  <link name="tip"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="j2" type=")" +
               joint2Type +
               R"("><parent link="upper"/><child link="lower"/><origin xyz="0 0 0.4"/><axis xyz="0 1 0"/>)" + limit2 +
               R"(</joint>
  <joint name="j3" type="fixed"><parent link="lower"/><child link="tip"/><origin xyz="0 0 0.4"/></joint>
)" + extra + "</robot>";
    }

    void expectError(const std::string &urdf, const std::string &needle, const std::string &baseLink = "base",
                     const std::string &tipLink = "tip")
    {
        try
        {
            UrdfArm("arm", nullptr, urdf, baseLink, tipLink, Eigen::Isometry3d::Identity());
            ADD_FAILURE() << "no error, expected one mentioning '" << needle << "'";
        }
        catch (const ompl::Exception &e)
        {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    }
}  // namespace

TEST(UrdfArm, PandaForwardKinematicsMatchesHandComputedPoses)
{
    const auto arm = panda();
    ASSERT_EQ(arm->getDimension(), 7u);
    EXPECT_EQ(arm->getKind(), "urdf_arm");
    // Zero configuration: flange at the published (0.088, 0, 0.926), pointing down.
    std::vector<double> q(7, 0.);
    auto tip = arm->computeTipPose(q.data());
    EXPECT_LT((tip.translation() - Eigen::Vector3d(0.088, 0., 0.926)).norm(), 1e-6);
    EXPECT_LT((tip.linear().col(2) - Eigen::Vector3d(0., 0., -1.)).norm(), 1e-6);
    // Joint 1 at +90 degrees turns it about z.
    q[0] = M_PI / 2;
    tip = arm->computeTipPose(q.data());
    EXPECT_LT((tip.translation() - Eigen::Vector3d(0., 0.088, 0.926)).norm(), 1e-6);
    // Elbow (joint 4) at -90 degrees: joint 5 at (0.0825 + 0.384, 0, 0.649 + 0.0825), the wrist offset 0.088
    // points down and the flange 0.107 back towards the base (worked out frame by frame with the DH table).
    q = {0., 0., 0., -M_PI / 2, 0., 0., 0.};
    tip = arm->computeTipPose(q.data());
    EXPECT_LT((tip.translation() - Eigen::Vector3d(0.3595, 0., 0.6435)).norm(), 1e-6);
    EXPECT_LT((tip.linear().col(2) - Eigen::Vector3d(-1., 0., 0.)).norm(), 1e-6);
    // The base pose moves everything: base at (1, 2, 0.5) turned by 180 degrees about z.
    const auto moved = panda(UrdfArm::pose(1., 2., 0.5, 0., 0., M_PI));
    q.assign(7, 0.);
    EXPECT_LT((moved->computeTipPose(q.data()).translation() - Eigen::Vector3d(1. - 0.088, 2., 1.426)).norm(), 1e-6);
}

TEST(UrdfArm, PandaLimitsGeometryAndSelfCollision)
{
    const auto arm = panda();
    EXPECT_DOUBLE_EQ(arm->getBounds().low[3], -3.0718);
    EXPECT_DOUBLE_EQ(arm->getBounds().high[5], 3.7525);
    // The hand (fixed below the tip) is folded into the last link.
    EXPECT_EQ(arm->getPrimitives().back().shape.name, "panda_hand");
    EXPECT_EQ(arm->getPrimitives().back().frame, 7u);
    EXPECT_FALSE(arm->getSelfCollisionPairs().empty());
    // The "ready" pose is valid; folding the hand into the base is self-collision.
    const std::vector<double> ready = {0., -M_PI / 4, 0., -3 * M_PI / 4, 0., M_PI / 2, M_PI / 4};
    EXPECT_EQ(arm->checkValidity(ready.data()), Robot::Validity::VALID);
    const std::vector<double> folded = {0., 1.7, 0., -3.0, 0., 3.7, 0.};
    EXPECT_EQ(arm->checkValidity(folded.data()), Robot::Validity::SELF_COLLISION);
}

TEST(UrdfArm, PrimitivesBecomeEnclosingCapsules)
{
    const UrdfArm arm("arm", nullptr, smallArm(), "base", "tip", Eigen::Isometry3d::Identity());
    ASSERT_EQ(arm.getDimension(), 2u);
    const std::vector<double> q = {0., 0.};
    CollisionBody body;
    arm.computeBody(q.data(), body);
    ASSERT_EQ(body.size(), 3u);
    // Sphere at the base; box 0.1 x 0.1 x 0.4 -> capsule along z over its length, radius = half-diagonal of
    // the 0.1 x 0.1 cross-section; cylinder -> same axis and radius.
    EXPECT_DOUBLE_EQ(body.radius_[0], 0.1);
    EXPECT_NEAR(body.radius_[1], std::sqrt(0.005), 1e-12);
    EXPECT_NEAR(body.az_[1], 0., 1e-12);
    EXPECT_NEAR(body.bz_[1], 0.4, 1e-12);
    EXPECT_DOUBLE_EQ(body.radius_[2], 0.05);
    EXPECT_NEAR(body.az_[2], 0.4, 1e-12);
    EXPECT_NEAR(body.bz_[2], 0.8, 1e-12);
    EXPECT_LT((arm.computeTipPose(q.data()).translation() - Eigen::Vector3d(0., 0., 0.8)).norm(), 1e-12);
    // Base and lower link are not adjacent: one self-collision pair, and they do not touch at zero.
    ASSERT_EQ(arm.getSelfCollisionPairs().size(), 1u);
}

TEST(UrdfArm, KinematicsOfJointsTurningAboutOtherAxesThanZ)
{
    // Both joints of the small arm turn about y: link k's direction is (sin s, 0, cos s) with s the sum of
    // the joint angles up to k, each link 0.4 long. Checks the body, the frames and IK through the Jacobian.
    const UrdfArm arm("arm", nullptr, smallArm(), "base", "tip", UrdfArm::pose(1., 2., 3., 0., 0., 0.));
    const std::vector<double> q = {0.5, -0.9};
    const Eigen::Vector3d base(1., 2., 3.), direction1(std::sin(0.5), 0., std::cos(0.5));
    const Eigen::Vector3d direction2(std::sin(-0.4), 0., std::cos(-0.4));
    const Eigen::Vector3d elbow = base + 0.4 * direction1, tip = elbow + 0.4 * direction2;
    CollisionBody body;
    arm.computeBody(q.data(), body);
    ASSERT_EQ(body.size(), 3u);
    EXPECT_LT((Eigen::Vector3d(body.bx_[1], body.by_[1], body.bz_[1]) - elbow).norm(), 1e-12);
    EXPECT_LT((Eigen::Vector3d(body.ax_[2], body.ay_[2], body.az_[2]) - elbow).norm(), 1e-12);
    EXPECT_LT((Eigen::Vector3d(body.bx_[2], body.by_[2], body.bz_[2]) - tip).norm(), 1e-12);
    std::vector<Eigen::Isometry3d> frames;
    arm.computeFrames(q.data(), frames);
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_LT((frames[2].translation() - elbow).norm(), 1e-12);
    EXPECT_LT((frames[2].linear() * Eigen::Vector3d::UnitZ() - direction2).norm(), 1e-12);
    EXPECT_LT((arm.computeTipPose(q.data()).translation() - tip).norm(), 1e-12);

    std::mt19937 rng(5);
    std::vector<double> solution;
    ASSERT_TRUE(arm.solvePositionIk(tip, rng, solution));
    EXPECT_LT((arm.computeTipPose(solution.data()).translation() - tip).norm(), 1e-4);
}

TEST(UrdfArm, ContinuousJointsAreBoundedToPlusMinusPi)
{
    const UrdfArm arm("arm", nullptr, smallArm("continuous", ""), "base", "tip", Eigen::Isometry3d::Identity());
    EXPECT_DOUBLE_EQ(arm.getBounds().low[1], -M_PI);
    EXPECT_DOUBLE_EQ(arm.getBounds().high[1], M_PI);
}

TEST(UrdfArm, ClearErrorsNameTheElement)
{
    expectError("<robot name=\"broken\"><link name=\"a\"></robot>", "malformed URDF");
    // urdfdom rejects a revolute joint without <limit>; its first error is the message's one line.
    expectError(smallArm("revolute", ""), "malformed URDF: Joint [j2] is of type REVOLUTE but it does not specify");
    expectError(smallArm("floating"), "joint 'j2' is not revolute, continuous, prismatic or fixed (unsupported)");
    expectError(smallArm("revolute", "<limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>"), "joint 'j2'");
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<mesh filename=\"upper.stl\"/>"),
                "link 'upper'");
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<box size=\"0.1 0.1 0.4\"/>",
                         "<link name=\"side\"/><joint name=\"branch\" type=\"floating\"><parent link=\"upper\"/>"
                         "<child link=\"side\"/></joint>"),
                "joint 'branch' is not revolute, continuous, prismatic or fixed");
    expectError(smallArm(), "no tip link 'nowhere'", "base", "nowhere");
    expectError(smallArm(), "tip link 'base' is not below base link 'tip'", "tip", "base");
    expectError(smallArm(), "chain 'lower' .. 'tip' has no movable joint", "lower", "tip");
}

TEST(UrdfArm, HostileUrdfsAreRefusedWithoutHangingOrOverflowing)
{
    // A joint whose parent and child are the same link, on the chain: the walk from the tip used to loop forever.
    const std::string selfLoop = R"(<robot name="loop">
  <link name="base"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="upper"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="self" type="fixed"><parent link="upper"/><child link="upper"/></joint>
</robot>)";
    expectError(selfLoop, "the URDF's joints form a loop through link 'upper'", "base", "upper");
    // The same off the chain: a fixed side link that is its own child (the collection recursed without end).
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<box size=\"0.1 0.1 0.4\"/>",
                         "<link name=\"side\"/><joint name=\"branch\" type=\"fixed\"><parent link=\"upper\"/>"
                         "<child link=\"side\"/></joint><joint name=\"again\" type=\"fixed\"><parent link=\"side\"/>"
                         "<child link=\"side\"/></joint>"),
                "the URDF's joints form a loop through link 'side'");
    // Two links that are each other's parent, off the chain: urdfdom linked them into a cycle it never freed
    // (found by fuzzing); refused before urdfdom reads the URDF. So is a link with two parents.
    const std::string pair =
        "<link name=\"p\"/><link name=\"q\"/><joint name=\"pq\" type=\"fixed\"><parent "
        "link=\"p\"/><child link=\"q\"/></joint><joint name=\"qp\" type=\"fixed\"><parent "
        "link=\"q\"/><child link=\"p\"/></joint>";
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<box size=\"0.1 0.1 0.4\"/>", pair),
                "the URDF's joints form a loop through link");
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<box size=\"0.1 0.1 0.4\"/>",
                         "<joint name=\"again\" type=\"fixed\"><parent link=\"base\"/><child link=\"lower\"/>"
                         "</joint>"),
                "link 'lower' is the child of two joints");
    // The same loop after a joint urdfdom cannot read (no <child>): still refused before urdfdom links the rest.
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<box size=\"0.1 0.1 0.4\"/>",
                         "<joint name=\"bad\" type=\"fixed\"><parent link=\"tip\"/></joint><joint name=\"self\" "
                         "type=\"fixed\"><parent link=\"lower\"/><child link=\"lower\"/></joint>"),
                "the URDF's joints form a loop through link 'lower'");
    // Text that is not UTF-8: a lead byte at the end made TinyXML (urdfdom's parser) read past the text (found by
    // fuzzing); a NUL would end the text TinyXML sees early.
    expectError(smallArm() + "<!-- \xd3", "malformed URDF: not UTF-8 text (byte");
    expectError(smallArm() + std::string(1, '\0') + "<x/>", "malformed URDF: not UTF-8 text (byte");
    expectError(smallArm() + "<!-- \xe2\x82 -->", "malformed URDF: not UTF-8 text (byte");
    EXPECT_NO_THROW(UrdfArm("arm", nullptr, smallArm() + "<!-- \xe2\x82\xac \xc3\xa9 -->", "base", "tip",
                            Eigen::Isometry3d::Identity()));
    // A negative radius is not a smaller shape.
    expectError(smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                         "<cylinder radius=\"-0.05\" length=\"0.4\"/>"),
                "link 'upper' has a collision primitive of non-positive size");
    // 15 000 fixed links in a row under the tip: a valid URDF, collected without recursion.
    std::string row;
    for (int k = 0; k < 15000; ++k)
        row += "<link name=\"f" + std::to_string(k + 1) + "\"/><joint name=\"g" + std::to_string(k) +
               "\" type=\"fixed\"><parent link=\"" + (k == 0 ? std::string("tip") : "f" + std::to_string(k)) +
               "\"/><child link=\"f" + std::to_string(k + 1) + "\"/></joint>";
    const UrdfArm arm("long", nullptr,
                      smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                               "<box size=\"0.1 0.1 0.4\"/>", row),
                      "base", "tip", Eigen::Isometry3d::Identity());
    EXPECT_EQ(arm.getDimension(), 2u);
}

namespace
{
    /** The small arm with link \e link's (0: base, 1: upper, 2: lower) <collision> element replaced by \e collision. */
    std::string smallArmWithCollision(int link, const std::string &collision)
    {
        std::string urdf = smallArm();
        std::size_t at = 0;
        for (int k = 0; k <= link; ++k)
            at = urdf.find("<collision>", at + (k == 0 ? 0 : 1));
        const std::size_t end = urdf.find("</collision>", at) + std::string("</collision>").size();
        return urdf.replace(at, end - at, collision);
    }

    /** Collision elements urdfdom cannot read in full: every shape with each attribute value that is not a
        positive finite number in plain notation, with too few or too many numbers, missing, unknown shapes,
        no or two geometries or shapes, and origins that are not three finite numbers. */
    std::vector<std::string> unreadableCollisions()
    {
        const std::vector<std::string> badNumbers = {"nan", "NaN", "inf", "-inf", "1e999",   "-1e999", "0.2abc", "abc",
                                                     "",    " ",   "0x1", "1,5",  "0.1 0.2", "--1",    "1e",     "."};
        const auto wrap = [](const std::string &geometry, const std::string &origin = "")
        { return "<collision>" + origin + "<geometry>" + geometry + "</geometry></collision>"; };
        std::vector<std::string> out;
        for (const std::string &v : badNumbers)
        {
            out.push_back(wrap("<sphere radius=\"" + v + "\"/>"));
            out.push_back(wrap("<cylinder radius=\"" + v + "\" length=\"0.3\"/>"));
            out.push_back(wrap("<cylinder radius=\"0.1\" length=\"" + v + "\"/>"));
            out.push_back(wrap("<box size=\"" + v + " 0.1 0.1\"/>"));
            out.push_back(wrap("<box size=\"0.1 0.1 " + v + "\"/>"));
            out.push_back(wrap("<sphere radius=\"0.1\"/>", "<origin xyz=\"" + v + " 0 0\"/>"));
            out.push_back(wrap("<sphere radius=\"0.1\"/>", "<origin rpy=\"0 " + v + " 0\"/>"));
        }
        for (const std::string &size : {"0.1 0.1", "0.1", "0.1 0.1 0.1 0.1", ""})
            out.push_back(wrap("<box size=\"" + std::string(size) + "\"/>"));
        for (const std::string &xyz : {"1 0", "1 0 0 0", "1", "a b c"})
            out.push_back(wrap("<sphere radius=\"0.1\"/>", "<origin xyz=\"" + std::string(xyz) + "\"/>"));
        for (const std::string &shape : {"<capsule radius=\"0.1\" length=\"0.2\"/>", "<cone radius=\"0.1\"/>",
                                         "<sphere/>", "<cylinder radius=\"0.1\"/>", "<cylinder length=\"0.1\"/>",
                                         "<box/>", "", "<sphere radius=\"0.1\"/><box size=\"1 1 1\"/>"})
            out.push_back(wrap(shape));
        out.push_back("<collision></collision>");
        out.push_back("<collision><origin xyz=\"0 0 0\"/></collision>");
        out.push_back(
            "<collision><geometry><sphere radius=\"0.1\"/></geometry><geometry><box size=\"1 1 1\"/>"
            "</geometry></collision>");
        out.push_back(
            "<collision><origin xyz=\"0 0 0\"/><origin xyz=\"1 0 0\"/><geometry><sphere radius=\"0.1\"/>"
            "</geometry></collision>");
        // Readable, but no volume: refused as non-positive (a negative size is not a smaller shape).
        for (const std::string &v : {"0", "-0.1", "1e-400"})
        {
            out.push_back(wrap("<sphere radius=\"" + v + "\"/>"));
            out.push_back(wrap("<box size=\"0.1 " + v + " 0.1\"/>"));
        }
        return out;
    }
}  // namespace

TEST(UrdfArm, EveryUrdfWithAnUnreadableCollisionElementIsRefused)
{
    // The control: the readable element each case below breaks is accepted on every link.
    for (int link = 0; link < 3; ++link)
        EXPECT_NO_THROW(UrdfArm("arm", nullptr,
                                smallArmWithCollision(link,
                                                      "<collision><origin xyz=\"0 0 0.1\" rpy=\"0 0.5 0\"/>"
                                                      "<geometry><sphere radius=\"0.05\"/></geometry>"
                                                      "</collision>"),
                                "base", "tip", Eigen::Isometry3d::Identity()));
    const auto cases = unreadableCollisions();
    ASSERT_GT(cases.size(), 130u);
    std::size_t refused = 0;
    for (int link = 0; link < 3; ++link)
        for (const std::string &collision : cases)
        {
            try
            {
                UrdfArm("arm", nullptr, smallArmWithCollision(link, collision), "base", "tip",
                        Eigen::Isometry3d::Identity());
                ADD_FAILURE() << "accepted link " << link << " with " << collision;
            }
            catch (const ompl::Exception &e)
            {
                ++refused;
                EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            }
        }
    EXPECT_EQ(refused, 3 * cases.size());
}

TEST(UrdfArm, MimicsOfUnknownJointsAndNonFiniteJointsAreRefused)
{
    expectError(
        smallArm("revolute", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/><mimic joint=\"nowhere\"/>"),
        "joint 'j2' mimics joint 'nowhere', which leads to unknown joint 'nowhere'");
    for (const std::string &v : {"nan", "inf", "1e999", "0.5x"})
    {
        SCOPED_TRACE(v);
        EXPECT_THROW(
            UrdfArm("arm", nullptr,
                    smallArm("revolute", "<limit lower=\"-1\" upper=\"" + v + "\" effort=\"1\" velocity=\"1\"/>"),
                    "base", "tip", Eigen::Isometry3d::Identity()),
            ompl::Exception);
    }
}

TEST(UrdfArm, ABasePoseThatPutsAFixedLinkIntoAnObstacleNamesBoth)
{
    // The small arm's base sphere (radius 0.1, never moving) 0.15 from a box's face: fine at 0.15, not at 0.05.
    auto environment = std::make_shared<Environment>();
    Obstacle wall;
    wall.name = "wall";
    wall.size = Eigen::Vector3d(0.2, 2., 2.);
    wall.pose.translation() = Eigen::Vector3d(1., 0., 0.);
    environment->addObstacle(wall);
    EXPECT_NO_THROW(UrdfArm("arm", environment, smallArm(), "base", "tip", UrdfArm::pose(0.75, 0., 0., 0., 0., 0.)));
    try
    {
        UrdfArm("arm", environment, smallArm(), "base", "tip", UrdfArm::pose(0.85, 0., 0., 0., 0., 0.));
        ADD_FAILURE() << "no error";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("robot 'arm': link 'base', fixed to the base, collides with obstacle "
                                             "'wall'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(UrdfArm, PositionIkReachesTargets)
{
    const auto arm = panda();
    std::mt19937 rng(3);
    std::vector<double> q;
    const Eigen::Vector3d target(0.4, 0.2, 0.5);
    ASSERT_TRUE(arm->solvePositionIk(target, rng, q));
    EXPECT_LT((arm->computeTipPose(q.data()).translation() - target).norm(), 1e-4);
    EXPECT_TRUE(arm->isValid(q.data()));
    EXPECT_FALSE(arm->solvePositionIk(Eigen::Vector3d(3., 0., 0.), rng, q, 3));  // out of reach
}
