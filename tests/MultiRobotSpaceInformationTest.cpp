#include "TestProblems.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Exception.h>

#include <functional>
#include <limits>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

TEST(MultiRobotSpaceInformation, ValidityCheckerChecksRobotsAndPairs)
{
    const auto problem = test::twoDiscs({-5, 0}, {5, 0}, {5, 0}, {-5, 0}, true);
    const auto &si = problem.getSpaceInformation();
    ob::ScopedState<> state(si);
    auto set = [&](double ax, double ay, double bx, double by)
    {
        state[0] = ax;
        state[1] = ay;
        state[2] = bx;
        state[3] = by;
    };
    set(-5, 0, 5, 0);
    EXPECT_TRUE(si->isValid(state.get()));
    set(-5, 0, -4.2, 0);  // 0.8 apart: discs of radius 0.5 overlap
    EXPECT_FALSE(si->isValid(state.get()));
    EXPECT_EQ(si->explainInvalid(state.get()), "robots 'a' and 'b' collide");
    set(0, 0, 5, 0);  // a inside the wall
    EXPECT_FALSE(si->isValid(state.get()));
    EXPECT_EQ(si->explainInvalid(state.get()), "robot 'a' is in collision with the environment");
    set(-5, 0, 11, 0);
    EXPECT_EQ(si->explainInvalid(state.get()), "robot 'b' is out of bounds");
}

/* A crowd of 300 discs and planar arms at random places: explainInvalid() names the first colliding pair in (i, j)
   order, as testing every pair does (its broad phase skips only pairs that cannot collide). */
TEST(MultiRobotSpaceInformation, ExplainInvalidNamesTheFirstCollidingPairOfACrowd)
{
    std::mt19937 rng(7);
    for (const char *scenario : {"mobile_circle", "planar_cross"})
    {
        const auto problem = scenarios::createScenario(scenario, scenario[0] == 'm' ? 300 : 32);
        const auto &si = *problem.getSpaceInformation();
        std::vector<CollisionBody> bodies(si.getRobotCount());
        int collided = 0;
        for (int k = 0; k < 30; ++k)
        {
            std::vector<std::vector<double>> configs;
            for (std::size_t i = 0; i < si.getRobotCount(); ++i)
            {
                const auto &bounds = si.getRobot(i)->getBounds();
                std::vector<double> q;
                for (std::size_t d = 0; d < bounds.low.size(); ++d)  // a shrinking room: from sparse to crowded
                {
                    const double middle = 0.5 * (bounds.low[d] + bounds.high[d]),
                                 half = 0.5 * (bounds.high[d] - bounds.low[d]) * (1. - k / 40.);
                    q.push_back(std::uniform_real_distribution<double>(middle - half, middle + half)(rng));
                }
                configs.push_back(q);
                si.getRobot(i)->computeBody(configs.back().data(), bodies[i]);
            }
            std::string expected;
            for (std::size_t i = 0; i < bodies.size() && expected.empty(); ++i)
                for (std::size_t j = i + 1; j < bodies.size() && expected.empty(); ++j)
                    if (bodiesCollide(bodies[i], bodies[j]))
                        expected = "robots '" + si.getRobot(i)->getName() + "' and '" + si.getRobot(j)->getName() +
                                   "' collide";
            std::vector<const double *> values;
            for (const auto &q : configs)
                values.push_back(q.data());
            const std::string got = si.explainInvalid(values);
            if (got.rfind("robot '", 0) == 0)
                continue;  // a robot alone is invalid (bounds, obstacles): it is reported before any pair
            EXPECT_EQ(got, expected) << scenario << " round " << k;
            collided += expected.empty() ? 0 : 1;
        }
        EXPECT_GE(collided, 3) << scenario;  // random arms are often invalid alone (self-collision)
    }
}

TEST(MultiRobotSpaceInformation, MotionsAreCheckedOncePerTimestep)
{
    const auto problem = test::twoDiscs({-5, 0}, {5, 0}, {5, 0}, {-5, 0}, false, 10.);
    const auto &si = problem.getSpaceInformation();
    ob::ScopedState<> a(si), b(si);
    a[0] = -5;
    a[1] = 0;
    a[2] = 5;
    a[3] = 0;
    b = a;
    b[0] = -3;  // robot a moves 2 units: 20 timesteps at resolution 10
    EXPECT_EQ(si->getStateSpace()->validSegmentCount(a.get(), b.get()), 20u);
}

TEST(MultiRobotSpaceInformation, RejectsBadTeams)
{
    ob::RealVectorBounds bounds(2);
    bounds.setLow(-1);
    bounds.setHigh(1);
    auto env = std::make_shared<Environment>();
    auto a = std::make_shared<DiscRobot>("a", env, 0.1, bounds);
    auto a2 = std::make_shared<DiscRobot>("a", env, 0.1, bounds);
    auto other = std::make_shared<DiscRobot>("o", std::make_shared<Environment>(), 0.1, bounds);
    EXPECT_THROW(MultiRobotSpaceInformation({}), ompl::Exception);
    EXPECT_THROW(MultiRobotSpaceInformation({a, nullptr}), ompl::Exception);
    EXPECT_THROW(MultiRobotSpaceInformation({a, a2}), ompl::Exception);
    EXPECT_THROW(MultiRobotSpaceInformation({a, other}), ompl::Exception);
    EXPECT_THROW(MultiRobotSpaceInformation({a}, 0.), ompl::Exception);
}

