#ifndef OMPL_PARC_STATESPACES_SPACE_TIME_
#define OMPL_PARC_STATESPACES_SPACE_TIME_

/** \file
    \brief The one place that picks the space-time state space and ST-RRT*: OMPL's own from OMPL 1.6 on,
    ours (same API and behaviour) before. Code that only needs the standard API includes this header and
    uses ompl_parc::spacetime::SpaceTimeStateSpace and ompl_parc::spacetime::STRRTstar. PP-ST-RRT needs a
    minimum goal time, which OMPL's planner lacks, so it always uses ompl_parc::STRRTstar. */

#include <ompl/config.h>

#if OMPL_VERSION_VALUE >= 1006000
#include <ompl/base/spaces/SpaceTimeStateSpace.h>
#include <ompl/geometric/planners/rrt/STRRTstar.h>
#else
#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/statespaces/SpaceTimeStateSpace.h"
#endif

namespace ompl_parc::spacetime
{
#if OMPL_VERSION_VALUE >= 1006000
    using SpaceTimeStateSpace = ompl::base::SpaceTimeStateSpace;
    using STRRTstar = ompl::geometric::STRRTstar;
    /** \brief True when OMPL's own space-time classes are used. */
    constexpr bool USES_OMPL_SPACE_TIME = true;
#else
    using SpaceTimeStateSpace = ompl_parc::SpaceTimeStateSpace;
    using STRRTstar = ompl_parc::STRRTstar;
    constexpr bool USES_OMPL_SPACE_TIME = false;
#endif
}  // namespace ompl_parc::spacetime

#endif
