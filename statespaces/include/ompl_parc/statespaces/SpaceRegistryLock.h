#ifndef OMPL_PARC_STATESPACES_SPACE_REGISTRY_LOCK_
#define OMPL_PARC_STATESPACES_SPACE_REGISTRY_LOCK_

#include <memory>
#include <utility>

namespace ompl_parc
{
    /** \brief Held while one of our state spaces is built or destroyed: one thread at a time, and a waiting thread
        spins (yielding its core) instead of sleeping.

        OMPL 1.5 records every StateSpace in one process-wide list under a std::mutex, in the space's constructor
        and destructor (removing an entry scans the list). P-ARC's workers build and drop small spaces for every
        robot they plan alone and every repair, thousands per Mobile Cross 256 solve, and two workers meeting on
        that mutex put one of them to sleep on a futex: about 70 times per solve (perf sched), each time a worker
        off its core for up to milliseconds on a virtual machine. Spaces made by makeStateSpace() are built and
        destroyed under this lock, so our own threads never contend for OMPL's mutex. One thread may nest it (a
        composite space destroys its robot spaces under its own lock). */
    class SpaceRegistryLock
    {
      public:
        SpaceRegistryLock();
        ~SpaceRegistryLock();
        SpaceRegistryLock(const SpaceRegistryLock &) = delete;
        SpaceRegistryLock &operator=(const SpaceRegistryLock &) = delete;
    };

    /** \brief A new Space(\e args...), built under a SpaceRegistryLock and destroyed under one when its last owner
        lets go. */
    template <typename Space, typename... Args>
    std::shared_ptr<Space> makeStateSpace(Args &&...args)
    {
        const SpaceRegistryLock lock;
        return std::shared_ptr<Space>(new Space(std::forward<Args>(args)...),
                                      [](Space *space)
                                      {
                                          const SpaceRegistryLock destroying;
                                          delete space;
                                      });
    }
}  // namespace ompl_parc

#endif
