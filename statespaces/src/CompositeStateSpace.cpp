#include "ompl_parc/statespaces/CompositeStateSpace.h"

#include "ompl_parc/statespaces/HugePageMemory.h"
#include "ompl_parc/statespaces/SpaceRegistryLock.h"

#include <ompl/util/Exception.h>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <string>
#include <typeinfo>

namespace ob = ompl::base;

namespace
{
    std::size_t align(std::size_t bytes)
    {
        return (bytes + alignof(std::max_align_t) - 1) / alignof(std::max_align_t) * alignof(std::max_align_t);
    }

    /** \brief The allocation that the states of one allocStates() call share (HugePageMemory: one path's states
        are written all over as soon as they are placed). It counts the states not yet freed and goes with the
        last. */
    class SharedStates
    {
      public:
        static SharedStates *create(std::size_t bytes, std::size_t states)
        {
            return new (ompl_parc::HugePageMemory::allocate(bytes)) SharedStates(bytes, states);
        }

        /** \brief One of its states was freed: the last one frees the allocation. */
        void release()
        {
            if (live_.fetch_sub(1, std::memory_order_acq_rel) != 1)
                return;
            const std::size_t bytes = bytes_;
            this->~SharedStates();
            ompl_parc::HugePageMemory::deallocate(static_cast<void *>(this), bytes);
        }

      private:
        SharedStates(std::size_t bytes, std::size_t states) : live_(states), bytes_(bytes) {}

        std::atomic<std::size_t> live_;
        std::size_t bytes_;
    };
}  // namespace

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
    plainVectors_ = true;
    for (const auto &space : robotSpaces)
    {
        const auto *rv = dynamic_cast<const ob::RealVectorStateSpace *>(space.get());
        singleBlock_ = singleBlock_ && rv != nullptr;
        const ob::StateSpace &robot = *space;
        plainVectors_ = plainVectors_ && typeid(robot) == typeid(ob::RealVectorStateSpace);
        valueStart_.push_back(values);
        values += space->getDimension();
        dimensions_.push_back(space->getDimension());
    }
    stateOffset_ = align(sizeof(SharedStates *));
    componentsOffset_ = stateOffset_ + align(sizeof(StateType));
    robotStatesOffset_ = componentsOffset_ + align(sizeof(ob::State *) * robotSpaces.size());
    valuesOffset_ = robotStatesOffset_ + align(sizeof(ob::RealVectorStateSpace::StateType) * robotSpaces.size());
    blockSize_ = align(valuesOffset_ + sizeof(double) * values);
}

ob::State *ompl_parc::CompositeStateSpace::placeState(char *block, void *shared) const
{
    new (block) void *(shared);
    auto *state = new (block + stateOffset_) StateType();
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

ob::State *ompl_parc::CompositeStateSpace::allocState() const
{
    if (!singleBlock_)
        return ob::CompoundStateSpace::allocState();
    return placeState(static_cast<char *>(::operator new(blockSize_)), nullptr);
}

void ompl_parc::CompositeStateSpace::allocStates(std::size_t count, ob::State **out) const
{
    if (!singleBlock_ || count < 2)
    {
        for (std::size_t k = 0; k < count; ++k)
            out[k] = allocState();
        return;
    }
    const std::size_t header = align(sizeof(SharedStates));
    if (count > (std::numeric_limits<std::size_t>::max() - header) / blockSize_)
        throw std::bad_alloc();
    SharedStates *shared = SharedStates::create(header + count * blockSize_, count);
    char *first = reinterpret_cast<char *>(shared) + header;
    for (std::size_t k = 0; k < count; ++k)
        out[k] = placeState(first + k * blockSize_, shared);
}

void ompl_parc::CompositeStateSpace::freeState(ob::State *state) const
{
    if (state == nullptr)  // e.g. a path whose allocation threw before its states were in place
        return;
    if (!singleBlock_)
        return ob::CompoundStateSpace::freeState(state);
    char *block = reinterpret_cast<char *>(state) - stateOffset_;
    if (auto *shared = static_cast<SharedStates *>(*reinterpret_cast<void **>(block)))
        shared->release();
    else
        ::operator delete(static_cast<void *>(block));
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
    if (!plainVectors_)
    {
        double d = 0.;
        for (unsigned int i = 0; i < componentCount_; ++i)
            d = std::max(d, components_[i]->distance(s1->components[i], s2->components[i]));
        return d;
    }
    // RealVectorStateSpace::distance's sums; the largest root is the root of the largest sum (sqrt is monotone).
    double largest = 0.;
    for (unsigned int i = 0; i < componentCount_; ++i)
    {
        const double *a = s1->as<ob::RealVectorStateSpace::StateType>(i)->values;
        const double *b = s2->as<ob::RealVectorStateSpace::StateType>(i)->values;
        double sum = 0.;
        for (unsigned int k = 0; k < dimensions_[i]; ++k)
        {
            const double diff = a[k] - b[k];
            sum += diff * diff;
        }
        largest = std::max(largest, sum);
    }
    return std::sqrt(largest);
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
