#include "ompl_parc/quality/PlanQuality.h"

#include <algorithm>
#include <vector>

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

void ompl_parc::PlanQuality::addProperties(std::map<std::string, std::string> &properties) const
{
    properties["makespan INTEGER"] = std::to_string(makespan);
    properties["sum_of_costs INTEGER"] = std::to_string(sumOfCosts);
    properties["makespan_bound INTEGER"] = std::to_string(makespanBound);
    properties["sum_of_costs_bound INTEGER"] = std::to_string(sumOfCostsBound);
    properties["makespan_ratio REAL"] = std::to_string(makespanRatio());
    properties["sum_of_costs_ratio REAL"] = std::to_string(sumOfCostsRatio());
}
