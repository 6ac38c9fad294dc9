#include "ompl_parc/model/MultiRobotValidityChecker.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollidingPairSweep.h"

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
        if (team_[i]->checkValidity(q, bodies[i]) != Robot::Validity::VALID)
            return false;
    }
    return !anyPairCollides(bodies);
}

bool ompl_parc::MultiRobotValidityChecker::anyPairCollides(const std::vector<CollisionBody> &bodies) const
{
    if (team_.size() >= SWEEP_FROM)
    {
        thread_local CollidingPairSweep sweep;
        return sweep.any(bodies);
    }
    for (std::size_t i = 0; i < team_.size(); ++i)
        for (std::size_t j = i + 1; j < team_.size(); ++j)
            if (bodiesCollide(bodies[i], bodies[j]))
                return true;
    return false;
}

bool ompl_parc::MultiRobotValidityChecker::allValid(const double *configs, std::size_t count) const
{
    thread_local std::vector<double> own;
    thread_local std::vector<CollisionBody> bodies;
    const std::size_t n = team_.size();
    std::size_t total = 0;
    for (const RobotPtr &robot : team_)
        total += robot->getDimension();
    // Each robot alone, on its own batch (its kernel may check several configurations at once)...
    for (std::size_t i = 0, offset = 0; i < n; offset += team_[i]->getDimension(), ++i)
    {
        const unsigned int d = team_[i]->getDimension();
        own.resize(count * d);
        for (std::size_t k = 0; k < count; ++k)
            std::copy(configs + k * total + offset, configs + k * total + offset + d, own.begin() + k * d);
        if (!team_[i]->allValid(own.data(), count))
            return false;
    }
    // ... then the robot pairs, sample by sample.
    if (n < 2)
        return true;
    bodies.resize(n);
    for (std::size_t k = 0; k < count; ++k)
    {
        for (std::size_t i = 0, offset = 0; i < n; offset += team_[i]->getDimension(), ++i)
            team_[i]->computeBody(configs + k * total + offset, bodies[i]);
        if (anyPairCollides(bodies))
            return false;
    }
    return true;
}

std::optional<bool> ompl_parc::MultiRobotValidityChecker::sweepValid(const double *from, const double *to) const
{
    if (team_.size() != 1)
        return std::nullopt;
    return team_[0]->sweepValid(from, to);
}
