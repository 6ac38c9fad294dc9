#ifndef OMPL_PARC_SCENARIOS_CONFLICTING_PAIRS_
#define OMPL_PARC_SCENARIOS_CONFLICTING_PAIRS_

#include "ompl_parc/model/MultiRobotProblem.h"

namespace ompl_parc
{
    namespace scenarios
    {
        /** \brief How many robot pairs of \e problem must coordinate: the pairs whose individual paths collide,
            with the paths ARC's first stage plans with seed \e seed (InitialPlanner, simplified, straight_initial off:
            every robot planned, so the stored tasks stay what they were) and every pair
            scanned to its first conflict. A task where this is 0 is solved by its first stage alone. Throws
            ompl::Exception if a robot finds no path within a minute. */
        std::size_t countConflictingPairs(const MultiRobotProblem &problem, unsigned int seed = 1);
    }  // namespace scenarios
}  // namespace ompl_parc

#endif
