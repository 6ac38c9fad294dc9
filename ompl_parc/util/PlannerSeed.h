#ifndef OMPL_PARC_UTIL_PLANNER_SEED_
#define OMPL_PARC_UTIL_PLANNER_SEED_

#include <cstdint>

namespace ompl_parc
{
    /** \brief The seed a planner runs with: \e seed itself, or for 0 (our planners' "draw one" value of the
        \e seed parameter) a seed in [1, INT_MAX] drawn from OMPL's global random sequence, so that
        ompl::RNG::setSeed() still makes a whole program reproducible. */
    std::uint_fast32_t seedOrDraw(unsigned int seed);
}  // namespace ompl_parc

#endif
