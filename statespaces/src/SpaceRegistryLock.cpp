#include "ompl_parc/statespaces/SpaceRegistryLock.h"

#include <atomic>
#include <thread>

namespace
{
    std::atomic_flag held = ATOMIC_FLAG_INIT;
    /** How many SpaceRegistryLocks this thread holds (nested ones take nothing more). */
    thread_local unsigned int depth = 0;
}  // namespace

ompl_parc::SpaceRegistryLock::SpaceRegistryLock()
{
    if (depth++ > 0)
        return;
    while (held.test_and_set(std::memory_order_acquire))
        std::this_thread::yield();
}

ompl_parc::SpaceRegistryLock::~SpaceRegistryLock()
{
    if (--depth == 0)
        held.clear(std::memory_order_release);
}
