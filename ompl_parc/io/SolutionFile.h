#ifndef OMPL_PARC_SOLUTION_FILE_
#define OMPL_PARC_SOLUTION_FILE_

#include "ompl_parc/model/MultiRobotPlan.h"

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Reads and writes plans as JSON (format "ompl_parc.solution", version 1).

        \code
        {
          "format": "ompl_parc.solution", "version": 1,
          "resolution": 128,                       // timesteps per unit of distance
          "robots": [
            {"name": "r0", "kind": "disc", "states": [[10.0, -2.5], [9.9922, -2.5], ...]},
            ...
          ]
        }
        \endcode
        States are per timestep from 0 to the robot's arrival; a robot holds its last state afterwards.
        Reading checks everything (types, equal state sizes, known format and version, robot names and
        kinds matching the team) and throws ompl::Exception naming the offending field. */
    class SolutionFile
    {
      public:
        /** \brief Write \e plan for the team of \e si to \e path; throws ompl::Exception if unwritable. */
        static void write(const std::string &path, const MultiRobotPlan &plan, const MultiRobotSpaceInformation &si);

        /** \brief Serialise to a JSON string. */
        static std::string toJson(const MultiRobotPlan &plan, const MultiRobotSpaceInformation &si);

        /** \brief Read a plan for the team of \e si from \e path. */
        static MultiRobotPlan read(const std::string &path, const MultiRobotSpaceInformation &si);

        /** \brief Parse a plan for the team of \e si from JSON text. */
        static MultiRobotPlan fromJson(const std::string &text, const MultiRobotSpaceInformation &si);
    };
}  // namespace ompl_parc

#endif
