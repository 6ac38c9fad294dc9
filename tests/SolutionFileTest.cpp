#include "TestProblems.h"

#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <ompl/base/ScopedState.h>

#include <cstdint>
#include <cstdio>
#include <fstream>

using namespace ompl_parc;
using nlohmann::json;

namespace
{
    struct SolutionFileTest : testing::Test
    {
        MultiRobotProblem problem = test::twoDiscs({-5, 3}, {5, 3}, {-5, -3}, {5, -3});
        MultiRobotPlan plan{*problem.getSpaceInformation()};
        void SetUp() override
        {
            plan.setRobotPath(0, test::straightLine({-5, 3}, {5, 3}, 128.));
            plan.setRobotPath(1, test::straightLine({-5, -3}, {-4, -3}, 128.));
        }
        /** The error message for a document edited by \e edit. */
        std::string errorFor(const std::function<void(json &)> &edit) const
        {
            json doc = json::parse(SolutionFile::toJson(plan, *problem.getSpaceInformation()));
            edit(doc);
            try
            {
                SolutionFile::fromJson(doc.dump(), *problem.getSpaceInformation());
            }
            catch (const ompl::Exception &e)
            {
                return e.what();
            }
            return "no error";
        }
    };
}  // namespace

TEST_F(SolutionFileTest, WriteAndReadBackIsExact)
{
    // A plan of laid pieces, spliced (cut pieces keep their anchors), with awkward numbers.
    const auto &si = *problem.getSpaceInformation();
    ompl::geometric::PathGeometric composite(problem.getSpaceInformation());
    ompl::base::ScopedState<> s(problem.getSpaceInformation());
    s = std::vector<double>{-5., 3., -5., -3.};
    composite.append(s.get());
    s = std::vector<double>{0.1, 3. + 1. / 3., -4., -3.};
    composite.append(s.get());
    s = std::vector<double>{5., 3., 5., -3.};
    composite.append(s.get());
    plan = MultiRobotPlan::fromPathGeometric(si, composite);
    plan.splice(1, 100, 180, MultiRobotPlan::layTeamPath(si, composite)[1]);
    ASSERT_GT(plan.getPath(1).getPieceCount(), 2u);

    const std::string path = testing::TempDir() + "/ompl_parc_solution.json";
    SolutionFile::write(path, plan, si);
    const auto back = SolutionFile::read(path, si);
    std::remove(path.c_str());
    ASSERT_EQ(back.getRobotCount(), 2u);
    EXPECT_EQ(back.getPath(0), plan.getPath(0));
    EXPECT_EQ(back.getPath(1), plan.getPath(1));
    EXPECT_EQ(back.getRobotPath(1), plan.getRobotPath(1));
    EXPECT_DOUBLE_EQ(back.getResolution(), 128.);
    EXPECT_EQ(json::parse(SolutionFile::toJson(plan, si))["version"], 2);
}

TEST_F(SolutionFileTest, Version1IsStillRead)
{
    json robots = json::array();
    for (std::size_t i = 0; i < 2; ++i)
    {
        json states = json::array();
        const auto flat = plan.getRobotPath(i);
        for (std::size_t k = 0; k < flat.size(); k += 2)
            states.push_back({flat[k], flat[k + 1]});
        robots.push_back(
            {{"name", problem.getSpaceInformation()->getRobot(i)->getName()}, {"kind", "disc"}, {"states", states}});
    }
    json doc = {{"format", "ompl_parc.solution"}, {"version", 1}, {"resolution", 128}, {"robots", robots}};
    const auto back = SolutionFile::fromJson(doc.dump(), *problem.getSpaceInformation());
    EXPECT_EQ(back.getRobotPath(0), plan.getRobotPath(0));
    EXPECT_EQ(back.getRobotPath(1), plan.getRobotPath(1));
    EXPECT_EQ(back.getArrival(1), 128u);
    // Its errors still name the field.
    doc["robots"][0]["states"][3] = {1.0};
    try
    {
        SolutionFile::fromJson(doc.dump(), *problem.getSpaceInformation());
        ADD_FAILURE() << "no error";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("robots[0].states[3]"), std::string::npos) << e.what();
    }
    doc["robots"][0]["states"] = json::array();
    EXPECT_THROW(SolutionFile::fromJson(doc.dump(), *problem.getSpaceInformation()), ompl::Exception);
}

