#ifndef OMPL_PARC_PLANNERS_ARC_
#define OMPL_PARC_PLANNERS_ARC_

#include "ompl_parc/planners/ArcPlannerBase.h"

namespace ompl_parc
{
    /** \brief Adaptive Robot Coordination (Solis et al.), sequential: plan each robot alone, then repeatedly
        repair the earliest robot-robot conflict by solving a locally coupled subproblem around it (window
        and robot set grown until a solver of the hierarchy succeeds, up to the global problem).

        The RepairLoop with one worker, which runs every stage on the calling thread. Works on a
        MultiRobotSpaceInformation (a clear ompl::Exception otherwise) with a GoalState goal. This is the
        yardstick P-ARC's speedups are measured against. */
    class ARC : public ArcPlannerBase
    {
      public:
        explicit ARC(const ompl::base::SpaceInformationPtr &si);
    };
}  // namespace ompl_parc

#endif
