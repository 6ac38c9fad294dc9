#include "ompl_parc/statespaces/SpaceTimeStateSpace.h"

#include <ompl/util/Exception.h>

#include <cmath>

namespace ob = ompl::base;

ompl_parc::SpaceTimeStateSpace::SpaceTimeStateSpace(const ob::StateSpacePtr &spaceComponent, double vMax,
                                                    double timeWeight)
    : vMax_(vMax)
{
    if (!(timeWeight >= 0. && timeWeight <= 1.))
        throw ompl::Exception("SpaceTimeStateSpace", "the time weight must be in [0, 1]");
    if (!(vMax > 0.))
        throw ompl::Exception("SpaceTimeStateSpace", "vMax must be positive");
    setName("SpaceTime" + spaceComponent->getName());
    addSubspace(spaceComponent, 1. - timeWeight);
    addSubspace(std::make_shared<ob::TimeStateSpace>(), timeWeight);
    lock();
}

double ompl_parc::SpaceTimeStateSpace::distance(const ob::State *state1, const ob::State *state2) const
{
    const double deltaSpace = distanceSpace(state1, state2);
    const double deltaTime = distanceTime(state1, state2);
    if (deltaSpace / vMax_ > deltaTime + eps_)
        return std::numeric_limits<double>::infinity();
    return weights_[0] * deltaSpace + weights_[1] * deltaTime;
}

double ompl_parc::SpaceTimeStateSpace::timeToCoverDistance(const ob::State *state1, const ob::State *state2) const
{
    return distanceSpace(state1, state2) / vMax_;
}

double ompl_parc::SpaceTimeStateSpace::distanceSpace(const ob::State *state1, const ob::State *state2) const
{
    return components_[0]->distance(state1->as<ob::CompoundState>()->components[0],
                                    state2->as<ob::CompoundState>()->components[0]);
}

double ompl_parc::SpaceTimeStateSpace::distanceTime(const ob::State *state1, const ob::State *state2) const
{
    return std::fabs(getStateTime(state1) - getStateTime(state2));
}

double ompl_parc::SpaceTimeStateSpace::getStateTime(const ob::State *state)
{
    return state->as<ob::CompoundState>()->as<ob::TimeStateSpace::StateType>(1)->position;
}

void ompl_parc::SpaceTimeStateSpace::setTimeBounds(double lb, double ub)
{
    getTimeComponent()->setBounds(lb, ub);
}

void ompl_parc::SpaceTimeStateSpace::setVMax(double vMax)
{
    if (!(vMax > 0.))
        throw ompl::Exception("SpaceTimeStateSpace", "vMax must be positive");
    vMax_ = vMax;
}

void ompl_parc::SpaceTimeStateSpace::updateEpsilon()
{
    const double extent = getTimeComponent()->isBounded() ? getTimeComponent()->getMaximumExtent()
                                                          : getSpaceComponent()->getMaximumExtent() / vMax_;
    eps_ = std::numeric_limits<float>::epsilon() * std::pow(10., std::ceil(std::log10(extent)));
}
