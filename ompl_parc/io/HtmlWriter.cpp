#include "ompl_parc/io/HtmlWriter.h"

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/io/GeometryFile.h"
#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/io/ViewerAssets.h"
#include "ompl_parc/validation/ClosestApproaches.h"

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <queue>
#include <tuple>

using nlohmann::json;

namespace
{
    /** \e values as little-endian float32 bytes, base64 (the page decodes them into a Float32Array). */
    std::string base64Floats(const std::vector<float> &values)
    {
        using namespace boost::archive::iterators;
        using Encoder = base64_from_binary<transform_width<const char *, 6, 8>>;
        const char *bytes = reinterpret_cast<const char *>(values.data());
        const std::size_t size = values.size() * sizeof(float);
        std::string out(Encoder(bytes), Encoder(bytes + size));
        out.append((3 - size % 3) % 3, '=');
        return out;
    }

    /** \e x rounded to 0.1 mm: enough for a picture, and a third of the digits. */
    double rounded(double x)
    {
        return std::round(x * 1e4) / 1e4;
    }

    /** Round every number of \e value in place. */
    void roundNumbers(json &value)
    {
        if (value.is_number_float())
            value = rounded(value.get<double>());
        else if (value.is_structured())
            for (auto &item : value)
                roundNumbers(item);
    }

    /** Append the end points of \e body's capsules (6 floats a capsule). */
    void appendCapsules(const ompl_parc::CollisionBody &body, std::vector<float> &out)
    {
        for (std::size_t c = 0; c < body.size(); ++c)
            for (double v : {body.ax_[c], body.ay_[c], body.az_[c], body.bx_[c], body.by_[c], body.bz_[c]})
                out.push_back(static_cast<float>(v));
    }

    /** The timesteps of \e path at which the page gets \e robot's capsules: its breakpoints (between two, the
        configuration moves on a line) and, between them, as many more as make the capsules' end points, interpolated
        linearly in the page, stray at most \e tolerance from where the kinematics put them at the intervals'
        midpoints (worst interval split first, at most \e budget timesteps in all unless the breakpoints are more). A
        disc moves on lines and gets its breakpoints alone; an arm's links sweep arcs and get more. */
    std::vector<std::size_t> keyframes(const ompl_parc::Robot &robot, const ompl_parc::TimedPath &path,
                                       double tolerance, std::size_t budget)
    {
        std::vector<std::size_t> keys;
        path.appendBreakpoints(keys);
        keys.push_back(0);
        keys.push_back(path.getArrival());
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        std::vector<double> q(robot.getDimension());
        ompl_parc::CollisionBody body;
        const auto endPoints = [&](std::size_t t)
        {
            std::vector<float> points;
            path.getConfig(t, q.data());
            robot.computeBody(q.data(), body);
            appendCapsules(body, points);
            return points;
        };
        // The largest distance between where the page puts the end points at the middle of [a, b] and where they are.
        const auto error = [&](std::size_t a, std::size_t b)
        {
            const auto pa = endPoints(a), pb = endPoints(b), pm = endPoints((a + b) / 2);
            const double f = static_cast<double>((a + b) / 2 - a) / static_cast<double>(b - a);
            double worst = 0.;
            for (std::size_t k = 0; k + 2 < pm.size(); k += 3)
            {
                double squared = 0.;
                for (std::size_t d = 0; d < 3; ++d)
                {
                    const double off = pa[k + d] + f * (pb[k + d] - pa[k + d]) - pm[k + d];
                    squared += off * off;
                }
                worst = std::max(worst, squared);
            }
            return std::sqrt(worst);
        };
        std::priority_queue<std::tuple<double, std::size_t, std::size_t>> split;
        const auto consider = [&](std::size_t a, std::size_t b)
        {
            if (b - a >= 2)
                if (const double e = error(a, b); e > tolerance)
                    split.emplace(e, a, b);
        };
        for (std::size_t k = 0; k + 1 < keys.size(); ++k)
            consider(keys[k], keys[k + 1]);
        for (std::size_t added = 0; !split.empty() && added < budget; ++added)
        {
            const auto [e, a, b] = split.top();
            split.pop();
            const std::size_t m = (a + b) / 2;
            keys.push_back(m);
            consider(a, m);
            consider(m, b);
        }
        std::sort(keys.begin(), keys.end());
        return keys;
    }

    void replaceOnce(std::string &text, const std::string &placeholder, const std::string &with)
    {
        const auto at = text.find(placeholder);
        if (at == std::string::npos)
            throw ompl::Exception("HtmlWriter", "the viewer page has no " + placeholder);
        text.replace(at, placeholder.size(), with);
    }

    struct Bounds
    {
        std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                                 std::numeric_limits<double>::infinity()};
        std::array<double, 3> hi{-lo[0], -lo[1], -lo[2]};

        void add(const ompl_parc::CollisionBody &body) { body.expandBox(lo, hi); }

        void add(const json &point)
        {
            for (int d = 0; d < 3; ++d)
            {
                lo[d] = std::min(lo[d], point[d].get<double>());
                hi[d] = std::max(hi[d], point[d].get<double>());
            }
        }
    };
}  // namespace

