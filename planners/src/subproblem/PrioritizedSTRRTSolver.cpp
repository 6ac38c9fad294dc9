#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"

#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/planners/subproblem/BlockingOrder.h"
#include "ompl_parc/spacetime/LatticeSearch.h"
#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"
#include "ompl_parc/spacetime/SpaceTimeInUse.h"
#include "ompl_parc/statespaces/SpaceRegistryLock.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <numeric>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** A space-time state (robot configuration \e q at time \e t) of \e si. */
    ob::ScopedState<> spaceTimeState(const ob::SpaceInformationPtr &si, const std::vector<double> &q, double t)
    {
        ob::ScopedState<> state(si);
        auto *compound = state->as<ob::CompoundState>();
        std::copy(q.begin(), q.end(), compound->as<ob::RealVectorStateSpace::StateType>(0)->values);
        compound->as<ob::TimeStateSpace::StateType>(1)->position = t;
        return state;
    }

    /** Apply \e settings to \e planner (also used to validate them). */
    void configure(ompl_parc::STRRTstar &planner, const ompl_parc::PrioritizedSTRRTSettings &settings)
    {
        planner.setRange(settings.range);
        planner.setRewiringState(settings.rewiring);
        planner.setBatchSize(settings.batchSize);
        planner.setInitialTimeBoundFactor(settings.initialTimeBoundFactor);
        planner.setTimeBoundFactorIncrease(settings.timeBoundFactorIncrease);
        planner.setStopAtFirstSolution(true);
    }

    /** A throw-away space-time space information, to check settings against STRRTstar up front. */
    ob::SpaceInformationPtr probeSpaceInformation()
    {
        return std::make_shared<ob::SpaceInformation>(
            ompl_parc::makeStateSpace<ompl_parc::spacetime::SpaceTimeStateSpace>(
                ompl_parc::makeStateSpace<ob::RealVectorStateSpace>(1)));
    }
}  // namespace

/** The state of a solve between calls (resume()): its seed, the robots planned alone for the unblocking order so far,
    the order being tried, its attempt, and its robots planned so far (order[0, planned)) with their paths and the
    bodies along them. */
class ompl_parc::PrioritizedSTRRTSolver::Progress : public SubproblemSolver::Memory
{
  public:
    std::optional<std::uint_fast32_t> seed;  // every draw of the solve derives from it; none: nothing done yet
    std::vector<TimedPath> alone;
    std::size_t aloneDone{0};
    std::vector<std::size_t> order;  // empty: no order chosen yet
    std::size_t attempt{0};
    std::size_t planned{0};
    std::vector<TimedPath> paths;  // by team position
    Tracks tracks;                 // of order[0, planned), in that order

    bool started() const { return !order.empty(); }

    /** Try \e first. */
    void start(std::vector<std::size_t> first)
    {
        paths.assign(first.size(), TimedPath());
        order = std::move(first);
        attempt = 0;
        restartOrder();
    }

    /** The order changed: none of its robots is planned. */
    void restartOrder()
    {
        planned = 0;
        tracks.clear();
    }
};

ompl_parc::PrioritizedSTRRTSolver::PrioritizedSTRRTSolver(PrioritizedSTRRTSettings settings)
    : settings_(std::move(settings))
{
    STRRTstar probe(probeSpaceInformation());
    configure(probe, settings_);
}

std::shared_ptr<ompl_parc::PrioritizedSTRRTSolver> ompl_parc::PrioritizedSTRRTSolver::makeReplanner(bool shuffle)
{
    PrioritizedSTRRTSettings settings;
    settings.shuffle = shuffle;
    return std::make_shared<PrioritizedSTRRTSolver>(settings);
}

std::vector<std::size_t> ompl_parc::PrioritizedSTRRTSolver::priorityOrder(std::size_t size,
                                                                          std::uint_fast32_t seed) const
{
    std::vector<std::size_t> order(size);
    std::iota(order.begin(), order.end(), 0);
    if (settings_.shuffle)
    {
        ompl::RNG rng;
        rng.setLocalSeed(mixSeed(seed, 0x0dde7));
        rng.shuffle(order.begin(), order.end());
    }
    return order;
}

