#include "ompl_parc/io/SvgWriter.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace
{
    using Point = Eigen::Vector2d;

    /** A number with at most four decimals, trailing zeros dropped (keeps long animations small). */
    std::string num(double v)
    {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.4f", v);
        std::string s = buffer;
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.')
            s.pop_back();
        return s == "-0" ? "0" : s;
    }

    /** Evenly spread hues, so neighbouring robot indices get distinguishable colours. */
    std::string colour(std::size_t index, std::size_t count)
    {
        const double h = 6. * static_cast<double>(index) / static_cast<double>(std::max<std::size_t>(count, 1));
        const double s = 0.75, v = 0.8, c = v * s, x = c * (1. - std::fabs(std::fmod(h, 2.) - 1.)), m = v - c;
        const int sector = static_cast<int>(h) % 6;
        const double rgb[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
        char buffer[8];
        std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", static_cast<int>(255 * (rgb[sector][0] + m)),
                      static_cast<int>(255 * (rgb[sector][1] + m)), static_cast<int>(255 * (rgb[sector][2] + m)));
        return buffer;
    }

    std::string escape(const std::string &text)
    {
        std::string out;
        for (char ch : text)
        {
            if (ch == '<')
                out += "&lt;";
            else if (ch == '>')
                out += "&gt;";
            else if (ch == '&')
                out += "&amp;";
            else if (ch == '"')
                out += "&quot;";
            else
                out += ch;
        }
        return out;
    }

    /** Andrew's monotone chain: the convex hull of \e points, counter-clockwise. */
    std::vector<Point> convexHull(std::vector<Point> points)
    {
        std::sort(points.begin(), points.end(),
                  [](const Point &a, const Point &b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
        if (points.size() < 3)
            return points;
        std::vector<Point> hull(2 * points.size());
        std::size_t k = 0;
        auto cross = [](const Point &o, const Point &a, const Point &b)
        { return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x(); };
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.)
                --k;
            hull[k++] = points[i];
        }
        for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
        {
            while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.)
                --k;
            hull[k++] = points[i];
        }
        hull.resize(k - 1);
        return hull;
    }

    /** The footprint of a box, cylinder or mesh: its corners (rim points, vertices) in the world, seen from
        above, and their convex hull. */
    std::vector<Point> footprint(const ompl_parc::Obstacle &o)
    {
        std::vector<Eigen::Vector3d> local;
        if (o.shape == ompl_parc::Obstacle::Shape::MESH)
            local = o.mesh->getVertices();
        else if (o.shape == ompl_parc::Obstacle::Shape::BOX)
        {
            for (int corner = 0; corner < 8; ++corner)
                local.emplace_back((corner & 1 ? 0.5 : -0.5) * o.size.x(), (corner & 2 ? 0.5 : -0.5) * o.size.y(),
                                   (corner & 4 ? 0.5 : -0.5) * o.size.z());
        }
        else
        {
            constexpr int RIM = 32;
            for (int k = 0; k < RIM; ++k)
            {
                const double a = 2. * M_PI * k / RIM;
                for (double z : {-0.5 * o.size.z(), 0.5 * o.size.z()})
                    local.emplace_back(o.size.x() * std::cos(a), o.size.x() * std::sin(a), z);
            }
        }
        std::vector<Point> points;
        for (const auto &p : local)
            points.push_back((o.pose * p).head<2>());
        return convexHull(points);
    }

    /** Runs of capsules that continue each other (same radius, each starting where the last ended): the
        links of an arm. Found on one body; every body of a robot has the same capsule layout. */
    std::vector<std::pair<std::size_t, std::size_t>> chains(const ompl_parc::CollisionBody &body)
    {
        std::vector<std::pair<std::size_t, std::size_t>> runs;
        for (std::size_t i = 0; i < body.size(); ++i)
        {
            const bool continues = i > 0 && body.radius_[i] == body.radius_[i - 1] && body.ax_[i] == body.bx_[i - 1] &&
                                   body.ay_[i] == body.by_[i - 1];
            if (continues)
                runs.back().second = i + 1;
            else
                runs.emplace_back(i, i + 1);
        }
        return runs;
    }

    bool isDot(const ompl_parc::CollisionBody &body, std::size_t i)
    {
        return body.ax_[i] == body.bx_[i] && body.ay_[i] == body.by_[i];
    }

    /** The polyline points of capsules [first, last) of \e body. */
    std::string chainPoints(const ompl_parc::CollisionBody &body, std::size_t first, std::size_t last)
    {
        std::string out = num(body.ax_[first]) + "," + num(body.ay_[first]);
        for (std::size_t i = first; i < last; ++i)
            out += " " + num(body.bx_[i]) + "," + num(body.by_[i]);
        return out;
    }

    /** The bodies of one robot over the sampled timesteps. */
    using Frames = std::vector<ompl_parc::CollisionBody>;

    class Document
    {
      public:
        Document(const ompl_parc::MultiRobotProblem &problem, const ompl_parc::MultiRobotPlan *plan,
                 const ompl_parc::SvgOptions &options)
            : problem_(problem), plan_(plan), options_(options)
        {
            if (plan_ != nullptr && plan_->getRobotCount() != problem_.getRobotCount())
                throw ompl::Exception("SvgWriter", "the plan has " + std::to_string(plan_->getRobotCount()) +
                                                       " robots, the problem " +
                                                       std::to_string(problem_.getRobotCount()));
            if (plan_ != nullptr)
                times_ = plan_->sampleTimesteps(options_.maxKeyframes);
        }

        std::string build()
        {
            const auto &si = *problem_.getSpaceInformation();
            std::vector<Frames> frames(si.getRobotCount());
            std::vector<ompl_parc::CollisionBody> starts(si.getRobotCount()), goals(si.getRobotCount());
            for (std::size_t i = 0; i < si.getRobotCount(); ++i)
            {
                const auto &robot = *si.getRobot(i);
                robot.computeBody(problem_.getStart(i).data(), starts[i]);
                robot.computeBody(problem_.getGoal(i).data(), goals[i]);
                include(starts[i]);
                include(goals[i]);
                std::vector<double> q(robot.getDimension());
                for (std::size_t t : times_)
                {
                    frames[i].emplace_back();
                    plan_->getConfig(i, t, q.data());
                    robot.computeBody(q.data(), frames[i].back());
                    include(frames[i].back());
                }
            }
            std::ostringstream obstacles;
            for (const auto &o : si.getRobot(0)->getEnvironment()->getObstacles())
                drawObstacle(o, obstacles);

            const Point extent = hi_ - lo_;
            const double margin = 0.03 * extent.maxCoeff();
            const Point lo = lo_ - Point::Constant(margin), size = extent + Point::Constant(2. * margin);
            const double pixels = options_.size / size.maxCoeff();
            lineWidth_ = 0.004 * size.maxCoeff();

            std::ostringstream svg;
            svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(size.x() * pixels) << "\" height=\""
                << num(size.y() * pixels) << "\" viewBox=\"" << num(lo.x()) << " " << num(-lo.y() - size.y()) << " "
                << num(size.x()) << " " << num(size.y()) << "\">\n"
                << "<title>" << escape(problem_.getName()) << "</title>\n"
                << "<rect x=\"" << num(lo.x()) << "\" y=\"" << num(-lo.y() - size.y()) << "\" width=\"" << num(size.x())
                << "\" height=\"" << num(size.y()) << "\" fill=\"white\"/>\n"
                << note(lo, size) << "<g transform=\"scale(1,-1)\">\n"  // world y points up
                << "<g class=\"obstacles\" fill=\"#888\" stroke=\"none\">\n"
                << obstacles.str() << "</g>\n";
            for (std::size_t i = 0; i < si.getRobotCount(); ++i)
                drawRobot(i, starts[i], goals[i], frames[i], svg);
            svg << "</g>\n</svg>\n";
            return svg.str();
        }

      private:
        /** The note over the top view of a problem that is not planar (empty for a planar one). */
        std::string note(const Point &lo, const Point &size) const
        {
            if (ompl_parc::SvgWriter::isPlanar(problem_))
                return "";
            const double font = 0.025 * size.maxCoeff();
            std::ostringstream text;
            text << "<text class=\"note\" x=\"" << num(lo.x() + font) << "\" y=\""
                 << num(-lo.y() - size.y() + 1.5 * font) << "\" font-size=\"" << num(font)
                 << "\" font-family=\"sans-serif\" fill=\"#a00\">" << escape(ompl_parc::SvgWriter::TOP_VIEW_NOTE)
                 << "</text>\n";
            return text.str();
        }

        void include(const Point &p, double radius)
        {
            lo_ = lo_.cwiseMin(p - Point::Constant(radius));
            hi_ = hi_.cwiseMax(p + Point::Constant(radius));
        }

        void include(const ompl_parc::CollisionBody &body)
        {
            for (std::size_t i = 0; i < body.size(); ++i)
            {
                include(Point(body.ax_[i], body.ay_[i]), body.radius_[i]);
                include(Point(body.bx_[i], body.by_[i]), body.radius_[i]);
            }
        }

        void drawObstacle(const ompl_parc::Obstacle &o, std::ostream &out)
        {
            const std::string title = "<title>" + escape(o.name) + "</title>";
            if (o.shape == ompl_parc::Obstacle::Shape::SPHERE)
            {
                const Point c = o.pose.translation().head<2>();
                include(c, o.size.x());
                out << "<circle class=\"obstacle\" cx=\"" << num(c.x()) << "\" cy=\"" << num(c.y()) << "\" r=\""
                    << num(o.size.x()) << "\">" << title << "</circle>\n";
                return;
            }
            out << "<polygon class=\"obstacle\" points=\"";
            for (const Point &p : footprint(o))
            {
                include(p, 0.);
                out << num(p.x()) << "," << num(p.y()) << " ";
            }
            out << "\">" << title << "</polygon>\n";
        }

        /** The elements of \e body in \e colour, solid or as a thin \e outline (a circle's rim, a chain's
            centre line); \e attributes add a class and style, and with \e frames they are animated over those
            bodies (which share \e body's layout). */
        void drawBody(const ompl_parc::CollisionBody &body, const std::string &colour, bool outline,
                      const std::string &attributes, const Frames *frames, std::ostream &out) const
        {
            for (const auto &chain : chains(body))
            {
                // Plain variables, not a structured binding: C++17 lambdas (below) cannot capture those.
                const std::size_t first = chain.first, last = chain.second;
                if (last == first + 1 && isDot(body, first))
                {
                    out << "<circle cx=\"" << num(body.ax_[first]) << "\" cy=\"" << num(body.ay_[first]) << "\" r=\""
                        << num(body.radius_[first]) << "\" fill=\"" << (outline ? "none" : colour) << "\" stroke=\""
                        << colour << "\" stroke-width=\"" << num(lineWidth_) << "\" " << attributes << ">";
                    if (frames != nullptr)
                    {
                        animate(
                            "cx", *frames, [&](const ompl_parc::CollisionBody &b) { return num(b.ax_[first]); }, out);
                        animate(
                            "cy", *frames, [&](const ompl_parc::CollisionBody &b) { return num(b.ay_[first]); }, out);
                    }
                    out << "</circle>\n";
                    continue;
                }
                out << "<polyline points=\"" << chainPoints(body, first, last) << "\" stroke-width=\""
                    << num(outline ? lineWidth_ : 2. * body.radius_[first])
                    << "\" stroke-linecap=\"round\" stroke-linejoin=\"round\" fill=\"none\" stroke=\"" << colour
                    << "\" " << attributes << ">";
                if (frames != nullptr)
                    animate(
                        "points", *frames,
                        [&](const ompl_parc::CollisionBody &b) { return chainPoints(b, first, last); }, out);
                out << "</polyline>\n";
            }
        }

        template <typename Value>
        void animate(const std::string &attribute, const Frames &frames, const Value &value, std::ostream &out) const
        {
            out << "<animate attributeName=\"" << attribute << "\" dur=\"" << num(options_.duration)
                << "s\" repeatCount=\"indefinite\" calcMode=\"linear\" values=\"";
            for (std::size_t k = 0; k < frames.size(); ++k)
                out << (k == 0 ? "" : ";") << value(frames[k]);
            out << "\"/>";
        }

        void drawRobot(std::size_t i, const ompl_parc::CollisionBody &start, const ompl_parc::CollisionBody &goal,
                       const Frames &frames, std::ostream &out) const
        {
            const auto &robot = *problem_.getSpaceInformation()->getRobot(i);
            const std::string c = colour(i, problem_.getRobotCount());
            out << "<g class=\"robot\" id=\"robot-" << escape(robot.getName()) << "\">\n<title>"
                << escape(robot.getName()) << " (" << robot.getKind() << ")</title>\n";
            // Start: faded; goal: a dashed outline.
            drawBody(start, c, false, "class=\"start\" opacity=\"0.3\"", nullptr, out);
            drawBody(goal, c, true, "class=\"goal\" stroke-dasharray=\"" + num(3. * lineWidth_) + "\" opacity=\"0.8\"",
                     nullptr, out);
            if (!frames.empty())
            {
                out << "<polyline class=\"trace\" fill=\"none\" stroke=\"" << c << "\" stroke-width=\""
                    << num(lineWidth_) << "\" points=\"";
                for (const auto &body : frames)
                    out << num(body.bx_[body.size() - 1]) << "," << num(body.by_[body.size() - 1]) << " ";
                out << "\"/>\n";
                if (options_.animate)
                    drawBody(frames.front(), c, false, "class=\"body\"", &frames, out);
            }
            out << "</g>\n";
        }

        const ompl_parc::MultiRobotProblem &problem_;
        const ompl_parc::MultiRobotPlan *plan_;
        const ompl_parc::SvgOptions &options_;
        std::vector<std::size_t> times_;
        Point lo_{Point::Constant(std::numeric_limits<double>::infinity())};
        Point hi_{Point::Constant(-std::numeric_limits<double>::infinity())};
        double lineWidth_{0.};
    };
}  // namespace

const char *const ompl_parc::SvgWriter::TOP_VIEW_NOTE =
    "3D problem: top view only (z dropped). For 3D, name the picture .html: an interactive 3D page";

bool ompl_parc::SvgWriter::isPlanar(const MultiRobotProblem &problem)
{
    const auto &si = *problem.getSpaceInformation();
    CollisionBody body;
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        for (const auto *q : {&problem.getStart(i), &problem.getGoal(i)})
        {
            si.getRobot(i)->computeBody(q->data(), body);
            for (std::size_t c = 0; c < body.size(); ++c)
                if (body.az_[c] != 0. || body.bz_[c] != 0.)
                    return false;
        }
    return true;
}

std::string ompl_parc::SvgWriter::toSvg(const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                        const SvgOptions &options)
{
    return Document(problem, plan, options).build();
}

void ompl_parc::SvgWriter::write(const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                 const SvgOptions &options)
{
    const std::string svg = toSvg(problem, plan, options);
    std::ofstream out(path);
    if (!out)
        throw ompl::Exception("SvgWriter", "cannot write '" + path + "'");
    out << svg;
    if (!out)
        throw ompl::Exception("SvgWriter", "error writing '" + path + "'");
}
