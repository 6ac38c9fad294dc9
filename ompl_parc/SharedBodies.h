#ifndef OMPL_PARC_SHARED_BODIES_
#define OMPL_PARC_SHARED_BODIES_

#include "ompl_parc/CollisionBody.h"
#include "ompl_parc/MultiRobotPlan.h"
#include "ompl_parc/MultiRobotSpaceInformation.h"

#include <atomic>
#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief The robots' bodies over one round of P-ARC's distributed conflict detection (timesteps [from,
        to)), computed once and shared by the workers.

        Robot pairs are dealt round-robin, so every worker scans pairs of (nearly) every robot: without sharing,
        each would run the same forward kinematics for the same robot and timestep, and for arms that is the
        bulk of detection. Here the first worker that needs a body claims its slot, computes it and publishes
        it; the others read it. A worker that finds a slot being computed computes a private copy instead of
        waiting, so no worker ever blocks on another (important when W exceeds the cores). Slots are claimed
        lazily: a body no pair needs (pruned by the broad phase, or past a pair's conflict) is never computed. */
    class SharedBodies
    {
      public:
        explicit SharedBodies(const MultiRobotSpaceInformation &si);

        /** \brief Start a round over timesteps [from, to) of \e plan: no body is computed yet. \e plan must
            outlive the round and not change during it. Not during a scan. */
        void reset(const MultiRobotPlan &plan, std::size_t from, std::size_t to);

        /** \brief True if \e timestep is in the current round. */
        bool covers(std::size_t timestep) const { return timestep >= from_ && timestep < to_; }

        /** \brief Robot \e robot's body at \e timestep (covered by the round): the shared one, or, while another
            thread is still computing that, a copy computed into \e scratch. Thread safe. */
        const CollisionBody &get(std::size_t robot, std::size_t timestep, CollisionBody &scratch);

      private:
        enum State : unsigned char
        {
            EMPTY,
            COMPUTING,
            READY
        };

        const MultiRobotSpaceInformation &si_;
        const MultiRobotPlan *plan_{nullptr};
        std::size_t from_{0}, to_{0};
        /** \brief Slot (robot, timestep - from) at index robot * (to - from) + timestep - from. */
        std::vector<CollisionBody> bodies_;
        std::unique_ptr<std::atomic<unsigned char>[]> states_;
        std::size_t capacity_{0};
    };
}  // namespace ompl_parc

#endif
