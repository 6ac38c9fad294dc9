/* ompl_parc_generate: write instances of a built-in scenario or generated problem family (ProblemFamilies.h) as
   scenario files OUT_DIR/<name>.json, e.g. 20 random "rooms" problems of 16 robots:
       ompl_parc_generate --scenario rooms --robots 16 --task 0 --count 20 --out-dir rooms16
   Instance k of a family is the same problem on every machine. Each file is read back and compared before the
   next one is written. Exit 0: all written; 2: bad input or an instance that could not be generated. */
#include "ToolSupport.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/util/ParseNumber.h"

#include <filesystem>
#include <iostream>

namespace po = boost::program_options;
using namespace ompl_parc;

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_generate",
        [&]
        {
            po::options_description options("Usage: ompl_parc_generate --out-dir DIR [options]\nOptions");
            tools::addProblemOptions(options);
            options.add_options()("count", po::value<std::string>()->default_value("1"),
                                  "number of instances: tasks --task, --task + 1, ...")(
                "out-dir", po::value<std::string>(), "write the scenario files into this folder (created)");
            const auto vm = tools::parse(argc, argv, options);
            if (!vm.count("out-dir"))
                throw std::invalid_argument("no --out-dir given (see --help)");
            if (vm.count("scenario-file"))
                throw std::invalid_argument("--scenario-file: this tool writes scenario files, give --scenario");
            const std::size_t count = parseInteger(vm["count"].as<std::string>(), "--count", 1, 100000);
            const std::size_t first = parseInteger(vm["task"].as<std::string>(), "--task", 0, MAX_TASK);
            const std::size_t robots = parseInteger(vm["robots"].as<std::string>(), "--robots", 1, MAX_ROBOTS);
            const std::filesystem::path folder = vm["out-dir"].as<std::string>();
            std::error_code error;
            std::filesystem::create_directories(folder, error);
            if (error)
                throw std::invalid_argument("cannot create --out-dir '" + folder.string() + "': " + error.message());
            for (std::size_t task = first; task < first + count; ++task)
            {
                const MultiRobotProblem problem =
                    scenarios::createScenario(vm["scenario"].as<std::string>(), robots, 128., task);
                const std::string name =
                    problem.getName().empty() ? "problem_" + std::to_string(task) : problem.getName();
                const std::string path = (folder / (name + ".json")).string();
                ScenarioFile::write(path, problem);
                if (ScenarioFile::toJson(ScenarioFile::read(path)) != ScenarioFile::toJson(problem))
                    throw std::runtime_error("'" + path + "' does not read back as the problem written");
                std::cout << path << std::endl;
            }
            return static_cast<int>(tools::EXIT_SOLVED);
        });
}
