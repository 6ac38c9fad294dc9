#include "TestProblems.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

using namespace ompl_parc;

TEST(ProblemFamilies, InstancesAreValidRepeatableAndDistinct)
{
    for (const auto &family : scenarios::familyNames())
        for (std::size_t robots : {2, 8, 16})
        {
            if (family == "panda_cell" && robots == 16)
                continue;  // valid too, but it takes seconds to draw
            SCOPED_TRACE(family + " " + std::to_string(robots));
            // generateFamilyInstance() checks the endpoints itself; check them here too.
            const MultiRobotProblem first = scenarios::generateFamilyInstance(family, robots, 0);
            EXPECT_EQ(first.getSpaceInformation()->getRobotCount(), robots);
            EXPECT_EQ(first.checkEndpoints(), "");
            EXPECT_EQ(first.getName(), family + "_" + std::to_string(robots) + "_0");
            const std::string json = ScenarioFile::toJson(first);
            EXPECT_EQ(ScenarioFile::toJson(scenarios::generateFamilyInstance(family, robots, 0)), json);
            EXPECT_EQ(ScenarioFile::toJson(scenarios::createScenario(family, robots, 128., 0)), json);
            EXPECT_NE(ScenarioFile::toJson(scenarios::generateFamilyInstance(family, robots, 1)), json);
        }
}

TEST(ProblemFamilies, BadRequestsAreRefused)
{
    EXPECT_THROW(scenarios::generateFamilyInstance("warehouse", 8, 0), ompl::Exception);
    EXPECT_THROW(scenarios::generateFamilyInstance("rooms", 1, 0), ompl::Exception);
    EXPECT_THROW(scenarios::generateFamilyInstance("panda_cell", 5, 0), ompl::Exception);
}

TEST(ProblemFamilies, ArcSolvesAnInstanceOfEachFamily)
{
    // One instance per family that needs repairs, solved by ARC with its default settings and re-checked by
    // the validator (the success rates over many instances are the benchmark's business: docs/results.md).
    const std::vector<std::pair<std::string, std::string>> cases = {{"rooms", "mobile"},
                                                                    {"crossing", "mobile"},
                                                                    {"ring", "mobile"},
                                                                    {"field", "mobile"},
                                                                    {"planar_cell", "planar"}};
    for (const auto &[family, profile] : cases)
    {
        SCOPED_TRACE(family);
        const MultiRobotProblem problem = scenarios::generateFamilyInstance(family, 8, 0);
        ARC arc(problem.getSpaceInformation());
        arc.params().setParam("profile", profile);
        arc.params().setParam("seed", "1");
        ASSERT_EQ(test::solveWith(arc, problem, 120.), ompl::base::PlannerStatus::EXACT_SOLUTION);
        EXPECT_GT(arc.getStatistics().conflicts, 0u);
        EXPECT_TRUE(SolutionValidator(problem).validate(arc.getPlan()).valid);
    }
}
