#include "ompl_parc/planners/setup/BenchmarkConfig.h"

#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/util/NameList.h"
#include "ompl_parc/util/ParseNumber.h"
#include "ompl_parc/util/TextFile.h"

#include <boost/lexical_cast.hpp>
#include <boost/property_tree/ini_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>
#include <type_traits>

namespace pt = boost::property_tree;

namespace
{

    /** \brief Throws unless every key of \e section is one of \e valid, naming the valid ones. */
    void checkKeys(const pt::ptree &section, const std::string &name, const std::vector<std::string> &valid)
    {
        for (const auto &entry : section)
        {
            if (!entry.second.empty())
                throw std::invalid_argument("[" + name + "] " + entry.first + ": nested keys are not supported");
            if (std::find(valid.begin(), valid.end(), entry.first) == valid.end())
                throw std::invalid_argument("unknown key '" + entry.first + "' in [" + name +
                                            "] (valid: " + ompl_parc::listNames(valid) + ")");
        }
    }

    std::string required(const pt::ptree &section, const std::string &name, const std::string &key)
    {
        const auto value = section.get_optional<std::string>(key);
        if (!value || value->empty())
            throw std::invalid_argument("[" + name + "] needs " + key);
        return *value;
    }

    /** \brief The number under \e key (or \e fallback if absent); throws unless it parses and is >= \e least. */
    /** The number \e key of \e section (its \e fallback if absent and one is given) within [\e least, \e most]:
        whole numbers digits only (no wrapping of "-1"), reals finite. */
    template <typename T>
    T number(const pt::ptree &section, const std::string &name, const std::string &key, std::optional<T> fallback,
             T least, T most)
    {
        const auto text = section.get_optional<std::string>(key);
        if (!text && fallback)
            return *fallback;
        const std::string value = text ? *text : required(section, name, key);
        const std::string what = "[" + name + "] " + key;
        if constexpr (std::is_integral_v<T>)
            return static_cast<T>(ompl_parc::parseInteger(value, what, least, most));
        else
            return static_cast<T>(ompl_parc::parseReal(value, what, least, most));
    }

