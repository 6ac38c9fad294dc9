#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/setup/MultiRobotSetup.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/util/InnerPlannerLog.h"

#include <gtest/gtest.h>
#include <ompl/util/Console.h>

#include <atomic>
#include <mutex>
#include <thread>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** Four discs crossing in pairs in a 20 x 20 room, named by their start side. */
    std::vector<RobotPtr> crossingPairs()
    {
        auto env = std::make_shared<Environment>();
        ob::RealVectorBounds room(2);
        room.setLow(-10.);
        room.setHigh(10.);
        std::vector<RobotPtr> team;
        for (const char *name : {"west_low", "east_low", "west_high", "east_high"})
            team.push_back(std::make_shared<DiscRobot>(name, env, 0.5, room));
        return team;
    }

    void setCrossing(MultiRobotSetup &setup)
    {
        setup.setStart("west_low", {-8., -1.});
        setup.setGoal("west_low", {8., -1.});
        setup.setStart("east_low", {8., -1.});
        setup.setGoal("east_low", {-8., -1.});
        setup.setStart("west_high", {-8., 1.});
        setup.setGoal("west_high", {8., 1.});
        setup.setStart("east_high", {8., 1.});
        setup.setGoal("east_high", {-8., 1.});
    }

    /** Expects \e call to throw E whose message contains \e text. */
    template <typename E, typename F>
    void expectThrow(F call, const std::string &text)
    {
        try
        {
            call();
            ADD_FAILURE() << "no exception, expected one saying: " << text;
        }
        catch (const E &e)
        {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    }
}  // namespace

TEST(PlannerRegistry, FindsPlannersByTheirNamesInAnySpelling)
{
    EXPECT_EQ(PlannerRegistry::canonicalName("parc"), "parc");
    EXPECT_EQ(PlannerRegistry::canonicalName("PARC"), "parc");
    EXPECT_EQ(PlannerRegistry::canonicalName("P-ARC"), "parc");
    EXPECT_EQ(PlannerRegistry::canonicalName("OR-P-ARC"), "orparc");
    EXPECT_EQ(PlannerRegistry::canonicalName("PP-ST-RRT"), "pp-st-rrt");
    EXPECT_EQ(PlannerRegistry::canonicalName("RRTConnect"), "rrtconnect");
    EXPECT_EQ(PlannerRegistry::canonicalName("or_ep_rrt_c"), "or-ep-rrt-c");
    expectThrow<std::invalid_argument>([] { PlannerRegistry::canonicalName("rrt"); },
                                       "unknown planner 'rrt' (valid: arc, ep-rrt-c, or-ep-rrt-c, or-pp-st-rrt, "
                                       "or-rrt-c, orparc, parc, pp-st-rrt, rrtconnect)");
}

/* The README's promise: a team, starts and goals by robot name, "parc" with typed parameters, the per-robot plan
   from the requested starts to the requested goals, validated; the progress properties at the end of the solve. */
