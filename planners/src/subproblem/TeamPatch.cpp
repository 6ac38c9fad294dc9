#include "ompl_parc/planners/subproblem/TeamPatch.h"

#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <algorithm>

bool ompl_parc::team_patch::fillEndpoints(const MultiRobotSpaceInformation &team, const Subproblem &subproblem,
                                          ompl::base::State *start, ompl::base::State *goal)
{
    for (std::size_t k = 0; k < subproblem.robots.size(); ++k)
    {
        std::copy(subproblem.starts[k].begin(), subproblem.starts[k].end(), team.getRobotValues(start, k));
        std::copy(subproblem.goals[k].begin(), subproblem.goals[k].end(), team.getRobotValues(goal, k));
    }
    return team.isValid(start) && team.isValid(goal);
}

void ompl_parc::team_patch::lay(const std::shared_ptr<MultiRobotSpaceInformation> &team,
                                ompl::geometric::PathGeometric &path, std::uint_fast32_t seed, bool simplify,
                                Patch &patch)
{
    if (simplify)
    {
        // Bounded like the initial paths: one pass of vertex reduction and of shortcutting (128 steps, stop after
        // 32 without improvement), each checked on the team's space (robots and environment).
        SeededPathSimplifier simplifier(team, mixSeed(seed, 0x5eed));
        simplifier.reduceVertices(path);
        compat::shortcutPath(simplifier, path, 128, 32);
    }
    patch.paths = MultiRobotPlan::layTeamPath(*team, path);
}
