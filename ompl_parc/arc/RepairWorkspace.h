#ifndef OMPL_PARC_ARC_REPAIR_WORKSPACE_
#define OMPL_PARC_ARC_REPAIR_WORKSPACE_

#include "ompl_parc/arc/BatchDetector.h"
#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/parallel/WorkerPool.h"

#include <memory>
#include <string>

namespace ompl_parc
{
    /** \brief What a RepairLoop works with that depends on the team and the worker count, not on the query: the
        worker pool, the conflict detector with its per-pair arrays, and the batch detector with its list of pairs
        in play.

        Why apart from the loop: the planners make it in ompl::base::Planner::setup(), where OMPL planners allocate,
        so that solve() neither starts threads nor faults in fresh pages: at hundreds of robots that serial work (the
        per-pair arrays are megabytes of fresh pages) is a visible share of a P-ARC solve. A later query (after
        clear()) reuses the workspace: a new RepairLoop resets it. One RepairLoop at a time may use it. */
    class RepairWorkspace
    {
      public:
        /** \brief A workspace for the team of \e si (kept by reference: it must outlive the workspace) with
            \e workers workers; until configure(), detection scans the whole plan in one round for one conflict
            per worker. Throws ompl::Exception for 0 workers. */
        RepairWorkspace(const MultiRobotSpaceInformation &si, unsigned int workers);

        /** \brief From now on: \e workers workers (a different count makes a new pool, and a new batch detector
            with every pair in play), sync horizon \e horizon, batches of \e batchPerWorker conflicts per worker
            (one in all for a single worker: ARC's earliest conflict) and \e optimistic batch independence
            (BatchDetector). Throws ompl::Exception for 0 workers, horizon or conflicts per worker. */
        void configure(unsigned int workers, std::size_t horizon, unsigned int batchPerWorker, bool optimistic);

        /** \brief Throws ompl::Exception, reported by \e who, unless a batch may hold \e batchPerWorker conflicts per
            worker (at least one): the one check of the value, made by configure() and, as a parameter is set, by
            P-ARC's \e batch_per_worker. */
        static void checkBatchPerWorker(unsigned int batchPerWorker, const std::string &who = "RepairWorkspace");

        /** \brief Forget the last query: every pair's frontier back to timestep 0 and every pair in play. */
        void reset();

        WorkerPool &getPool() { return *pool_; }
        ConflictDetector &getDetector() { return detector_; }
        BatchDetector &getBatchDetector() { return *batchDetector_; }

      private:
        /** \brief The batch capacity for \e workers workers with \e batchPerWorker conflicts each. */
        static std::size_t capacityFor(unsigned int workers, unsigned int batchPerWorker);

        ConflictDetector detector_;
        std::unique_ptr<WorkerPool> pool_;
        std::unique_ptr<BatchDetector> batchDetector_;
    };
}  // namespace ompl_parc

#endif