TEST(PlannerRegistry, EveryParameterOfEveryPlannerIsReadByItsType)
{
    // OMPL's own reading takes any text but "0", "false" and "" as true, wraps "-1" and truncates "2.5":
    // through the registry (the tools, benchmark configurations, MultiRobotSetup, Python) every value is read
    // by its parameter's type or refused.
    const auto si = scenarios::createMobileCross(4).getSpaceInformation();
    std::size_t bools = 0, wholes = 0, reals = 0;
    for (const std::string &name : PlannerRegistry::names())
    {
        const auto planner = PlannerRegistry::create(name, si);
        for (const auto &[key, parameter] : planner->params().getParams())
        {
            SCOPED_TRACE(name + " " + key);
            const std::string before = parameter->getValue();
            if (dynamic_cast<const ompl::base::SpecificParam<bool> *>(parameter.get()) != nullptr)
            {
                ++bools;
                for (const std::string &no : {"0", "false", "off", "no", "No", "FALSE"})
                {
                    PlannerRegistry::setParameter(*planner, key, no);
                    EXPECT_EQ(parameter->getValue(), "0") << no;
                }
                for (const std::string &yes : {"1", "true", "on", "yes", "Yes"})
                {
                    PlannerRegistry::setParameter(*planner, key, yes);
                    EXPECT_EQ(parameter->getValue(), "1") << yes;
                }
                for (const std::string &bad : {"", "maybe", "2", "-1", "0.5", "n", "offf"})
                    EXPECT_THROW(PlannerRegistry::setParameter(*planner, key, bad), std::invalid_argument) << bad;
            }
            else if (dynamic_cast<const ompl::base::SpecificParam<unsigned int> *>(parameter.get()) != nullptr)
            {
                ++wholes;
                for (const std::string &bad :
                     {"", "-1", "2.5", "1e3", "+3", " 3", "0x10", "3 ", "abc", "99999999999999999999", "4294967296"})
                    EXPECT_THROW(PlannerRegistry::setParameter(*planner, key, bad), std::invalid_argument) << bad;
            }
            else if (dynamic_cast<const ompl::base::SpecificParam<double> *>(parameter.get()) != nullptr)
            {
                ++reals;
                for (const std::string &bad : {"", "nan", "inf", "-inf", "1e999", "0.5abc", "abc"})
                    EXPECT_THROW(PlannerRegistry::setParameter(*planner, key, bad), std::invalid_argument) << bad;
            }
            // A refused value leaves the parameter as it was.
            if (dynamic_cast<const ompl::base::SpecificParam<bool> *>(parameter.get()) == nullptr)
                EXPECT_EQ(parameter->getValue(), before);
        }
    }
    EXPECT_GT(bools, 10u);
    EXPECT_GT(wholes, 10u);
    EXPECT_GT(reals, 5u);
}

TEST(MultiRobotSetup, SolvesByNameWithTypedParameters)
{
    MultiRobotSetup setup(crossingPairs());
    setCrossing(setup);
    setup.setPlanner("parc");
    setup.setPlannerParameter("workers", 2);
    setup.setPlannerParameter("seed", 3u);
    setup.setPlannerParameter("optimistic", true);
    setup.setPlannerParameter("smooth", 0.25);
    setup.setPlannerParameter("growth", "exponential");
    const auto &parc = static_cast<const PARC &>(*setup.getPlanner());
    EXPECT_EQ(parc.getWorkers(), 2u);
    EXPECT_EQ(parc.getSmoothing(), 0.25);
    EXPECT_EQ(parc.getGrowth(), "exponential");

    ASSERT_EQ(setup.solve(60.), ob::PlannerStatus::EXACT_SOLUTION);
    const ValidationReport report = setup.validate();
    EXPECT_TRUE(report.valid) << report.message;
    const MultiRobotPlan &plan = setup.getPlan();
    const std::size_t east = setup.getRobotIndex("east_high");
    double at[2];
    plan.getConfig(east, 0, at);
    EXPECT_EQ(std::vector<double>(at, at + 2), (std::vector<double>{8., 1.}));
    plan.getConfig(east, plan.getMakespan(), at);
    EXPECT_EQ(std::vector<double>(at, at + 2), (std::vector<double>{-8., 1.}));

    const auto progress = setup.getProgress();
    EXPECT_EQ(progress.size(), 8u);
    EXPECT_EQ(progress.at("stage INTEGER"), "4");
    EXPECT_EQ(progress.at("robots planned INTEGER"), "4");
    EXPECT_EQ(progress.at("conflicts resolved INTEGER"), std::to_string(parc.getStatistics().repairs));
    EXPECT_EQ(progress.at("current makespan INTEGER"), std::to_string(plan.getMakespan()));

    const std::size_t before = plan.getMakespan();
    const SmoothingReport smoothing = setup.simplify(0.2);
    EXPECT_EQ(smoothing.makespanBefore, before);
    EXPECT_LE(setup.getPlan().getMakespan(), before);
    EXPECT_TRUE(setup.validate().valid);
}

