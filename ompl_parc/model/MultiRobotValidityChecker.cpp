#include "ompl_parc/model/MultiRobotValidityChecker.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollidingPairSweep.h"
#include "ompl_parc/robots/UrdfArmLanes.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>

ompl_parc::MultiRobotValidityChecker::MultiRobotValidityChecker(ompl::base::SpaceInformation *si,
                                                                std::vector<RobotPtr> team)
    : ompl::base::StateValidityChecker(si), team_(std::move(team))
{
    offsets_.push_back(0);
    for (const RobotPtr &robot : team_)
    {
        lanes_.push_back(robot->getLanes());
        offsets_.push_back(offsets_.back() + robot->getDimension());
    }
    if (std::find(lanes_.begin(), lanes_.end(), nullptr) != lanes_.end())
        lanes_.clear();
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
    if (n >= 2 && !lanes_.empty())
        return lanesValid(configs, count);
    const std::size_t total = offsets_[n];
    // Each robot alone, on its own batch (its kernel may check several configurations at once)...
    for (std::size_t i = 0; i < n; ++i)
    {
        const unsigned int d = team_[i]->getDimension();
        own.resize(count * d);
        for (std::size_t k = 0; k < count; ++k)
            std::copy_n(configs + k * total + offsets_[i], d, own.begin() + k * d);
        if (!team_[i]->allValid(own.data(), count))
            return false;
    }
    // ... then the robot pairs, sample by sample.
    if (n < 2)
        return true;
    bodies.resize(n);
    for (std::size_t k = 0; k < count; ++k)
    {
        for (std::size_t i = 0; i < n; ++i)
            team_[i]->computeBody(configs + k * total + offsets_[i], bodies[i]);
        if (anyPairCollides(bodies))
            return false;
    }
    return true;
}

bool ompl_parc::MultiRobotValidityChecker::lanesValid(const double *configs, std::size_t count) const
{
    thread_local std::vector<double> own;
    thread_local std::vector<UrdfArmLanes::Placed> placed;
    thread_local CollisionBody bodyI, bodyJ;
    const std::size_t n = team_.size(), width = UrdfArmLanes::width(), total = offsets_[n];
    placed.resize(n);
    for (std::size_t first = 0; first < count; first += width)
    {
        const std::size_t lanes = std::min(width, count - first);
        for (std::size_t i = 0; i < n; ++i)
        {
            // The robot alone (bounds, then itself and the environment in lanes, which also places it).
            const Robot &robot = *team_[i];
            const unsigned int d = robot.getDimension();
            own.resize(lanes * d);
            for (std::size_t l = 0; l < lanes; ++l)
                std::copy_n(configs + (first + l) * total + offsets_[i], d, own.begin() + l * d);
            if (!robot.withinBounds(own.data(), lanes))
                return false;
            if (lanes_[i]->anyCollides(own.data(), lanes, robot.getEnvironment()->getObstacleSet(), &placed[i]))
                return false;
        }
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
            {
                unsigned int touching = 0;
                const unsigned int near =
                    UrdfArmLanes::nearLanes(*lanes_[i], placed[i], *lanes_[j], placed[j], touching);
                if (touching != 0)
                    return false;
                for (std::size_t l = 0; l < lanes; ++l)
                {
                    if (((near >> l) & 1u) == 0)
                        continue;
                    const double *q = configs + (first + l) * total;
                    team_[i]->computeBody(q + offsets_[i], bodyI);
                    team_[j]->computeBody(q + offsets_[j], bodyJ);
                    if (bodiesCollide(bodyI, bodyJ))
                        return false;
                }
            }
    }
    return true;
}

std::optional<bool> ompl_parc::MultiRobotValidityChecker::sweepValid(const double *from, const double *to) const
{
    if (team_.size() != 1)
        return std::nullopt;
    return team_[0]->sweepValid(from, to);
}
