#include "ompl_parc/arc/BatchDetector.h"

#include "ompl_parc/parallel/StageClock.h"

#include <ompl/util/Exception.h>

#include <algorithm>

ompl_parc::BatchDetector::BatchDetector(ConflictDetector &detector, WorkerPool &pool, unsigned int horizon,
                                        bool optimistic)
    : detector_(detector), pool_(pool), horizon_(horizon), optimistic_(optimistic), workerPairs_(pool.getWorkerCount())
{
    if (horizon == 0)
        throw ompl::Exception("BatchDetector", "the horizon must be at least 1 timestep");
    for (std::size_t p = 0; p < detector_.getPairCount(); ++p)
        workerPairs_[p % workerPairs_.size()].push_back(p);  // round-robin, as in the paper
}

std::vector<ompl_parc::BatchEntry> ompl_parc::BatchDetector::detect(const MultiRobotPlan &plan,
                                                                    const RepairCache &cache, std::size_t window,
                                                                    const ompl::base::PlannerTerminationCondition &ptc,
                                                                    double &projected, unsigned int &teamGrowths)
{
    ConflictBatch batch(optimistic_, workerPairs_.size(), plan.getRobotCount());
    const auto skip = [&batch](std::size_t i, std::size_t j) { return batch.skipPair(i, j); };
    const std::size_t makespan = plan.getMakespan();
    std::vector<std::vector<Conflict>> found(workerPairs_.size());
    for (std::size_t from = detector_.firstUnvalidated(plan); from <= makespan && !batch.full() && !ptc;
         from += horizon_)
    {
        const std::size_t to = std::min<std::size_t>(from + horizon_, makespan + 1);
        const auto cpu =
            pool_.run([&](unsigned int worker)
                      { found[worker] = detector_.scan(plan, workerPairs_[worker], from, to, false, skip); });
        // The coordinator merges the candidates in temporal order and grows the batch.
        const double mergeStart = StageClock::threadCpu();
        std::vector<Conflict> candidates;
        for (const auto &f : found)
            candidates.insert(candidates.end(), f.begin(), f.end());
        std::sort(candidates.begin(), candidates.end());
        for (const Conflict &c : candidates)
        {
            if (batch.full())
                break;
            auto team = cache.expand(c, window);
            const bool grown = team.size() > 2;
            if (batch.offer(c, std::move(team)))
                teamGrowths += grown ? 1 : 0;
        }
        projected += *std::max_element(cpu.begin(), cpu.end()) + (StageClock::threadCpu() - mergeStart);
    }
    return batch.getEntries();
}
