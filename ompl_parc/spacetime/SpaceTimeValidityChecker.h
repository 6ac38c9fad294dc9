#ifndef OMPL_PARC_SPACE_TIME_VALIDITY_CHECKER_
#define OMPL_PARC_SPACE_TIME_VALIDITY_CHECKER_

#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <ompl/base/StateValidityChecker.h>

namespace ompl_parc
{
    /** \brief Validity of a robot's space-time state (a SpaceTimeStateSpace over the robot's real vector
        space, time in units of resolution timesteps) among DynamicObstacles.

        Plans live on integer timesteps, so a state at time t is checked at the timesteps floor(t x res) and
        ceil(t x res): the two a path through it can be laid on. Negative times are invalid. */
    class SpaceTimeValidityChecker : public ompl::base::StateValidityChecker
    {
      public:
        SpaceTimeValidityChecker(ompl::base::SpaceInformation *si, DynamicObstaclesPtr obstacles);

        bool isValid(const ompl::base::State *state) const override;

      private:
        DynamicObstaclesPtr obstacles_;
    };
}  // namespace ompl_parc

#endif
