#ifndef OMPL_PARC_PLANNERS_PARC_
#define OMPL_PARC_PLANNERS_PARC_

#include "ompl_parc/planners/ArcPlannerBase.h"

namespace ompl_parc
{
    /** \brief Parallel ARC (Motes, Morales, Amato): ARC's three stages spread over W worker threads.

        Initial paths are handed out to workers as they free up; in conflict detection the workers claim chunks
        of the robot pairs as they free up (the paper deals them round-robin), each scanning the next H timesteps
        (the synchronisation horizon)
        before the coordinator merges the candidates in temporal order into a batch of robot-disjoint
        (optimistically) independent conflicts (ConflictBatch), up to W of them in the paper, W x batch_per_worker
        here, more while the batches' repairs do not meet (grow_batches); the batch is repaired
        concurrently with ARC's conflict resolution, idle workers running extra randomised attempts of
        unsolved tasks (local OR) whose first success cancels the rest. The RepairLoop does all of it; this
        shell declares its parameters. With W = 1 it computes exactly what ARC computes for the same seed.

        The parallel parameters, one entry each of ompl_parc/arc/ParcKnobs.def (ARC's are ArcSettings'):
        \verbinclude ompl_parc/arc/ParcKnobs.def */
    class PARC : public ArcPlannerBase
    {
      public:
        explicit PARC(const ompl::base::SpaceInformationPtr &si);

        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief P-ARC's counters and projected W-core times (zero before the first solve()). */
        const ParcStatistics &getParallelStatistics() const;

        /** \name Declared parameters: W, H, conflicts per worker in a batch, growing batches, optimistic or strict
            batches, local OR
            @{ */
#define OMPL_PARC_PARALLEL_KNOB(Name, ...)                                                                             \
    using ArcPlannerBase::set##Name;                                                                                   \
    using ArcPlannerBase::get##Name;
#include "ompl_parc/arc/ParcKnobs.def"
        /** @} */
    };
}  // namespace ompl_parc

#endif
