#include "ompl_parc/quality/PlanQuality.h"

#include <ompl/base/ScopedState.h>

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
                                                      std::size_t robot)
{
    const Robot &r = *si.getRobot(robot);
    std::vector<double> start(r.getDimension()), goal(r.getDimension());
    plan.getConfig(robot, 0, start.data());
    plan.getConfig(robot, plan.getArrival(robot), goal.data());
    ompl::base::ScopedState<> a(r.getStateSpace()), b(r.getStateSpace());
    r.configToState(start.data(), a.get());
    r.configToState(goal.data(), b.get());
    return MultiRobotPlan::stepsFor(r.getStateSpace()->distance(a.get(), b.get()), plan.getResolution());
}
