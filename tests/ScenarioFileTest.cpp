#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace ompl_parc;
using nlohmann::json;

namespace
{
    /** The example files in demos/scenarios/ (not built-ins), with the ARC profile that suits them. */
    const std::vector<std::pair<std::string, std::string>> EXAMPLES = {
        {"doorway_swap", "mobile"}, {"warehouse_aisle", "mobile"}, {"arm_trio", "planar"}};

    std::string examplePath(const std::string &name)
    {
        return std::string(OMPL_PARC_SCENARIO_DIR) + "/" + name + ".json";
    }

    std::string slurp(const std::string &path)
    {
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }

    void expectSameBounds(const ompl::base::RealVectorBounds &a, const ompl::base::RealVectorBounds &b)
    {
        EXPECT_EQ(a.low, b.low);
        EXPECT_EQ(a.high, b.high);
    }

    /** Everything a scenario file holds must come back: robots, parameters, obstacles, starts, goals. */
    void expectSameProblem(const MultiRobotProblem &a, const MultiRobotProblem &b)
    {
        const auto &sa = *a.getSpaceInformation(), &sb = *b.getSpaceInformation();
        EXPECT_EQ(a.getName(), b.getName());
        EXPECT_EQ(sa.getResolution(), sb.getResolution());
        ASSERT_EQ(sa.getRobotCount(), sb.getRobotCount());
        for (std::size_t i = 0; i < sa.getRobotCount(); ++i)
        {
            const Robot &ra = *sa.getRobot(i), &rb = *sb.getRobot(i);
            EXPECT_EQ(ra.getName(), rb.getName());
            ASSERT_EQ(ra.getKind(), rb.getKind());
            expectSameBounds(ra.getBounds(), rb.getBounds());
            if (const auto *da = dynamic_cast<const DiscRobot *>(&ra))
                EXPECT_EQ(da->getRadius(), dynamic_cast<const DiscRobot &>(rb).getRadius());
            if (const auto *pa = dynamic_cast<const PlanarArm *>(&ra))
            {
                const auto &pb = dynamic_cast<const PlanarArm &>(rb);
                EXPECT_EQ(pa->getBaseX(), pb.getBaseX());
                EXPECT_EQ(pa->getBaseY(), pb.getBaseY());
                EXPECT_EQ(pa->getBaseYaw(), pb.getBaseYaw());
                EXPECT_EQ(pa->getLinkLengths(), pb.getLinkLengths());
                EXPECT_EQ(pa->getLinkWidth(), pb.getLinkWidth());
            }
            if (const auto *ua = dynamic_cast<const UrdfArm *>(&ra))
            {
                const auto &ub = dynamic_cast<const UrdfArm &>(rb);
                EXPECT_EQ(ua->getUrdfXml(), ub.getUrdfXml());
                EXPECT_EQ(ua->getBaseLink(), ub.getBaseLink());
                EXPECT_EQ(ua->getTipLink(), ub.getTipLink());
                EXPECT_TRUE(ua->getBasePose().isApprox(ub.getBasePose(), 1e-12));
            }
            EXPECT_EQ(a.getStart(i), b.getStart(i));
            EXPECT_EQ(a.getGoal(i), b.getGoal(i));
        }
        const auto &oa = sa.getRobot(0)->getEnvironment()->getObstacles();
        const auto &ob = sb.getRobot(0)->getEnvironment()->getObstacles();
        ASSERT_EQ(oa.size(), ob.size());
        for (std::size_t k = 0; k < oa.size(); ++k)
        {
            EXPECT_EQ(oa[k].name, ob[k].name);
            EXPECT_EQ(oa[k].shape, ob[k].shape);
            EXPECT_EQ(oa[k].size, ob[k].size);
            // Rotations pass through a yaw or quaternion, exact for the axis-aligned obstacles used here.
            EXPECT_TRUE(oa[k].pose.matrix().isApprox(ob[k].pose.matrix(), 1e-12)) << oa[k].name;
        }
    }

