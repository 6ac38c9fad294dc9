#include "TestProblems.h"

#include "ompl_parc/robots/DiscRobot.h"
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
    // The lines are 6 apart and 1 from the wall: the broad phase and the swept discs rule out every test.
    EXPECT_EQ(report.configurationsChecked, 0u);
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

TEST(SolutionValidator, TunnellingBetweenTimestepsIsCaughtBySamples)
{
    // At resolution 0.5 one timestep may move 2 units: a disc of radius 0.5 can hop from x = -0.7 to
    // x = 0.7 over the 0.2-thick wall; both timesteps are clear, the middle of the step is not.
    const auto problem = test::twoDiscs({-0.7, 0}, {0.7, 0}, {5, -5}, {5, -5}, true, 0.5);
    MultiRobotPlan plan(*problem.getSpaceInformation());
    plan.setRobotPath(0, {-0.7, 0., 0.7, 0.});
    plan.setRobotPath(1, {5., -5.});
    // Every value of the option checks between timesteps: substeps is only the fewest samples.
    for (unsigned int substeps : {0u, 1u, 2u, 4u})
    {
        ValidationOptions options;
        options.substeps = substeps;
        EXPECT_EQ(SolutionValidator(problem, options).validate(plan).message,
                  "t=0.5 (sub-step): robot 'a' hits obstacle 'wall'")
            << substeps;
    }
}

namespace
{
    /** Discs of radius \e radius in a 20 x 20 box with a wall of thickness \e wall at x = 0 (|y| <= 2), at
        resolution 128: starts and goals are the ends of \e paths. */
    MultiRobotProblem tinyDiscs(double radius, double wall, const std::vector<std::vector<double>> &paths)
    {
        auto env = std::make_shared<Environment>();
        env->addBox2D("wall", 0., 0., wall, 4.);
        ompl::base::RealVectorBounds bounds(2);
        bounds.setLow(-10.);
        bounds.setHigh(10.);
        std::vector<RobotPtr> team;
        std::vector<std::vector<double>> starts, goals;
        for (std::size_t i = 0; i < paths.size(); ++i)
        {
            team.push_back(
                std::make_shared<DiscRobot>(std::string(1, static_cast<char>('a' + i)), env, radius, bounds));
            starts.push_back({paths[i][0], paths[i][1]});
            goals.push_back({paths[i][paths[i].size() - 2], paths[i].back()});
        }
        return MultiRobotProblem(std::make_shared<MultiRobotSpaceInformation>(team, 128.), starts, goals);
    }

    MultiRobotPlan planOf(const MultiRobotProblem &problem, const std::vector<std::vector<double>> &paths)
    {
        MultiRobotPlan plan(*problem.getSpaceInformation());
        for (std::size_t i = 0; i < paths.size(); ++i)
            plan.setRobotPath(i, paths[i]);
        return plan;
    }
}  // namespace

TEST(SolutionValidator, TunnellingThroughAThinWallIsRejected)
{
    // A disc of radius 0.001 crosses a wall 1e-4 thick in one timestep (0.0078 long, just under 1/128): clear at
    // both timesteps and at every sample of 4 or 16 evenly spaced sub-steps (the crossing falls between them).
    const std::vector<std::vector<double>> paths = {{-0.003, 1., 0.0048, 1.}, {5., 5.}};
    const auto problem = tinyDiscs(0.001, 1e-4, paths);
    const auto plan = planOf(problem, paths);
    for (unsigned int substeps : {0u, 1u, 2u, 4u, 16u})
    {
        ValidationOptions options;
        options.substeps = substeps;
        const auto report = SolutionValidator(problem, options).validate(plan);
        EXPECT_FALSE(report.valid) << substeps;
        EXPECT_NE(report.message.find("(sub-step): robot 'a' hits obstacle 'wall'"), std::string::npos)
            << report.message;
    }
}

TEST(SolutionValidator, TunnellingThroughAnotherRobotIsRejected)
{
    // Two discs of radius 0.001 swap sides of each other on one line within one timestep.
    const std::vector<std::vector<double>> paths = {{4.995, 3., 5.0028, 3.}, {5.005, 3., 4.9972, 3.}};
    const auto problem = tinyDiscs(0.001, 1e-4, paths);
    for (unsigned int substeps : {0u, 1u, 4u})
    {
        ValidationOptions options;
        options.substeps = substeps;
        const auto report = SolutionValidator(problem, options).validate(planOf(problem, paths));
        EXPECT_FALSE(report.valid) << substeps;
        EXPECT_NE(report.message.find("(sub-step): robots 'a' and 'b' collide"), std::string::npos) << report.message;
    }
}

