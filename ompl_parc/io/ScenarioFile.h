#ifndef OMPL_PARC_SCENARIO_FILE_
#define OMPL_PARC_SCENARIO_FILE_

#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    /** \brief Reads and writes multi-robot problems as JSON (format "ompl_parc.scenario", version 1), so
        scenarios other than the built-in ones can be planned without recompiling.

        \code
        {
          "format": "ompl_parc.scenario", "version": 1,
          "name": "doorway_swap",
          "resolution": 128,                        // timesteps per unit of distance (optional, 128)
          "obstacles": [                            // optional
            {"name": "wall", "shape": "box2d", "center": [0, 3], "size": [1, 4], "yaw": 0},
            {"shape": "box", "size": [1, 2, 3], "position": [0, 0, 0], "orientation": [1, 0, 0, 0]},
            {"shape": "sphere", "radius": 0.5, "position": [2, 2, 0]},
            {"shape": "cylinder", "radius": 0.3, "length": 2, "position": [4, 0, 0]}
          ],
          "robots": [
            {"name": "r0", "kind": "disc", "radius": 0.5, "bounds": {"low": [-10, -10], "high": [10, 10]},
             "start": [-5, 0], "goal": [5, 0]},
            {"name": "arm0", "kind": "planar_arm", "base": {"x": 0, "y": 0, "yaw": 0},
             "link_lengths": [0.3, 0.3], "link_width": 0.1,
             "joint_limits": {"low": [-3.14, -3.14], "high": [3.14, 3.14]},
             "start": [0.5, 0], "goal": [-0.5, 0]},
            {"name": "panda0", "kind": "urdf_arm", "builtin_urdf": "panda",
             "base_link": "panda_link0", "tip_link": "panda_link8",
             "base_pose": {"position": [0, 0, 0], "orientation": [1, 0, 0, 0]},   // optional, identity
             "start": [0, 0, 0, -1.5, 0, 1.5, 0], "goal": [0, 0.5, 0, -1.5, 0, 2, 0]}
          ]
        }
        \endcode
        Obstacles: "box" (full extents), "sphere", "cylinder" (along its local z axis), placed by
        "position" (default origin) and a unit quaternion "orientation" [w, x, y, z] (default identity);
        "box2d" is a footprint extruded over z in [-1, 1], turned by "yaw", as Environment::addBox2D().
        Obstacle names are optional. Robot kinds: "disc", "planar_arm" and "urdf_arm" (UrdfArm: the chain
        "base_link" .. "tip_link" of a URDF given by exactly one of "urdf" (the XML inline), "builtin_urdf"
        (a model compiled into the library: "panda", models::pandaUrdf()) or "urdf_file" (a path, relative
        to the scenario file's folder). write() names a built-in model rather than inlining it.

        Reading is strict so mistakes surface at load time, not as odd plans: every value is type- and
        range-checked, unknown fields are rejected (typos), robot names must be unique, names (the scenario's, the
        robots', the obstacles') hold no control characters (the tools print them to terminals), and the starts
        and goals must pass MultiRobotProblem::checkEndpoints(). Errors throw ompl::Exception naming the field
        ("robots[2].radius must be a positive number") or, for a syntax error, the line and column. */
    class ScenarioFile
    {
      public:
        /** \brief Write \e problem to \e path; throws ompl::Exception if unwritable or not representable
            (robots of another kind, or not sharing one Environment). */
        static void write(const std::string &path, const MultiRobotProblem &problem);

        /** \brief Serialise \e problem to a JSON string. */
        static std::string toJson(const MultiRobotProblem &problem);

        /** \brief Read a problem from \e path. */
        static MultiRobotProblem read(const std::string &path);

        /** \brief Parse a problem from JSON text; relative "urdf_file" paths start from \e folder (the current
            directory if empty). */
        static MultiRobotProblem fromJson(const std::string &text, const std::string &folder = "");
    };
}  // namespace ompl_parc

#endif
