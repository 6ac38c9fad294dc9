#include "ompl_parc/robots/Robot.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/robots/RakeMotionValidator.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ob = ompl::base;

ompl_parc::Robot::Robot(std::string name, EnvironmentPtr environment, const ob::RealVectorBounds &bounds)
    : name_(std::move(name)),
      environment_(environment ? std::move(environment) : std::make_shared<Environment>()),
      bounds_(bounds),
      dimension_(static_cast<unsigned int>(bounds.low.size()))
{
    if (dimension_ == 0 || bounds.high.size() != dimension_)
        throw ompl::Exception("Robot", "robot '" + name_ + "' needs bounds with equal, non-zero dimensions");
    for (unsigned int i = 0; i < dimension_; ++i)
        if (!(bounds.low[i] < bounds.high[i]))
            throw ompl::Exception("Robot", "robot '" + name_ + "' has empty bounds in dimension " + std::to_string(i));
    auto space = std::make_shared<ob::RealVectorStateSpace>(dimension_);
    space->setBounds(bounds);
    space->setName(name_);
    si_ = std::make_shared<ob::SpaceInformation>(space);
    si_->setStateValidityChecker([this](const ob::State *state) { return isValid(state); });
    si_->setMotionValidator(std::make_shared<RakeMotionValidator>(
        si_.get(), [this](const double *configs, std::size_t count) { return allValid(configs, count); },
        si_->getStateValidityChecker().get(),
        [this](const double *from, const double *to) { return sweepValid(from, to); }));
    setResolution(128.);
}

void ompl_parc::Robot::checkTimesteps(const std::string &name, const ob::RealVectorBounds &bounds, double resolution)
{
    if (!(resolution > 0.) || !std::isfinite(resolution))
        throw ompl::Exception("Robot", "resolution must be a positive, finite number");
    double extent2 = 0.;
    for (std::size_t d = 0; d < bounds.low.size(); ++d)
    {
        if (!std::isfinite(bounds.low[d]) || !std::isfinite(bounds.high[d]))
            throw ompl::Exception("Robot",
                                  "bounds of robot '" + name + "' are not finite in dimension " + std::to_string(d));
        extent2 += (bounds.high[d] - bounds.low[d]) * (bounds.high[d] - bounds.low[d]);
    }
    const double crossing = resolution * std::sqrt(extent2);
    if (!(crossing <= static_cast<double>(MultiRobotPlan::MAX_TIMESTEP)))
    {
        std::ostringstream out;
        out << "robot '" << name << "': resolution " << resolution << " times the diagonal of its bounds ("
            << std::sqrt(extent2) << ") is " << crossing << " timesteps, more than a plan may hold ("
            << MultiRobotPlan::MAX_TIMESTEP << "): lower the resolution or shrink the bounds";
        throw ompl::Exception("Robot", out.str());
    }
}

void ompl_parc::Robot::setResolution(double stepsPerUnit)
{
    checkTimesteps(name_, bounds_, stepsPerUnit);
    const double fraction = std::min(0.5, 1. / (stepsPerUnit * getStateSpace()->getMaximumExtent()));
    si_->setStateValidityCheckingResolution(fraction);
    si_->setup();
}

bool ompl_parc::Robot::withinBounds(const double *configs, std::size_t count) const
{
    for (std::size_t c = 0; c < count; ++c, configs += dimension_)
        for (unsigned int i = 0; i < dimension_; ++i)
            if (!(configs[i] >= bounds_.low[i] && configs[i] <= bounds_.high[i]))
                return false;
    return true;
}

ompl_parc::Robot::Validity ompl_parc::Robot::checkValidity(const double *q) const
{
    thread_local CollisionBody body;
    return checkValidity(q, body);
}

ompl_parc::Robot::Validity ompl_parc::Robot::checkValidity(const double *q, CollisionBody &body) const
{
    if (!withinBounds(q, 1))
        return Validity::OUT_OF_BOUNDS;
    computeBody(q, body);
    if (selfCollides(body))
        return Validity::SELF_COLLISION;
    if (!body.hasBoxes())
        body.updateBoxes();  // a body with group bounds has none yet: the environment test reads them
    if (environment_->collides(body))
        return Validity::ENVIRONMENT_COLLISION;
    return Validity::VALID;
}

bool ompl_parc::Robot::isValid(const ob::State *state) const
{
    return isValid(state->as<ob::RealVectorStateSpace::StateType>()->values);
}

bool ompl_parc::Robot::allValid(const double *configs, std::size_t count) const
{
    for (std::size_t k = 0; k < count; ++k)
        if (!isValid(configs + k * dimension_))
            return false;
    return true;
}

std::optional<bool> ompl_parc::Robot::sweepValid(const double *, const double *) const
{
    return std::nullopt;
}

bool ompl_parc::Robot::expandBoxOver(const double *, const double *, std::array<double, 3> &,
                                     std::array<double, 3> &) const
{
    return false;
}

bool ompl_parc::Robot::selfCollides(const CollisionBody &body) const
{
    // Most listed pairs are far apart: their capsules' bounding spheres (set by updateBound()) rule them out
    // with a few multiplications, so the exact segment distance runs only for the few that are close.
    const double *x = body.sphereX_.data(), *y = body.sphereY_.data(), *z = body.sphereZ_.data();
    const double *r = body.sphereRadius_.data();
    for (const auto &[i, j] : selfCollisionPairs_)
    {
        const double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j], rr = r[i] + r[j];
        if (dx * dx + dy * dy + dz * dz < rr * rr && capsulesCollide(body, i, body, j))
            return true;
    }
    return false;
}

double ompl_parc::Robot::distance(const double *a, const double *b) const
{
    ob::ScopedState<> sa(getStateSpace()), sb(getStateSpace());
    configToState(a, sa.get());
    configToState(b, sb.get());
    return getStateSpace()->distance(sa.get(), sb.get());
}

void ompl_parc::Robot::stateToConfig(const ob::State *state, double *q) const
{
    const double *values = state->as<ob::RealVectorStateSpace::StateType>()->values;
    std::copy(values, values + dimension_, q);
}

void ompl_parc::Robot::configToState(const double *q, ob::State *state) const
{
    std::copy(q, q + dimension_, state->as<ob::RealVectorStateSpace::StateType>()->values);
}

void ompl_parc::Robot::setMotionLimits(MotionLimits limits)
{
    const std::string problem = limits.check(dimension_);
    if (!problem.empty())
        throw ompl::Exception("robot '" + name_ + "': motion limits: " + problem);
    motionLimits_ = std::move(limits);
}

ompl_parc::MotionLimits ompl_parc::Robot::defaultMotionLimits() const
{
    return MotionLimits::perCoordinate(std::vector<double>(dimension_, 1.), std::vector<double>(dimension_, 3.));
}

std::vector<std::string> ompl_parc::Robot::getCoordinateNames() const
{
    std::vector<std::string> names;
    for (unsigned int k = 0; k < dimension_; ++k)
        names.push_back("q" + std::to_string(k));
    return names;
}

std::string ompl_parc::Robot::toString(Validity validity)
{
    switch (validity)
    {
        case Validity::VALID:
            return "valid";
        case Validity::OUT_OF_BOUNDS:
            return "out of bounds";
        case Validity::SELF_COLLISION:
            return "in self-collision";
        case Validity::ENVIRONMENT_COLLISION:
            return "in collision with the environment";
    }
    return "unknown";
}
