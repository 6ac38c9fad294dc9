#ifndef OMPL_PARC_INITIAL_PLANNER_
#define OMPL_PARC_INITIAL_PLANNER_

#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/model/TimedPath.h"

#include <ompl/base/Planner.h>
#include <ompl/base/PlannerTerminationCondition.h>

#include <cstdint>
#include <optional>

namespace ompl_parc
{
    /** \brief ARC's first stage: a path for one robot alone (static environment only), on the timestep grid.

        Each call plans in a fresh single-robot space seeded by \e seed (so calls are independent, may run
        concurrently, and repeat exactly), with an OMPL planner from the allocator (RRTConnect by default),
        then shortcuts the path with OMPL's simplifier (bounded effort, as the authors do). With \e straightFirst
        (ArcSettings::straightInitial, ARC's default) a robot whose straight motion is valid takes it without a
        planner; scenario generators that define tasks by the planned paths (ConflictingPairs) leave it off, so
        their tasks stay what they were. */
    class InitialPlanner
    {
      public:
        explicit InitialPlanner(const MultiRobotProblem &problem, bool simplify = true,
                                ompl::base::PlannerAllocator allocator = {}, bool straightFirst = false);

        /** \brief Plan robot \e robot from its start to its goal; on success fill \e path (laid on the
            timestep grid as waypoints, from start to goal) and return true; false if \e ptc fired first. */
        bool plan(std::size_t robot, const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                  TimedPath &path) const;

      private:
        /** \brief The straight motion from \e robot's start to its goal, laid on the grid, if the start is valid and
            the robot's motion validator accepts the motion at every timestep (or, for kinds that can tell, at every
            point: Robot::sweepValid()); std::nullopt if not, or if the planning stopped during the check. */
        std::optional<TimedPath> straightPath(std::size_t robot) const;

        const MultiRobotProblem &problem_;
        bool simplify_, straightFirst_;
        ompl::base::PlannerAllocator allocator_;
    };
}  // namespace ompl_parc

#endif
