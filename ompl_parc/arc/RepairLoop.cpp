#include "ompl_parc/arc/RepairLoop.h"

#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/parallel/OrTaskRunner.h"
#include "ompl_parc/parallel/StageClock.h"
#include "ompl_parc/util/InnerPlannerLog.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>

namespace ob = ompl::base;

namespace
{
    double largest(const std::vector<double> &values)
    {
        return values.empty() ? 0. : *std::max_element(values.begin(), values.end());
    }

    /** Seeds of the repair stage live apart from the initial stage's (one per robot). */
    constexpr std::uint_fast32_t REPAIR_SEEDS = 0x10000;

    /** "0, 3, 5": the robots of a conflict's team, for the log. */
    std::string listed(const std::vector<std::size_t> &robots)
    {
        std::ostringstream out;
        for (std::size_t k = 0; k < robots.size(); ++k)
            out << (k == 0 ? "" : ", ") << robots[k];
        return out.str();
    }
}  // namespace

ompl_parc::RepairLoop::RepairLoop(const MultiRobotProblem &problem, std::uint_fast32_t seed, RepairWorkspace &workspace)
    : problem_(problem),
      seed_(seed),
      plan_(*problem.getSpaceInformation()),
      planned_(problem.getSpaceInformation()->getRobotCount(), 0),
      workspace_(workspace),
      lastRepair_(problem.getSpaceInformation()->getRobotCount(), -1)
{
    if (&workspace.getDetector().getSpaceInformation() != problem.getSpaceInformation().get())
        throw ompl::Exception("RepairLoop", "the workspace is for another team");
    workspace.reset();
}

ompl_parc::RepairLoop::~RepairLoop() = default;

void ompl_parc::RepairLoop::configure(RepairLoopOptions options)
{
    // The workspace checks the parallel values (RepairWorkspace::configure()) before anything here changes.
    workspace_.configure(options.workers, options.horizon, options.batchPerWorker, options.optimistic);
    baseCapacity_ = capacity_ = workspace_.getBatchDetector().getCapacity();
    resolver_ =
        std::make_unique<ConflictResolver>(*problem_.getSpaceInformation(), options.settings, options.hierarchy);
    options_ = std::move(options);
}

bool ompl_parc::RepairLoop::isInitialised() const
{
    return std::all_of(planned_.begin(), planned_.end(), [](char planned) { return planned != 0; });
}

std::size_t ompl_parc::RepairLoop::getPlannedCount() const
{
    return static_cast<std::size_t>(std::count(planned_.begin(), planned_.end(), 1));
}

bool ompl_parc::RepairLoop::planInitial(const ob::PlannerTerminationCondition &ptc)
{
    StageClock clock(statistics_.initialWall, statistics_.initialCpu);
    ArcProgress *progress = options_.progress;
    if (progress != nullptr)
        progress->reachStage(ArcProgress::Stage::INITIAL);
    std::vector<std::size_t> robots;
    for (std::size_t r = 0; r < planned_.size(); ++r)
        if (!planned_[r])
            robots.push_back(r);
    const InitialPlanner planner(problem_, options_.settings.simplifyInitial, {}, options_.settings.straightInitial);
    const std::size_t n = planned_.size();
    OrTaskStatistics stats;
    // A robot counts as planned once, at its first path (local OR may find several).
    const auto counted = std::make_unique<std::atomic<bool>[]>(robots.size());
    const auto paths = OrTaskRunner<TimedPath>(workspace_.getPool(), options_.localOr)
                           .run(
                               robots.size(), ptc,
                               [&](std::size_t task, unsigned int attempt,
                                   const ob::PlannerTerminationCondition &stop) -> std::optional<TimedPath>
                               {
                                   const InnerPlannerLog::Scope inner;
                                   const std::size_t r = robots[task];
                                   // Attempt 0 uses the robot's own seed; extra OR attempts new ones.
                                   TimedPath path;
                                   if (!planner.plan(r, stop, mixSeed(seed_, r + n * attempt), path))
                                       return std::nullopt;
                                   if (progress != nullptr && !counted[task].exchange(true))
                                       progress->addRobotsPlanned(1);
                                   return path;
                               },
                               stats);
    parallel_.initialAttempts += stats.attempts;
    parallel_.cancelledInitialAttempts += stats.cancelled;
    parallel_.projectedInitial += largest(stats.workerCpu);
    for (std::size_t k = 0; k < robots.size(); ++k)
        if (paths[k])
        {
            plan_.setPath(robots[k], *paths[k]);
            planned_[robots[k]] = 1;
        }
    const bool initialised = isInitialised();
    if (initialised)  // a robot without a path has no arrival yet
    {
        statistics_.initialMakespan = plan_.getMakespan();
        statistics_.initialSumOfCosts = plan_.getSumOfCosts();
        if (progress != nullptr)
            progress->setMakespan(plan_.getMakespan());
    }
    return initialised;
}