bool ompl_parc::HtmlWriter::isPagePath(const std::string &path)
{
    std::string lower(path);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    const auto endsWith = [&](const std::string &suffix) {
        return lower.size() >= suffix.size() && lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    return endsWith(".html") || endsWith(".htm");
}

std::string ompl_parc::HtmlWriter::toHtml(const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                          const HtmlOptions &options)
{
    const auto &si = *problem.getSpaceInformation();
    if (plan != nullptr && plan->getRobotCount() != si.getRobotCount())
        throw ompl::Exception("HtmlWriter", "the plan has " + std::to_string(plan->getRobotCount()) +
                                                " robots, the problem " + std::to_string(si.getRobotCount()));
    // The obstacles, the start and goal bodies and the tip traces, as the geometry file has them.
    json geometry = json::parse(GeometryFile::toJson(problem, plan, options.traceSamples));
    roundNumbers(geometry);

    Bounds bounds;
    for (const auto &obstacle : geometry["obstacles"])
        for (const char *key : {"a", "b", "center"})
            if (obstacle.contains(key))
                bounds.add(obstacle[key]);
    for (const auto &obstacle : geometry["obstacles"])
        if (obstacle.contains("corners"))
            for (const auto &corner : obstacle["corners"])
                bounds.add(corner);
    json robots = json::array();
    CollisionBody body;
    double thinnest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        const Robot &robot = *si.getRobot(i);
        json &entry = geometry["robots"][i];
        robot.computeBody(problem.getStart(i).data(), body);
        bounds.add(body);
        json radii = json::array();
        double smallest = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < body.size(); ++c)
        {
            radii.push_back(rounded(body.radius_[c]));
            smallest = std::min(smallest, body.radius_[c]);
        }
        thinnest = std::min(thinnest, smallest);
        robot.computeBody(problem.getGoal(i).data(), body);
        bounds.add(body);
        json out = {{"name", entry["name"]}, {"start", entry["start"]}, {"goal", entry["goal"]}, {"radii", radii}};
        if (plan != nullptr)
        {
            const auto keys =
                keyframes(robot, plan->getPath(i), HtmlOptions::KEYFRAME_TOLERANCE * smallest, options.maxKeyframes);
            std::vector<float> frames;
            frames.reserve(keys.size() * radii.size() * 6);
            json seconds = json::array();
            std::vector<double> q(robot.getDimension());
            for (std::size_t t : keys)
            {
                plan->getPath(i).getConfig(t, q.data());
                robot.computeBody(q.data(), body);
                if (body.size() != radii.size())
                    throw ompl::Exception("HtmlWriter",
                                          "robot '" + robot.getName() + "' changes its number of collision capsules");
                bounds.add(body);
                appendCapsules(body, frames);
                seconds.push_back(static_cast<double>(t) / plan->getResolution());
            }
            out["times"] = std::move(seconds);
            out["frames"] = base64Floats(frames);
            out["tip_path"] = entry["tip_path"];
        }
        robots.push_back(std::move(out));
    }

    const double resolution = plan != nullptr ? plan->getResolution() : 1.;
    json closest = json::array();
    if (plan != nullptr)
        for (const auto &c :
             ClosestApproaches::find(si, *plan, plan->sampleTimesteps(options.approachSamples), options.closest))
        {
            json points = c.points;
            roundNumbers(points);
            // The clearance unrounded: tight plans pass at fractions of a millimetre.
            closest.push_back({{"robots", {c.first, c.second}},
                               {"time", rounded(static_cast<double>(c.timestep) / resolution)},
                               {"clearance", c.clearance},
                               {"points", points}});
        }
    const json scene = {{"name", problem.getName()},
                        {"planar", SvgWriter::isPlanar(problem)},
                        {"thinnest", std::isfinite(thinnest) ? thinnest : 0.1},
                        {"bounds", {bounds.lo, bounds.hi}},
                        {"obstacles", geometry["obstacles"]},
                        {"duration", plan != nullptr ? static_cast<double>(plan->getMakespan()) / resolution : 0.},
                        {"robots", robots},
                        {"closest", closest}};
    // Inside a script element, "</" could end it early: JSON lets it be written "<\/".
    std::string data = scene.dump();
    for (std::size_t at = data.find("</"); at != std::string::npos; at = data.find("</", at + 3))
        data.replace(at, 2, "<\\/");
    std::string page = viewer::pageTemplate();
    replaceOnce(page, "/*THREE_JS*/", viewer::threeJs());
    replaceOnce(page, "/*ORBIT_CONTROLS_JS*/", viewer::orbitControlsJs());
    replaceOnce(page, "/*SCENE_JSON*/", data);
    return page;
}

void ompl_parc::HtmlWriter::write(const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                  const HtmlOptions &options)
{
    const std::string page = toHtml(problem, plan, options);
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw ompl::Exception("HtmlWriter", "cannot write '" + path + "'");
    out << page;
    if (!out)
        throw ompl::Exception("HtmlWriter", "error writing '" + path + "'");
}
