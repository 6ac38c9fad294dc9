#include "ompl_parc/spacetime/SpaceTimeValidityChecker.h"

#include "ompl_parc/spacetime/SpaceTimeInUse.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <cmath>

namespace ob = ompl::base;

ompl_parc::SpaceTimeValidityChecker::SpaceTimeValidityChecker(ob::SpaceInformation *si, DynamicObstaclesPtr obstacles)
    : ob::StateValidityChecker(si), obstacles_(std::move(obstacles))
{
}

bool ompl_parc::SpaceTimeValidityChecker::isValid(const ob::State *state) const
{
    const double step = spacetime::SpaceTimeStateSpace::getStateTime(state) * obstacles_->getResolution();
    if (!(step >= 0.))
        return false;
    const double *q = state->as<ob::CompoundState>()->as<ob::RealVectorStateSpace::StateType>(0)->values;
    const auto below = static_cast<std::size_t>(std::floor(step)), above = static_cast<std::size_t>(std::ceil(step));
    return obstacles_->isClear(q, below) && (above == below || obstacles_->isClear(q, above));
}