ompl_parc::TimedPath ompl_parc::PrioritizedSTRRTSolver::planRobot(
    const ob::StateSpacePtr &space, const DynamicObstaclesPtr &obstacles, const std::vector<double> &start,
    const std::vector<double> &goal, std::size_t hold, const Subproblem &subproblem,
    const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, bool lattice) const
{
    if (hold == 0 && start == goal)
        return TimedPath(static_cast<unsigned int>(start.size()), start.data());  // already there, and safe to stay
    const auto *vectors = dynamic_cast<const ob::RealVectorStateSpace *>(space.get());
    if (lattice && vectors != nullptr && LatticeSearch::applies(*obstacles->getRobot()))
    {
        const auto &bounds = vectors->getBounds();
        LatticeSearch search(obstacles, bounds.low, bounds.high,
                             settings_.latticeStep > 0. ? settings_.latticeStep
                                                        : LatticeSearch::defaultStep(*obstacles->getRobot(), start));
        // The lattice has its own expansion cap; the sample cap counts ST-RRT's iterations only.
        TimedPath path = search.plan(start, goal, hold, ptc);
        if (!path.empty() || ptc)
            return path;
    }
    const auto capped = subproblem.cappedTermination(ptc);
    const auto si = createSpaceTimeSpaceInformation(space, obstacles);

    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    pdef->setStartAndGoalStates(spaceTimeState(si, start, 0.), spaceTimeState(si, goal, 0.));
    STRRTstar planner(si);
    configure(planner, settings_);
    planner.setMinimumGoalTime(static_cast<double>(hold) / obstacles->getResolution());
    planner.setLocalSeed(seed);
    planner.setProblemDefinition(pdef);
    planner.setup();
    if (planner.solve(capped) != ob::PlannerStatus::EXACT_SOLUTION)
        return TimedPath();
    return std::static_pointer_cast<SpaceTimeMotionValidator>(si->getMotionValidator())
        ->layOnGrid(*pdef->getSolutionPath()->as<og::PathGeometric>());
}

std::optional<std::vector<std::size_t>> ompl_parc::PrioritizedSTRRTSolver::unblockedOrder(
    const MultiRobotSpaceInformation &si, const Subproblem &subproblem, const MultiRobotSpaceInformation &local,
    const std::vector<std::size_t> &order, const ob::PlannerTerminationCondition &ptc, Progress &progress) const
{
    const auto &team = local.getRobots();
    progress.alone.resize(team.size());
    for (std::size_t &k = progress.aloneDone; k < team.size(); ++k)
    {
        if (ptc)
            return std::nullopt;
        progress.alone[k] =
            planRobot(local.getCompositeSpace()->getRobotSpace(k),
                      std::make_shared<DynamicObstacles>(team[k], si.getResolution()), subproblem.starts[k],
                      subproblem.goals[k], 0, subproblem, ptc, mixSeed(*progress.seed, 0xa10e + k), settings_.lattice);
        if (progress.alone[k].empty() && ptc)
            return std::nullopt;  // cut while planning robot k, which is planned again next time
    }
    auto unblocked = BlockingOrder(team, progress.alone, subproblem.starts, subproblem.goals, ptc).order(order);
    if (ptc)
        return std::nullopt;  // some paths were not looked at
    return unblocked;
}

std::optional<std::size_t> ompl_parc::PrioritizedSTRRTSolver::planInOrder(
    const MultiRobotSpaceInformation &si, const Subproblem &subproblem, const MultiRobotSpaceInformation &local,
    const Tracks &context, const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, bool lattice,
    Progress &progress, bool &hopeless) const
{
    const auto &team = local.getRobots();
    hopeless = true;
    // Each robot's bodies along its path are computed once and shared by the obstacles of all robots after it.
    for (; progress.planned < progress.order.size(); ++progress.planned)
    {
        const std::size_t k = progress.order[progress.planned];
        if (ptc)
            return k;
        auto obstacles = std::make_shared<DynamicObstacles>(team[k], si.getResolution());
        for (const auto &track : progress.tracks)
            obstacles->addTrack(track);
        for (const auto &track : context)
            obstacles->addTrack(track);
        if (!obstacles->isClear(subproblem.starts[k].data(), 0))
            return k;
        const auto hold = obstacles->earliestHold(subproblem.goals[k].data());
        if (!hold)
        {
            hopeless = false;
            return k;
        }
        // The sample cap bounds each robot's ST-RRT iterations.
        TimedPath &path = progress.paths[k];
        path = planRobot(local.getCompositeSpace()->getRobotSpace(k), obstacles, subproblem.starts[k],
                         subproblem.goals[k], *hold, subproblem, ptc, mixSeed(seed, 0x57aa + k), lattice);
        if (path.empty())
        {
            hopeless = static_cast<bool>(ptc);
            return k;
        }
        if (progress.planned + 1 < team.size())  // a robot is planned after this one
        {
            if (!DynamicObstacles::fits(path))
                return k;  // too many timesteps to plan around (a resolution far above the usual)
            progress.tracks.push_back(DynamicObstacles::computeTrack(*team[k], path));
        }
    }
    return std::nullopt;
}

