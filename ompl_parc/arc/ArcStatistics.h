#ifndef OMPL_PARC_ARC_ARC_STATISTICS_
#define OMPL_PARC_ARC_ARC_STATISTICS_

#include <cstddef>
#include <map>
#include <string>

namespace ompl_parc
{
    /** \brief Counters and per-stage times of an ARC-family solve (wall and summed CPU seconds), collected
        by the RepairLoop. */
    struct ArcStatistics
    {
        double initialWall{0.}, initialCpu{0.}, detectionWall{0.}, detectionCpu{0.}, resolutionWall{0.},
            resolutionCpu{0.};
        unsigned int conflicts{0}, repairs{0}, teamGrowths{0}, globalRepairs{0};
        /** \brief Over every repair attempt, successful or not (failed ones explain a timeout). */
        unsigned int solverCalls{0}, expansions{0};
        /** \brief The longest single subproblem solver call, in seconds of wall time. */
        double longestSolverCall{0.};
        std::map<std::string, unsigned int> solverWins;
        /** \brief Where a plan's length comes from. Per solver that repaired (the keys of solverWins), the timesteps
            its repairs added to the repaired robots' arrivals (summed over those robots; a repair can also shorten)
            and to the plan's makespan; globalDelay is the part of the delays added by global repairs. The plan's
            makespan is initialMakespan plus the makespan added, its sum of costs initialSumOfCosts plus the delays. */
        std::map<std::string, long long> solverDelays, solverMakespanAdded;
        long long globalDelay{0};
        /** \brief The initial stage's plan (every robot planned alone). */
        std::size_t initialMakespan{0}, initialSumOfCosts{0};
    };

    /** \brief Counters of P-ARC's parallel stages, and its projected W-core times.

        A stage's projected time is, summed over its fork-join rounds, the largest CPU time any worker
        spent in the round plus the coordinator's serial work: the wall time the stage would take with one
        core per worker. On a machine with fewer cores than workers it is a projection, and labelled so. */
    struct ParcStatistics
    {
        unsigned int batches{0}, firstBatchSize{0}, largestBatch{0}, batchedConflicts{0}, repairAttempts{0},
            cancelledAttempts{0}, initialAttempts{0}, cancelledInitialAttempts{0};
        double projectedInitial{0.}, projectedDetection{0.}, projectedResolution{0.};
    };
}  // namespace ompl_parc

#endif
