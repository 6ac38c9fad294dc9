#include "TestProblems.h"

#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <cstdio>

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
    const std::string path = testing::TempDir() + "/ompl_parc_solution.json";
    SolutionFile::write(path, plan, *problem.getSpaceInformation());
    const auto back = SolutionFile::read(path, *problem.getSpaceInformation());
    std::remove(path.c_str());
    ASSERT_EQ(back.getRobotCount(), 2u);
    EXPECT_EQ(back.getRobotPath(0), plan.getRobotPath(0));
    EXPECT_EQ(back.getRobotPath(1), plan.getRobotPath(1));
    EXPECT_DOUBLE_EQ(back.getResolution(), 128.);
}

TEST_F(SolutionFileTest, MalformedFilesNameTheField)
{
    auto has = [](const std::string &message, const std::string &part)
    { return message.find(part) != std::string::npos; };
    EXPECT_TRUE(has(errorFor([](json &d) { d["format"] = "other"; }), "'format'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["version"] = 2; }), "'version'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d.erase("resolution"); }), "missing field 'resolution'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["resolution"] = -1; }), "'resolution'"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"].erase(1); }), "'robots' has 1 entries"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][1]["name"] = "zz"; }), "robots[1].name"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["kind"] = "arm"; }), "robots[0].kind"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["states"] = json::array(); }), "robots[0].states"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][0]["states"][3] = {1.0}; }), "robots[0].states[3]"));
    EXPECT_TRUE(has(errorFor([](json &d) { d["robots"][1]["states"][2][0] = nullptr; }), "non-number"));
    EXPECT_THROW(SolutionFile::fromJson("{\"format\": ", *problem.getSpaceInformation()), ompl::Exception);
    EXPECT_THROW(SolutionFile::fromJson("[1, 2]", *problem.getSpaceInformation()), ompl::Exception);
    EXPECT_THROW(SolutionFile::read("/nonexistent/solution.json", *problem.getSpaceInformation()), ompl::Exception);
}
