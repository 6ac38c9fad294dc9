/* SRDF: allowed link pairs for self-collision and chains named by group, from C++ and from scenario files. */
#include "TestProblems.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/Srdf.h"
#include "ompl_parc/robots/UrdfArm.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace ompl_parc;

namespace
{
    const std::string PANDA_SRDF = R"(<?xml version="1.0"?>
<robot name="panda">
  <group name="arm"><chain base_link="panda_link0" tip_link="panda_link8"/></group>
  <group_state name="ready" group="arm"><joint name="panda_joint1" value="0"/></group_state>
  <disable_collisions link1="panda_link1" link2="panda_link3" reason="Never"/>
</robot>)";

    std::shared_ptr<UrdfArm> panda(SrdfPtr srdf)
    {
        return std::make_shared<UrdfArm>("arm", std::make_shared<Environment>(), models::pandaUrdf(), "panda_link0",
                                         "panda_link8", Eigen::Isometry3d::Identity(), std::move(srdf));
    }
}  // namespace

TEST(Srdf, ReadsAllowedPairsInEitherOrderAndChainGroups)
{
    const Srdf srdf = Srdf::parse(PANDA_SRDF);
    EXPECT_TRUE(srdf.allows("panda_link1", "panda_link3"));
    EXPECT_TRUE(srdf.allows("panda_link3", "panda_link1"));
    EXPECT_FALSE(srdf.allows("panda_link1", "panda_link4"));
    EXPECT_EQ(srdf.getChain("arm"), std::make_pair(std::string("panda_link0"), std::string("panda_link8")));
    EXPECT_NE(test::messageOf([&] { srdf.getChain("hand"); }).find("no group 'hand' (chain groups: arm)"), std::string::npos);
}

TEST(Srdf, RefusesMalformedInputWithOneLine)
{
    for (const auto &[text, expected] : std::vector<std::pair<std::string, std::string>>{
             {"<robot><disable_collisions link1=\"a\"/></robot>", "has no link2"},
             {"<robot><group name=\"g\"><chain base_link=\"a\" tip_link=\"b\"/><chain base_link=\"a\" "
              "tip_link=\"c\"/></group></robot>",
              "more than one <chain>"},
             {"<robot><group name=\"g\"><link name=\"a\"/></group><group name=\"g\"><link name=\"b\"/></group>"
              "</robot>",
              "defined twice"},
             {"<robot><group name=\"g\"><chain base_link=\"a\" tip_link=\"b\"/></group>"
              "<group name=\"g\"><chain base_link=\"a\" tip_link=\"b\"/></group></robot>",
              "defined twice"},
             {"<robot><group", "malformed SRDF"},
             {"<model/>", "not <robot>"}})
    {
        const std::string message = test::messageOf([&] { Srdf::parse(text); });
        EXPECT_NE(message.find(expected), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST(Srdf, RemovesTheAllowedPairsFromTheArmsSelfCollisionCheck)
{
    const auto plain = panda(nullptr);
    const auto &primitives = plain->getPrimitives();
    const auto links = [&](const std::pair<std::size_t, std::size_t> &p)
    { return std::make_pair(primitives[p.first].shape.name, primitives[p.second].shape.name); };
    std::size_t checked = 0;
    for (const auto &pair : plain->getSelfCollisionPairs())
        checked += links(pair) == std::make_pair(std::string("panda_link1"), std::string("panda_link3")) ||
                   links(pair) == std::make_pair(std::string("panda_link3"), std::string("panda_link1"));
    ASSERT_GT(checked, 0u) << "the plain Panda checks panda_link1 against panda_link3";
    const auto allowed = panda(std::make_shared<Srdf>(Srdf::parse(PANDA_SRDF)));
    EXPECT_EQ(allowed->getSelfCollisionPairs().size(), plain->getSelfCollisionPairs().size() - checked);
    for (const auto &pair : allowed->getSelfCollisionPairs())
        EXPECT_FALSE(allowed->getSrdf()->allows(links(pair).first, links(pair).second));
}

TEST(Srdf, NamingALinkTheUrdfDoesNotHaveIsRefused)
{
    const auto srdf = std::make_shared<Srdf>(Srdf::parse(
        R"(<robot><disable_collisions link1="panda_link1" link2="gripper_finger" reason="Adjacent"/></robot>)"));
    const std::string message = test::messageOf([&] { panda(srdf); });
    EXPECT_NE(message.find("the SRDF names link 'gripper_finger', which the URDF does not have"), std::string::npos)
        << message;
}

TEST(Srdf, ScenarioFilesNameTheChainByGroupAndKeepTheSrdf)
{
    const auto folder = std::filesystem::temp_directory_path() / "ompl_parc_srdf_test";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "panda.srdf") << PANDA_SRDF;
    const std::string robot = R"({"name": "a", "kind": "urdf_arm", "builtin_urdf": "panda", ROBOT_FIELDS,
        "start": [0, 0, 0, -1.5, 0, 1.5, 0], "goal": [0.5, 0, 0, -1.5, 0, 1.5, 0]})";
    const auto scenario = [&](const std::string &fields)
    {
        std::string r = robot;
        r.replace(r.find("ROBOT_FIELDS"), std::string("ROBOT_FIELDS").size(), fields);
        return R"({"format": "ompl_parc.scenario", "version": 1, "name": "srdf", "obstacles": [], "robots": [)" + r +
               "]}";
    };
    const auto problem =
        ScenarioFile::fromJson(scenario(R"("srdf_file": "panda.srdf", "group": "arm")"), folder.string());
    const auto &arm = dynamic_cast<const UrdfArm &>(*problem.getSpaceInformation()->getRobot(0));
    EXPECT_EQ(arm.getBaseLink(), "panda_link0");
    EXPECT_EQ(arm.getTipLink(), "panda_link8");
    ASSERT_TRUE(arm.getSrdf());
    // Written back inline, read again the same.
    const auto again = ScenarioFile::fromJson(ScenarioFile::toJson(problem));
    const auto &armAgain = dynamic_cast<const UrdfArm &>(*again.getSpaceInformation()->getRobot(0));
    ASSERT_TRUE(armAgain.getSrdf());
    EXPECT_EQ(armAgain.getSelfCollisionPairs(), arm.getSelfCollisionPairs());

    for (const auto &[fields, expected] : std::vector<std::pair<std::string, std::string>>{
             {R"("group": "arm")", "group needs the SRDF"},
             {R"("srdf_file": "panda.srdf", "group": "hand")", "no group 'hand'"},
             {R"("srdf_file": "missing.srdf", "group": "arm")", "missing.srdf"},
             {R"("srdf_file": "panda.srdf", "srdf": "<robot/>", "group": "arm")", "give one"},
             {R"("srdf_file": "panda.srdf", "group": "arm", "base_link": "panda_link0")", "give the group or"}})
        EXPECT_NE(test::messageOf([&] { ScenarioFile::fromJson(scenario(fields), folder.string()); }).find(expected),
                  std::string::npos)
            << fields;
    std::filesystem::remove_all(folder);
}
