#include "ompl_parc/statespaces/CompositeStateSpace.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <string>

namespace ob = ompl::base;

ompl_parc::CompositeStateSpace::CompositeStateSpace(const std::vector<ob::StateSpacePtr> &robotSpaces)
{
    if (robotSpaces.empty())
        throw ompl::Exception("CompositeStateSpace", "a team needs at least one robot");
    setName("Composite" + getName());
    for (const auto &space : robotSpaces)
    {
        if (!space)
            throw ompl::Exception("CompositeStateSpace", "null robot space");
        addSubspace(space, 1.0);
    }
    lock();
}

ompl_parc::CompositeStateSpacePtr ompl_parc::CompositeStateSpace::createSubspace(
    const std::vector<std::size_t> &robots) const
{
    checkRobots(robots);
    std::vector<ob::StateSpacePtr> spaces;
    spaces.reserve(robots.size());
    for (std::size_t r : robots)
        spaces.push_back(getRobotSpace(r));
    return std::make_shared<CompositeStateSpace>(spaces);
}

void ompl_parc::CompositeStateSpace::splitState(const ob::State *state, const std::vector<std::size_t> &robots,
                                                ob::State *sub) const
{
    checkRobots(robots);
    const auto *from = state->as<StateType>();
    auto *to = sub->as<StateType>();
    for (std::size_t k = 0; k < robots.size(); ++k)
        getRobotSpace(robots[k])->copyState(to->components[k], from->components[robots[k]]);
}

void ompl_parc::CompositeStateSpace::joinState(ob::State *state, const std::vector<std::size_t> &robots,
                                               const ob::State *sub) const
{
    checkRobots(robots);
    auto *to = state->as<StateType>();
    const auto *from = sub->as<StateType>();
    for (std::size_t k = 0; k < robots.size(); ++k)
        getRobotSpace(robots[k])->copyState(to->components[robots[k]], from->components[k]);
}

double ompl_parc::CompositeStateSpace::distance(const ob::State *state1, const ob::State *state2) const
{
    const auto *s1 = state1->as<StateType>();
    const auto *s2 = state2->as<StateType>();
    double d = 0.;
    for (unsigned int i = 0; i < componentCount_; ++i)
        d = std::max(d, components_[i]->distance(s1->components[i], s2->components[i]));
    return d;
}

double ompl_parc::CompositeStateSpace::getMaximumExtent() const
{
    double e = 0.;
    for (unsigned int i = 0; i < componentCount_; ++i)
        e = std::max(e, components_[i]->getMaximumExtent());
    return e;
}

void ompl_parc::CompositeStateSpace::checkRobots(const std::vector<std::size_t> &robots) const
{
    for (std::size_t r : robots)
        if (r >= getRobotCount())
            throw ompl::Exception(
                "CompositeStateSpace",
                "robot index " + std::to_string(r) + " out of range for a team of " + std::to_string(getRobotCount()));
}
