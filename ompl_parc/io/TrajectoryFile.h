#ifndef OMPL_PARC_TRAJECTORY_FILE_
#define OMPL_PARC_TRAJECTORY_FILE_

#include "ompl_parc/execution/TeamTrajectory.h"
#include "ompl_parc/execution/TemporalPlanGraph.h"
#include "ompl_parc/execution/TimeParameterization.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ompl_parc
{
    /** \brief A team trajectory for robots: per robot, what a ROS `trajectory_msgs/JointTrajectory` holds (joint
        names; points with positions, velocities, accelerations and time_from_start in seconds), and the temporal plan
        graph that coordinates the robots when they run late.

        The points are the instants where the robot's acceleration changes (TeamTrajectory::getBreakTimes()), so the
        cubic interpolation of positions and velocities that trajectory controllers do between points reproduces the
        trajectory exactly. Format "ompl_parc.trajectory", version 1; times from the team's start. */
    class TrajectoryFile
    {
      public:
        static nlohmann::ordered_json toJson(const MultiRobotProblem &problem, const TeamTrajectory &trajectory,
                                             const TemporalPlanGraph *graph);

        /** \brief toJson() of \e plan's conflict-free trajectory (TimeParameterization::computeConflictFree()) and its
            temporal plan graph with phases of at most \e phaseSteps timesteps, corners cut by at most
            \e maxDeviation; throws std::invalid_argument if the
            plan does not pass the validator. */
        static nlohmann::ordered_json fromPlan(const MultiRobotProblem &problem, const MultiRobotPlan &plan,
                                               std::size_t phaseSteps = 4,
                                               double maxDeviation = TimeParameterization::DEFAULT_MAX_DEVIATION);

        /** \brief Write \e doc (toJson(), fromPlan()) to \e path; throws std::runtime_error naming the file if it
            cannot. */
        static void write(const std::string &path, const nlohmann::ordered_json &doc);
    };
}  // namespace ompl_parc

#endif
