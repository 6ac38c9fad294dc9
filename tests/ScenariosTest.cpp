#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace ompl_parc;

TEST(Scenarios, MobileCrossFollowsTheFormula)
{
    for (std::size_t n : {4u, 16u, 64u, 256u})
    {
        const auto problem = scenarios::createMobileCross(n);
        ASSERT_EQ(problem.getRobotCount(), n);
        const double pairs = n / 2., reach = 5. * pairs;
        for (std::size_t i = 0; i < n / 2; ++i)
        {
            const double y = (i - (pairs - 1.) / 2.) * 5.;
            EXPECT_EQ(problem.getStart(2 * i), (std::vector<double>{reach, y}));
            EXPECT_EQ(problem.getGoal(2 * i), (std::vector<double>{-reach, y}));
            EXPECT_EQ(problem.getStart(2 * i + 1), (std::vector<double>{-reach, y}));
            EXPECT_EQ(problem.getGoal(2 * i + 1), (std::vector<double>{reach, y}));
        }
        // Square bounds centred on the starts/goals, half-extent max(width, height)/2 + 2r.
        const auto &b = problem.getSpaceInformation()->getRobot(0)->getBounds();
        const double half = 0.5 * std::max(2. * reach, (pairs - 1.) * 5.) + 1.;
        EXPECT_DOUBLE_EQ(b.low[0], -half);
        EXPECT_DOUBLE_EQ(b.high[1], half);
        EXPECT_EQ(problem.checkEndpoints(), "");
    }
}

TEST(Scenarios, MobileCircleFollowsTheFormula)
{
    for (std::size_t n : {4u, 8u, 16u, 64u})
    {
        const auto problem = scenarios::createMobileCircle(n);
        const double radius = std::max(5., 5. * n / (2. * M_PI));
        for (std::size_t i = 0; i < n; ++i)
        {
            const double a = 2. * M_PI * i / n;
            EXPECT_NEAR(problem.getStart(i)[0], radius * std::cos(a), 1e-12);
            EXPECT_NEAR(problem.getStart(i)[1], radius * std::sin(a), 1e-12);
            EXPECT_EQ(problem.getGoal(i), problem.getStart((i + n / 2) % n));
        }
        EXPECT_NEAR(problem.getSpaceInformation()->getRobot(0)->getBounds().high[0], radius + 1., 1e-12);
        EXPECT_EQ(problem.checkEndpoints(), "");
    }
}

TEST(Scenarios, PlanarCrossFollowsTheLayout)
{
    for (std::size_t n : {4u, 16u, 256u})
    {
        const auto problem = scenarios::createPlanarCross(n);
        const auto &si = *problem.getSpaceInformation();
        ASSERT_EQ(si.getRobotCount(), n);
        for (std::size_t i = 0; i < n; ++i)
        {
            const auto &arm = dynamic_cast<const PlanarArm &>(*si.getRobot(i));
            const bool left = i < n / 2;
            const double row = left ? i : i - n / 2;
            EXPECT_DOUBLE_EQ(arm.getBaseX(), left ? -0.675 : 0.675);
            EXPECT_DOUBLE_EQ(arm.getBaseYaw(), left ? 0. : M_PI);
            EXPECT_DOUBLE_EQ(arm.getBaseY(), (row - (n / 2. - 1.) / 2.) * 1.2);
            EXPECT_EQ(problem.getStart(i), (std::vector<double>{M_PI / 6., 0., 0.}));
            EXPECT_EQ(problem.getGoal(i), (std::vector<double>{-M_PI / 6., 0., 0.}));
        }
        EXPECT_EQ(si.getEnvironment()->getObstacles().size(), 4u);
        EXPECT_EQ(problem.checkEndpoints(), "");
    }
}

TEST(Scenarios, PlanarCrossArmsReachIntoEachOther)
{
    // The facing arms of a row must need coordination: swinging straight through collides at 0 degrees.
    const auto problem = scenarios::createPlanarCross(2);
    const double level[3] = {0., 0., 0.};
    EXPECT_TRUE(problem.getSpaceInformation()->robotsCollide(0, level, 1, level));
}

TEST(Scenarios, BadRobotCountsAndNamesAreRejected)
{
    EXPECT_THROW(scenarios::createMobileCross(3), ompl::Exception);
    EXPECT_THROW(scenarios::createMobileCross(0), ompl::Exception);
    EXPECT_THROW(scenarios::createMobileCircle(5), ompl::Exception);
    EXPECT_THROW(scenarios::createPlanarCross(1), ompl::Exception);
    try
    {
        scenarios::createScenario("warehouse", 4);
        FAIL();
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("mobile_cross"), std::string::npos);
    }
}

/* A team over MAX_ROBOTS is refused before a robot is built, by every scenario alike (the tools and the Python module
   build their teams through createScenario()): a million discs would take gigabytes and minutes to drop. */
TEST(Scenarios, TeamsOverTheLimitAreRefusedBeforeTheyAreBuilt)
{
    for (const std::string name : {"mobile_cross", "field", "ring"})
    {
        try
        {
            scenarios::createScenario(name, 1000000);
            FAIL() << name;
        }
        catch (const std::invalid_argument &e)
        {
            EXPECT_EQ(std::string(e.what()),
                      "scenario '" + name + "': a team of 1000000 robots is over the limit of " +
                          std::to_string(MAX_ROBOTS));
        }
    }
    EXPECT_NO_THROW(checkTeamSize(MAX_ROBOTS, "team"));
    EXPECT_THROW(checkTeamSize(MAX_ROBOTS + 1, "team"), std::invalid_argument);
}
