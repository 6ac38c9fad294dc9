#ifndef OMPL_PARC_COLLIDING_PAIR_SWEEP_
#define OMPL_PARC_COLLIDING_PAIR_SWEEP_

#include "ompl_parc/collision/BoundingBox.h"
#include "ompl_parc/collision/CollisionBody.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief The colliding pairs among many bodies (one per robot of a team at one moment), found by sweeping
        their boxes along the axis where the boxes spread furthest: only pairs whose boxes overlap get the exact
        test. Testing every pair costs n (n - 1) / 2 exact tests per team state (32 640 at 256 robots, 75-115 us
        here), and OMPL checks a solution path state by state (`PathGeometric::check()` in its benchmark,
        a coupled planner's motions); apart from a crowd few boxes overlap, so the sweep tests few pairs after an
        O(n log n) sort. The answers are those of testing every pair: boxes are compared with a margin relative to
        the coordinates, so rounding in a box never hides a touching pair.

        The buffers are kept between calls (no allocation per state once warm): one object per thread. */
    class CollidingPairSweep
    {
      public:
        /** \brief The first pair (i, j), i < j, in (i, j) order whose bodies collide, if any. */
        std::optional<std::pair<std::size_t, std::size_t>> first(const std::vector<CollisionBody> &bodies);

        /** \brief Whether two of \e bodies collide (the sweep stops at the first pair found). */
        bool any(const std::vector<CollisionBody> &bodies);

      private:
        /** \brief Boxes of \e bodies, the margin, and the bodies' extents along the sweep axis in order. */
        void sort(const std::vector<CollisionBody> &bodies);

        /** \brief Calls \e visit(i, j) with i < j for every pair whose boxes overlap, in sweep order, until it
            returns true; true if one did. */
        template <typename Visit>
        bool sweep(Visit &&visit) const;

        /** \brief A body's extent along the sweep axis, kept beside its index so that the sweep reads one array. */
        struct Extent
        {
            double lo, hi;
            std::size_t body;
        };

        std::vector<BoundingBox> boxes_;
        std::vector<Extent> order_;  // by lo
        double margin_{0.};
    };
}  // namespace ompl_parc

#endif
