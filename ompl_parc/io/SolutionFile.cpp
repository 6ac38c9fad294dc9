#include "ompl_parc/io/SolutionFile.h"

#include "ompl_parc/io/JsonFields.h"

#include "ompl_parc/util/TextFile.h"

#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <cstdint>
#include <fstream>
#include <sstream>

using nlohmann::json;

namespace
{
    const char *const FORMAT = "ompl_parc.solution";
    constexpr int VERSION = 2;

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

    /** A configuration of \e dimension numbers at \e value, appended to \e out. */
    void readConfig(const json &value, unsigned int dimension, const std::string &where, std::vector<double> &out)
    {
        if (!value.is_array() || value.size() != dimension)
            fail(where + " must be an array of " + std::to_string(dimension) + " numbers");
        for (const json &v : value)
        {
            if (!v.is_number())
                fail(where + " holds a non-number");
            out.push_back(v.get<double>());
        }
    }

    /** A timestep or step count: a whole number up to MultiRobotPlan::MAX_TIMESTEP. */
    std::size_t readCount(const json &value, const std::string &where)
    {
        if (!value.is_number_unsigned() || value.get<std::uint64_t>() > ompl_parc::MultiRobotPlan::MAX_TIMESTEP)
            fail(where + " must be a whole number from 0 to " +
                 std::to_string(ompl_parc::MultiRobotPlan::MAX_TIMESTEP));
        return value.get<std::size_t>();
    }

    /** Version 1: "states", one configuration per timestep from 0 to the arrival. */
    ompl_parc::TimedPath readStates(const json &robot, unsigned int dimension, const std::string &where)
    {
        const json &states = field(robot, "states", where);
        if (!states.is_array() || states.empty())
            fail(where + ".states must be a non-empty array");
        std::vector<double> flat;
        flat.reserve(states.size() * dimension);
        for (std::size_t t = 0; t < states.size(); ++t)
            readConfig(states[t], dimension, where + ".states[" + std::to_string(t) + "]", flat);
        return ompl_parc::TimedPath::fromDense(dimension, flat);
    }

    /** Version 2: "arrival" and "pieces", each [start, offset, steps, from, to] (TimedPath). */
    ompl_parc::TimedPath readPieces(const json &robot, unsigned int dimension, const std::string &where)
    {
        const std::size_t arrival = readCount(field(robot, "arrival", where), where + ".arrival");
        const json &pieces = field(robot, "pieces", where);
        if (!pieces.is_array() || pieces.empty())
            fail(where + ".pieces must be a non-empty array");
        ompl_parc::TimedPath path(dimension);
        std::vector<double> from, to;
        std::size_t expected = 0;  // where the next piece must start
        for (std::size_t k = 0; k < pieces.size(); ++k)
        {
            const std::string at = where + ".pieces[" + std::to_string(k) + "]";
            const json &piece = pieces[k];
            if (!piece.is_array() || piece.size() != 5)
                fail(at + " must be [start, offset, steps, from, to]");
            const std::size_t start = readCount(piece[0], at + "[0]");
            if (start != expected)
                fail(at + " starts at timestep " + std::to_string(start) + ", expected " + std::to_string(expected) +
                     " (pieces follow each other from timestep 0)");
            from.clear();
            to.clear();
            readConfig(piece[3], dimension, at + "[3]", from);
            readConfig(piece[4], dimension, at + "[4]", to);
            std::size_t last = arrival;
            if (k + 1 < pieces.size())
            {
                const json &next = pieces[k + 1];
                if (!next.is_array() || next.empty())
                    fail(where + ".pieces[" + std::to_string(k + 1) + "] must be [start, offset, steps, from, to]");
                last = readCount(next[0], where + ".pieces[" + std::to_string(k + 1) + "][0]");
                if (last <= start)
                    fail(where + ".pieces must start at increasing timesteps");
                --last;
            }
            if (last < start)
                fail(where + ".arrival " + std::to_string(arrival) + " is before the last piece's start");
            path.appendPiece({start, readCount(piece[1], at + "[1]"), readCount(piece[2], at + "[2]")}, from.data(),
                             to.data(), last);
            expected = last + 1;
        }
        return path;
    }
}  // namespace

