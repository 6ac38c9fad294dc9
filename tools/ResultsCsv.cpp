#include "ResultsCsv.h"
#include "ToolSupport.h"

#include "ompl_parc/Version.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace
{
    /** Our columns after the authors' ones, each from a run property. */
    const std::vector<std::pair<std::string, std::string>> &propertyColumns()
    {
        static const std::vector<std::pair<std::string, std::string>> columns = {
            {"makespan_ratio", "makespan_ratio REAL"},
            {"sum_of_costs_ratio", "sum_of_costs_ratio REAL"},
            {"makespan_path_ratio", "makespan_path_ratio REAL"},
            {"sum_of_costs_path_ratio", "sum_of_costs_path_ratio REAL"},
            {"smoothing_time", "smoothing_time REAL"},
            {"makespan_unsmoothed", "makespan_unsmoothed INTEGER"},
            {"initial_time", "initial_wall_time REAL"},
            {"detection_time", "detection_wall_time REAL"},
            {"resolution_time", "resolution_wall_time REAL"},
            {"longest_call", "longest_solver_call REAL"},
            {"projected_time", "projected_total_time REAL"},
            {"batches", "batches INTEGER"},
            {"first_batch_size", "first_batch_size INTEGER"},
            {"average_batch_size", "average_batch_size REAL"},
            {"memory", "memory REAL"},
        };
        return columns;
    }

    /** \e text as one CSV field: quoted (quotes doubled) if it holds a comma, a quote or a line break. */
    std::string field(const std::string &text)
    {
        if (text.find_first_of(",\"\n\r") == std::string::npos)
            return text;
        std::string quoted = "\"";
        for (char c : text)
            quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        return quoted + "\"";
    }

    /** "mobile_cross" -> "Mobile Cross". */
    std::string title(const std::string &scenario)
    {
        std::string out;
        bool start = true;
        for (char c : scenario)
        {
            out += c == '_' ? ' ' : start ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
            start = c == '_';
        }
        return out;
    }

    std::string valueOf(const std::map<std::string, std::string> &properties, const std::string &name)
    {
        const auto it = properties.find(name);
        return it == properties.end() ? std::string() : it->second;
    }

    /** Every property, named without its type, numbers as numbers: the run's metrics_json. */
    std::string metricsJson(const std::map<std::string, std::string> &properties)
    {
        nlohmann::json metrics = nlohmann::json::object();
        for (const auto &[property, value] : properties)
        {
            const auto [key, type] = ompl_parc::tools::splitPropertyKey(property);
            char *end = nullptr;
            const double number = std::strtod(value.c_str(), &end);
            const bool numeric =
                type != "STRING" && !value.empty() && end == value.c_str() + value.size() && std::isfinite(number);
            metrics[key] = numeric ? nlohmann::json(number) : nlohmann::json(value);
        }
        return metrics.dump();
    }
}  // namespace

ompl_parc::tools::ResultsCsv::ResultsCsv(std::ostream &out) : out_(out)
{
    out_ << "case,case_title,task_index,seed,method,time_limit_seconds,success,first_solution_time_seconds,"
            "planning_time_seconds,makespan_timesteps,sum_of_cost_timesteps,metrics_json,scenario,robots,type,workers,"
            "status";
    for (const auto &column : propertyColumns())
        out_ << ',' << column.first;
    out_ << ",ompl_parc_version\n";
}

void ompl_parc::tools::ResultsCsv::write(const CsvRun &run, const std::map<std::string, std::string> &properties)
{
    const std::string time = valueOf(properties, "time REAL"), first = valueOf(properties, "first_solution_time REAL");
    out_ << field(run.scenario + "_" + std::to_string(run.robots)) << ','
         << field(title(run.scenario) + ", " + std::to_string(run.robots) + " robots") << ',' << run.task << ','
         << run.seed << ',' << field(run.method) << ',' << run.timeLimit << ',' << (run.success ? 1 : 0) << ','
         << (run.success ? (first.empty() ? time : first) : "") << ',' << time << ','
         << valueOf(properties, "makespan INTEGER") << ',' << valueOf(properties, "sum_of_costs INTEGER") << ','
         << field(metricsJson(properties)) << ',' << field(run.scenario) << ',' << run.robots << ',' << run.type << ','
         << run.workers << ',' << field(run.status);
    for (const auto &column : propertyColumns())
        out_ << ',' << valueOf(properties, column.second);
    out_ << ',' << OMPL_PARC_VERSION << std::endl;
}
