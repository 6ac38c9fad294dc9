#ifndef OMPL_PARC_ARC_ARC_PROGRESS_
#define OMPL_PARC_ARC_ARC_PROGRESS_

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <string>

namespace ompl_parc
{
    /** \brief Where an ARC-family solve is, readable from any thread while it runs: what OMPL's planner progress
        properties (ompl::tools::Benchmark's progress table), the demo's live line and a user's own monitor show.

        ArcStatistics are plain members written by the planning threads; these are atomics, so that another thread
        may read them at any time. Counters only grow until reset(); the stage only advances, so several P-ARC
        instances reporting into one ArcProgress (OR-P-ARC) show the furthest stage and the sums of their counters. */
    class ArcProgress
    {
      public:
        /** \brief The stages in the order a solve passes them. */
        enum class Stage : int
        {
            IDLE = 0,
            INITIAL = 1,
            RESOLVING = 2,
            SMOOTHING = 3,
            SOLVED = 4
        };

        /** \brief Everything back to zero and IDLE (a planner's clear()). */
        void reset();
        /** \brief Marks the start of a solve: the elapsed time counts from here. */
        void startSolve();
        /** \brief Advances to \e stage (never back). */
        void reachStage(Stage stage);

        void addRobotsPlanned(unsigned int n) { robotsPlanned_ += n; }
        void addConflictsFound(unsigned int n) { conflictsFound_ += n; }
        void addConflictsResolved(unsigned int n) { conflictsResolved_ += n; }
        void addBatches(unsigned int n) { batches_ += n; }
        void addSolverCalls(unsigned int n) { solverCalls_ += n; }
        /** \brief The makespan of the plan being repaired (with several instances: of the last that changed it). */
        void setMakespan(std::size_t makespan) { makespan_ = makespan; }

        Stage getStage() const { return static_cast<Stage>(stage_.load()); }
        unsigned int getRobotsPlanned() const { return robotsPlanned_; }
        unsigned int getConflictsFound() const { return conflictsFound_; }
        unsigned int getConflictsResolved() const { return conflictsResolved_; }
        unsigned int getBatches() const { return batches_; }
        unsigned int getSolverCalls() const { return solverCalls_; }
        std::size_t getMakespan() const { return makespan_; }
        /** \brief Seconds since startSolve() (0 before it). */
        double getElapsed() const;

        /** \brief "idle", "initial", "resolving", "smoothing" or "solved". */
        static const char *stageName(Stage stage);

        /** \brief The values as OMPL planner progress properties, for Planner::addPlannerProgressProperty: "stage
            INTEGER" (the Stage number), "robots planned INTEGER", "conflicts found INTEGER", "conflicts resolved
            INTEGER", "batches detected INTEGER", "solver calls made INTEGER", "current makespan INTEGER", "elapsed
            REAL". The functions read this object, which must outlive them. OMPL 1.5's Benchmark also stores their
            final values with the run's properties: the names differ from every PlannerData property of ours (one
            database column each). */
        std::map<std::string, std::function<std::string()>> properties() const;

      private:
        std::atomic<int> stage_{0};
        std::atomic<unsigned int> robotsPlanned_{0}, conflictsFound_{0}, conflictsResolved_{0}, batches_{0},
            solverCalls_{0};
        std::atomic<std::size_t> makespan_{0};
        /** \brief steady_clock ticks at startSolve(); 0 before. */
        std::atomic<std::chrono::steady_clock::rep> start_{0};
    };
}  // namespace ompl_parc

#endif