    /** The error message for the scenario \e text (default: the example file doorway_swap) edited by \e edit. */
    std::string errorFor(const std::function<void(json &)> &edit, const std::string &text = "")
    {
        json doc = json::parse(text.empty() ? slurp(examplePath("doorway_swap")) : text);
        edit(doc);
        try
        {
            ScenarioFile::fromJson(doc.dump());
        }
        catch (const ompl::Exception &e)
        {
            return e.what();
        }
        return "no error";
    }
}  // namespace

TEST(ScenarioFile, BuiltInScenariosRoundTrip)
{
    const std::string path = testing::TempDir() + "/ompl_parc_scenario.json";
    for (const auto &name : scenarios::scenarioNames())
        for (std::size_t robots : {2u, 4u, 8u, 16u})
        {
            SCOPED_TRACE(name + " " + std::to_string(robots));
            const auto problem = scenarios::createScenario(name, robots, 64.);
            ScenarioFile::write(path, problem);
            expectSameProblem(problem, ScenarioFile::read(path));
        }
    std::remove(path.c_str());
}

TEST(ScenarioFile, ObstacleShapesRoundTrip)
{
    auto text = json::parse(slurp(examplePath("doorway_swap")));
    text["obstacles"].push_back({{"name", "ball"}, {"shape", "sphere"}, {"radius", 0.3}, {"position", {6, 6, 0}}});
    text["obstacles"].push_back({{"name", "crate"},
                                 {"shape", "box"},
                                 {"size", {1, 2, 0.5}},
                                 {"position", {-6, 6, 0}},
                                 {"orientation", {0.5, 0.5, 0.5, 0.5}}});
    text["obstacles"].push_back(
        {{"name", "turned"}, {"shape", "box2d"}, {"center", {6, -6}}, {"size", {1, 0.5}}, {"yaw", 0.7}});
    const auto problem = ScenarioFile::fromJson(text.dump());
    ASSERT_EQ(problem.getSpaceInformation()->getRobot(0)->getEnvironment()->getObstacles().size(), 5u);
    expectSameProblem(problem, ScenarioFile::fromJson(ScenarioFile::toJson(problem)));
}

TEST(ScenarioFile, ErrorsNameTheField)
{
    auto has = [](const std::string &message, const std::string &part)
    { return message.find(part) != std::string::npos; };
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["robots"][2]["radius"] = -1; }), "robots[2].radius must be a positive number"));
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["robots"][1]["radius"] = "big"; }), "robots[1].radius must be a positive number"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][3]["name"] = "west_a"; }),
                    "robots[3].name 'west_a' is already used by robots[0]"));
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["robots"][0]["start"] = {1}; }), "robots[0].start must be an array of 2 numbers"));
    EXPECT_TRUE(has(errorFor(
                        [](json &d) {
                            d["robots"][0]["goal"] = {1, 2, 3};
                        }),
                    "robots[0].goal must be an array of 2 numbers"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0].erase("bounds"); }), "robots[0]: missing field 'bounds'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["bounds"]["low"][1] = 9; }),
                    "robots[0].bounds.low[1] must be below robots[0].bounds.high[1]"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["raduis"] = 1; }), "robots[0]: unknown field 'raduis'"));
    // Names are printed by the tools: a control character (an escape sequence, a line break, DEL, a C1 control in
    // UTF-8) is refused with the place it is at, without echoing it; other UTF-8 text loads.
    EXPECT_EQ(errorFor([](json &d) { d["robots"][2]["name"] = "east\x1b[2J"; }),
              "ScenarioFile: robots[2].name must be printable: it holds a control character at byte 4");
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["robots"][0]["name"] = "csi\xc2\x9b"; }), "robots[0].name must be printable"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["name"] = "two\nlines"; }), "name must be printable"));
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["obstacles"][0]["name"] = "wall\x7f"; }), "obstacles[0].name must be printable"));
    EXPECT_EQ(errorFor([](json &d) { d["robots"][1]["name"] = "röbot → east"; }), "no error");
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][1]["kind"] = "urdf_arm"; }), "robots[1]: unknown field"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][1]["kind"] = "tank"; }),
                    "robots[1].kind must be one of disc, planar_arm"));
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["obstacles"][0]["shape"] = "cone"; }), "obstacles[0].shape must be one of"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["obstacles"][1]["size"][0] = 0; }),
                    "obstacles[1].size[0] must be a positive number"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["format"] = "ompl_parc.solution"; }), "'format'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["version"] = 2; }), "unsupported 'version'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"] = json::array(); }), "robots must be a non-empty array"));
    // Starts and goals are checked like the built-ins: in collision with each other or a wall.
    EXPECT_TRUE(has(errorFor(
                        [](json &d) {
                            d["robots"][1]["start"] = {-5, 2.5};
                        }),
                    "starts of robots 'west_a' and 'west_b' collide"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][2]["goal"] = {0, 5}; }), "goal of robot 'east_a' is"));
    // A syntax error gives its line and column.
    try
    {
        ScenarioFile::fromJson("{\n  \"format\": \"ompl_parc.scenario\",\n  \"version\" 1\n}");
        FAIL() << "no error";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_TRUE(has(e.what(), "not valid JSON at line 3, column")) << e.what();
    }
    EXPECT_THROW(ScenarioFile::read(testing::TempDir() + "/no_such_scenario.json"), ompl::Exception);
}

