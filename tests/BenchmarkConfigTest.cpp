#include "ompl_parc/planners/setup/BenchmarkConfig.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>

#include <sstream>

using ompl_parc::BenchmarkConfig;

namespace
{
    const std::string PROBLEM = "[problem]\nname = cross\nscenario = mobile_cross\nrobots = 8\n";
    const std::string BENCHMARK = "[benchmark]\ntime_limit = 30\nmem_limit = 4096\nrun_count = 3\n";

    BenchmarkConfig parse(const std::string &text)
    {
        std::istringstream in(text);
        return BenchmarkConfig::parse(in, "/configs");
    }

    /** The one-line reason parsing \e text fails with (empty if it parses). */
    std::string reason(const std::string &text)
    {
        try
        {
            parse(text);
        }
        catch (const std::invalid_argument &e)
        {
            return e.what();
        }
        return "";
    }
}  // namespace

TEST(BenchmarkConfig, ReadsOmplAppSectionsLabelsAndParameters)
{
    const auto config = parse("# comment\n" + PROBLEM + "resolution = 64\n" + BENCHMARK +
                              "output = results\nseed = 5\nworkers = 4\n"
                              "[planner]\narc =\nparc =\nparc.workers = 2\nparc.name = P-ARC-2\n"
                              "parc4 = parc\nparc4.workers = 4\n");
    EXPECT_EQ(config.getProblemName(), "cross");
    EXPECT_EQ(config.getScenario(), "mobile_cross");
    EXPECT_EQ(config.getRobots(), 8u);
    EXPECT_DOUBLE_EQ(config.getResolution(), 64.);
    EXPECT_DOUBLE_EQ(config.getTimeLimit(), 30.);
    EXPECT_DOUBLE_EQ(config.getMemLimit(), 4096.);
    EXPECT_EQ(config.getRunCount(), 3u);
    EXPECT_EQ(config.getOutput(), "/configs/results");
    EXPECT_EQ(config.getSeed(), 5u);
    EXPECT_EQ(config.getWorkers(), 4u);
    ASSERT_EQ(config.getPlanners().size(), 3u);
    const auto &p = config.getPlanners();
    EXPECT_EQ(p[0].type, "arc");
    EXPECT_EQ(p[0].name, "arc");
    EXPECT_TRUE(p[0].params.empty());
    EXPECT_EQ(p[1].type, "parc");
    EXPECT_EQ(p[1].name, "P-ARC-2");
    EXPECT_EQ(p[1].params, std::vector<std::string>{"workers=2"});
    EXPECT_EQ(p[2].label, "parc4");
    EXPECT_EQ(p[2].type, "parc");
    EXPECT_EQ(p[2].name, "parc4");

    // Optional keys: the output folder is the config's, the seed 1, and an absolute output stays.
    const auto defaults = parse(PROBLEM + BENCHMARK + "output = /tmp/x\n[planner]\nor-pp-st-rrt =\n");
    EXPECT_EQ(defaults.getOutput(), "/tmp/x");
    EXPECT_EQ(defaults.getSeed(), 1u);
    EXPECT_GE(defaults.getWorkers(), 1u);
    EXPECT_EQ(parse(PROBLEM + BENCHMARK + "[planner]\narc =\n").getOutput(), "/configs");
}

TEST(BenchmarkConfig, BadInputIsOneLineNamingTheValidChoices)
{
    const std::string planner = "[planner]\narc =\n";
    const auto has = [](const std::string &text, const std::string &part)
    { return text.find(part) != std::string::npos && text.find('\n') == std::string::npos; };
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + planner + "[extra]\nx = 1\n"), "valid: [problem], [benchmark]"));
    EXPECT_TRUE(has(reason("stray = 1\n" + PROBLEM + BENCHMARK + planner), "outside a section"));
    EXPECT_TRUE(has(reason(BENCHMARK + planner), "needs a [problem]"));
    EXPECT_TRUE(has(reason(PROBLEM + "colour = red\n" + BENCHMARK + planner), "valid: name, scenario"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "save_paths = all\n" + planner), "valid: time_limit"));
    EXPECT_TRUE(has(reason(PROBLEM + "[benchmark]\ntime_limit = 30\nrun_count = 3\n" + planner), "needs mem_limit"));
    const std::string workers = "[benchmark] workers must be a whole number from 1 to 1024";
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "workers = two\n" + planner), workers + " (got 'two')"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "workers = -1\n" + planner), workers + " (got '-1')"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "workers = 0\n" + planner), workers + " (got '0')"));
    EXPECT_TRUE(has(reason("[problem]\nname = c\nscenario = mobile_cross\nrobots = 1\n" + BENCHMARK + planner),
                    "[problem] robots must be a whole number from 2 to 20000 (got '1')"));
    // The last run's seed (seed + run_count - 1) must fit in 32 bits, not wrap round to 0; limits are finite.
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "seed = 4294967295\n" + planner),
                    "[benchmark] seed must be a whole number from 1 to"));
    EXPECT_TRUE(has(reason(PROBLEM + "[benchmark]\ntime_limit = inf\nmem_limit = 1\nrun_count = 3\n" + planner),
                    "[benchmark] time_limit must be a number from"));
    // Names become file names in the output folder: no way out of it.
    EXPECT_TRUE(
        has(reason("[problem]\nname = ../../escaped\nscenario = mobile_cross\nrobots = 4\n" + BENCHMARK + planner),
            "[problem] name '../../escaped' must be letters, digits"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "[planner]\nrrt =\n"), "valid: arc"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "[planner]\n"), "planner"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "[planner]\narc =\nparc.workers = 2\n"), "declared: arc"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "[planner]\narc =\narc =\n"), "its own label"));
    EXPECT_TRUE(has(reason(PROBLEM + BENCHMARK + "[planner]\narc =\nx = arc\nx.name = arc\n"), "named 'arc'"));
}

TEST(BenchmarkConfig, PlannerParametersAreCheckedByName)
{
    // Declared names are checked when the planners are created, with the valid ones listed.
    const auto problem = ompl_parc::scenarios::createMobileCross(4);
    const auto si = problem.getSpaceInformation();
    EXPECT_NO_THROW(ompl_parc::PlannerRegistry::create("or-ep-rrt-c", si, {"instances=2", "total_workers=4"}));
    try
    {
        ompl_parc::PlannerRegistry::create("ep-rrt-c", si, {"threads=2"});
        FAIL() << "an unknown parameter was accepted";
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_NE(std::string(e.what()).find("valid: "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("workers"), std::string::npos) << e.what();
    }
}

TEST(BenchmarkConfig, ScenarioFilesAreTakenRelativeToTheConfigFolder)
{
    const std::string planner = "[planner]\narc =\n";
    EXPECT_EQ(parse("[problem]\nname = f\nfile = ../scenarios/a.json\n" + BENCHMARK + planner).getScenarioFile(),
              "/scenarios/a.json");
    EXPECT_EQ(parse("[problem]\nname = f\nfile = /data/b.json\n" + BENCHMARK + planner).getScenarioFile(),
              "/data/b.json");
    EXPECT_TRUE(parse(PROBLEM + BENCHMARK + planner).getScenarioFile().empty());
    EXPECT_NE(reason("[problem]\nname = f\nfile = a.json\nrobots = 4\n" + BENCHMARK + planner).find("not both"),
              std::string::npos);
    EXPECT_NE(reason("[problem]\nname = f\nfile =\n" + BENCHMARK + planner).find("file"), std::string::npos);
}