TEST(SolutionValidator, OptionsThatWouldSwitchTheCheckBetweenTimestepsOffAreRefused)
{
    const auto problem = tinyDiscs(0.1, 0.2, {{1., 1.}, {5., 5.}});
    for (double slack : {0., std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
    {
        ValidationOptions options;
        options.substepSlack = slack;
        EXPECT_THROW(SolutionValidator(problem, options), std::invalid_argument) << slack;
    }
    ValidationOptions negative;
    negative.contactTolerance = -1.;
    EXPECT_THROW(SolutionValidator(problem, negative), std::invalid_argument);
}

TEST(SolutionValidator, LongWaitsCostTheirPiecesNotTheirTimesteps)
{
    // Robot a waits 9 million timesteps, then crosses the wall's line beside it; robot b waits, then crosses
    // through a, hopping a little each timestep: found at the end of the waits, after a check that skips them.
    const std::size_t wait = 9000000;
    const double a0[2] = {-5., 5.}, a1[2] = {-4.995, 5.}, b0[2] = {-5., 6.}, b1[2] = {-5., 4.};
    TimedPath a(2, a0), b(2, b0);
    a.appendHold(a0, wait);
    a.appendMotion(a0, a1, 1);
    b.appendHold(b0, wait);
    b.appendMotion(b0, b1, 256);  // 1/128 per timestep
    MultiRobotPlan plan(std::vector<unsigned int>{2, 2}, 128.);
    plan.setPath(0, a);
    plan.setPath(1, b);
    const auto problem = tinyDiscs(0.1, 0.2, {{-5., 5., -4.995, 5.}, {-5., 6., -5., 4.}});
    const auto report = SolutionValidator(problem).validate(plan);
    EXPECT_FALSE(report.valid);
    EXPECT_NE(report.message.find("robots 'a' and 'b' collide"), std::string::npos) << report.message;
    EXPECT_GT(std::stod(report.message.substr(2)), static_cast<double>(wait) + 64.) << report.message;
    // Past the largest timestep a plan may have, the plan is refused before any check.
    TimedPath late(2, b0);
    late.appendHold(b0, MultiRobotPlan::MAX_TIMESTEP + 1);
    plan.setPath(1, late);
    EXPECT_NE(SolutionValidator(problem).validate(plan).message.find("beyond the largest timestep"), std::string::npos);
}

TEST(SolutionValidator, GrazingBetweenTimestepsIsTolerated)
{
    // Discs of radius 0.5 pass each other on lines 0.99998 apart, closest exactly between two timesteps: 1.00001
    // apart at the timesteps, an overlap of 2e-5 between them (far below the slack of half a timestep).
    const double h = 1. / 128.;
    std::vector<std::vector<double>> paths(2);
    for (int t = -20; t <= 20; ++t)
    {
        paths[0].insert(paths[0].end(), {(t - 0.5) * h, 5.});
        paths[1].insert(paths[1].end(), {(0.5 - t) * h, 5.99998});
    }
    const auto problem = tinyDiscs(0.5, 0.2, paths);
    const auto report = SolutionValidator(problem).validate(planOf(problem, paths));
    EXPECT_TRUE(report.valid) << report.message;
    EXPECT_GT(report.configurationsChecked, 0u);  // the swept discs overlap: it went down to the samples
    // 1e-4 closer, they overlap at the timesteps, too.
    for (std::size_t k = 1; k < paths[1].size(); k += 2)
        paths[1][k] -= 1e-4;
    const auto closer = tinyDiscs(0.5, 0.2, paths);
    EXPECT_EQ(SolutionValidator(closer).validate(planOf(closer, paths)).message, "t=20: robots 'a' and 'b' collide");
}

TEST(SolutionValidator, ReportDoesNotDependOnThreads)
{
    std::mt19937 rng(7);
    const auto team = test::twoDiscs({0, 0}, {0, 0}, {0, 0}, {0, 0}, true, 16.).getSpaceInformation();
    std::size_t invalid = 0;
    for (int k = 0; k < 20; ++k)
    {
        const MultiRobotPlan plan = test::randomWalkPlan(*team, rng, 0.04);
        const MultiRobotProblem problem = test::problemOfPlan(team, plan);
        ValidationOptions one, two;
        one.threads = 1;
        two.threads = 2;
        const auto a = SolutionValidator(problem, one).validate(plan);
        const auto b = SolutionValidator(problem, two).validate(plan);
        EXPECT_EQ(a.valid, b.valid);
        EXPECT_EQ(a.message, b.message);
        EXPECT_EQ(a.configurationsChecked, b.configurationsChecked);
        invalid += a.valid ? 0 : 1;
    }
    EXPECT_GT(invalid, 0u);
}

TEST(SolutionValidator, RobotWithoutDisplacementBoundIsRejectedClearly)
{
    struct Blob : Robot
    {
        Blob(EnvironmentPtr env, const ompl::base::RealVectorBounds &bounds) : Robot("blob", std::move(env), bounds) {}
        std::string getKind() const override { return "blob"; }
        void computeCapsules(const double *q, CollisionBody &body) const override
        {
            body.clear();
            body.addSphere(q[0], q[1], 0., 0.1);
        }
    };
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(-1.);
    bounds.setHigh(1.);
    const auto robot = std::make_shared<Blob>(std::make_shared<Environment>(), bounds);
    const MultiRobotProblem problem(std::make_shared<MultiRobotSpaceInformation>(std::vector<RobotPtr>{robot}, 128.),
                                    {{0., 0.}}, {{0., 0.}});
    try
    {
        SolutionValidator validator(problem);
        ADD_FAILURE() << "no exception";
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_NE(std::string(e.what()).find("kind 'blob'"), std::string::npos) << e.what();
    }
}