bool ompl_parc::RepairLoop::resolve(const ob::PlannerTerminationCondition &ptc)
{
    if (options_.progress != nullptr)
        options_.progress->reachStage(ArcProgress::Stage::RESOLVING);
    while (!ptc)
    {
        DetectedBatch batch;
        {
            StageClock clock(statistics_.detectionWall, statistics_.detectionCpu);
            workspace_.getBatchDetector().setCapacity(capacity_);
            batch = workspace_.getBatchDetector().detect(plan_, cache_, options_.settings.window, ptc);
        }
        parallel_.projectedDetection += batch.projectedSeconds;
        if (batch.entries.empty())
            return !ptc;
        ++parallel_.batches;
        parallel_.batchedConflicts += static_cast<unsigned int>(batch.entries.size());
        if (options_.progress != nullptr)
        {
            options_.progress->addBatches(1);
            options_.progress->addConflictsFound(static_cast<unsigned int>(batch.entries.size()));
        }
        if (parallel_.batches == 1)
            parallel_.firstBatchSize = static_cast<unsigned int>(batch.entries.size());
        for (const BatchEntry &entry : batch.entries)
            statistics_.teamGrowths += entry.team.size() > 2 ? 1 : 0;
        parallel_.largestBatch = std::max(parallel_.largestBatch, static_cast<unsigned int>(batch.entries.size()));
        if (options_.growBatches && baseCapacity_ > 1)
            capacity_ = nextBatchCapacity(baseCapacity_, capacity_, batch.entries, lastRepair_);
        std::fill(lastRepair_.begin(), lastRepair_.end(), -1);
        for (std::size_t k = 0; k < batch.entries.size(); ++k)
            for (std::size_t r : batch.entries[k].team)
                lastRepair_[r] = static_cast<int>(k);
        StageClock clock(statistics_.resolutionWall, statistics_.resolutionCpu);
        if (!repairBatch(batch.entries, ptc))
            return false;
    }
    return false;
}