std::string ompl_parc::SolutionFile::toJson(const MultiRobotPlan &plan, const MultiRobotSpaceInformation &si)
{
    // The file names the team's robots: a plan of another team would be written under wrong names and kinds.
    if (const std::string mismatch = plan.checkTeam(si); !mismatch.empty())
        fail(mismatch);
    // One robot per line: compact, yet a diff or a reader can still find a robot.
    std::string text = json{{"format", FORMAT}, {"version", VERSION}, {"resolution", plan.getResolution()}}.dump();
    text.pop_back();
    text += ",\"robots\":[";
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        const TimedPath &path = plan.getPath(i);
        const unsigned int d = path.getDimension();
        json pieces = json::array();
        for (std::size_t k = 0; k < path.getPieceCount(); ++k)
        {
            const auto &p = path.getPiece(k);
            pieces.push_back({p.start, p.offset, p.steps, std::vector<double>(path.getFrom(k), path.getFrom(k) + d),
                              std::vector<double>(path.getTo(k), path.getTo(k) + d)});
        }
        const json robot = {{"name", si.getRobot(i)->getName()},
                            {"kind", si.getRobot(i)->getKind()},
                            {"arrival", path.getArrival()},
                            {"pieces", std::move(pieces)}};
        text += (i == 0 ? "\n " : ",\n ") + robot.dump();
    }
    return text + "\n]}";
}

void ompl_parc::SolutionFile::write(const std::string &path, const MultiRobotPlan &plan,
                                    const MultiRobotSpaceInformation &si)
{
    const std::string text = toJson(plan, si);  // before the file is opened: a refused plan leaves no file
    std::ofstream out(path);
    if (!out)
        fail("cannot write '" + path + "'");
    out << text << '\n';
    if (!out)
        fail("error writing '" + path + "'");
}

ompl_parc::MultiRobotPlan ompl_parc::SolutionFile::read(const std::string &path, const MultiRobotSpaceInformation &si)
{
    return fromJson(TextFile::read(path, "SolutionFile"), si);
}

ompl_parc::MultiRobotPlan ompl_parc::SolutionFile::fromJson(const std::string &text,
                                                            const MultiRobotSpaceInformation &si)
{
    json doc;
    try
    {
        doc = json::parse(text);
    }
    catch (const json::exception &e)  // syntax, or a number beyond double's range (1e999)
    {
        fail(std::string("not valid JSON: ") + e.what());
    }
    const json &format = field(doc, "format", "solution");
    ompl_parc::allowOnlyFields(doc, {"format", "version", "resolution", "robots"}, "solution", "SolutionFile");
    if (!format.is_string() || format.get<std::string>() != FORMAT)
        fail("'format' must be \"" + std::string(FORMAT) + "\"");
    const json &version = field(doc, "version", "solution");
    if (!version.is_number_integer() || version.get<std::int64_t>() < 1 || version.get<std::int64_t>() > VERSION)
        fail("unsupported 'version' (this build reads versions 1 to " + std::to_string(VERSION) + ")");
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
        if (robots[i].is_object())
            ompl_parc::allowOnlyFields(robots[i],
                                       version.get<int>() == 1
                                           ? std::set<std::string>{"name", "kind", "states"}
                                           : std::set<std::string>{"name", "kind", "arrival", "pieces"},
                                       where, "SolutionFile");
        const json &name = field(robots[i], "name", where);
        if (!name.is_string() || name.get<std::string>() != robot.getName())
            fail(where + ".name must be \"" + robot.getName() + "\"");
        const json &kind = field(robots[i], "kind", where);
        if (!kind.is_string() || kind.get<std::string>() != robot.getKind())
            fail(where + ".kind must be \"" + robot.getKind() + "\"");
        plan.setPath(
            i, version.get<int>() == 1 ? readStates(robots[i], dims[i], where) : readPieces(robots[i], dims[i], where));
    }
    return plan;
}