TEST(ScenarioFile, HostileNumbersAndFilesAreRefused)
{
    auto has = [](const std::string &message, const std::string &part)
    { return message.find(part) != std::string::npos; };
    // A version past int's range is not version 1 (it used to wrap to 1).
    EXPECT_TRUE(has(errorFor([](json &d) { d["version"] = 4294967297ull; }), "unsupported 'version'"));
    // A number past double's range: one line saying the JSON is not valid, not a bare library exception.
    auto text = slurp(examplePath("doorway_swap"));
    text.replace(text.find("\"resolution\""), 0, "\"big\": 1e999, ");
    try
    {
        ScenarioFile::fromJson(text);
        ADD_FAILURE() << "no error";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_TRUE(has(e.what(), "not valid JSON: ")) << e.what();
    }
    // A huge quaternion is a rotation like any other: [1e200, 1e200, 0, 0] turns 90 degrees about x.
    auto doc = json::parse(slurp(examplePath("doorway_swap")));
    doc["obstacles"].push_back({{"name", "tilted"},
                                {"shape", "box"},
                                {"size", {1, 2, 0.5}},
                                {"position", {6, 6, 0}},
                                {"orientation", {1e200, 1e200, 0, 0}}});
    const auto problem = ScenarioFile::fromJson(doc.dump());
    const auto &tilted = problem.getSpaceInformation()->getRobot(0)->getEnvironment()->getObstacles().back();
    EXPECT_TRUE(tilted.pose.rotation().isApprox(
        Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(), 1e-12));
    // Not a regular file: refused at once instead of read forever.
    try
    {
        ScenarioFile::read("/dev/zero");
        ADD_FAILURE() << "no error";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_TRUE(has(e.what(), "'/dev/zero' is not a regular file")) << e.what();
    }
}

