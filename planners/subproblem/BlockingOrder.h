#ifndef OMPL_PARC_BLOCKING_ORDER_
#define OMPL_PARC_BLOCKING_ORDER_

#include "ompl_parc/collision/BodyTrack.h"
#include "ompl_parc/collision/CollisionBody.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief A priority order for prioritised planning in which robots get out of each other's way, from each
        robot's path planned alone.

        Prioritised planning fails when a robot planned early parks on the only way of a robot planned later, or
        sweeps through the start of a later robot before that one can leave. Both can be seen before planning:
        robot a goes \e before robot b when a's start lies on b's path alone (a leaves first), and \e after b when
        a's goal lies on b's path alone (a parks once b has passed). The order is a topological order of these
        constraints; ties, and the cycles that dense teams make, go by a base order (the given or shuffled one). */
    class BlockingOrder
    {
      public:
        /** \brief Robot k's path alone as \e tracks[k] (its bodies per timestep; null: not known, no constraint)
            and its bodies at its start and goal. */
        BlockingOrder(std::vector<std::shared_ptr<const BodyTrack>> tracks, std::vector<CollisionBody> starts,
                      std::vector<CollisionBody> goals);

        /** \brief \e base (a permutation of the team's positions) reordered by the constraints. */
        std::vector<std::size_t> order(const std::vector<std::size_t> &base) const;

        /** \brief Whether robot \e a must go before robot \e b. */
        bool before(std::size_t a, std::size_t b) const { return before_[a * size_ + b] != 0; }

      private:
        /** \brief Whether \e body touches robot \e k's path alone at a timestep from \e first on. */
        bool onPath(const CollisionBody &body, std::size_t k, std::size_t first, CollisionBody &scratch) const;

        std::size_t size_;
        std::vector<std::shared_ptr<const BodyTrack>> tracks_;
        /** \brief before_[a * size_ + b]: robot a must go before robot b. */
        std::vector<char> before_;
    };
}  // namespace ompl_parc

#endif
