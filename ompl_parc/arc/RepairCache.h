#ifndef OMPL_PARC_REPAIR_CACHE_
#define OMPL_PARC_REPAIR_CACHE_

#include "ompl_parc/arc/Conflict.h"

#include <map>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief Remembers the time intervals of applied repairs per robot pair, to grow the robot set of a new
        conflict (ARC's robot-set expansion).

        Robots that had to be coordinated over some interval are likely to need it again there: a new
        conflict {i, j, t} takes in, transitively, every robot with a cached repair overlapping
        [t - w, t + w] together with a robot already in the set. */
    class RepairCache
    {
      public:
        /** \brief Record a repair of \e team (any order) over timesteps [from, to]. */
        void add(const std::vector<std::size_t> &team, std::size_t from, std::size_t to);

        /** \brief The robot set of \e conflict: its two robots closed under cached repairs overlapping
            [t - halfWidth, t + halfWidth]; sorted. */
        std::vector<std::size_t> expand(const Conflict &conflict, std::size_t halfWidth) const;

        void clear() { intervals_.clear(); }

      private:
        std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, std::size_t>>> intervals_;
    };
}  // namespace ompl_parc

#endif
