#ifndef OMPL_PARC_BOUNDING_BOX_
#define OMPL_PARC_BOUNDING_BOX_

#include "ompl_parc/collision/CollisionBody.h"

#include <array>
#include <cmath>

namespace ompl_parc
{
    /** \brief An axis-aligned box in double precision around bodies over some stretch of time: the broad phases of
        the planner's side (conflict detection's swept bounds, a repair's context, the blocking order). Empty as
        constructed (it overlaps no finite box until something is added). The independent validator keeps its own. */
    struct BoundingBox
    {
        std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

        /** \brief Grow to contain \e body. */
        void add(const CollisionBody &body) { body.expandBox(lo, hi); }

        /** \brief Grow to contain \e other. */
        void add(const BoundingBox &other)
        {
            for (int d = 0; d < 3; ++d)
            {
                lo[d] = std::fmin(lo[d], other.lo[d]);
                hi[d] = std::fmax(hi[d], other.hi[d]);
            }
        }

        /** \brief True unless the boxes are more than \e margin apart along some axis. A NaN in \e lo or \e hi
            counts as overlapping (add() does not produce one: the bodies' own box growth drops NaN). */
        bool overlaps(const BoundingBox &other, double margin = 0.) const
        {
            for (int d = 0; d < 3; ++d)
                if (lo[d] > other.hi[d] + margin || other.lo[d] > hi[d] + margin)
                    return false;
            return true;
        }
    };
}  // namespace ompl_parc

#endif
