#ifndef OMPL_PARC_SOLUTION_FILE_
#define OMPL_PARC_SOLUTION_FILE_

#include "ompl_parc/model/MultiRobotPlan.h"

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Reads and writes plans as JSON (format "ompl_parc.solution"): writes version 2, reads 1 and 2.

        Version 2 stores each robot's TimedPath, one robot per line:
        \code
        {"format":"ompl_parc.solution","resolution":128,"version":2,"robots":[
         {"arrival":1371,"kind":"disc","name":"r0","pieces":[[0,0,0,[10.0,-2.5],[10.0,-2.5]],[1,1,1371,[10.0,-2.5],[-10.0,-2.5]]]},
         ...
        ]}
        \endcode
        A piece [start, offset, steps, from, to] covers the timesteps from \e start to the next piece's start
        (the last one to \e arrival); local step s = offset + (t - start) is \e to for s >= steps, else
        from + (to - from) x s / steps; a robot holds its arrival state afterwards. Numbers are written to
        round-trip, so a plan reads back bit for bit. Its size grows with the pieces, not with the timesteps.

        Version 1 (still read) lists "states": one configuration per timestep from 0 to the robot's arrival.

        Reading checks everything (types, sizes, pieces following each other from timestep 0, known format
        and version, robot names and kinds matching the team) and throws ompl::Exception naming the
        offending field. */
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
