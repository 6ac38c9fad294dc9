#include "ompl_parc/io/SolutionFile.h"

#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <fstream>
#include <sstream>

using nlohmann::json;

namespace
{
    const char *const FORMAT = "ompl_parc.solution";
    constexpr int VERSION = 1;

    [[noreturn]] void fail(const std::string &what)
    {
        throw ompl::Exception("SolutionFile", what);
    }

    const json &field(const json &object, const std::string &key, const std::string &where)
    {
        if (!object.is_object() || !object.contains(key))
            fail(where + ": missing field '" + key + "'");
        return object.at(key);
    }
}  // namespace

std::string ompl_parc::SolutionFile::toJson(const MultiRobotPlan &plan, const MultiRobotSpaceInformation &si)
{
    json robots = json::array();
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        json states = json::array();
        const auto &flat = plan.getRobotPath(i);
        const unsigned int d = plan.getDimension(i);
        for (std::size_t k = 0; k + d <= flat.size(); k += d)
            states.push_back(std::vector<double>(flat.begin() + k, flat.begin() + k + d));
        robots.push_back(
            {{"name", si.getRobot(i)->getName()}, {"kind", si.getRobot(i)->getKind()}, {"states", std::move(states)}});
    }
    const json doc = {
        {"format", FORMAT}, {"version", VERSION}, {"resolution", plan.getResolution()}, {"robots", std::move(robots)}};
    return doc.dump(1);
}

void ompl_parc::SolutionFile::write(const std::string &path, const MultiRobotPlan &plan,
                                    const MultiRobotSpaceInformation &si)
{
    std::ofstream out(path);
    if (!out)
        fail("cannot write '" + path + "'");
    out << toJson(plan, si) << '\n';
    if (!out)
        fail("error writing '" + path + "'");
}

ompl_parc::MultiRobotPlan ompl_parc::SolutionFile::read(const std::string &path, const MultiRobotSpaceInformation &si)
{
    std::ifstream in(path);
    if (!in)
        fail("cannot open '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return fromJson(text.str(), si);
}

ompl_parc::MultiRobotPlan ompl_parc::SolutionFile::fromJson(const std::string &text,
                                                            const MultiRobotSpaceInformation &si)
{
    json doc;
    try
    {
        doc = json::parse(text);
    }
    catch (const json::parse_error &e)
    {
        fail(std::string("not valid JSON: ") + e.what());
    }
    const json &format = field(doc, "format", "solution");
    if (!format.is_string() || format.get<std::string>() != FORMAT)
        fail("'format' must be \"" + std::string(FORMAT) + "\"");
    const json &version = field(doc, "version", "solution");
    if (!version.is_number_integer() || version.get<int>() != VERSION)
        fail("unsupported 'version' (this build reads version " + std::to_string(VERSION) + ")");
    const json &resolution = field(doc, "resolution", "solution");
    if (!resolution.is_number() || !(resolution.get<double>() > 0.))
        fail("'resolution' must be a positive number");
    const json &robots = field(doc, "robots", "solution");
    if (!robots.is_array())
        fail("'robots' must be an array");
    if (robots.size() != si.getRobotCount())
        fail("'robots' has " + std::to_string(robots.size()) + " entries, the problem has " +
             std::to_string(si.getRobotCount()) + " robots");

    std::vector<unsigned int> dims;
    for (const auto &robot : si.getRobots())
        dims.push_back(robot->getDimension());
    MultiRobotPlan plan(dims, resolution.get<double>());
    for (std::size_t i = 0; i < robots.size(); ++i)
    {
        const std::string where = "robots[" + std::to_string(i) + "]";
        const auto &robot = *si.getRobot(i);
        const json &name = field(robots[i], "name", where);
        if (!name.is_string() || name.get<std::string>() != robot.getName())
            fail(where + ".name must be \"" + robot.getName() + "\"");
        const json &kind = field(robots[i], "kind", where);
        if (!kind.is_string() || kind.get<std::string>() != robot.getKind())
            fail(where + ".kind must be \"" + robot.getKind() + "\"");
        const json &states = field(robots[i], "states", where);
        if (!states.is_array() || states.empty())
            fail(where + ".states must be a non-empty array");
        std::vector<double> flat;
        flat.reserve(states.size() * dims[i]);
        for (std::size_t t = 0; t < states.size(); ++t)
        {
            const json &state = states[t];
            if (!state.is_array() || state.size() != dims[i])
                fail(where + ".states[" + std::to_string(t) + "] must be an array of " + std::to_string(dims[i]) +
                     " numbers");
            for (const json &v : state)
            {
                if (!v.is_number())
                    fail(where + ".states[" + std::to_string(t) + "] holds a non-number");
                flat.push_back(v.get<double>());
            }
        }
        plan.setRobotPath(i, std::move(flat));
    }
    return plan;
}
