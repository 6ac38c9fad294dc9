#ifndef OMPL_PARC_BATCH_DETECTOR_
#define OMPL_PARC_BATCH_DETECTOR_

#include "ompl_parc/arc/ConflictBatch.h"
#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/arc/RepairCache.h"
#include "ompl_parc/parallel/WorkerPool.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <limits>
#include <string>

namespace ompl_parc
{
    /** \brief One detection call's batch, and the call's projected W-core seconds (see ParcStatistics). */
    struct DetectedBatch
    {
        std::vector<BatchEntry> entries;
        double projectedSeconds{0.};
    };

    /** \brief P-ARC's distributed conflict detection (paper §III-B).

        The robot pairs are shared by the pool's W workers: the paper deals them round-robin; here each round's
        pairs are cut into chunks that the workers claim as they finish the previous one (about 4 per worker,
        at least 256 pairs each, at most an even share: W chunks for small teams; one for W = 1), so a worker with slow
       pairs or on a slower core is not waited for. In rounds, the workers scan their pairs over the next H timesteps
       (the synchronisation horizon) for each pair's first conflict, skipping pairs the batch no longer needs; the
       coordinator then merges the candidates in temporal order, grows each into its robot set through the repair cache
       and offers it to the ConflictBatch, until the batch is full (W conflicts in the paper,
       RepairLoopOptions::batchPerWorker x W here) or the plan ends. Workers scan only the pairs still in play (not
       known conflict-free to their end since their robots last changed). A round starts at the first timestep after the
       previous round's window that some pair still needs checked, so stretches known to be clear (disc pairs are
       scanned ahead from the plan's pieces) cost no rounds. The frontiers of the shared ConflictDetector carry over
       between calls. With a capacity of one (W = 1) the batch is exactly the sequential earliest conflict (ARC's
       detection: its scans stop at the first timestep with a conflict), and robot-set growth happens here for ARC and
       P-ARC alike. */
    class BatchDetector
    {
      public:
        /** \brief \e horizon H (timesteps scanned per round; UNBOUNDED: the whole plan in one round, as ARC
            does); a batch is full at \e capacity conflicts (the paper's W; 1: the earliest conflict alone, and
            scans stop at the first timestep with one). Throws ompl::Exception for a zero horizon or capacity. */
        BatchDetector(ConflictDetector &detector, WorkerPool &pool, std::size_t horizon, std::size_t capacity,
                      bool optimistic);

        /** \brief Use \e horizon, \e capacity and \e optimistic (as in the constructor) from the next detect() on;
            the pairs in play stay. Throws ompl::Exception for a zero horizon or capacity. */
        void configure(std::size_t horizon, std::size_t capacity, bool optimistic);
        /** \brief Throws ompl::Exception, reported by \e who, for a zero horizon: the one check of a sync horizon,
            made here and, as a parameter is set, by P-ARC's \e horizon. */
        static void checkHorizon(std::size_t horizon, const std::string &who = "BatchDetector");

        /** \brief A batch is full at \e capacity conflicts from the next detect() on (horizon and independence as
            configured). Throws ompl::Exception for 0. */
        void setCapacity(std::size_t capacity);
        std::size_t getCapacity() const { return capacity_; }

        /** \brief Every pair the detector tracks in play again (a new query; the detector is reset apart). */
        void reset();

        static constexpr std::size_t UNBOUNDED = std::numeric_limits<std::size_t>::max() / 2;

        /** \brief The next batch of \e plan (empty: conflict-free, or \e ptc fired), each conflict with its
            robot set grown through \e cache over the half-width \e window. The detector's new pairs (see
            ConflictDetector::discoverPairs) come into play first. */
        DetectedBatch detect(const MultiRobotPlan &plan, const RepairCache &cache, std::size_t window,
                             const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief Robot \e robot's path changed from timestep \e timestep on: ConflictDetector::invalidate, and its
            pairs are scanned again. Not during detect(). */
        void invalidate(std::size_t robot, std::size_t timestep);

      private:
        ConflictDetector &detector_;
        WorkerPool &pool_;
        std::size_t horizon_{0}, capacity_{0};
        bool optimistic_{false};
        /** \brief The pair count of one chunk of \e live pairs in play (see the class documentation). */
        std::size_t chunkSize(std::size_t live) const;

        /** \brief The detector's pairs not yet in isLive_ (new ones, or all after a reset) into the live list. */
        void addNewPairs();

        /** \brief The tracked pairs that are not settled: a pair known to be conflict-free to its end leaves the list
            at the end of a detect() call, and comes back when one of its robots is invalidated. A call costs
            O(pairs still in play), not O(tracked pairs): of Mobile Cross 1024's tracked pairs a few hundred have a
            conflict or a changed robot. */
        std::vector<std::size_t> live_;
        /** \brief Per tracked pair, 1 while it is in the live list. */
        std::vector<char> isLive_;
    };
}  // namespace ompl_parc

#endif
