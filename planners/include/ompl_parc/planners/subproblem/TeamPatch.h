#ifndef OMPL_PARC_TEAM_PATCH_
#define OMPL_PARC_TEAM_PATCH_

#include "ompl_parc/arc/Patch.h"
#include "ompl_parc/arc/Subproblem.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/geometric/PathGeometric.h>

#include <cstdint>

namespace ompl_parc
{
    /** \brief The two ends of the solvers that plan a team's path in its composite space (composite and sequential
        RRT-Connect): the subproblem's local starts and goals as composite states of the team, and the found path
        turned into a patch. */
    namespace team_patch
    {
        /** \brief \e start and \e goal (states of \e team) set to the subproblem's local starts and goals; false if
            either is invalid for the team (a robot in collision, two robots touching). */
        bool fillEndpoints(const MultiRobotSpaceInformation &team, const Subproblem &subproblem,
                           ompl::base::State *start, ompl::base::State *goal);

        /** \brief \e path (valid for \e team, whose SpaceInformation it was planned in) laid on the timestep grid as
            \e patch, after a bounded shortening with OMPL's simplifier when \e simplify is set (one pass of vertex
            reduction and 128 shortcut steps, stopping after 32 without improvement, drawn from \e seed). */
        void lay(const std::shared_ptr<MultiRobotSpaceInformation> &team, ompl::geometric::PathGeometric &path,
                 std::uint_fast32_t seed, bool simplify, Patch &patch);
    }  // namespace team_patch
}  // namespace ompl_parc

#endif
