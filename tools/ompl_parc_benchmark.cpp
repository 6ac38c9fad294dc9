/* ompl_parc_benchmark CONFIG.cfg: run an OMPL.app-style benchmark configuration (see BenchmarkConfig.h) with
   OMPL's own ompl::tools::Benchmark (BenchmarkRunner): <output>/<name>.log (OMPL's log format, for
   ompl_benchmark_statistics; one per task with [problem] instances = N) and <output>/<name>.csv (one row per run,
   for scripts/plot_benchmarks.py), a line per run on stderr and a table of success rate and median time per planner
   on stdout.
   Ctrl-C: no further run starts; the one in progress ends at its time limit (a second Ctrl-C quits at once), then the
   CSV holds the rows of the runs done and each task whose runs all ended has its log.
   Exit 0: all runs done and every solution valid; 1: some solution failed validation; 2: bad input; 130:
   interrupted. */
#include "BenchmarkRunner.h"
#include "Interruption.h"
#include "ToolSupport.h"

#include <iostream>

namespace po = boost::program_options;
using namespace ompl_parc;

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_benchmark",
        [&]
        {
            po::options_description options("Usage: ompl_parc_benchmark [options] CONFIG.cfg\nOptions");
            options.add_options()("config", po::value<std::string>(), "benchmark configuration (OMPL.app INI)")(
                "check", "only check the config: load the problem, create every planner, then exit");
            po::positional_options_description positional;
            positional.add("config", 1);
            const auto vm = tools::parse(argc, argv, options, positional);
            if (!vm.count("config"))
                throw std::invalid_argument("no configuration file given (see --help)");

            // Everything that can be wrong with the input is checked before the first run.
            tools::BenchmarkRunner runner(BenchmarkConfig::read(vm["config"].as<std::string>()));
            if (vm.count("check"))
            {
                std::cout << runner.describe() << std::endl;
                return static_cast<int>(tools::EXIT_SOLVED);
            }
            const tools::Interruption interruption("ompl_parc_benchmark", tools::Interruption::FirstSignal::STOP,
                                                   "no further run starts (this one ends by its time limit)");
            const tools::BenchmarkResults results = runner.run(std::cerr, tools::Interruption::raised);
            std::cout << results.summary;
            if (tools::Interruption::raised())
            {
                tools::printError("ompl_parc_benchmark", "interrupted after " + std::to_string(results.runs) + " of " +
                                                             std::to_string(runner.getRunCount()) + " runs");
                return static_cast<int>(tools::EXIT_INTERRUPTED);
            }
            return static_cast<int>(results.invalid ? tools::EXIT_FAILED : tools::EXIT_SOLVED);
        });
}
