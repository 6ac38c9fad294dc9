#ifndef OMPL_PARC_BATCH_DETECTOR_
#define OMPL_PARC_BATCH_DETECTOR_

#include "ompl_parc/arc/ConflictBatch.h"
#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/arc/RepairCache.h"
#include "ompl_parc/parallel/WorkerPool.h"

#include <ompl/base/PlannerTerminationCondition.h>

namespace ompl_parc
{
    /** \brief P-ARC's distributed conflict detection (paper §III-B).

        The robot pairs are dealt round-robin to the pool's W workers. In rounds, every worker scans its
        pairs over the next H timesteps (the synchronisation horizon) for each pair's first conflict, skipping
        pairs the batch no longer needs; the coordinator then merges the candidates in temporal order, grows
        each into its robot set through the repair cache and offers it to the ConflictBatch, until the batch
        holds W conflicts or the plan ends. The frontiers of the shared ConflictDetector carry over between
        calls. With W = 1 the batch is exactly the sequential earliest conflict. */
    class BatchDetector
    {
      public:
        BatchDetector(ConflictDetector &detector, WorkerPool &pool, unsigned int horizon, bool optimistic);

        /** \brief The next batch of \e plan (empty: conflict-free, or \e ptc fired). \e window is the half-width
            used for robot-set expansion. Adds the projected W-core time of the call to \e projected and the
            number of accepted conflicts whose robot set grew to \e teamGrowths. */
        std::vector<BatchEntry> detect(const MultiRobotPlan &plan, const RepairCache &cache, std::size_t window,
                                       const ompl::base::PlannerTerminationCondition &ptc, double &projected,
                                       unsigned int &teamGrowths);

      private:
        ConflictDetector &detector_;
        WorkerPool &pool_;
        unsigned int horizon_;
        bool optimistic_;
        std::vector<std::vector<std::size_t>> workerPairs_;
    };
}  // namespace ompl_parc

#endif
