#include "ompl_parc/io/TrajectoryFile.h"

#include "ompl_parc/execution/TimeParameterization.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <fstream>
#include <stdexcept>

nlohmann::ordered_json ompl_parc::TrajectoryFile::toJson(const MultiRobotProblem &problem,
                                                         const TeamTrajectory &trajectory,
                                                         const TemporalPlanGraph *graph)
{
    const auto &si = *problem.getSpaceInformation();
    if (trajectory.getRobotCount() != si.getRobotCount())
        throw std::invalid_argument("TrajectoryFile: the trajectory is for another team");
    nlohmann::ordered_json out{{"format", "ompl_parc.trajectory"},
                               {"version", 1},
                               {"problem", problem.getName()},
                               {"duration", trajectory.getDuration()},
                               {"robots", nlohmann::ordered_json::array()}};
    const double origin = trajectory.getStartTime();
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        const auto &robot = *si.getRobot(i);
        const unsigned int dim = robot.getDimension();
        auto velocityLimits = nlohmann::ordered_json::array(), accelerationLimits = nlohmann::ordered_json::array();
        for (const auto &group : robot.getMotionLimits().groups)
        {
            velocityLimits.push_back(group.velocity);
            accelerationLimits.push_back(group.acceleration);
        }
        auto points = nlohmann::ordered_json::array();
        std::vector<double> q(dim), v(dim), a(dim);
        for (double t : trajectory.getBreakTimes(i))
        {
            trajectory.evaluate(i, t, q.data(), v.data(), a.data());
            points.push_back(
                {{"positions", q}, {"velocities", v}, {"accelerations", a}, {"time_from_start", t - origin}});
        }
        out["robots"].push_back({{"name", robot.getName()},
                                 {"kind", robot.getKind()},
                                 {"joint_names", robot.getCoordinateNames()},
                                 {"limits", {{"velocity", velocityLimits}, {"acceleration", accelerationLimits}}},
                                 {"arrival_time", trajectory.getArrivalTime(i)},
                                 {"max_deviation", trajectory.getMaxDeviation(i)},
                                 {"points", points}});
    }
    if (graph)
        out["temporal_plan_graph"] = graph->toJson();
    return out;
}

nlohmann::ordered_json ompl_parc::TrajectoryFile::fromPlan(const MultiRobotProblem &problem, const MultiRobotPlan &plan,
                                                           std::size_t phaseSteps, double maxDeviation)
{
    if (const auto report = SolutionValidator(problem).validate(plan); !report.valid)
        throw std::invalid_argument("the plan does not pass the validator: " + report.message);
    const auto result = TimeParameterization(problem, maxDeviation).computeConflictFree(plan);
    if (!result.valid)
        throw std::invalid_argument("the plan is not conflict-free: " + result.message);
    const TemporalPlanGraph graph(problem, plan, phaseSteps);
    return toJson(problem, result.trajectory, &graph);
}

void ompl_parc::TrajectoryFile::write(const std::string &path, const nlohmann::ordered_json &doc)
{
    const std::string text = doc.dump();
    std::ofstream out(path);
    if (!out)
        throw std::runtime_error("cannot write '" + path + "'");
    out << text << '\n';
    if (!out)
        throw std::runtime_error("error writing '" + path + "'");
}
