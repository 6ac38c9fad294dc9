#include "ompl_parc/quality/PlanQuality.h"

#include "ompl_parc/quality/ShortestPathBound.h"
#include "ompl_parc/robots/DiscRobot.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace
{
    /** Taken off a path's length before it is made timesteps: the length's rounding errors (relative, about the
        double epsilon times the number of legs) may not round its timesteps up past the true shortest path's. */
    constexpr double LENGTH_SHORTFALL = 1e-9;
}  // namespace

ompl_parc::PlanQuality ompl_parc::PlanQuality::measure(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan)
{
    PlanQuality quality;
    quality.makespan = plan.getMakespan();
    quality.sumOfCosts = plan.getSumOfCosts();
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        const std::size_t bound = straightLineSteps(si, plan, i);
        quality.makespanBound = std::max(quality.makespanBound, bound);
        quality.sumOfCostsBound += bound;
    }
    for (std::size_t bound : pathSteps(si, plan))
    {
        quality.makespanPathBound = std::max(quality.makespanPathBound, bound);
        quality.sumOfCostsPathBound += bound;
    }
    return quality;
}

std::size_t ompl_parc::PlanQuality::straightLineSteps(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                                      std::size_t robot, std::size_t from, std::size_t to)
{
    const Robot &r = *si.getRobot(robot);
    std::vector<double> a(r.getDimension()), b(r.getDimension());
    plan.getConfig(robot, from, a.data());
    plan.getConfig(robot, std::min(to, plan.getArrival(robot)), b.data());
    return MultiRobotPlan::stepsFor(r.distance(a.data(), b.data()), plan.getResolution());
}

std::vector<std::size_t> ompl_parc::PlanQuality::pathSteps(const MultiRobotSpaceInformation &si,
                                                           const MultiRobotPlan &plan)
{
    std::map<std::pair<const Environment *, double>, ShortestPathBound> bounds;
    std::vector<std::size_t> steps;
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        const std::size_t straight = straightLineSteps(si, plan, i);
        const auto *disc = dynamic_cast<const DiscRobot *>(si.getRobot(i).get());
        if (disc == nullptr)
        {
            steps.push_back(straight);
            continue;
        }
        const std::pair<const Environment *, double> key(disc->getEnvironment().get(), disc->getRadius());
        auto it = bounds.find(key);
        if (it == bounds.end())
            it = bounds.emplace(key, ShortestPathBound(*key.first, key.second, plan.getResolution())).first;
        double start[2], goal[2];
        plan.getConfig(i, 0, start);
        plan.getConfig(i, plan.getArrival(i), goal);
        const double length = it->second.length(start, goal) * (1. - LENGTH_SHORTFALL);
        steps.push_back(std::max(straight, MultiRobotPlan::stepsFor(length, plan.getResolution())));
    }
    return steps;
}

void ompl_parc::PlanQuality::addProperties(std::map<std::string, std::string> &properties) const
{
    properties["makespan INTEGER"] = std::to_string(makespan);
    properties["sum_of_costs INTEGER"] = std::to_string(sumOfCosts);
    properties["makespan_bound INTEGER"] = std::to_string(makespanBound);
    properties["sum_of_costs_bound INTEGER"] = std::to_string(sumOfCostsBound);
    properties["makespan_ratio REAL"] = std::to_string(makespanRatio());
    properties["sum_of_costs_ratio REAL"] = std::to_string(sumOfCostsRatio());
    properties["makespan_path_bound INTEGER"] = std::to_string(makespanPathBound);
    properties["sum_of_costs_path_bound INTEGER"] = std::to_string(sumOfCostsPathBound);
    properties["makespan_path_ratio REAL"] = std::to_string(makespanPathRatio());
    properties["sum_of_costs_path_ratio REAL"] = std::to_string(sumOfCostsPathRatio());
}
