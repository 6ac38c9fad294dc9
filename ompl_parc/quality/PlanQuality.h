#ifndef OMPL_PARC_PLAN_QUALITY_
#define OMPL_PARC_PLAN_QUALITY_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief A plan's makespan and sum of costs beside lower bounds that no plan of the same endpoints can beat.

        Two bounds, each robot's time alone at vmax = 1 (one timestep moves a robot at most 1/resolution):
        - the straight-line bound: MultiRobotPlan::stepsFor(distance(start, goal)) timesteps (the space's distance
          obeys the triangle inequality). In open spaces (the mobile scenarios) it is the robot's shortest path,
          around obstacles it is optimistic;
        - the obstacle-aware (path) bound: for a disc, the length of its shortest path around the static obstacles
          as ShortestPathBound computes it, never above the true one, made timesteps without rounding up past it
          and never below the straight-line bound; for the other kinds (arms: joint space) the straight-line bound.
        The makespan bounds are the largest of these, the sum-of-costs bounds their sums. They are the same for every
        planner and seed (an initial stage's RRT-Connect paths are not bounds: they are neither shortest nor computed
        by every planner), so ratios can be compared across planners. */
    struct PlanQuality
    {
        std::size_t makespan{0}, sumOfCosts{0};
        std::size_t makespanBound{0}, sumOfCostsBound{0};
        /** \brief The obstacle-aware bounds (pathSteps()). */
        std::size_t makespanPathBound{0}, sumOfCostsPathBound{0};

        /** \brief makespan / makespanBound (1 for a team that does not move). */
        double makespanRatio() const { return ratio(makespan, makespanBound); }
        /** \brief sumOfCosts / sumOfCostsBound (1 for a team that does not move). */
        double sumOfCostsRatio() const { return ratio(sumOfCosts, sumOfCostsBound); }
        /** \brief makespan / makespanPathBound (1 for a team that does not move). */
        double makespanPathRatio() const { return ratio(makespan, makespanPathBound); }
        /** \brief sumOfCosts / sumOfCostsPathBound (1 for a team that does not move). */
        double sumOfCostsPathRatio() const { return ratio(sumOfCosts, sumOfCostsPathBound); }

        /** \brief The quality of \e plan (a non-empty path per robot of \e si's team), its endpoints taken as the
            robots' starts and goals. */
        static PlanQuality measure(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan);

        /** \brief Timesteps of robot \e robot's straight motion from its state at timestep \e from to its state at
            \e to: between 0 and its arrival (the default), its straight-line bound. */
        static std::size_t straightLineSteps(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                             std::size_t robot, std::size_t from = 0,
                                             std::size_t to = static_cast<std::size_t>(-1));

        /** \brief Per robot of \e plan, its obstacle-aware bound in timesteps from its state at timestep 0 to its
            state at its arrival: for a disc the larger of its straight-line bound and the ShortestPathBound length
            (one ShortestPathBound per environment and radius, shared by the robots that have them), for the other
            kinds the straight-line bound. */
        static std::vector<std::size_t> pathSteps(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan);

        /** \brief Write makespan, sum_of_costs, their bounds and ratios as PlannerData / benchmark properties
            ("makespan INTEGER", ..., "sum_of_costs_ratio REAL", then "makespan_path_bound INTEGER", ...,
            "sum_of_costs_path_ratio REAL"). */
        void addProperties(std::map<std::string, std::string> &properties) const;

      private:
        static double ratio(std::size_t value, std::size_t bound)
        {
            return bound == 0 ? (value == 0 ? 1. : static_cast<double>(value)) : static_cast<double>(value) / bound;
        }
    };
}  // namespace ompl_parc

#endif
