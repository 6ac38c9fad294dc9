#include "ompl_parc/util/PlannerSeed.h"

#include <ompl/util/RandomNumbers.h>

#include <limits>

std::uint_fast32_t ompl_parc::seedOrDraw(unsigned int seed)
{
    return seed != 0 ? seed : ompl::RNG().uniformInt(1, std::numeric_limits<int>::max());
}
