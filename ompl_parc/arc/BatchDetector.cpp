#include "ompl_parc/arc/BatchDetector.h"

#include "ompl_parc/parallel/StageClock.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <limits>

ompl_parc::BatchDetector::BatchDetector(ConflictDetector &detector, WorkerPool &pool, std::size_t horizon,
                                        std::size_t capacity, bool optimistic)
    : detector_(detector), pool_(pool)
{
    configure(horizon, capacity, optimistic);
    reset();
}

void ompl_parc::BatchDetector::checkHorizon(std::size_t horizon, const std::string &who)
{
    if (horizon == 0)
        throw ompl::Exception(who, "horizon must be at least 1 timestep");
}

void ompl_parc::BatchDetector::configure(std::size_t horizon, std::size_t capacity, bool optimistic)
{
    checkHorizon(horizon);
    if (capacity == 0)
        throw ompl::Exception("BatchDetector", "a batch must hold at least one conflict");
    horizon_ = horizon;
    capacity_ = capacity;
    optimistic_ = optimistic;
}

void ompl_parc::BatchDetector::setCapacity(std::size_t capacity)
{
    configure(horizon_, capacity, optimistic_);
}

void ompl_parc::BatchDetector::reset()
{
    live_.clear();
    isLive_.clear();
    addNewPairs();
}

void ompl_parc::BatchDetector::addNewPairs()
{
    for (std::size_t p = isLive_.size(); p < detector_.getPairCount(); ++p)
        live_.push_back(p);
    isLive_.resize(detector_.getPairCount(), 1);
}

std::size_t ompl_parc::BatchDetector::chunkSize(std::size_t live) const
{
    constexpr std::size_t CHUNKS_PER_WORKER = 4, MIN_CHUNK = 256;
    const std::size_t workers = pool_.getWorkerCount();
    if (workers == 1)
        return std::max<std::size_t>(1, live);  // one scan over all pairs, as ARC's
    const std::size_t share = std::max<std::size_t>(1, (live + workers - 1) / workers);
    return std::min(share, std::max(MIN_CHUNK, live / (CHUNKS_PER_WORKER * workers)));
}

void ompl_parc::BatchDetector::invalidate(std::size_t robot, std::size_t timestep)
{
    detector_.invalidate(robot, timestep);
    for (std::size_t p : detector_.getPairsOf(robot))
        if (!isLive_[p])
        {
            isLive_[p] = 1;
            live_.push_back(p);
        }
}

ompl_parc::DetectedBatch ompl_parc::BatchDetector::detect(const MultiRobotPlan &plan, const RepairCache &cache,
                                                          std::size_t window,
                                                          const ompl::base::PlannerTerminationCondition &ptc)
{
    {
        const StopSignal::Scope scope(ptc);
        if (!detector_.discoverPairs(plan))
            return {};
    }
    addNewPairs();
    ConflictBatch batch(optimistic_, capacity_, plan.getRobotCount());
    // A batch of one is the earliest conflict: scans may stop at the first timestep with one.
    const bool earliestOnly = capacity_ == 1;
    double projected = 0.;
    const auto skip = [&batch](std::size_t i, std::size_t j) { return batch.skipPair(i, j); };
    const std::size_t makespan = plan.getMakespan();
    const std::size_t workers = pool_.getWorkerCount();
    std::vector<std::vector<Conflict>> found(workers);
    std::vector<std::size_t> resume(workers);
    std::vector<std::vector<std::size_t>> chunks(workers);
    for (std::size_t from = 0; from <= makespan && !batch.full() && !ptc;)
    {
        const std::size_t to = std::min<std::size_t>(from + horizon_, makespan + 1);
        const std::size_t chunk = chunkSize(live_.size());
        std::atomic<std::size_t> next{0};
        const auto cpu = pool_.run(
            [&](unsigned int worker)
            {
                const StopSignal::Scope scope(ptc);
                found[worker].clear();
                resume[worker] = std::numeric_limits<std::size_t>::max();
                for (std::size_t first; (first = next.fetch_add(chunk, std::memory_order_relaxed)) < live_.size();)
                {
                    auto &pairs = chunks[worker];
                    pairs.assign(live_.begin() + static_cast<std::ptrdiff_t>(first),
                                 live_.begin() + static_cast<std::ptrdiff_t>(std::min(first + chunk, live_.size())));
                    std::size_t resumeAt = std::numeric_limits<std::size_t>::max();
                    const auto conflicts = detector_.scan(plan, pairs, from, to, earliestOnly, skip, &resumeAt);
                    found[worker].insert(found[worker].end(), conflicts.begin(), conflicts.end());
                    resume[worker] = std::min(resume[worker], resumeAt);
                }
            });
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
            batch.offer(c, cache.expand(c, window));
        }
        projected += *std::max_element(cpu.begin(), cpu.end()) + (StageClock::threadCpu() - mergeStart);
        // The next round starts where some pair still needs checking (the first round's scans tell where that
        // is): stretches every pair is known to be clear of (disc pairs are scanned ahead) cost no rounds.
        from = std::max(to, *std::min_element(resume.begin(), resume.end()));
    }
    // Settled pairs leave until one of their robots changes.
    live_.erase(std::remove_if(live_.begin(), live_.end(),
                               [&](std::size_t p)
                               {
                                   if (!detector_.isSettled(plan, p))
                                       return false;
                                   isLive_[p] = 0;
                                   return true;
                               }),
                live_.end());
    return {batch.getEntries(), projected};
}
