#include "ompl_parc/statespaces/CompositeStateSpace.h"

#include "ompl_parc/statespaces/SpaceRegistryLock.h"

#include <ompl/util/Exception.h>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cstddef>
#include <new>
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

    singleBlock_ = true;
    std::size_t values = 0;
    for (const auto &space : robotSpaces)
    {
        const auto *rv = dynamic_cast<const ob::RealVectorStateSpace *>(space.get());
        singleBlock_ = singleBlock_ && rv != nullptr;
        valueStart_.push_back(values);
        values += space->getDimension();
    }
    const auto align = [](std::size_t bytes)
    { return (bytes + alignof(std::max_align_t) - 1) / alignof(std::max_align_t) * alignof(std::max_align_t); };
    componentsOffset_ = align(sizeof(StateType));
    robotStatesOffset_ = componentsOffset_ + align(sizeof(ob::State *) * robotSpaces.size());
    valuesOffset_ = robotStatesOffset_ + align(sizeof(ob::RealVectorStateSpace::StateType) * robotSpaces.size());
    blockSize_ = valuesOffset_ + sizeof(double) * values;
}

ob::State *ompl_parc::CompositeStateSpace::allocState() const
{
    if (!singleBlock_)
        return ob::CompoundStateSpace::allocState();
    char *block = static_cast<char *>(::operator new(blockSize_));
    auto *state = new (block) StateType();
    state->components = reinterpret_cast<ob::State **>(block + componentsOffset_);
    auto *robots = reinterpret_cast<ob::RealVectorStateSpace::StateType *>(block + robotStatesOffset_);
    auto *values = reinterpret_cast<double *>(block + valuesOffset_);
    for (unsigned int i = 0; i < componentCount_; ++i)
    {
        auto *robot = new (robots + i) ob::RealVectorStateSpace::StateType();
        robot->values = values + valueStart_[i];
        state->components[i] = robot;
    }
    return state;
}

void ompl_parc::CompositeStateSpace::freeState(ob::State *state) const
{
    if (!singleBlock_)
        return ob::CompoundStateSpace::freeState(state);
    ::operator delete(static_cast<void *>(state));
}

ompl_parc::CompositeStateSpacePtr ompl_parc::CompositeStateSpace::createSubspace(
    const std::vector<std::size_t> &robots) const
{
    checkRobots(robots);
    std::vector<ob::StateSpacePtr> spaces;
    spaces.reserve(robots.size());
    for (std::size_t r : robots)
        spaces.push_back(getRobotSpace(r));
    return makeStateSpace<CompositeStateSpace>(spaces);
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
