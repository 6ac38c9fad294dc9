#include "TestProblems.h"

#include "ompl_parc/UrdfArm.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_parc;
namespace ob = ompl::base;

TEST(PandaCage, TasksAreValidWithEndEffectorsInsideTheCage)
{
    for (std::size_t robots : {2, 4, 8})
        for (std::size_t task = 0; task < scenarios::PANDA_CAGE_TASKS; ++task)
        {
            const auto problem = scenarios::createPandaCage(robots, task);
            const auto &si = *problem.getSpaceInformation();
            ASSERT_EQ(si.getRobotCount(), robots);
            EXPECT_TRUE(problem.checkEndpoints().empty()) << robots << "/" << task << ": " << problem.checkEndpoints();
            for (std::size_t i = 0; i < robots; ++i)
            {
                const auto &arm = dynamic_cast<const UrdfArm &>(*si.getRobot(i));
                for (const auto *q : {&problem.getStart(i), &problem.getGoal(i)})
                {
                    EXPECT_TRUE(arm.isValid(q->data()));
                    const Eigen::Vector3d tip = arm.computeTipPose(q->data()).translation();
                    EXPECT_LT(std::max(std::abs(tip.x()), std::abs(tip.y())), 0.35 + (robots > 4 ? 0.1 : 0.));
                    for (std::size_t j = 0; j < i; ++j)
                    {
                        const auto *other = q == &problem.getStart(i) ? &problem.getStart(j) : &problem.getGoal(j);
                        EXPECT_FALSE(si.robotsCollide(i, q->data(), j, other->data()));
                    }
                }
            }
        }
    EXPECT_EQ(scenarios::createScenario("panda_cage", 2).getStart(0), scenarios::createPandaCage(2, 0).getStart(0));
    EXPECT_THROW(scenarios::createPandaCage(3), ompl::Exception);
    EXPECT_THROW(scenarios::createPandaCage(16), ompl::Exception);
    EXPECT_THROW(scenarios::createPandaCage(4, scenarios::PANDA_CAGE_TASKS), ompl::Exception);
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
