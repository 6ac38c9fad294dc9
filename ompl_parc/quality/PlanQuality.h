#ifndef OMPL_PARC_PLAN_QUALITY_
#define OMPL_PARC_PLAN_QUALITY_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <cstddef>
#include <map>
#include <string>

namespace ompl_parc
{
    /** \brief A plan's makespan and sum of costs beside lower bounds that no plan of the same endpoints can beat.

        Robot i needs at least its straight-line time: MultiRobotPlan::stepsFor(distance(start, goal)) timesteps at
        vmax = 1 (the space's distance obeys the triangle inequality, and one timestep moves a robot at most
        1/resolution). The makespan bound is the largest of these, the sum-of-costs bound their sum. They are the
        same for every planner and seed (an initial stage's RRT-Connect paths are not bounds: they are neither
        shortest nor computed by every planner), so ratios can be compared across planners; in open spaces (the
        mobile scenarios) they are the robots' shortest paths, around obstacles they are optimistic. */
    struct PlanQuality
    {
        std::size_t makespan{0}, sumOfCosts{0};
        std::size_t makespanBound{0}, sumOfCostsBound{0};

        /** \brief makespan / makespanBound (1 for a team that does not move). */
        double makespanRatio() const { return ratio(makespan, makespanBound); }
        /** \brief sumOfCosts / sumOfCostsBound (1 for a team that does not move). */
        double sumOfCostsRatio() const { return ratio(sumOfCosts, sumOfCostsBound); }

        /** \brief The quality of \e plan (a non-empty path per robot of \e si's team), its endpoints taken as the
            robots' starts and goals. */
        static PlanQuality measure(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan);

        /** \brief Timesteps of robot \e robot's straight motion from its state at timestep \e from to its state at
            \e to: between 0 and its arrival (the default), its straight-line bound. */
        static std::size_t straightLineSteps(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                             std::size_t robot, std::size_t from = 0,
                                             std::size_t to = static_cast<std::size_t>(-1));

        /** \brief Write makespan, sum_of_costs, their bounds and ratios as PlannerData / benchmark properties
            ("makespan INTEGER", ..., "sum_of_costs_ratio REAL"). */
        void addProperties(std::map<std::string, std::string> &properties) const;

      private:
        static double ratio(std::size_t value, std::size_t bound)
        {
            return bound == 0 ? (value == 0 ? 1. : static_cast<double>(value)) : static_cast<double>(value) / bound;
        }
    };
}  // namespace ompl_parc

#endif
