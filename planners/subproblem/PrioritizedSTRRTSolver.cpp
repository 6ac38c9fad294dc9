#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"

#include "ompl_parc/planners/STRRTstar.h"
#include "ompl_parc/planners/subproblem/BlockingOrder.h"
#include "ompl_parc/spacetime/LatticeSearch.h"
#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"
#include "ompl_parc/spacetime/SpaceTimeStateSpace.h"
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

ompl_parc::PrioritizedSTRRTSolver::PrioritizedSTRRTSolver(PrioritizedSTRRTSettings settings)
    : settings_(std::move(settings))
{
    STRRTstar probe(probeSpaceInformation());
    configure(probe, settings_);
}

std::shared_ptr<ompl_parc::PrioritizedSTRRTSolver> ompl_parc::PrioritizedSTRRTSolver::makeReplanner()
{
    PrioritizedSTRRTSettings settings;
    settings.lattice = false;
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

std::vector<std::size_t> ompl_parc::PrioritizedSTRRTSolver::unblockedOrder(
    const MultiRobotSpaceInformation &si, const Subproblem &subproblem, const MultiRobotSpaceInformation &local,
    const std::vector<std::size_t> &order, const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed) const
{
    const auto &team = local.getRobots();
    std::vector<TimedPath> alone(team.size());
    for (std::size_t k = 0; k < team.size(); ++k)
    {
        if (ptc)
            return order;  // after the stop nobody is planned: the order no longer matters
        alone[k] = planRobot(local.getCompositeSpace()->getRobotSpace(k),
                             std::make_shared<DynamicObstacles>(team[k], si.getResolution()), subproblem.starts[k],
                             subproblem.goals[k], 0, subproblem, ptc, mixSeed(seed, 0xa10e + k), settings_.lattice);
    }
    return BlockingOrder(team, alone, subproblem.starts, subproblem.goals, ptc).order(order);
}

std::optional<std::size_t> ompl_parc::PrioritizedSTRRTSolver::planInOrder(
    const MultiRobotSpaceInformation &si, const Subproblem &subproblem, const MultiRobotSpaceInformation &local,
    const std::vector<std::size_t> &order, const Tracks &context, const ob::PlannerTerminationCondition &ptc,
    std::uint_fast32_t seed, bool lattice, std::vector<TimedPath> &paths, bool &hopeless) const
{
    const auto &team = local.getRobots();
    hopeless = true;
    // Each robot's bodies along its path are computed once and shared by the obstacles of all robots after it.
    Tracks planned;
    for (std::size_t k : order)
    {
        if (ptc)
            return k;
        auto obstacles = std::make_shared<DynamicObstacles>(team[k], si.getResolution());
        for (const auto &track : planned)
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
        paths[k] = planRobot(local.getCompositeSpace()->getRobotSpace(k), obstacles, subproblem.starts[k],
                             subproblem.goals[k], *hold, subproblem, ptc, mixSeed(seed, 0x57aa + k), lattice);
        if (paths[k].empty())
        {
            hopeless = static_cast<bool>(ptc);
            return k;
        }
        if (planned.size() + 1 < team.size())  // a robot is planned after this one
        {
            if (!DynamicObstacles::fits(paths[k]))
                return k;  // too many timesteps to plan around (a resolution far above the usual)
            planned.push_back(DynamicObstacles::computeTrack(*team[k], paths[k]));
        }
    }
    return std::nullopt;
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
    retry = false;
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
    std::vector<TimedPath> paths(size);
    std::vector<std::size_t> order = priorityOrder(size, seed);
    if (settings_.unblock && size > 1)
        order = unblockedOrder(si, subproblem, *local, order, ptc, seed);
    // The first order draws with the solve's seed, each later one with fresh samples.
    for (std::size_t attempt = 0;; ++attempt)
    {
        bool hopeless = false;
        // Orders alternate between the lattice and ST-RRT alone: the lattice's paths (waits where the others
        // let a robot get furthest) can wall in robots that ST-RRT's would not, and the other way round.
        const bool lattice = settings_.lattice && attempt % 2 == 0;
        const auto failed = planInOrder(si, subproblem, *local, order, context, ptc,
                                        attempt == 0 ? seed : mixSeed(seed, 0x9e0 + attempt), lattice, paths, hopeless);
        if (!failed)
            break;
        retry = !hopeless;
        if (hopeless || !settings_.promote || attempt + 1 >= size || order.front() == *failed)
            return false;
        order.erase(std::find(order.begin(), order.end(), *failed));
        order.insert(order.begin(), *failed);
    }

    // Robots that arrive early wait at their goal (held safely from their arrival on).
    std::size_t arrival = 0;
    for (const auto &path : paths)
        arrival = std::max(arrival, path.getArrival());
    for (std::size_t k = 0; k < size; ++k)
        paths[k].appendHold(subproblem.goals[k].data(), arrival);
    patch.paths = std::move(paths);
    return true;
}
