#include "ompl_parc/SharedBodies.h"

ompl_parc::SharedBodies::SharedBodies(const MultiRobotSpaceInformation &si) : si_(si) {}

void ompl_parc::SharedBodies::reset(const MultiRobotPlan &plan, std::size_t from, std::size_t to)
{
    plan_ = &plan;
    from_ = from;
    to_ = std::max(from, to);
    const std::size_t slots = si_.getRobotCount() * (to_ - from_);
    if (slots > capacity_)  // bodies keep their arrays' memory across rounds; only growth allocates
    {
        states_ = std::make_unique<std::atomic<unsigned char>[]>(slots);
        capacity_ = slots;
    }
    if (bodies_.size() < slots)
        bodies_.resize(slots);
    for (std::size_t k = 0; k < slots; ++k)
        states_[k].store(EMPTY, std::memory_order_relaxed);  // published to the workers by the pool's fork
}

const ompl_parc::CollisionBody &ompl_parc::SharedBodies::get(std::size_t robot, std::size_t timestep,
                                                             CollisionBody &scratch)
{
    const std::size_t slot = robot * (to_ - from_) + (timestep - from_);
    std::atomic<unsigned char> &state = states_[slot];
    unsigned char seen = state.load(std::memory_order_acquire);
    if (seen == READY)
        return bodies_[slot];
    if (seen == EMPTY && state.compare_exchange_strong(seen, COMPUTING, std::memory_order_acq_rel))
    {
        si_.getRobot(robot)->computeBody(plan_->getConfig(robot, timestep), bodies_[slot]);
        state.store(READY, std::memory_order_release);
        return bodies_[slot];
    }
    if (seen == READY)  // finished between the load and the exchange
        return bodies_[slot];
    si_.getRobot(robot)->computeBody(plan_->getConfig(robot, timestep), scratch);
    return scratch;
}
