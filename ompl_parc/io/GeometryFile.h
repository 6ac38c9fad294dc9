#ifndef OMPL_PARC_GEOMETRY_FILE_
#define OMPL_PARC_GEOMETRY_FILE_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    /** \brief Writes the world-frame geometry of a problem and its plan as JSON (format "ompl_parc.geometry",
        version 1), so that 3D pictures (scripts/draw_panda_cage.py) are drawn from exactly the shapes the
        collision checks use, without re-implementing any robot's kinematics.

        \code
        {
          "format": "ompl_parc.geometry", "version": 1, "name": "panda_cage_8_0",
          "obstacles": [
            {"name": "bar0", "shape": "cylinder", "a": [x, y, z], "b": [x, y, z], "radius": 0.05},
            {"name": "ball", "shape": "sphere", "center": [x, y, z], "radius": 0.3},
            {"name": "crate", "shape": "box", "corners": [[x, y, z], ...]}       // 8 corners, x bit fastest
          ],
          "robots": [
            {"name": "panda0",
             "start": [[ax, ay, az, bx, by, bz, radius], ...],   // the capsules of Robot::computeBody
             "start_tip": [x, y, z],
             "goal": [[...], ...], "goal_tip": [x, y, z],
             "tip_path": [[x, y, z], ...]}                       // only with a plan: sampled timesteps
          ]
        }
        \endcode
        The tip is a UrdfArm's tip link origin, otherwise the end of the robot's last capsule. */
    class GeometryFile
    {
      public:
        /** \brief The JSON document for \e problem and, if not null, \e plan (a plan of its team), whose tip
            paths are sampled at up to \e maxSamples timesteps (MultiRobotPlan::sampleTimesteps()). */
        static std::string toJson(const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                  std::size_t maxSamples = 200);

        /** \brief Write toJson() to \e path; throws ompl::Exception if unwritable. */
        static void write(const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                          std::size_t maxSamples = 200);
    };
}  // namespace ompl_parc

#endif