std::unique_ptr<ompl_parc::SubproblemSolver::Memory> ompl_parc::PrioritizedSTRRTSolver::makeMemory() const
{
    return std::make_unique<Progress>();
}

bool ompl_parc::PrioritizedSTRRTSolver::solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                              const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                              Patch &patch) const
{
    bool retry = false;
    return solve(si, subproblem, ptc, seed, patch, retry);
}

bool ompl_parc::PrioritizedSTRRTSolver::solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                              const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                              Patch &patch, bool &retry) const
{
    Progress progress;
    return solveFrom(si, subproblem, ptc, seed, patch, retry, progress);
}

bool ompl_parc::PrioritizedSTRRTSolver::resume(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                               const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                               Patch &patch, Memory *memory) const
{
    auto *progress = dynamic_cast<Progress *>(memory);
    if (progress == nullptr)
        return solve(si, subproblem, ptc, seed, patch);
    bool retry = false;
    return solveFrom(si, subproblem, ptc, seed, patch, retry, *progress);
}

bool ompl_parc::PrioritizedSTRRTSolver::solveFrom(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                                  const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                                  Patch &patch, bool &retry, Progress &progress) const
{
    retry = false;
    seed = progress.seed.value_or(seed);  // the first call's, so that later calls go on as that call would have
    const auto local = subproblem.createSpaceInformation(si, seed);
    if (!local)
        return false;
    const std::size_t size = local->getRobots().size();

    if (ptc)
        return false;
    Tracks context;
    if (settings_.avoidOthers)
        for (std::size_t o = 0; o < subproblem.others.size(); ++o)
        {
            if (!DynamicObstacles::fits(subproblem.otherPaths[o]))
                return false;  // too many timesteps to plan around (a resolution far above the usual)
            context.push_back(
                DynamicObstacles::computeTrack(*si.getRobot(subproblem.others[o]), subproblem.otherPaths[o]));
        }
    progress.seed = seed;  // from here on, the solve has begun
    if (!progress.started())
    {
        std::vector<std::size_t> order = priorityOrder(size, seed);
        if (settings_.unblock && size > 1)
        {
            auto unblocked = unblockedOrder(si, subproblem, *local, order, ptc, progress);
            if (!unblocked)
                return false;  // cut: the robots planned alone so far stay in progress
            order = std::move(*unblocked);
        }
        progress.start(std::move(order));
    }
    // The first order draws with the solve's seed, each later one with fresh samples.
    for (;; ++progress.attempt)
    {
        bool hopeless = false;
        // Orders alternate between the lattice and ST-RRT alone: the lattice's paths (waits where the others
        // let a robot get furthest) can wall in robots that ST-RRT's would not, and the other way round.
        const std::size_t attempt = progress.attempt;
        const bool lattice = settings_.lattice && attempt % 2 == 0;
        const auto failed =
            planInOrder(si, subproblem, *local, context, ptc, attempt == 0 ? seed : mixSeed(seed, 0x9e0 + attempt),
                        lattice, progress, hopeless);
        if (!failed)
            break;
        if (ptc)
            return false;  // cut: the robots planned so far stay in progress for the next call
        retry = !hopeless;
        auto &order = progress.order;
        if (hopeless || !settings_.promote || attempt + 1 >= size || order.front() == *failed)
        {
            progress = Progress();  // the next call starts over
            return false;
        }
        order.erase(std::find(order.begin(), order.end(), *failed));
        order.insert(order.begin(), *failed);
        progress.restartOrder();
    }

    // Robots that arrive early wait at their goal (held safely from their arrival on).
    std::vector<TimedPath> paths = std::move(progress.paths);
    progress = Progress();
    std::size_t arrival = 0;
    for (const auto &path : paths)
        arrival = std::max(arrival, path.getArrival());
    for (std::size_t k = 0; k < size; ++k)
        paths[k].appendHold(subproblem.goals[k].data(), arrival);
    patch.paths = std::move(paths);
    return true;
}
