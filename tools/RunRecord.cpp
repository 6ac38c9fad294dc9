#include "RunRecord.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

using json = nlohmann::json;

std::string ompl_parc::tools::RunRecord::toJson() const
{
    return json{{"instance", instance},
                {"planner", planner},
                {"run", run},
                {"invalid", invalid},
                {"planner_name", plannerName},
                {"properties", properties},
                {"common", common},
                {"progress_names", progressNames},
                {"progress", progress},
                {"host", host},
                {"cpu_info", cpuInfo},
                {"setup_info", setupInfo},
                {"program_seed", programSeed},
                {"started", started},
                {"duration", duration}}
        .dump();
}

ompl_parc::tools::RunRecord ompl_parc::tools::RunRecord::fromJson(const std::string &text)
{
    try
    {
        const json j = json::parse(text);
        RunRecord r;
        j.at("instance").get_to(r.instance);
        j.at("planner").get_to(r.planner);
        j.at("run").get_to(r.run);
        j.at("invalid").get_to(r.invalid);
        j.at("planner_name").get_to(r.plannerName);
        j.at("properties").get_to(r.properties);
        j.at("common").get_to(r.common);
        j.at("progress_names").get_to(r.progressNames);
        j.at("progress").get_to(r.progress);
        j.at("host").get_to(r.host);
        j.at("cpu_info").get_to(r.cpuInfo);
        j.at("setup_info").get_to(r.setupInfo);
        j.at("program_seed").get_to(r.programSeed);
        j.at("started").get_to(r.started);
        j.at("duration").get_to(r.duration);
        return r;
    }
    catch (const json::exception &e)
    {
        throw std::invalid_argument(std::string("not a benchmark run record: ") + e.what());
    }
}
