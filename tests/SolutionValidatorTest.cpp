#include "TestProblems.h"

#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>

using namespace ompl_parc;

namespace
{
    /** Robots a and b on parallel lines y = 0 and y = 3, moving left to right: a valid plan. */
    struct ParallelLines : testing::Test
    {
        MultiRobotProblem problem = test::twoDiscs({-5, 3}, {5, 3}, {-5, -3}, {5, -3}, true, 16.);
        MultiRobotPlan plan{*problem.getSpaceInformation()};
        void SetUp() override
        {
            plan.setRobotPath(0, test::straightLine({-5, 3}, {5, 3}, 16.));
            plan.setRobotPath(1, test::straightLine({-5, -3}, {5, -3}, 16.));
        }
        std::string violation() const
        {
            const auto report = SolutionValidator(problem).validate(plan);
            EXPECT_FALSE(report.valid);
            return report.message;
        }
    };
}  // namespace

TEST_F(ParallelLines, ValidPlanPasses)
{
    const auto report = SolutionValidator(problem).validate(plan);
    EXPECT_TRUE(report.valid) << report.message;
    EXPECT_EQ(report.configurationsChecked, 2u * (160u * 4u + 1u));
}

TEST_F(ParallelLines, InjectedObstacleHitIsCaught)
{
    // A legal-speed detour of a through (0, 1.4): the disc then overlaps the wall (|y| <= 2, |x| <= 0.1).
    auto path = test::straightLine({-5, 3}, {0, 1.4}, 16.);
    const auto second = test::straightLine({0, 1.4}, {5, 3}, 16.);
    path.insert(path.end(), second.begin() + 2, second.end());
    plan.setRobotPath(0, path);
    const auto message = violation();
    EXPECT_NE(message.find("robot 'a' hits obstacle 'wall'"), std::string::npos) << message;
}

TEST_F(ParallelLines, InjectedPairConflictIsCaught)
{
    auto path = plan.getRobotPath(1);
    for (std::size_t t = 0; t <= 160; ++t)
        path[2 * t + 1] = 2.5;  // b runs 0.5 below a: discs of radius 0.5 overlap all along
    plan.setRobotPath(1, path);
    problem = test::twoDiscs({-5, 3}, {5, 3}, {-5, 2.5}, {5, 2.5}, false, 16.);
    const auto message = violation();
    EXPECT_EQ(message, "t=0: robots 'a' and 'b' collide");
}

TEST_F(ParallelLines, TeleportingStepIsCaught)
{
    auto path = plan.getRobotPath(0);
    path[2 * 50] += 0.5;
    plan.setRobotPath(0, path);
    const auto message = violation();
    EXPECT_NE(message.find("t=49: robot 'a' moves"), std::string::npos) << message;
}

TEST_F(ParallelLines, WrongGoalAndWrongStartAreCaught)
{
    auto path = plan.getRobotPath(1);
    path.resize(path.size() - 2);
    plan.setRobotPath(1, path);
    EXPECT_EQ(violation(), "robot 'b' does not end at its goal");
    path = plan.getRobotPath(0);
    path[0] = -4.99;
    plan.setRobotPath(0, path);
    EXPECT_EQ(violation(), "robot 'a' does not start at its start");
}

TEST_F(ParallelLines, WrongTeamSizeAndResolutionAreCaught)
{
    MultiRobotPlan three({2, 2, 2}, 16.);
    EXPECT_EQ(SolutionValidator(problem).validate(three).message, "plan has 3 robots, problem has 2");
    MultiRobotPlan coarse({2, 2}, 8.);
    EXPECT_NE(SolutionValidator(problem).validate(coarse).message.find("resolution"), std::string::npos);
}

TEST(SolutionValidator, ArrivedRobotsHoldTheirGoalAndCanBeHit)
{
    // a stops at (0, 3); b later drives through that spot.
    auto problem = test::twoDiscs({-5, 3}, {0, 3}, {5, 3}, {-5, 3}, false, 16.);
    MultiRobotPlan plan(*problem.getSpaceInformation());
    plan.setRobotPath(0, test::straightLine({-5, 3}, {0, 3}, 16.));
    auto b = test::straightLine({5, 3}, {5, 3.0001}, 16.);
    for (int k = 0; k < 200; ++k)  // b waits, then moves through a's goal
        b.insert(b.end(), {5., 3.0001});
    const auto drive = test::straightLine({5, 3.0001}, {-5, 3}, 16.);
    b.insert(b.end(), drive.begin() + 2, drive.end());
    plan.setRobotPath(1, b);
    const auto report = SolutionValidator(problem).validate(plan);
    EXPECT_FALSE(report.valid);
    EXPECT_NE(report.message.find("robots 'a' and 'b' collide"), std::string::npos) << report.message;
}

TEST(SolutionValidator, SelfCollisionOfAnArmIsCaught)
{
    auto problem = scenarios::createPlanarCross(2);
    MultiRobotPlan plan(*problem.getSpaceInformation());
    // Arm 0 folds its last link back across its first and returns; arm 1 waits, then swings.
    const std::vector<double> fold = {0., 2.9, -2.9};  // a Z: link 2 parallel to link 0, 0.07 above it
    auto out = test::straightLine(problem.getStart(0), {0., 0., 0.}, 128.);
    const auto in = test::straightLine({0., 0., 0.}, fold, 128.);
    out.insert(out.end(), in.begin() + 3, in.end());
    const auto back = test::straightLine(fold, problem.getGoal(0), 128.);
    out.insert(out.end(), back.begin() + 3, back.end());
    plan.setRobotPath(0, out);
    std::vector<double> wait;
    for (int k = 0; k < 1000; ++k)
        wait.insert(wait.end(), problem.getStart(1).begin(), problem.getStart(1).end());
    const auto swing = test::straightLine(problem.getStart(1), problem.getGoal(1), 128.);
    wait.insert(wait.end(), swing.begin() + 3, swing.end());
    plan.setRobotPath(1, wait);
    const auto report = SolutionValidator(problem).validate(plan);
    EXPECT_FALSE(report.valid);
    EXPECT_NE(report.message.find("self-collision"), std::string::npos) << report.message;
}

TEST(SolutionValidator, TunnellingBetweenTimestepsIsCaughtBySubsteps)
{
    // At resolution 0.5 one timestep may move 2 units: a disc of radius 0.5 can hop from x = -0.7 to
    // x = 0.7 over the 0.2-thick wall; both timesteps are clear, the middle of the step is not.
    const auto problem = test::twoDiscs({-0.7, 0}, {0.7, 0}, {5, -5}, {5, -5}, true, 0.5);
    MultiRobotPlan plan(*problem.getSpaceInformation());
    plan.setRobotPath(0, {-0.7, 0., 0.7, 0.});
    plan.setRobotPath(1, {5., -5.});
    ValidationOptions onlyTimesteps;
    onlyTimesteps.substeps = 1;
    EXPECT_TRUE(SolutionValidator(problem, onlyTimesteps).validate(plan).valid);
    const auto report = SolutionValidator(problem).validate(plan);
    EXPECT_FALSE(report.valid);
    EXPECT_EQ(report.message, "t=0.5 (sub-step): robot 'a' hits obstacle 'wall'");
}
