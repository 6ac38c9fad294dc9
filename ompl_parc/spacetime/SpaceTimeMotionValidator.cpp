#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"

#include "ompl_parc/spacetime/SpaceTimeStateSpace.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <cmath>

namespace ob = ompl::base;

namespace
{
    const double *configOf(const ob::State *state)
    {
        return state->as<ob::CompoundState>()->as<ob::RealVectorStateSpace::StateType>(0)->values;
    }
}  // namespace

ompl_parc::SpaceTimeMotionValidator::SpaceTimeMotionValidator(ob::SpaceInformation *si, DynamicObstaclesPtr obstacles)
    : ob::MotionValidator(si), obstacles_(std::move(obstacles))
{
}

bool ompl_parc::SpaceTimeMotionValidator::forEachTimestep(
    const ob::State *s1, const ob::State *s2, const std::function<bool(std::size_t, const double *)> &visit) const
{
    const double res = obstacles_->getResolution();
    const double t1 = spacetime::SpaceTimeStateSpace::getStateTime(s1),
                 t2 = spacetime::SpaceTimeStateSpace::getStateTime(s2);
    const double *q1 = configOf(s1), *q2 = configOf(s2);
    const unsigned int d = obstacles_->getRobot()->getDimension();
    thread_local std::vector<double> q;
    q.resize(d);
    const auto first = static_cast<std::size_t>(std::ceil(t1 * res)),
               last = static_cast<std::size_t>(std::floor(t2 * res));
    for (std::size_t k = first; k <= last; ++k)
    {
        const double f = std::clamp((static_cast<double>(k) / res - t1) / (t2 - t1), 0., 1.);
        for (unsigned int i = 0; i < d; ++i)
            q[i] = q1[i] + (q2[i] - q1[i]) * f;
        if (!visit(k, q.data()))
            return false;
    }
    return true;
}

bool ompl_parc::SpaceTimeMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2) const
{
    const auto *space = si_->getStateSpace()->as<spacetime::SpaceTimeStateSpace>();
    const double dt =
        spacetime::SpaceTimeStateSpace::getStateTime(s2) - spacetime::SpaceTimeStateSpace::getStateTime(s1);
    if (!(dt > 0.) || !(space->distanceSpace(s1, s2) <= space->getVMax() * dt * (1. + 1e-12)) || !si_->isValid(s2))
    {
        ++invalid_;
        return false;
    }
    const bool clear =
        forEachTimestep(s1, s2, [this](std::size_t k, const double *q) { return obstacles_->isClear(q, k); });
    ++(clear ? valid_ : invalid_);
    return clear;
}

bool ompl_parc::SpaceTimeMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2,
                                                      std::pair<ob::State *, double> &lastValid) const
{
    if (checkMotion(s1, s2))
        return true;
    if (lastValid.first != nullptr)
        si_->copyState(lastValid.first, s1);
    lastValid.second = 0.;
    return false;
}

std::vector<double> ompl_parc::SpaceTimeMotionValidator::layOnGrid(const ompl::geometric::PathGeometric &path) const
{
    if (path.getStateCount() == 0)
        throw ompl::Exception("SpaceTimeMotionValidator", "cannot lay an empty path on the timestep grid");
    const unsigned int d = obstacles_->getRobot()->getDimension();
    std::vector<double> flat;
    std::size_t next = 0;  // the next timestep to emit
    const auto append = [&](std::size_t k, const double *q)
    {
        if (k == next)
        {
            flat.insert(flat.end(), q, q + d);
            ++next;
        }
        return true;
    };
    if (path.getStateCount() == 1)
        append(0, configOf(path.getState(0)));
    for (std::size_t s = 1; s < path.getStateCount(); ++s)
        forEachTimestep(path.getState(s - 1), path.getState(s), append);
    // The arrival, rounded up: the end state itself (checked at that timestep as a state).
    const ob::State *end = path.getState(path.getStateCount() - 1);
    const auto arrival = static_cast<std::size_t>(
        std::ceil(spacetime::SpaceTimeStateSpace::getStateTime(end) * obstacles_->getResolution()));
    if (flat.size() < arrival * d)
        throw ompl::Exception("SpaceTimeMotionValidator", "the path must start at time 0 and go forward in time");
    flat.resize(arrival * d);
    flat.insert(flat.end(), configOf(end), configOf(end) + d);
    return flat;
}
