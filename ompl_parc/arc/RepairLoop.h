#ifndef OMPL_PARC_ARC_REPAIR_LOOP_
#define OMPL_PARC_ARC_REPAIR_LOOP_

#include "ompl_parc/arc/ArcProgress.h"
#include "ompl_parc/arc/ArcSettings.h"
#include "ompl_parc/arc/ArcStatistics.h"
#include "ompl_parc/arc/BatchDetector.h"
#include "ompl_parc/arc/ConflictResolver.h"
#include "ompl_parc/arc/RepairCache.h"
#include "ompl_parc/arc/RepairWorkspace.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief How a RepairLoop runs: ARC's settings, the subproblem solvers in the order they are tried, and
        P-ARC's parallel knobs (the planners' parameters for them: ompl_parc/arc/ParcKnobs.def). ARC is one worker
        with an unbounded horizon. */
    struct RepairLoopOptions
    {
        ArcSettings settings;
        std::vector<SubproblemSolverPtr> hierarchy;
        /** \brief W worker threads (1: every stage on the calling thread). */
        unsigned int workers{1};
        /** \brief Sync horizon H of P-ARC's detection rounds; BatchDetector::UNBOUNDED scans the whole plan. */
        std::size_t horizon{BatchDetector::UNBOUNDED};
        /** \brief Conflicts a batch may hold per worker (the paper's batch holds W: 1; default 8). With more, a batch's
            repairs are handed out as workers free up, so one slow repair no longer idles the other workers
            until the next batch. W = 1 keeps batches of one (ARC's earliest conflict). */
        unsigned int batchPerWorker{8};
        /** \brief Batches grow while their repairs do not meet (W > 1): after a full batch none of whose conflicts
            pairs robots of two different repairs of the batch before, the next may hold twice as many conflicts, up
            to MAX_BATCH_GROWTH x W x batchPerWorker; a conflict between two such robots (concurrent repairs that did
            not see each other) brings it back to W x batchPerWorker. Teams whose conflicts are far apart need fewer
            batches (each waits for its last repair), dense ones keep small batches (an optimistic repair made stale by
            another is wasted). */
        bool growBatches{true};
        static constexpr unsigned int MAX_BATCH_GROWTH = 8;
        /** \brief Optimistic (true) or strict batch independence; local OR multi-start of idle workers. */
        bool optimistic{true}, localOr{true};
        /** \brief Where the stages report their progress as they go (the planner's; none if null). */
        ArcProgress *progress{nullptr};
    };

    /** \brief The ARC / P-ARC engine: owns the plan being repaired, the repair cache, the resolver and the
        statistics, works with a RepairWorkspace's worker pool and detectors, and runs the paper's pipeline on them.

        planInitial() is the first stage (each robot planned alone; robots handed to workers as they free up,
        idle workers running extra attempts with local OR). resolve() then loops: detect the next batch of
        robot-disjoint conflicts (BatchDetector: W = 1 gives the earliest conflict, ARC's), each with its
        robot set grown through the repair cache; repair the batch concurrently (ConflictResolver: windows
        that grow up to the global problem); apply each repair in batch order (one of every robot first)
        with applyRepair(), the one place that splices a patch, pulls back the detector's frontiers and records
        the repair in the cache.
        Seeds are derived from one seed per stage and task, so the same seed gives the same plan, and W = 1 is
        exactly ARC. Both stages resume where they stopped when the termination condition fired. */
    class RepairLoop
    {
      public:
        /** \brief An engine for \e problem seeded with \e seed, working in \e workspace (made for the same team;
            reset here). Both are kept by reference and must outlive the loop. Throws ompl::Exception if the
            workspace is for another team (another MultiRobotSpaceInformation). */
        RepairLoop(const MultiRobotProblem &problem, std::uint_fast32_t seed, RepairWorkspace &workspace);
        ~RepairLoop();

        /** \brief Use \e options from the next stage on; keeps the plan, frontiers, cache and statistics. Throws
            ompl::Exception for 0 workers, horizon or conflicts per worker, or an empty hierarchy. */
        void configure(RepairLoopOptions options);

        /** \brief Plan the robots that have no path yet; false if \e ptc fired first (resume later). */
        bool planInitial(const ompl::base::PlannerTerminationCondition &ptc);
        /** \brief True once every robot has its individual path. */
        bool isInitialised() const;
        /** \brief How many robots have their individual path. */
        std::size_t getPlannedCount() const;

        /** \brief Detect and repair conflicts until none is left (true) or \e ptc fires (false). */
        bool resolve(const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief The plan as a composite path, one state per breakpoint (MultiRobotPlan::toPathGeometric),
            its states allocated at once and filled by all workers. */
        ompl::geometric::PathGeometricPtr buildSolutionPath() const;

        /** \brief The capacity of the batch after \e batch when batches grow (RepairLoopOptions::growBatches):
            \e base after a conflict of \e batch between robots of two different repairs of the batch before it
            (\e lastRepair: per robot the index of its repair there, -1 for none), \e current after a batch that
            was not full, else twice \e current, at most MAX_BATCH_GROWTH x \e base. */
        static std::size_t nextBatchCapacity(std::size_t base, std::size_t current,
                                             const std::vector<BatchEntry> &batch, const std::vector<int> &lastRepair);

        const MultiRobotPlan &getPlan() const { return plan_; }
        const ArcStatistics &getStatistics() const { return statistics_; }
        const ParcStatistics &getParallelStatistics() const { return parallel_; }
        std::uint_fast32_t getSeed() const { return seed_; }

      private:
        /** \brief Splice \e repair into the plan, pull back the frontiers of its robots, cache its interval. */
        void applyRepair(const Repair &repair);
        /** \brief Repair \e batch concurrently and apply the repairs in batch order (a repair that grew to every
            robot first, the batch's other repairs of its robots dropped); false if \e ptc fired. */
        bool repairBatch(const std::vector<BatchEntry> &batch, const ompl::base::PlannerTerminationCondition &ptc);

        const MultiRobotProblem &problem_;
        std::uint_fast32_t seed_;
        RepairLoopOptions options_;
        MultiRobotPlan plan_;
        std::vector<char> planned_;
        /** \brief The worker pool and the detectors (the planner's, made at its setup()). */
        RepairWorkspace &workspace_;
        RepairCache cache_;
        std::unique_ptr<ConflictResolver> resolver_;
        ArcStatistics statistics_;
        ParcStatistics parallel_;
        /** \brief The configured batch capacity (W x batchPerWorker, 1 for W = 1), the next batch's, and per robot the
            index of its repair in the last batch (-1: none). */
        std::size_t baseCapacity_{1}, capacity_{1};
        std::vector<int> lastRepair_;
    };
}  // namespace ompl_parc

#endif
