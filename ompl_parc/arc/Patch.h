#ifndef OMPL_PARC_ARC_PATCH_
#define OMPL_PARC_ARC_PATCH_

#include "ompl_parc/arc/Subproblem.h"
#include "ompl_parc/model/MultiRobotPlan.h"

#include <vector>

namespace ompl_parc
{
    /** \brief A subproblem's answer: one timed path per team robot, all with the same arrival, from its
        local start (timestep 0) to its local goal (last timestep), one timestep at most 1/resolution, team
        collision-free at every timestep. Robots that arrive early wait at their goal. */
    struct Patch
    {
        std::vector<TimedPath> paths;

        /** \brief Number of timesteps the patch lasts (its paths' arrival). */
        std::size_t getDuration() const { return paths.empty() ? 0 : paths.front().getArrival(); }

        /** \brief The paper's splice: each robot of \e subproblem keeps its path before the window, then
            follows its patch path, then the rest of its old path shifted by (patch duration - window
            duration) (MultiRobotPlan::splice). */
        void spliceInto(MultiRobotPlan &plan, const Subproblem &subproblem) const
        {
            for (std::size_t k = 0; k < subproblem.robots.size(); ++k)
                plan.splice(subproblem.robots[k], subproblem.windowStart, subproblem.windowEnd, paths[k]);
        }
    };
}  // namespace ompl_parc

#endif