TEST(ScenarioFile, UrdfArmsNameABuiltInModelOrAFileBesideTheScenario)
{
    // Written Pandas name the built-in model instead of inlining its URDF.
    const auto panda = scenarios::createPandaCage(2, 0);
    auto doc = json::parse(ScenarioFile::toJson(panda));
    EXPECT_EQ(doc["robots"][0]["builtin_urdf"], "panda");
    EXPECT_FALSE(doc["robots"][0].contains("urdf"));

    // A relative "urdf_file" is found beside the scenario file, whatever the current folder.
    const std::string folder = testing::TempDir() + "/ompl_parc_urdf_scenario";
    std::filesystem::create_directories(folder);
    std::ofstream(folder + "/arm.urdf") << models::pandaUrdf();
    doc["robots"][0].erase("builtin_urdf");
    doc["robots"][0]["urdf_file"] = "arm.urdf";
    std::ofstream(folder + "/scenario.json") << doc.dump();
    const auto loaded = ScenarioFile::read(folder + "/scenario.json");
    EXPECT_EQ(dynamic_cast<const UrdfArm &>(*loaded.getSpaceInformation()->getRobot(0)).getUrdfXml(),
              models::pandaUrdf());
    EXPECT_EQ(ScenarioFile::toJson(loaded), ScenarioFile::toJson(panda));
    std::filesystem::remove_all(folder);

    const std::string written = ScenarioFile::toJson(panda);
    EXPECT_NE(errorFor([](json &d) { d["robots"][1]["builtin_urdf"] = "kuka"; }, written)
                  .find("robots[1].builtin_urdf must be one of panda (got 'kuka')"),
              std::string::npos);
    EXPECT_NE(
        errorFor([](json &d) { d["robots"][1]["urdf"] = "<robot/>"; }, written).find("robots[1] needs exactly one of"),
        std::string::npos);
}

class ScenarioExample : public testing::TestWithParam<std::pair<std::string, std::string>>
{
};

TEST_P(ScenarioExample, LoadsAndArcSolvesIt)
{
    const auto problem = ScenarioFile::read(examplePath(GetParam().first));
    EXPECT_EQ(problem.getName(), GetParam().first);
    EXPECT_EQ(problem.checkEndpoints(), "");
    ARC arc(problem.getSpaceInformation());
    arc.setProfile(GetParam().second);
    arc.setSeed(1);
    arc.setProblemDefinition(problem.createProblemDefinition());
    arc.setup();
    ASSERT_EQ(arc.solve(ompl::base::timedPlannerTerminationCondition(120.)), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const auto report = SolutionValidator(problem).validate(arc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}

INSTANTIATE_TEST_SUITE_P(Examples, ScenarioExample, testing::ValuesIn(EXAMPLES),
                         [](const auto &info) { return info.param.first; });

/** Damaged files (bytes flipped, inserted, deleted, digits changed, truncated) must load or throw
    ompl::Exception, never crash or throw anything else; run under ASan this also catches memory errors. */
TEST(ScenarioFile, DamagedFilesLoadOrThrowCleanly)
{
    std::mt19937 rng(12345);
    const std::string alphabet = "{}[]\":,0123456789.-eE tfnrx";
    unsigned int loaded = 0, rejected = 0;
    for (const auto &example : EXAMPLES)
    {
        const std::string original = slurp(examplePath(example.first));
        ASSERT_FALSE(original.empty());
        for (int trial = 0; trial < 1000; ++trial)
        {
            std::string text = original;
            const int edits = 1 + static_cast<int>(rng() % 3);
            for (int e = 0; e < edits && !text.empty(); ++e)
            {
                const std::size_t at = rng() % text.size();
                switch (rng() % 5)
                {
                    case 0:
                        text[at] = alphabet[rng() % alphabet.size()];
                        break;
                    case 1:
                        text.insert(at, 1, alphabet[rng() % alphabet.size()]);
                        break;
                    case 2:
                        text.erase(at, 1 + rng() % 8);
                        break;
                    case 3:
                        if (std::isdigit(static_cast<unsigned char>(text[at])))
                            text[at] = static_cast<char>('0' + rng() % 10);
                        break;
                    default:
                        text.resize(at);
                }
            }
            try
            {
                ScenarioFile::fromJson(text);
                ++loaded;
            }
            catch (const ompl::Exception &)
            {
                ++rejected;
            }
        }
    }
    EXPECT_GT(loaded, 0u);  // some damage is harmless (a changed digit), so both outcomes are exercised
    EXPECT_GT(rejected, 0u);
}
