#include "ompl_parc/planners/PARC.h"

#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/parallel/OrTaskRunner.h"
#include "ompl_parc/parallel/StageClock.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/util/Exception.h>

#include <algorithm>

namespace ob = ompl::base;

namespace
{
    double largest(const std::vector<double> &values)
    {
        return values.empty() ? 0. : *std::max_element(values.begin(), values.end());
    }
}  // namespace

ompl_parc::PARC::PARC(const ob::SpaceInformationPtr &si) : ArcPlannerBase(si, "PARC")
{
    specs_.multithreaded = true;
    declareParam<unsigned int>("workers", this, &PARC::setWorkers, &PARC::getWorkers, "1:1:64");
    declareParam<unsigned int>("horizon", this, &PARC::setHorizon, &PARC::getHorizon, "1:50:2000");
    declareParam<bool>("optimistic", this, &PARC::setOptimistic, &PARC::getOptimistic, "0,1");
    declareParam<bool>("local_or", this, &PARC::setLocalOr, &PARC::getLocalOr, "0,1");
}

ompl_parc::PARC::~PARC() = default;

void ompl_parc::PARC::setWorkers(unsigned int workers)
{
    if (workers == 0)
        throw ompl::Exception(getName(), "workers must be at least 1");
    workers_ = workers;
    batchDetector_.reset();
    pool_.reset();
}

void ompl_parc::PARC::setHorizon(unsigned int horizon)
{
    if (horizon == 0)
        throw ompl::Exception(getName(), "horizon must be at least 1 timestep");
    horizon_ = horizon;
    batchDetector_.reset();
}

void ompl_parc::PARC::clear()
{
    ArcPlannerBase::clear();
    parallel_ = ParcStatistics();
    batchDetector_.reset();
}

ompl_parc::WorkerPool &ompl_parc::PARC::pool() const
{
    if (!pool_)
        pool_ = std::make_unique<WorkerPool>(workers_);
    return *pool_;
}

bool ompl_parc::PARC::computeInitialPlans(const ob::PlannerTerminationCondition &ptc)
{
    std::vector<std::size_t> robots;
    for (std::size_t r = 0; r < mrsi_->getRobotCount(); ++r)
        if (!planned_[r])
            robots.push_back(r);
    const InitialPlanner planner(*problem_, settings_.simplifyInitial);
    const std::size_t n = mrsi_->getRobotCount();
    OrTaskStatistics stats;
    const auto paths = OrTaskRunner<std::vector<double>>(pool(), localOr_)
                           .run(
                               robots.size(), ptc,
                               [&](std::size_t task, unsigned int attempt,
                                   const ob::PlannerTerminationCondition &stop) -> std::optional<std::vector<double>>
                               {
                                   const std::size_t r = robots[task];
                                   // Attempt 0 uses ARC's seed for this robot; extra OR attempts new ones.
                                   const auto seed = mixSeed(effectiveSeed_, r + n * attempt);
                                   std::vector<double> path;
                                   if (!planner.plan(r, stop, seed, path))
                                       return std::nullopt;
                                   return path;
                               },
                               stats);
    parallel_.initialAttempts += stats.attempts;
    parallel_.cancelledInitialAttempts += stats.cancelled;
    parallel_.projectedInitial += largest(stats.workerCpu);
    bool all = true;
    for (std::size_t k = 0; k < robots.size(); ++k)
        if (paths[k])
        {
            plan_.setRobotPath(robots[k], *paths[k]);
            planned_[robots[k]] = 1;
        }
        else
            all = false;
    return all;
}

bool ompl_parc::PARC::repairBatch(const std::vector<BatchEntry> &batch, const ob::PlannerTerminationCondition &ptc)
{
    // Attempt 0 of the k-th conflict uses the seed ARC would use for it; extra OR attempts derive new ones.
    const unsigned int first = statistics_.conflicts;
    OrTaskStatistics stats;
    const auto repairs =
        OrTaskRunner<Repair>(pool(), localOr_)
            .run(
                batch.size(), ptc,
                [&](std::size_t task, unsigned int attempt, const ob::PlannerTerminationCondition &stop)
                {
                    auto seed = mixSeed(effectiveSeed_, 0x10000 + first + task + 1);
                    if (attempt > 0)
                        seed = mixSeed(seed, attempt);
                    return resolver_->resolve(plan_, batch[task].team, batch[task].conflict.timestep, stop, seed);
                },
                stats);
    parallel_.repairAttempts += stats.attempts;
    parallel_.cancelledAttempts += stats.cancelled;
    parallel_.projectedResolution += largest(stats.workerCpu);
    bool all = true;
    for (const auto &repair : repairs)  // batch order: deterministic
    {
        ++statistics_.conflicts;
        if (repair)
            applyRepair(*repair);
        else
            all = false;
    }
    return all;
}

bool ompl_parc::PARC::resolveConflicts(const ob::PlannerTerminationCondition &ptc)
{
    while (!ptc)
    {
        std::vector<BatchEntry> batch;
        {
            StageClock clock(statistics_.detectionWall, statistics_.detectionCpu);
            if (!batchDetector_)
                batchDetector_ = std::make_unique<BatchDetector>(*detector_, pool(), horizon_, optimistic_);
            batch = batchDetector_->detect(plan_, cache_, settings_.window, ptc, parallel_.projectedDetection,
                                           statistics_.teamGrowths);
        }
        if (batch.empty())
            return !ptc;
        ++parallel_.batches;
        parallel_.batchedConflicts += static_cast<unsigned int>(batch.size());
        if (parallel_.batches == 1)
            parallel_.firstBatchSize = static_cast<unsigned int>(batch.size());
        StageClock clock(statistics_.resolutionWall, statistics_.resolutionCpu);
        if (!repairBatch(batch, ptc))
            return false;
    }
    return false;
}

ompl::geometric::PathGeometricPtr ompl_parc::PARC::buildSolutionPath() const
{
    auto path = std::make_shared<ompl::geometric::PathGeometric>(mrsi_);
    auto &states = path->getStates();
    states.resize(plan_.getMakespan() + 1);
    const std::size_t w = pool().getWorkerCount(), chunk = (states.size() + w - 1) / w;
    pool().run(
        [&](unsigned int worker)
        {
            const std::size_t from = std::min(states.size(), worker * chunk),
                              to = std::min(states.size(), from + chunk);
            plan_.allocateStates(*mrsi_, from, to, states.data() + from);
        });
    return path;
}

void ompl_parc::PARC::getPlannerData(ob::PlannerData &data) const
{
    ArcPlannerBase::getPlannerData(data);
    auto &p = data.properties;
    const auto &s = parallel_;
    p["workers INTEGER"] = std::to_string(workers_);
    p["batches INTEGER"] = std::to_string(s.batches);
    p["first_batch_size INTEGER"] = std::to_string(s.firstBatchSize);
    p["average_batch_size REAL"] = std::to_string(s.batches ? double(s.batchedConflicts) / s.batches : 0.);
    p["repair_attempts INTEGER"] = std::to_string(s.repairAttempts);
    p["cancelled_attempts INTEGER"] = std::to_string(s.cancelledAttempts + s.cancelledInitialAttempts);
    p["projected_initial_time REAL"] = std::to_string(s.projectedInitial);
    p["projected_detection_time REAL"] = std::to_string(s.projectedDetection);
    p["projected_resolution_time REAL"] = std::to_string(s.projectedResolution);
    p["projected_total_time REAL"] = std::to_string(s.projectedInitial + s.projectedDetection + s.projectedResolution);
}