TEST_F(SolutionFileTest, MalformedFilesNameTheField)
{
    auto has = [](const std::string &message, const std::string &part)
    { return message.find(part) != std::string::npos; };
    EXPECT_TRUE(has(errorFor([](json &d) { d["format"] = "other"; }), "'format'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["version"] = 3; }), "'version'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["version"] = 0; }), "'version'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d.erase("resolution"); }), "missing field 'resolution'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["resolution"] = -1; }), "'resolution'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"].erase(1); }), "'robots' has 1 entries"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][1]["name"] = "zz"; }), "robots[1].name"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["kind"] = "arm"; }), "robots[0].kind"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["pieces"] = json::array(); }), "robots[0].pieces"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0].erase("arrival"); }), "missing field 'arrival'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["arrival"] = -3; }), "robots[0].arrival"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["pieces"][1][3] = {1.0}; }), "robots[0].pieces[1][3]"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][1]["pieces"][1][4][0] = nullptr; }), "non-number"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["pieces"][0][0] = 3; }), "robots[0].pieces[0] starts"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["pieces"][1][0] = 7; }), "increasing timesteps"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["pieces"][1].erase(2); }), "[start, offset, steps"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["pieces"][1][2] = 0.5; }), "robots[0].pieces[1][2]"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["arrival"] = 0; }), "robots[0].arrival"));
    EXPECT_THROW(SolutionFile::fromJson("{\"format\": ", *problem.getSpaceInformation()), ompl::Exception);
    EXPECT_THROW(SolutionFile::fromJson("[1, 2]", *problem.getSpaceInformation()), ompl::Exception);
    EXPECT_THROW(SolutionFile::read("/nonexistent/solution.json", *problem.getSpaceInformation()), ompl::Exception);
    // Unknown fields are refused, at the top and in a robot's entry, as in scenario files.
    EXPECT_TRUE(has(errorFor([](json &d) { d["comment"] = "x"; }), "solution: unknown field 'comment'"));
    EXPECT_TRUE(
        has(errorFor([](json &d) { d["robots"][1]["states"] = json::array(); }), "robots[1]: unknown field 'states'"));
    // Timesteps beyond the largest a plan may have (a 300-byte file used to keep the validator busy for hours).
    const std::string late = std::to_string(static_cast<std::uint64_t>(1) << 62);
    EXPECT_TRUE(has(errorFor([&](json &d) { d["robots"][0]["arrival"] = json::parse(late); }),
                    "robots[0].arrival must be a whole number from 0 to 100000000"));
    EXPECT_TRUE(
        has(errorFor([&](json &d) { d["robots"][0]["pieces"][1][2] = json::parse(late); }), "robots[0].pieces[1][2]"));
}

TEST_F(SolutionFileTest, APlanOfAnotherTeamIsNotWritten)
{
    MultiRobotPlan three(std::vector<unsigned int>{2, 2, 2}, 128.);
    MultiRobotPlan arm(std::vector<unsigned int>{2, 3}, 128.);
    MultiRobotPlan coarse(std::vector<unsigned int>{2, 2}, 64.);
    const std::string path = testing::TempDir() + "/not_written.json";
    for (const MultiRobotPlan *other : {&three, &arm, &coarse})
    {
        std::remove(path.c_str());
        EXPECT_THROW(SolutionFile::write(path, *other, *problem.getSpaceInformation()), ompl::Exception);
        EXPECT_FALSE(std::ifstream(path).good());
    }
}