/* A changed goal is a new problem: the planner starts over instead of continuing the last one. */
TEST(MultiRobotSetup, SolvesAChangedProblemAnew)
{
    MultiRobotSetup setup(crossingPairs());
    setCrossing(setup);
    setup.setPlanner("arc");
    setup.setPlannerParameter("seed", 4);
    ASSERT_EQ(setup.solve(60.), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(setup.validate().valid);
    setup.setGoal("west_low", {8., -4.});
    ASSERT_EQ(setup.solve(60.), ob::PlannerStatus::EXACT_SOLUTION);
    const ValidationReport report = setup.validate();
    EXPECT_TRUE(report.valid) << report.message;
    double at[2];
    setup.getPlan().getConfig(0, setup.getPlan().getMakespan(), at);
    EXPECT_EQ(std::vector<double>(at, at + 2), (std::vector<double>{8., -4.}));
}

TEST(MultiRobotSetup, RefusesBadInputWithAReason)
{
    MultiRobotSetup setup(crossingPairs());
    expectThrow<std::invalid_argument>(
        [&] {
            setup.setStart("north", {0., 0.});
        },
        "no robot named 'north' (the team: west_low, east_low, west_high, east_high)");
    expectThrow<std::invalid_argument>(
        [&] {
            setup.setGoal(1, {0., 0., 0.});
        },
        "robot 'east_low' has 2 degrees of freedom, got 3 values");
    expectThrow<std::invalid_argument>([&] { setup.setStart(4, {0., 0.}); }, "no robot 4 (the team has 4)");
    expectThrow<std::invalid_argument>([&] { setup.setPlannerParameter("workers", 2); }, "set a planner");
    expectThrow<std::invalid_argument>([&] { setup.solve(1.); }, "set a planner");
    expectThrow<std::invalid_argument>([&] { setup.setPlanner("prm"); }, "unknown planner 'prm'");
    setup.setPlanner("arc");
    expectThrow<std::invalid_argument>([&] { setup.setPlannerParameter("workers", 2); },
                                       "planner 'ARC' has no parameter 'workers'");
    expectThrow<std::invalid_argument>([&] { setup.setPlannerParameter("window", -1); },
                                       "parameter 'window' must be a whole number from 1 to 2000 (got '-1')");
    expectThrow<std::invalid_argument>([&] { setup.setPlannerParameter("growth", "quadratic"); }, "bad value");
    setup.setStart("west_low", {-8., -1.});
    expectThrow<std::invalid_argument>([&] { setup.solve(1.); }, "robot 'west_low' has no goal");
    expectThrow<std::logic_error>([&] { setup.getPlan(); }, "no solution");
    expectThrow<std::logic_error>([&] { setup.simplify(0.1); }, "no solution");
}

/* Every registry planner through the setup, each plan re-checked by the independent validator. */
TEST(MultiRobotSetup, EveryRegistryPlannerSolvesAndValidates)
{
    const MultiRobotProblem problem = scenarios::createMobileCross(4);
    for (const std::string &name : PlannerRegistry::names())
    {
        MultiRobotSetup setup(problem);
        setup.setPlanner(name);
        if (setup.getPlanner()->params().hasParam("seed"))
            setup.setPlannerParameter("seed", 5);
        ASSERT_EQ(setup.solve(60.), ob::PlannerStatus::EXACT_SOLUTION) << name;
        const ValidationReport report = setup.validate();
        EXPECT_TRUE(report.valid) << name << ": " << report.message;
    }
}

/* The progress properties are read from another thread while P-ARC and OR-P-ARC plan (as OMPL's Benchmark does; TSan
   runs this): the stage never goes back, the counters never drop, and the last values are the statistics'. */
TEST(ParcProgress, IsReadableFromAnotherThreadWhileSolving)
{
    const MultiRobotProblem problem = scenarios::createMobileCircle(8);
    for (const std::string &name : {"parc", "orparc"})
    {
        MultiRobotSetup setup(problem);
        setup.setPlanner(name);
        setup.setPlannerParameter("seed", 2);
        setup.setPlannerParameter("smooth", 0.2);
        const auto properties = setup.getPlanner()->getPlannerProgressProperties();
        ASSERT_EQ(properties.size(), 8u);
        std::atomic<bool> done{false};
        std::vector<int> stages;
        unsigned int resolvedBefore = 0;
        bool dropped = false;
        std::thread reader(
            [&]
            {
                while (!done)
                {
                    stages.push_back(std::stoi(properties.at("stage INTEGER")()));
                    const unsigned int resolved = std::stoul(properties.at("conflicts resolved INTEGER")());
                    dropped = dropped || resolved < resolvedBefore;
                    resolvedBefore = resolved;
                    std::stod(properties.at("elapsed REAL")());
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                }
            });
        const auto status = setup.solve(60.);
        done = true;
        reader.join();
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << name;
        EXPECT_TRUE(setup.validate().valid) << name;
        EXPECT_TRUE(std::is_sorted(stages.begin(), stages.end())) << name;
        EXPECT_FALSE(dropped) << name;
        EXPECT_GT(stages.size(), 10u) << name;
        EXPECT_EQ(properties.at("stage INTEGER")(), "4") << name;
        EXPECT_EQ(properties.at("current makespan INTEGER")(), std::to_string(setup.getPlan().getMakespan())) << name;
    }
}

/* A stop in the initial stage, when some robots have no path yet (so no arrival, no makespan): a timeout, its
   progress at the initial stage with fewer robots planned than the team. */
TEST(ParcProgress, StopsCleanlyInTheInitialStage)
{
    MultiRobotSetup setup(scenarios::createPandaCage(16, 3));
    setup.setPlanner("arc");
    setup.setPlannerParameter("profile", "panda");
    setup.setPlannerParameter("seed", 1);
    // Stop once the first robot has its path: a time limit raced the initial stage (16 Pandas now plan in tens of
    // milliseconds) and let it finish in some runs.
    const ob::PlannerTerminationCondition afterFirstRobot(
        [&setup] { return std::stoul(setup.getProgress().at("robots planned INTEGER")) >= 1; });
    EXPECT_EQ(setup.solve(afterFirstRobot), ob::PlannerStatus::TIMEOUT);
    const auto progress = setup.getProgress();
    EXPECT_EQ(progress.at("stage INTEGER"), "1");
    EXPECT_LT(std::stoul(progress.at("robots planned INTEGER")), 16u);
    EXPECT_EQ(progress.at("current makespan INTEGER"), "0");
}

namespace
{
    /** Keeps every message OMPL logs. */
    class CapturedLog : public ompl::msg::OutputHandler
    {
      public:
        void log(const std::string &text, ompl::msg::LogLevel, const char *, int) override
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            text_ += text + "\n";
        }
        std::string text()
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            return text_;
        }

      private:
        std::mutex mutex_;
        std::string text_;
    };

    /** What ARC logs at INFO on Mobile Cross 8, with the inner planners' messages shown or not. */
    std::string arcLog(bool shown)
    {
        CapturedLog captured;
        ompl::msg::OutputHandler *before = ompl::msg::getOutputHandler();
        ompl::msg::useOutputHandler(&captured);
        ompl::msg::setLogLevel(ompl::msg::LOG_INFO);
        InnerPlannerLog::setShown(shown);
        MultiRobotSetup setup(scenarios::createMobileCross(8));
        setup.setPlanner("arc");
        setup.setPlannerParameter("seed", 1);
        const auto status = setup.solve(60.);
        EXPECT_TRUE(status != ob::PlannerStatus::EXACT_SOLUTION || setup.validate().valid);
        EXPECT_EQ(ompl::msg::getOutputHandler(), &captured) << "the filter stayed in place after the solve";
        // OMPL's previous handler is the one before ours again, not the filter.
        ompl::msg::restorePreviousOutputHandler();
        EXPECT_EQ(ompl::msg::getOutputHandler(), before);
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        InnerPlannerLog::setShown(false);
        EXPECT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION);
        return captured.text();
    }
}  // namespace

TEST(InnerPlannerLog, KeepsTheInnerPlannersQuietUnlessAsked)
{
    const std::string quiet = arcLog(false);
    EXPECT_NE(quiet.find("ARC: initial stage done"), std::string::npos) << quiet;
    EXPECT_NE(quiet.find("ARC: conflict-free after"), std::string::npos) << quiet;
    EXPECT_EQ(quiet.find("RRTConnect"), std::string::npos) << quiet;
    const std::string shown = arcLog(true);
    EXPECT_NE(shown.find("RRTConnect: Created"), std::string::npos) << shown;
    EXPECT_NE(shown.find("ARC: conflict-free after"), std::string::npos) << shown;
}
