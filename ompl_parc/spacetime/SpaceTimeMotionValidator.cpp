#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"

#include "ompl_parc/spacetime/SpaceTimeInUse.h"
#include "ompl_parc/util/StopSignal.h"

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

bool ompl_parc::SpaceTimeMotionValidator::gridAnchors(const ob::State *s1, const ob::State *s2, std::size_t &first,
                                                      std::size_t &last, double *a, double *b) const
{
    const double res = obstacles_->getResolution();
    const double t1 = spacetime::SpaceTimeStateSpace::getStateTime(s1),
                 t2 = spacetime::SpaceTimeStateSpace::getStateTime(s2);
    const double *q1 = configOf(s1), *q2 = configOf(s2);
    const unsigned int d = obstacles_->getRobot()->getDimension();
    first = static_cast<std::size_t>(std::ceil(t1 * res));
    last = static_cast<std::size_t>(std::floor(t2 * res));
    if (!(t2 > t1) || first > last)
        return false;
    for (const auto &[k, out] : {std::pair<std::size_t, double *>{first, a}, {last, b}})
    {
        const double f = std::clamp((static_cast<double>(k) / res - t1) / (t2 - t1), 0., 1.);
        for (unsigned int i = 0; i < d; ++i)
            out[i] = q1[i] + (q2[i] - q1[i]) * f;
    }
    return true;
}

bool ompl_parc::SpaceTimeMotionValidator::forEachTimestep(
    const ob::State *s1, const ob::State *s2, const std::function<bool(std::size_t, const double *)> &visit) const
{
    const unsigned int d = obstacles_->getRobot()->getDimension();
    thread_local std::vector<double> q, a, b;
    q.resize(d);
    a.resize(d);
    b.resize(d);
    std::size_t first = 0, last = 0;
    if (!gridAnchors(s1, s2, first, last, a.data(), b.data()))
        return true;
    for (std::size_t k = first; k <= last; ++k)
    {
        TimedPath::interpolate(a.data(), b.data(), k - first, last - first, d, q.data());
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
    const bool clear = forEachTimestep(s1, s2,
                                       [this](std::size_t k, const double *q)
                                       {
                                           // A motion given up on (the planning stopped) counts as invalid: never a
                                           // wrong "valid".
                                           return obstacles_->isClear(q, k) &&
                                                  (k % StopSignal::POLL_INTERVAL != 0 || !StopSignal::raised());
                                       });
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

ompl_parc::TimedPath ompl_parc::SpaceTimeMotionValidator::layOnGrid(const ompl::geometric::PathGeometric &path) const
{
    if (path.getStateCount() == 0)
        throw ompl::Exception("SpaceTimeMotionValidator", "cannot lay an empty path on the timestep grid");
    const unsigned int d = obstacles_->getRobot()->getDimension();
    const ob::State *end = path.getState(path.getStateCount() - 1);
    // The arrival, rounded up, is the end state itself (checked at that timestep as a state); before it, each
    // timestep gets the configuration its first motion checked there: one piece per motion.
    const auto arrival = static_cast<std::size_t>(
        std::ceil(spacetime::SpaceTimeStateSpace::getStateTime(end) * obstacles_->getResolution()));
    const auto fail = []
    { throw ompl::Exception("SpaceTimeMotionValidator", "the path must start at time 0 and go forward in time"); };
    TimedPath laid(d);
    std::vector<double> a(d), b(d);
    for (std::size_t s = 1; s < path.getStateCount() && arrival > 0; ++s)
    {
        std::size_t first = 0, last = 0;
        if (!gridAnchors(path.getState(s - 1), path.getState(s), first, last, a.data(), b.data()))
            continue;
        const std::size_t next = laid.empty() ? 0 : laid.getArrival() + 1;
        if (first > next)
            fail();
        if (std::min(last, arrival - 1) >= next)
            laid.appendPiece({next, next - first, last - first}, a.data(), b.data(), std::min(last, arrival - 1));
    }
    if (arrival > 0 && (laid.empty() || laid.getArrival() + 1 < arrival))
        fail();
    laid.appendHold(configOf(end), arrival);
    return laid;
}