bool ompl_parc::RepairLoop::repairBatch(const std::vector<BatchEntry> &batch,
                                        const ob::PlannerTerminationCondition &ptc)
{
    // Attempt 0 of the k-th conflict has the k-th conflict's seed whatever W is; extra OR attempts derive new ones.
    const unsigned int first = statistics_.conflicts;
    OrTaskStatistics stats;
    std::mutex traced;  // every resolve's calls and longest call, found or not (one lock per resolve)
    const auto repairs =
        OrTaskRunner<Repair>(workspace_.getPool(), options_.localOr)
            .run(
                batch.size(), ptc,
                [&](std::size_t task, unsigned int attempt, const ob::PlannerTerminationCondition &stop)
                {
                    auto seed = mixSeed(seed_, REPAIR_SEEDS + first + task + 1);
                    if (attempt > 0)
                        seed = mixSeed(seed, attempt);
                    const InnerPlannerLog::Scope inner;
                    ResolveTrace trace;
                    auto repair =
                        resolver_->resolve(plan_, batch[task].team, batch[task].conflict.timestep, stop, seed, &trace);
                    if (options_.progress != nullptr)
                        options_.progress->addSolverCalls(trace.calls);
                    const std::lock_guard<std::mutex> lock(traced);
                    statistics_.solverCalls += trace.calls;
                    statistics_.expansions += trace.expansions;
                    statistics_.longestSolverCall = std::max(statistics_.longestSolverCall, trace.longestCall);
                    return repair;
                },
                stats);
    parallel_.repairAttempts += stats.attempts;
    parallel_.cancelledAttempts += stats.cancelled;
    parallel_.projectedResolution += largest(stats.workerCpu);
    // A patch continues the plan it was made from, so two patches of one robot cannot both be spliced. The batch's
    // teams are robot-disjoint, but a repair that grew to every robot (ConflictResolver) is not: it goes first and
    // the batch's other repairs of its robots are dropped (a conflict its patch left is found again by detection).
    std::vector<std::size_t> order(repairs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_partition(order.begin(), order.end(),
                          [&](std::size_t k)
                          { return repairs[k] && repairs[k]->subproblem.robots.size() > batch[k].team.size(); });
    std::vector<char> patched(problem_.getRobotCount(), 0);
    bool all = true;
    for (std::size_t k : order)  // batch order (grown repairs first): deterministic
    {
        const Conflict &conflict = batch[k].conflict;
        const auto &repair = repairs[k];
        if (repair && std::any_of(repair->subproblem.robots.begin(), repair->subproblem.robots.end(),
                                  [&](std::size_t r) { return patched[r] != 0; }))
        {
            // Not counted: the repair of every robot replaced its robots' paths; a conflict left is found again.
            OMPL_DEBUG(
                "robots %zu and %zu at t=%zu, team {%s}: repair dropped (a repair of every robot came before it "
                "in the batch)",
                conflict.first, conflict.second, conflict.timestep, listed(batch[k].team).c_str());
            continue;
        }
        ++statistics_.conflicts;
        if (repair)
        {
            OMPL_DEBUG(
                "conflict %u: robots %zu and %zu at t=%zu, team {%s}: repaired by %s over [%zu, %zu]%s, "
                "patch of %zu timesteps",
                statistics_.conflicts, conflict.first, conflict.second, conflict.timestep,
                listed(batch[k].team).c_str(), repair->solver.c_str(), repair->subproblem.windowStart,
                repair->subproblem.windowEnd, repair->subproblem.global ? " (global)" : "",
                repair->patch.getDuration());
            applyRepair(*repair);
            for (std::size_t r : repair->subproblem.robots)
                patched[r] = 1;
        }
        else
        {
            OMPL_DEBUG("conflict %u: robots %zu and %zu at t=%zu, team {%s}: not repaired before the stop",
                       statistics_.conflicts, conflict.first, conflict.second, conflict.timestep,
                       listed(batch[k].team).c_str());
            all = false;
        }
    }
    return all;
}

std::size_t ompl_parc::RepairLoop::nextBatchCapacity(std::size_t base, std::size_t current,
                                                     const std::vector<BatchEntry> &batch,
                                                     const std::vector<int> &lastRepair)
{
    const bool met = std::any_of(batch.begin(), batch.end(),
                                 [&lastRepair](const BatchEntry &entry)
                                 {
                                     const int a = lastRepair[entry.conflict.first],
                                               b = lastRepair[entry.conflict.second];
                                     return a >= 0 && b >= 0 && a != b;
                                 });
    if (met)
        return base;
    if (batch.size() < current)
        return current;
    return std::min(2 * current, std::size_t{RepairLoopOptions::MAX_BATCH_GROWTH} * base);
}

void ompl_parc::RepairLoop::applyRepair(const Repair &repair)
{
    const Subproblem &sub = repair.subproblem;
    const auto makespan = static_cast<long long>(plan_.getMakespan());
    long long delay = 0;
    for (std::size_t robot : sub.robots)
        delay -= static_cast<long long>(plan_.getArrival(robot));
    repair.patch.spliceInto(plan_, sub);
    for (std::size_t robot : sub.robots)
        delay += static_cast<long long>(plan_.getArrival(robot));
    statistics_.solverDelays[repair.solver] += delay;
    statistics_.solverMakespanAdded[repair.solver] += static_cast<long long>(plan_.getMakespan()) - makespan;
    statistics_.globalDelay += sub.global ? delay : 0;
    for (std::size_t robot : sub.robots)
        workspace_.getBatchDetector().invalidate(robot, sub.windowStart);
    const std::size_t duration = repair.patch.getDuration();
    // A repair of every robot is not cached: every later conflict would grow to every robot (and P-ARC's batches to
    // one conflict each).
    if (sub.robots.size() < problem_.getRobotCount())
        cache_.add(sub.robots, sub.windowStart, sub.windowStart + duration);
    ++statistics_.repairs;
    statistics_.globalRepairs += sub.global ? 1 : 0;
    ++statistics_.solverWins[repair.solver];
    if (options_.progress != nullptr)
    {
        options_.progress->addConflictsResolved(1);
        options_.progress->setMakespan(plan_.getMakespan());
    }
}

ompl::geometric::PathGeometricPtr ompl_parc::RepairLoop::buildSolutionPath() const
{
    const auto &si = problem_.getSpaceInformation();
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si);
    const auto times = plan_.getBreakpoints();
    auto &states = path->getStates();
    states.resize(times.size());
    // Each worker allocates its share of the states at once (one block: CompositeStateSpace::allocStates) and fills
    // it: placing the states and the block's first-touch page faults are most of the work at hundreds of robots
    // (hundreds of states of kilobytes each).
    WorkerPool &pool = workspace_.getPool();
    const std::size_t w = pool.getWorkerCount(), chunk = (states.size() + w - 1) / w;
    pool.run(
        [&](unsigned int worker)
        {
            const std::size_t from = std::min(states.size(), worker * chunk),
                              to = std::min(states.size(), from + chunk);
            si->getCompositeSpace()->allocStates(to - from, states.data() + from);
            plan_.fillStates(*si, times, from, to, states.data() + from);
        });
    return path;
}
