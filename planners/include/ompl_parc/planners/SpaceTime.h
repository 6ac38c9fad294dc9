#ifndef OMPL_PARC_PLANNERS_SPACE_TIME_
#define OMPL_PARC_PLANNERS_SPACE_TIME_

/** \file
    \brief The space-time state space and ST-RRT* in use: OMPL's own from OMPL 1.6 on, ours (same API and
    behaviour) before. Code that only needs the standard API includes this header and uses
    ompl_parc::spacetime::SpaceTimeStateSpace and ompl_parc::spacetime::STRRTstar. PP-ST-RRT needs a minimum
    goal time, which OMPL's planner lacks, so it always uses ompl_parc::STRRTstar (in the same space). */

#include "ompl_parc/spacetime/SpaceTimeInUse.h"

#if OMPL_PARC_OMPL_HAS_SPACE_TIME
#include <ompl/geometric/planners/rrt/STRRTstar.h>
#else
#include "ompl_parc/planners/STRRTstar.h"
#endif

namespace ompl_parc::spacetime
{
#if OMPL_PARC_OMPL_HAS_SPACE_TIME
    using STRRTstar = ompl::geometric::STRRTstar;
#else
    using STRRTstar = ompl_parc::STRRTstar;
#endif
}  // namespace ompl_parc::spacetime

#endif
