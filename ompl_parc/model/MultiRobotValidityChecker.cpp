#include "ompl_parc/model/MultiRobotValidityChecker.h"

#include "ompl_parc/collision/CapsuleCollision.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

ompl_parc::MultiRobotValidityChecker::MultiRobotValidityChecker(ompl::base::SpaceInformation *si,
                                                                std::vector<RobotPtr> team)
    : ompl::base::StateValidityChecker(si), team_(std::move(team))
{
}

bool ompl_parc::MultiRobotValidityChecker::isValid(const ompl::base::State *state) const
{
    thread_local std::vector<CollisionBody> bodies;
    const std::size_t n = team_.size();
    bodies.resize(n);
    const auto *compound = state->as<ompl::base::CompoundState>();
    for (std::size_t i = 0; i < n; ++i)
    {
        const double *q =
            compound->as<ompl::base::RealVectorStateSpace::StateType>(static_cast<unsigned int>(i))->values;
        if (!team_[i]->isValid(q))
            return false;
        team_[i]->computeBody(q, bodies[i]);
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (bodiesCollide(bodies[i], bodies[j]))
                return false;
    return true;
}
