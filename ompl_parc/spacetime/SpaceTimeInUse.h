#ifndef OMPL_PARC_SPACETIME_SPACE_TIME_IN_USE_
#define OMPL_PARC_SPACETIME_SPACE_TIME_IN_USE_

/** \file
    \brief The space-time state space all of ompl_parc plans in: OMPL's own from OMPL 1.6 on, ours (the same
    API and behaviour, see ompl_parc/statespaces/SpaceTimeStateSpace.h) before. ompl_parc/planners/SpaceTime.h adds the
    matching ST-RRT*. */

#include "ompl_parc/util/OmplCompat.h"

#if OMPL_PARC_OMPL_HAS_SPACE_TIME
#include <ompl/base/spaces/SpaceTimeStateSpace.h>
#else
#include "ompl_parc/statespaces/SpaceTimeStateSpace.h"
#endif

namespace ompl_parc::spacetime
{
#if OMPL_PARC_OMPL_HAS_SPACE_TIME
    using SpaceTimeStateSpace = ompl::base::SpaceTimeStateSpace;
#else
    using SpaceTimeStateSpace = ompl_parc::SpaceTimeStateSpace;
#endif
    /** \brief True when OMPL's own space-time classes are used. */
    constexpr bool USES_OMPL_SPACE_TIME = OMPL_PARC_OMPL_HAS_SPACE_TIME;
}  // namespace ompl_parc::spacetime

#endif