    /** Names become file names in the output folder: letters, digits, '.', '_' and '-', not starting with '.'. */
    void checkFileName(const std::string &name, const std::string &what)
    {
        const bool plain =
            !name.empty() && name.front() != '.' &&
            std::all_of(name.begin(), name.end(),
                        [](char c)
                        { return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'; });
        if (!plain)
            throw std::invalid_argument(what + " '" + name +
                                        "' must be letters, digits, '.', '_' and '-' (not starting with '.'): it "
                                        "names the files written in the output folder");
    }
}  // namespace

ompl_parc::BenchmarkConfig ompl_parc::BenchmarkConfig::read(const std::string &path)
{
    std::istringstream in(TextFile::read(path, "BenchmarkConfig"));
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    return parse(in, folder.empty() ? "." : folder.string());
}

ompl_parc::BenchmarkConfig ompl_parc::BenchmarkConfig::parse(std::istream &in, const std::string &folder)
{
    pt::ptree tree;
    try
    {
        pt::read_ini(in, tree);
    }
    catch (const pt::ini_parser_error &e)
    {
        throw std::invalid_argument("config line " + std::to_string(e.line()) + ": " + e.message() +
                                    (e.message() == "duplicate key name"
                                         ? " (give a second planner of a type its own label: 'label = type')"
                                         : ""));
    }
    for (const auto &section : tree)
        if (section.first != "problem" && section.first != "benchmark" && section.first != "planner")
            throw std::invalid_argument(section.second.empty() ? "key '" + section.first + "' outside a section"
                                                               : "unknown section [" + section.first +
                                                                     "] (valid: [problem], [benchmark], [planner])");
    for (const char *name : {"problem", "benchmark", "planner"})
        if (tree.count(name) == 0)
            throw std::invalid_argument(std::string("config needs a [") + name + "] section");

    BenchmarkConfig config;
    const pt::ptree &problem = tree.get_child("problem");
    checkKeys(problem, "problem", {"name", "scenario", "robots", "resolution", "task", "instances", "file"});
    config.problemName_ = required(problem, "problem", "name");
    checkFileName(config.problemName_, "[problem] name");
    if (problem.count("file") != 0)
    {
        // A scenario file holds the team and the resolution itself.
        for (const char *key : {"scenario", "robots", "resolution", "task", "instances"})
            if (problem.count(key) != 0)
                throw std::invalid_argument(
                    std::string("[problem] give either file or scenario and robots, not both (") + key + " is set)");
        const std::filesystem::path file = required(problem, "problem", "file");
        config.scenarioFile_ =
            (file.is_absolute() ? file : std::filesystem::path(folder) / file).lexically_normal().string();
    }
    else
    {
        config.scenario_ = required(problem, "problem", "scenario");
        config.robots_ = number<std::size_t>(problem, "problem", "robots", std::nullopt, 2, MAX_ROBOTS);
        config.resolution_ = number<double>(problem, "problem", "resolution", 128., 1e-9, 1e9);
        config.task_ = number<std::size_t>(problem, "problem", "task", 0, 0, MAX_TASK);
        config.instances_ = number<std::size_t>(problem, "problem", "instances", 1, 1, 100000);
    }

    const pt::ptree &benchmark = tree.get_child("benchmark");
    checkKeys(benchmark, "benchmark", {"time_limit", "mem_limit", "run_count", "output", "seed", "workers"});
    config.timeLimit_ = number<double>(benchmark, "benchmark", "time_limit", std::nullopt, 1e-9, 1e7);
    config.memLimit_ = number<double>(benchmark, "benchmark", "mem_limit", std::nullopt, 1., 1e9);
    config.runCount_ = number<unsigned int>(benchmark, "benchmark", "run_count", std::nullopt, 1u, 1000000u);
    // Run k uses seed + k: the last run's seed must still fit, not wrap round to 0.
    config.seed_ = number<unsigned int>(benchmark, "benchmark", "seed", 1u, 1u, UINT32_MAX - (config.runCount_ - 1));
    config.workers_ = number<unsigned int>(benchmark, "benchmark", "workers",
                                           std::max(1u, std::thread::hardware_concurrency()), 1u, 1024u);
    const std::filesystem::path output = benchmark.get<std::string>("output", "");
    config.output_ =
        output.empty()
            ? folder
            : (output.is_absolute() ? output : std::filesystem::path(folder) / output).lexically_normal().string();

    // Planner entries are the keys without a dot; "label.param" lines configure them.
    const pt::ptree &planners = tree.get_child("planner");
    std::map<std::string, std::size_t> byLabel;
    const std::vector<std::string> types = PlannerRegistry::names();
    for (const auto &entry : planners)
        if (entry.first.find('.') == std::string::npos)
        {
            std::string type;
            try
            {
                type = PlannerRegistry::canonicalName(entry.second.data().empty() ? entry.first : entry.second.data());
            }
            catch (const std::invalid_argument &e)
            {
                throw std::invalid_argument("[planner] " + entry.first + ": " + e.what());
            }
            byLabel[entry.first] = config.planners_.size();
            config.planners_.push_back({entry.first, type, entry.first, {}});
        }
    if (config.planners_.empty())
        throw std::invalid_argument("[planner] lists no planner (valid: " + listNames(types) + ")");
    for (const auto &entry : planners)
    {
        const auto dot = entry.first.find('.');
        if (dot == std::string::npos)
            continue;
        const std::string label = entry.first.substr(0, dot), key = entry.first.substr(dot + 1);
        const auto it = byLabel.find(label);
        if (it == byLabel.end())
        {
            std::vector<std::string> labels;
            for (const auto &p : config.planners_)
                labels.push_back(p.label);
            throw std::invalid_argument("[planner] " + entry.first + ": no planner labelled '" + label +
                                        "' (declared: " + listNames(labels) + ")");
        }
        BenchmarkPlanner &planner = config.planners_[it->second];
        if (key == "name")
            planner.name = entry.second.data();
        else
            planner.params.push_back(key + "=" + entry.second.data());
    }
    std::set<std::string> names;
    for (const auto &planner : config.planners_)
        if (!names.insert(planner.name).second)
            throw std::invalid_argument("[planner] two planners are named '" + planner.name +
                                        "': set label.name so the log can tell them apart");
    return config;
}
