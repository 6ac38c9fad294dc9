#include "TestProblems.h"

#include "ompl_parc/UrdfArm.h"
#include "ompl_parc/planners/ARC.h"
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

TEST(PandaCage, ArcSolvesPandaCage4Task0Validated)
{
    const auto problem = scenarios::createPandaCage(4, 0);
    ARC arc(problem.getSpaceInformation());
    arc.setProfile("panda");
    arc.setSeed(1);
    arc.setProblemDefinition(problem.createProblemDefinition());
    arc.setup();
    ASSERT_EQ(arc.solve(ob::timedPlannerTerminationCondition(60.)), ob::PlannerStatus::EXACT_SOLUTION)
        << arc.getStatusMessage();
    const auto report = SolutionValidator(problem).validate(arc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}
