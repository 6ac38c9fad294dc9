#include "ompl_parc/quality/PlanObjective.h"

#include <ompl/util/Exception.h>

ompl_parc::PlanObjective ompl_parc::parsePlanObjective(const std::string &name)
{
    if (name == "first")
        return PlanObjective::FIRST;
    if (name == "makespan")
        return PlanObjective::MAKESPAN;
    if (name == "sum_of_costs")
        return PlanObjective::SUM_OF_COSTS;
    throw ompl::Exception("objective", "objective must be first, makespan or sum_of_costs (got '" + name + "')");
}

std::string ompl_parc::toString(PlanObjective objective)
{
    switch (objective)
    {
        case PlanObjective::MAKESPAN:
            return "makespan";
        case PlanObjective::SUM_OF_COSTS:
            return "sum_of_costs";
        case PlanObjective::FIRST:
            break;
    }
    return "first";
}

std::pair<std::size_t, std::size_t> ompl_parc::objectiveKey(const MultiRobotPlan &plan, PlanObjective objective)
{
    if (objective == PlanObjective::SUM_OF_COSTS)
        return {plan.getSumOfCosts(), plan.getMakespan()};
    return {plan.getMakespan(), plan.getSumOfCosts()};
}
