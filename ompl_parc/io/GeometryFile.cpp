#include "ompl_parc/io/GeometryFile.h"

#include "ompl_parc/robots/UrdfArm.h"

#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <fstream>

using nlohmann::json;

namespace
{
    json point(const Eigen::Vector3d &p)
    {
        return {p.x(), p.y(), p.z()};
    }

    json obstacleToJson(const ompl_parc::Obstacle &o)
    {
        using Shape = ompl_parc::Obstacle::Shape;
        json out = {{"name", o.name}};
        switch (o.shape)
        {
            case Shape::CYLINDER:
            {
                const Eigen::Vector3d half(0., 0., 0.5 * o.size.z());
                out["shape"] = "cylinder";
                out["a"] = point(o.pose * (-half));
                out["b"] = point(o.pose * half);
                out["radius"] = o.size.x();
                break;
            }
            case Shape::SPHERE:
                out["shape"] = "sphere";
                out["center"] = point(o.pose.translation());
                out["radius"] = o.size.x();
                break;
            case Shape::BOX:
            {
                out["shape"] = "box";
                out["corners"] = json::array();
                for (int corner = 0; corner < 8; ++corner)
                {
                    const Eigen::Vector3d sign(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5,
                                               corner & 4 ? 0.5 : -0.5);
                    out["corners"].push_back(point(o.pose * sign.cwiseProduct(o.size)));
                }
                break;
            }
            case Shape::MESH:
            {
                out["shape"] = "mesh";
                json vertices = json::array(), triangles = json::array();
                for (const Eigen::Vector3d &v : o.mesh->getVertices())
                {
                    const Eigen::Vector3d world = o.pose * v;
                    vertices.insert(vertices.end(), {world.x(), world.y(), world.z()});
                }
                for (const auto &t : o.mesh->getTriangles())
                    triangles.insert(triangles.end(), {t[0], t[1], t[2]});
                out["vertices"] = std::move(vertices);
                out["triangles"] = std::move(triangles);
                break;
            }
        }
        return out;
    }

    json capsulesToJson(const ompl_parc::CollisionBody &body)
    {
        json out = json::array();
        for (std::size_t k = 0; k < body.size(); ++k)
            out.push_back(
                {body.ax_[k], body.ay_[k], body.az_[k], body.bx_[k], body.by_[k], body.bz_[k], body.radius_[k]});
        return out;
    }

    /** Where robot \e robot's tip is at \e q: a UrdfArm's tip link, otherwise the end of its last capsule. */
    json tip(const ompl_parc::Robot &robot, const double *q, ompl_parc::CollisionBody &scratch)
    {
        if (const auto *arm = dynamic_cast<const ompl_parc::UrdfArm *>(&robot))
            return point(arm->computeTipPose(q).translation());
        robot.computeBody(q, scratch);
        const std::size_t last = scratch.size() - 1;
        return {scratch.bx_[last], scratch.by_[last], scratch.bz_[last]};
    }
}  // namespace

std::string ompl_parc::GeometryFile::toJson(const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                            std::size_t maxSamples)
{
    const auto &si = *problem.getSpaceInformation();
    if (plan != nullptr && plan->getRobotCount() != si.getRobotCount())
        throw ompl::Exception("GeometryFile", "the plan has " + std::to_string(plan->getRobotCount()) +
                                                  " robots, the problem " + std::to_string(si.getRobotCount()));
    json obstacles = json::array();
    if (const auto &environment = si.getRobot(0)->getEnvironment())
        for (const auto &o : environment->getObstacles())
            obstacles.push_back(obstacleToJson(o));
    const auto times = plan != nullptr ? plan->sampleTimesteps(maxSamples) : std::vector<std::size_t>{};
    json robots = json::array();
    CollisionBody body;
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        const Robot &robot = *si.getRobot(i);
        json entry = {{"name", robot.getName()}};
        const std::pair<std::string, const double *> ends[] = {{"start", problem.getStart(i).data()},
                                                               {"goal", problem.getGoal(i).data()}};
        for (const auto &[end, q] : ends)
        {
            robot.computeBody(q, body);
            entry[end] = capsulesToJson(body);
            entry[end + "_tip"] = tip(robot, q, body);
        }
        if (plan != nullptr)
        {
            entry["tip_path"] = json::array();
            std::vector<double> q(robot.getDimension());
            for (std::size_t t : times)
            {
                plan->getConfig(i, t, q.data());
                entry["tip_path"].push_back(tip(robot, q.data(), body));
            }
        }
        robots.push_back(std::move(entry));
    }
    const json doc = {{"format", "ompl_parc.geometry"},
                      {"version", 1},
                      {"name", problem.getName()},
                      {"obstacles", std::move(obstacles)},
                      {"robots", std::move(robots)}};
    return doc.dump();
}

void ompl_parc::GeometryFile::write(const std::string &path, const MultiRobotProblem &problem,
                                    const MultiRobotPlan *plan, std::size_t maxSamples)
{
    const std::string text = toJson(problem, plan, maxSamples);
    std::ofstream out(path);
    if (!out)
        throw ompl::Exception("GeometryFile", "cannot write '" + path + "'");
    out << text << '\n';
    if (!out)
        throw ompl::Exception("GeometryFile", "error writing '" + path + "'");
}
