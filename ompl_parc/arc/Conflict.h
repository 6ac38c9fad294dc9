#ifndef OMPL_PARC_CONFLICT_
#define OMPL_PARC_CONFLICT_

#include <cstddef>
#include <tuple>

namespace ompl_parc
{
    /** \brief Robots \e first < \e second collide at timestep \e timestep of the current plan. Conflicts
        order by (timestep, first, second): the paper's "earliest conflict", ties broken by robot index. */
    struct Conflict
    {
        std::size_t first{0}, second{0}, timestep{0};

        bool operator<(const Conflict &other) const
        {
            return std::tie(timestep, first, second) < std::tie(other.timestep, other.first, other.second);
        }
        bool operator==(const Conflict &other) const
        {
            return first == other.first && second == other.second && timestep == other.timestep;
        }
    };
}  // namespace ompl_parc

#endif
