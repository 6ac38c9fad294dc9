#include "ToolSupport.h"

#include "ompl_parc/Version.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/util/NameList.h"
#include "ompl_parc/util/ParseNumber.h"

#include <ompl/util/Console.h>

#include <iostream>
#include <stdexcept>

namespace po = boost::program_options;

void ompl_parc::tools::checkProblemSource(const po::variables_map &vm)
{
    if (vm.count("scenario-file") &&
        (!vm["scenario"].defaulted() || !vm["robots"].defaulted() || !vm["task"].defaulted()))
        throw std::invalid_argument("give --scenario-file or --scenario/--robots/--task, not both");
}

ompl_parc::MultiRobotProblem ompl_parc::tools::problemFromOptions(const po::variables_map &vm)
{
    checkProblemSource(vm);
    if (vm.count("scenario-file"))
        return ScenarioFile::read(vm["scenario-file"].as<std::string>());  // checks the endpoints itself
    MultiRobotProblem problem = scenarios::createScenario(
        vm["scenario"].as<std::string>(), parseInteger(vm["robots"].as<std::string>(), "--robots", 1, MAX_ROBOTS), 128.,
        parseInteger(vm["task"].as<std::string>(), "--task", 0, MAX_TASK));
    const std::string reason = problem.checkEndpoints();
    if (!reason.empty())
        throw std::invalid_argument(reason);
    return problem;
}

void ompl_parc::tools::addProblemOptions(po::options_description &options)
{
    const std::string names = listNames(scenarios::scenarioNames());
    options.add_options()("scenario", po::value<std::string>()->default_value("mobile_cross"),
                          ("built-in scenario: " + names).c_str())(
        "robots", po::value<std::string>()->default_value("4"), "number of robots of the built-in scenario")(
        "task", po::value<std::string>()->default_value("0"),
        "task of the built-in scenario (panda_cage: 0 to 4; a generated family: the instance)")(
        "scenario-file", po::value<std::string>(), "read the problem from this scenario file (JSON) instead");
}

namespace
{
    /** \brief Thrown by parse() after --help or --version did their job: runTool() returns EXIT_SOLVED. */
    struct Answered
    {
    };
}  // namespace

std::pair<std::string, std::string> ompl_parc::tools::splitPropertyKey(const std::string &key)
{
    const auto space = key.rfind(' ');
    if (space == std::string::npos)
        return {key, ""};
    return {key.substr(0, space), key.substr(space + 1)};
}

std::string ompl_parc::tools::versionLine()
{
    return std::string("ompl_parc ") + OMPL_PARC_VERSION + " (OMPL " + OMPL_PARC_OMPL_VERSION + ")";
}

po::variables_map ompl_parc::tools::parse(int argc, char **argv, const po::options_description &options,
                                          const po::positional_options_description &positional)
{
    po::options_description all(options);
    all.add_options()("version", "print the version of ompl_parc (and of OMPL) and exit")("help,h", "show this help");
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    if (vm.count("help"))
    {
        std::cout << all << std::endl;
        throw Answered();
    }
    if (vm.count("version"))
    {
        std::cout << versionLine() << std::endl;
        throw Answered();
    }
    po::notify(vm);
    return vm;
}

void ompl_parc::tools::printError(const std::string &tool, const std::string &message)
{
    std::cout.flush();
    std::cerr << (tool + ": " + message + "\n");  // std::cerr is unbuffered: one write
}

int ompl_parc::tools::runTool(const std::string &tool, const std::function<int()> &body)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    try
    {
        return body();
    }
    catch (const Answered &)
    {
        return EXIT_SOLVED;
    }
    catch (const std::exception &e)
    {
        printError(tool, e.what());
        return EXIT_BAD_INPUT;
    }
}
