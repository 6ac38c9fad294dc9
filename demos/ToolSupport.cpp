#include "ToolSupport.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/EPRRTConnect.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/ORPPSTRRT.h"
#include "ompl_parc/planners/ORRRTConnect.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <ompl/util/Console.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace po = boost::program_options;

ompl_parc::MultiRobotProblem ompl_parc::tools::problemFromOptions(const po::variables_map &vm)
{
    if (vm.count("scenario-file"))
    {
        if (!vm["scenario"].defaulted() || !vm["robots"].defaulted() || !vm["task"].defaulted())
            throw std::invalid_argument("give --scenario-file or --scenario/--robots/--task, not both");
        return ScenarioFile::read(vm["scenario-file"].as<std::string>());  // checks the endpoints itself
    }
    MultiRobotProblem problem = scenarios::createScenario(
        vm["scenario"].as<std::string>(), parseInteger(vm["robots"].as<std::string>(), "--robots", 1, MAX_ROBOTS), 128.,
        parseInteger(vm["task"].as<std::string>(), "--task", 0, MAX_TASK));
    const std::string reason = problem.checkEndpoints();
    if (!reason.empty())
        throw std::invalid_argument(reason);
    return problem;
}

namespace
{
    /** The bounds of a declared numeric parameter range "lo:step:hi" (or "lo:hi"), if \e range is one. */
    std::optional<std::pair<double, double>> numericRange(const std::string &range)
    {
        const auto first = range.find(':'), last = range.rfind(':');
        if (first == std::string::npos)
            return std::nullopt;
        char *end = nullptr;
        const double lo = std::strtod(range.c_str(), &end);
        if (end != range.c_str() + first)
            return std::nullopt;
        const double hi = std::strtod(range.c_str() + last + 1, &end);
        if (end == range.c_str() + last + 1 || *end != '\0')
            return std::nullopt;
        return std::make_pair(lo, hi);
    }

    const std::map<std::string, ompl::base::PlannerAllocator> &planners()
    {
        static const std::map<std::string, ompl::base::PlannerAllocator> table = {
            {"arc", [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ompl_parc::ARC>(si); }},
            {"parc", [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ompl_parc::PARC>(si); }},
            {"orparc",
             [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ompl_parc::ORPARC>(si); }},
            {"pp-st-rrt", [](const ompl::base::SpaceInformationPtr &si)
             { return std::make_shared<ompl_parc::PrioritizedSTRRT>(si); }},
            {"rrtconnect", [](const ompl::base::SpaceInformationPtr &si)
             { return std::make_shared<ompl::geometric::RRTConnect>(si); }},
            {"or-rrt-c",
             [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ompl_parc::ORRRTConnect>(si); }},
            {"ep-rrt-c",
             [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ompl_parc::EPRRTConnect>(si); }},
            // OR-EP-RRT-C is ORRRTConnect with EP-RRT-C instances: two workers each unless configured.
            {"or-ep-rrt-c",
             [](const ompl::base::SpaceInformationPtr &si)
             {
                 auto planner = std::make_shared<ompl_parc::ORRRTConnect>(si);
                 planner->setName("OREPRRTConnect");
                 planner->setWorkers(2);
                 return planner;
             }},
            {"or-pp-st-rrt",
             [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<ompl_parc::ORPPSTRRT>(si); }},
        };
        return table;
    }

    std::string join(const std::vector<std::string> &names)
    {
        std::string out;
        for (const auto &n : names)
            out += (out.empty() ? "" : ", ") + n;
        return out;
    }
}  // namespace

void ompl_parc::tools::addProblemOptions(po::options_description &options)
{
    const std::string names = join(scenarios::scenarioNames());
    options.add_options()("scenario", po::value<std::string>()->default_value("mobile_cross"),
                          ("built-in scenario: " + names).c_str())(
        "robots", po::value<std::string>()->default_value("4"), "number of robots of the built-in scenario")(
        "task", po::value<std::string>()->default_value("0"),
        "task of the built-in scenario (panda_cage: 0 to 4; a generated family: the instance)")(
        "scenario-file", po::value<std::string>(), "read the problem from this scenario file (JSON) instead");
}

std::vector<std::string> ompl_parc::tools::plannerNames()
{
    std::vector<std::string> names;
    for (const auto &entry : planners())
        names.push_back(entry.first);
    return names;
}

ompl::base::PlannerPtr ompl_parc::tools::createPlanner(const std::string &name,
                                                       const ompl::base::SpaceInformationPtr &si,
                                                       const std::vector<std::string> &params)
{
    const auto it = planners().find(name);
    if (it == planners().end())
        throw std::invalid_argument("unknown planner '" + name + "' (valid: " + join(plannerNames()) + ")");
    auto planner = it->second(si);
    // A named profile first, so that the parameters given with it override its values whatever their order.
    std::vector<std::string> ordered(params);
    std::stable_partition(ordered.begin(), ordered.end(),
                          [](const std::string &assignment) { return assignment.rfind("profile=", 0) == 0; });
    for (const auto &assignment : ordered)
    {
        const auto eq = assignment.find('=');
        if (eq == std::string::npos)
            throw std::invalid_argument("--param needs key=value, got '" + assignment + "'");
        setPlannerParameter(*planner, assignment.substr(0, eq), assignment.substr(eq + 1));
    }
    return planner;
}

void ompl_parc::tools::setPlannerParameter(ompl::base::Planner &planner, const std::string &key,
                                           const std::string &value)
{
    if (!planner.params().hasParam(key))
    {
        std::vector<std::string> valid;
        planner.params().getParamNames(valid);
        throw std::invalid_argument("planner '" + planner.getName() + "' has no parameter '" + key +
                                    "' (valid: " + join(valid) + ")");
    }
    if (const auto range = numericRange(planner.params().getParams().at(key)->getRangeSuggestion()))
        parseReal(value, "parameter '" + key + "'", range->first, range->second);
    if (!planner.params().setParam(key, value))
        throw std::invalid_argument("bad value '" + value + "' for parameter '" + key + "'");
}

ompl_parc::MultiRobotPlan ompl_parc::tools::planOf(const ompl::base::Planner &planner,
                                                   const MultiRobotSpaceInformationPtr &si, bool simplify)
{
    if (const auto *arc = dynamic_cast<const ArcPlannerBase *>(&planner))
        return arc->getPlan();
    if (const auto *orparc = dynamic_cast<const ORPARC *>(&planner))
        return orparc->getPlan();
    if (const auto *prioritized = dynamic_cast<const PrioritizedSTRRT *>(&planner))
        return prioritized->getPlan();
    auto &path = *planner.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    if (simplify)
        ompl::geometric::PathSimplifier(si).simplify(path, 1.0);
    return MultiRobotPlan::fromPathGeometric(*si, path);
}

std::uint64_t ompl_parc::tools::parseInteger(const std::string &text, const std::string &what, std::uint64_t lo,
                                             std::uint64_t hi)
{
    std::uint64_t value = 0;
    const char *end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || ptr != end || value < lo || value > hi)
        throw std::invalid_argument(what + " must be a whole number from " + std::to_string(lo) + " to " +
                                    std::to_string(hi) + " (got '" + text + "')");
    return value;
}

double ompl_parc::tools::parseReal(const std::string &text, const std::string &what, double lo, double hi)
{
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < lo || value > hi)
    {
        std::ostringstream message;
        message << what << " must be a number from " << lo << " to " << hi << " (got '" << text << "')";
        throw std::invalid_argument(message.str());
    }
    return value;
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
