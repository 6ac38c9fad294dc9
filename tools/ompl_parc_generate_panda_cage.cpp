/* ompl_parc_generate_panda_cage: generate the Panda Cage tasks (scenarios::generatePandaCageTask) and store them
   as scenario files OUT_DIR/panda_cage_<robots>_<task>.json, the files the library compiles in. For each task it
   reports how many robot pairs must coordinate: the pairs whose individual paths (ARC's first stage, as ARC plans
   them with its seed parameter set to --seed) collide, found by scanning every pair to its first conflict.
   Exit 0: all written; 2: bad input or a task that could not be generated. */
#include "ToolSupport.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/scenarios/ConflictingPairs.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/util/ParseNumber.h"

#include <ompl/util/Time.h>

#include <iomanip>
#include <iostream>
#include <numeric>

namespace po = boost::program_options;
using namespace ompl_parc;

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_generate_panda_cage",
        [&]
        {
            po::options_description options("Usage: ompl_parc_generate_panda_cage --out-dir DIR [options]\nOptions");
            options.add_options()("out-dir", po::value<std::string>(), "write the scenario files into this folder")(
                "robots", po::value<std::vector<std::string>>()->composing(),
                "team size to generate (repeatable; default 2, 4, 8 and 16)")(
                "task", po::value<std::vector<std::string>>()->composing(),
                "task to generate (repeatable; default all)")("seed", po::value<std::string>()->default_value("1"),
                                                              "ARC seed parameter of the conflict report");
            const auto vm = tools::parse(argc, argv, options);
            if (!vm.count("out-dir"))
                throw std::invalid_argument("no --out-dir given (see --help)");
            const auto numbers = [&vm](const char *name, std::uint64_t hi)
            {
                std::vector<std::size_t> values;
                for (const auto &text : vm[name].as<std::vector<std::string>>())
                    values.push_back(parseInteger(text, std::string("--") + name, 0, hi));
                return values;
            };
            // The generator's own checks name the team sizes and tasks it has; these bounds only stop wrapping.
            const auto teams = vm.count("robots") ? numbers("robots", 1000) : scenarios::pandaCageTeamSizes();
            std::vector<std::size_t> tasks(scenarios::PANDA_CAGE_TASKS);
            std::iota(tasks.begin(), tasks.end(), 0);
            if (vm.count("task"))
                tasks = numbers("task", 1000);
            const auto seed =
                static_cast<unsigned int>(parseInteger(vm["seed"].as<std::string>(), "--seed", 0, UINT32_MAX));
            for (std::size_t robots : teams)
                for (std::size_t task : tasks)
                {
                    const ompl::time::point start = ompl::time::now();
                    const MultiRobotProblem problem = scenarios::generatePandaCageTask(robots, task);
                    const double seconds = ompl::time::seconds(ompl::time::now() - start);
                    const std::string reason = problem.checkEndpoints();
                    if (!reason.empty())
                        throw std::runtime_error(problem.getName() + ": " + reason);
                    const std::string path = vm["out-dir"].as<std::string>() + "/" + problem.getName() + ".json";
                    ScenarioFile::write(path, problem);
                    std::cout << path << "  generated in " << std::fixed << std::setprecision(1) << seconds
                              << " s, conflicting pairs " << scenarios::countConflictingPairs(problem, seed) << " of "
                              << robots * (robots - 1) / 2 << std::endl;
                }
            return static_cast<int>(tools::EXIT_SOLVED);
        });
}
