#include "ToolSupport.h"

#include "ompl_parc/scenarios/Scenarios.h"

#include <ompl/util/Console.h>

#include <iostream>
#include <stdexcept>

namespace po = boost::program_options;

void ompl_parc::tools::addProblemOptions(po::options_description &options)
{
    std::string names;
    for (const auto &n : scenarios::scenarioNames())
        names += (names.empty() ? "" : ", ") + n;
    options.add_options()("scenario", po::value<std::string>()->default_value("mobile_cross"),
                          ("built-in scenario: " + names).c_str())("robots", po::value<std::size_t>()->default_value(4),
                                                                   "number of robots");
}

ompl_parc::MultiRobotProblem ompl_parc::tools::problemFromOptions(const po::variables_map &vm)
{
    MultiRobotProblem problem =
        scenarios::createScenario(vm["scenario"].as<std::string>(), vm["robots"].as<std::size_t>());
    const std::string reason = problem.checkEndpoints();
    if (!reason.empty())
        throw std::invalid_argument(reason);
    return problem;
}

po::variables_map ompl_parc::tools::parse(int argc, char **argv, const po::options_description &options,
                                          const po::positional_options_description &positional)
{
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(options).positional(positional).run(), vm);
    po::notify(vm);
    return vm;
}

int ompl_parc::tools::runTool(const std::string &tool, const std::function<int()> &body)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    try
    {
        return body();
    }
    catch (const std::exception &e)
    {
        std::cerr << tool << ": " << e.what() << std::endl;
        return EXIT_BAD_INPUT;
    }
}
