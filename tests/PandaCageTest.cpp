#include "TestProblems.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/scenarios/ConflictingPairs.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    std::string storedFile(std::size_t robots, std::size_t task)
    {
        return std::string(OMPL_PARC_SCENARIO_DIR) + "/panda_cage/panda_cage_" + std::to_string(robots) + "_" +
               std::to_string(task) + ".json";
    }

    /** Every start and goal valid, pairwise collision-free, and every end effector inside the cage. */
    void expectValidTask(const MultiRobotProblem &problem)
    {
        EXPECT_EQ(problem.checkEndpoints(), "");
        const auto &si = *problem.getSpaceInformation();
        for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        {
            const auto &arm = dynamic_cast<const UrdfArm &>(*si.getRobot(i));
            for (const auto *q : {&problem.getStart(i), &problem.getGoal(i)})
                EXPECT_TRUE(scenarios::pandaCageInterior().contains(arm.computeTipPose(q->data()).translation()))
                    << arm.getName();
        }
    }

    /** The message of the ompl::Exception \e body throws ("no error" if none). */
    template <typename Body>
    std::string errorOf(const Body &body)
    {
        try
        {
            body();
        }
        catch (const ompl::Exception &e)
        {
            return e.what();
        }
        return "no error";
    }
}  // namespace

TEST(PandaCage, StoredTasksAreValidWithEndEffectorsInsideTheCage)
{
    for (std::size_t robots : scenarios::pandaCageTeamSizes())
        for (std::size_t task = 0; task < scenarios::PANDA_CAGE_TASKS; ++task)
        {
            SCOPED_TRACE(std::to_string(robots) + " robots, task " + std::to_string(task));
            const auto problem = scenarios::createPandaCage(robots, task);
            ASSERT_EQ(problem.getRobotCount(), robots);
            EXPECT_EQ(problem.getName(), "panda_cage_" + std::to_string(robots) + "_" + std::to_string(task));
            expectValidTask(problem);
        }
    EXPECT_THROW(scenarios::createPandaCage(3), ompl::Exception);
    EXPECT_THROW(scenarios::createPandaCage(32), ompl::Exception);
    EXPECT_THROW(scenarios::createPandaCage(4, scenarios::PANDA_CAGE_TASKS), ompl::Exception);
}

TEST(PandaCage, BuiltInTasksAreTheStoredFiles)
{
    for (std::size_t robots : scenarios::pandaCageTeamSizes())
        for (std::size_t task = 0; task < scenarios::PANDA_CAGE_TASKS; ++task)
        {
            SCOPED_TRACE(storedFile(robots, task));
            std::ifstream in(storedFile(robots, task));
            std::stringstream text;
            text << in.rdbuf();
            EXPECT_EQ(scenarios::pandaCageTaskJson(robots, task), text.str());
            // The --scenario and --scenario-file routes build the same problem (same serialisation).
            EXPECT_EQ(ScenarioFile::toJson(scenarios::createScenario("panda_cage", robots, 128., task)),
                      ScenarioFile::toJson(ScenarioFile::read(storedFile(robots, task))));
        }
    EXPECT_EQ(scenarios::createPandaCage(4, 1, 64.).getSpaceInformation()->getResolution(), 64.);
    EXPECT_TRUE(errorOf([] { scenarios::createScenario("mobile_cross", 4, 128., 1); }).find("only task 0") !=
                std::string::npos);
}

TEST(PandaCage, GeneratorMakesValidTasksThatNeedCoordination)
{
    const auto problem = scenarios::generatePandaCageTask(2, 4);  // the quickest: its first draw is kept
    expectValidTask(problem);
    EXPECT_GT(scenarios::countConflictingPairs(problem), 0u);
}

TEST(PandaCage, BaseInABarIsNamedInTheError)
{
    // Panda 0 moved onto post bar0 at (-0.5, -1): its base link (which never moves) is inside the bar.
    auto doc = nlohmann::json::parse(scenarios::pandaCageTaskJson(2, 0));
    doc["robots"][0]["base_pose"]["position"] = {-0.5, -1.0, -0.3};
    const std::string message = errorOf([&] { ScenarioFile::fromJson(doc.dump()); });
    for (const char *part : {"robot 'panda0'", "link 'panda_link0'", "obstacle 'bar0'"})
        EXPECT_NE(message.find(part), std::string::npos) << message;
    // The same through the API.
    const auto environment = scenarios::createPandaCage(2, 0).getSpaceInformation()->getRobot(0)->getEnvironment();
    EXPECT_NE(errorOf(
                  [&]
                  {
                      UrdfArm("arm", environment, models::pandaUrdf(), "panda_link0", "panda_link8",
                              UrdfArm::pose(-0.5, -1.0, -0.3, 0., 0., 0.));
                  })
                  .find("link 'panda_link0', fixed to the base, collides with obstacle 'bar0'"),
              std::string::npos);
}

class PandaCage4 : public testing::TestWithParam<std::tuple<std::size_t, unsigned int>>
{
};

/* ARC (workers 0) and P-ARC with 2 workers solve every Panda Cage 4 task well within the paper's 100 s limit
   (typically in under a second), and the independent validator agrees. */
TEST_P(PandaCage4, SolvedAndTheValidatorAgrees)
{
    const auto [task, workers] = GetParam();
    const auto problem = scenarios::createPandaCage(4, task);
    std::unique_ptr<ArcPlannerBase> planner;
    if (workers == 0)
        planner = std::make_unique<ARC>(problem.getSpaceInformation());
    else
    {
        auto parc = std::make_unique<PARC>(problem.getSpaceInformation());
        parc->setWorkers(workers);
        planner = std::move(parc);
    }
    planner->setProfile("panda");
    planner->setSeed(1);
    ASSERT_EQ(test::solveWith(*planner, problem, 100.), ob::PlannerStatus::EXACT_SOLUTION)
        << planner->getStatusMessage();
    const auto report = SolutionValidator(problem).validate(planner->getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}

// "Parc" in the P-ARC cases' names puts them in the ThreadSanitizer pass (scripts/test.sh).
INSTANTIATE_TEST_SUITE_P(Tasks, PandaCage4,
                         testing::Combine(testing::Range<std::size_t>(0, scenarios::PANDA_CAGE_TASKS),
                                          testing::Values(0u, 2u)),
                         [](const auto &info)
                         {
                             const unsigned int workers = std::get<1>(info.param);
                             return "task" + std::to_string(std::get<0>(info.param)) +
                                    (workers == 0 ? std::string("_Arc") : "_Parc" + std::to_string(workers));
                         });