TEST(MultiRobotSpaceInformation, ResolutionsAndBoundsNoPlanCouldCrossAreRefusedNamingTheRobot)
{
    // Crossing the bounds once must fit in a plan (MultiRobotPlan::MAX_TIMESTEP): beyond it OMPL's own check
    // used to fail with "The fraction of the extent must be larger than 0 and less than 1", naming nothing.
    ob::RealVectorBounds bounds(2);
    bounds.setLow(-1);
    bounds.setHigh(1);
    auto env = std::make_shared<Environment>();
    auto a = std::make_shared<DiscRobot>("a", env, 0.1, bounds);
    const auto message = [&](const std::function<void()> &call)
    {
        try
        {
            call();
        }
        catch (const ompl::Exception &e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    for (double resolution : {1e308, 1e8})
        EXPECT_NE(message([&] { MultiRobotSpaceInformation({a}, resolution); }).find("robot 'a': resolution"),
                  std::string::npos)
            << resolution;
    for (double resolution : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
        EXPECT_NE(message([&] { MultiRobotSpaceInformation({a}, resolution); })
                      .find("resolution must be a positive, finite number"),
                  std::string::npos);
    EXPECT_NO_THROW(MultiRobotSpaceInformation({a}, 3e7));  // 2.83 x 3e7 timesteps cross the bounds
    ob::RealVectorBounds huge(2);
    huge.setLow(-1e15);
    huge.setHigh(1e15);
    EXPECT_EQ(
        message([&] { DiscRobot("wide", env, 0.1, huge); }),
        "Robot: robot 'wide': resolution 128 times the diagonal of its bounds (2.82843e+15) is 3.62039e+17 timesteps, "
        "more than a plan may hold (100000000): lower the resolution or shrink the bounds");
    huge.setLow(0, -std::numeric_limits<double>::infinity());
    EXPECT_NE(message([&] { DiscRobot("open", env, 0.1, huge); }).find("are not finite in dimension 0"),
              std::string::npos);
}

TEST(MultiRobotSpaceInformation, PlainSpaceInformationIsRejectedWithAClearError)
{
    auto plain = std::make_shared<ob::SpaceInformation>(std::make_shared<ob::RealVectorStateSpace>(2));
    try
    {
        MultiRobotSpaceInformation::get(plain, "ARC");
        FAIL() << "expected ompl::Exception";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("MultiRobotSpaceInformation"), std::string::npos);
    }
    const auto problem = scenarios::createMobileCross(4);
    EXPECT_EQ(MultiRobotSpaceInformation::get(problem.getSpaceInformation(), "ARC"), problem.getSpaceInformation());
}

TEST(MultiRobotProblem, RejectsMismatchedStartsAndGoals)
{
    const auto problem = scenarios::createMobileCross(4);
    const auto &si = problem.getSpaceInformation();
    std::vector<std::vector<double>> three(3, {0., 0.}), four(4, {0., 0.}), badSize = four;
    badSize[2] = {0.};
    EXPECT_THROW(MultiRobotProblem(si, three, four), ompl::Exception);
    EXPECT_THROW(MultiRobotProblem(si, four, three), ompl::Exception);
    EXPECT_THROW(MultiRobotProblem(si, badSize, four), ompl::Exception);
    EXPECT_THROW(MultiRobotProblem(nullptr, four, four), ompl::Exception);
}

TEST(MultiRobotProblem, CheckEndpointsNamesTheProblem)
{
    EXPECT_EQ(test::twoDiscs({-5, 0}, {5, 0}, {5, 3}, {-5, 3}).checkEndpoints(), "");
    EXPECT_EQ(test::twoDiscs({-11, 0}, {5, 0}, {5, 3}, {-5, 3}).checkEndpoints(),
              "start of robot 'a' is out of bounds");
    EXPECT_EQ(test::twoDiscs({-5, 0}, {0, 0}, {5, 3}, {-5, 3}, true).checkEndpoints(),
              "goal of robot 'a' is in collision with the environment");
    EXPECT_EQ(test::twoDiscs({-5, 0}, {5, 0}, {-5, 0.5}, {-5, 3}).checkEndpoints(),
              "starts of robots 'a' and 'b' collide");
}

/* The point of the composite model: OMPL's own planners run on it unchanged. */
class OmplOnComposite : public testing::TestWithParam<std::pair<std::string, std::size_t>>
{
};

TEST_P(OmplOnComposite, RRTConnectSolvesUnchangedAndTheResultValidates)
{
    const auto problem = scenarios::createScenario(GetParam().first, GetParam().second);
    auto pdef = problem.createProblemDefinition();
    ompl::geometric::RRTConnect planner(problem.getSpaceInformation());
    planner.setProblemDefinition(pdef);
    planner.setup();
    ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(60.)), ob::PlannerStatus::EXACT_SOLUTION);
    auto *path = pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    EXPECT_TRUE(path->check());
    const auto report =
        SolutionValidator(problem).validate(MultiRobotPlan::fromPathGeometric(*problem.getSpaceInformation(), *path));
    EXPECT_TRUE(report.valid) << report.message;
}

INSTANTIATE_TEST_SUITE_P(Scenarios, OmplOnComposite,
                         testing::Values(std::make_pair("mobile_cross", 4), std::make_pair("mobile_circle", 4),
                                         std::make_pair("planar_cross", 4)),
                         [](const auto &info) { return info.param.first + std::to_string(info.param.second); });
