#ifndef OMPL_PARC_PLAN_OBJECTIVE_
#define OMPL_PARC_PLAN_OBJECTIVE_

#include "ompl_parc/model/MultiRobotPlan.h"

#include <cstddef>
#include <string>
#include <utility>

namespace ompl_parc
{
    /** \brief What an anytime planner of ours minimises after its first solution (the \e objective parameter of ARC,
        P-ARC and OR-P-ARC): FIRST stops at the first solution (the paper's planners), MAKESPAN and SUM_OF_COSTS keep
        improving the plan until the termination condition. */
    enum class PlanObjective
    {
        FIRST,
        MAKESPAN,
        SUM_OF_COSTS
    };

    /** \brief "first", "makespan" or "sum_of_costs"; throws ompl::Exception naming the accepted values otherwise. */
    PlanObjective parsePlanObjective(const std::string &name);

    std::string toString(PlanObjective objective);

    /** \brief \e plan's objective value (FIRST: the makespan) and, to break ties, the other one: plans compare by
        this key. */
    std::pair<std::size_t, std::size_t> objectiveKey(const MultiRobotPlan &plan, PlanObjective objective);
}  // namespace ompl_parc

#endif
