#ifndef OMPL_PARC_PLANNERS_PARC_
#define OMPL_PARC_PLANNERS_PARC_

#include "ompl_parc/arc/BatchDetector.h"
#include "ompl_parc/parallel/WorkerPool.h"
#include "ompl_parc/planners/ArcPlannerBase.h"

#include <memory>

namespace ompl_parc
{
    /** \brief Counters of P-ARC's parallel stages, and its projected W-core times.

        A stage's projected time is, summed over its fork-join rounds, the largest CPU time any worker
        spent in the round plus the coordinator's serial work: the wall time the stage would take with one
        core per worker. On a machine with fewer cores than workers it is a projection, and labelled so. */
    struct ParcStatistics
    {
        unsigned int batches{0}, firstBatchSize{0}, batchedConflicts{0}, repairAttempts{0}, cancelledAttempts{0},
            initialAttempts{0}, cancelledInitialAttempts{0};
        double projectedInitial{0.}, projectedDetection{0.}, projectedResolution{0.};
    };

    /** \brief Parallel ARC (Motes, Morales, Amato): ARC's three stages spread over W worker threads.

        Initial paths are handed out to workers as they free up; conflict detection splits the robot pairs
        round-robin over the workers, each scanning the next H timesteps (the synchronisation horizon)
        before the coordinator merges the candidates in temporal order into a batch of robot-disjoint
        (optimistically) independent conflicts (ConflictBatch), up to W of them; the batch is repaired
        concurrently with ARC's conflict resolution, idle workers running extra randomised attempts of
        unsolved tasks (local OR) whose first success cancels the rest. With W = 1 it computes exactly what
        ARC computes for the same seed. */
    class PARC : public ArcPlannerBase
    {
      public:
        explicit PARC(const ompl::base::SpaceInformationPtr &si);
        ~PARC() override;

        void clear() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        const ParcStatistics &getParallelStatistics() const { return parallel_; }

        /** \name Declared parameters
            @{ */
        void setWorkers(unsigned int workers);
        unsigned int getWorkers() const { return workers_; }
        void setHorizon(unsigned int horizon);
        unsigned int getHorizon() const { return horizon_; }
        void setOptimistic(bool optimistic)
        {
            optimistic_ = optimistic;
            batchDetector_.reset();
        }
        bool getOptimistic() const { return optimistic_; }
        void setLocalOr(bool localOr) { localOr_ = localOr; }
        bool getLocalOr() const { return localOr_; }
        /** @} */

      protected:
        bool computeInitialPlans(const ompl::base::PlannerTerminationCondition &ptc) override;
        bool resolveConflicts(const ompl::base::PlannerTerminationCondition &ptc) override;
        /** \brief The composite solution path, its states allocated by all workers (a large share of the
            work for long plans of big teams). */
        ompl::geometric::PathGeometricPtr buildSolutionPath() const override;

      private:
        /** \brief Repair \e batch concurrently and splice the patches in batch order; false if \e ptc fired. */
        bool repairBatch(const std::vector<BatchEntry> &batch, const ompl::base::PlannerTerminationCondition &ptc);
        WorkerPool &pool() const;

        unsigned int workers_{1}, horizon_{400};
        bool optimistic_{true}, localOr_{true};
        mutable std::unique_ptr<WorkerPool> pool_;
        std::unique_ptr<BatchDetector> batchDetector_;
        ParcStatistics parallel_;
    };
}  // namespace ompl_parc

#endif
