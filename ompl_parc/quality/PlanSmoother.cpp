#include "ompl_parc/quality/PlanSmoother.h"

#include "ompl_parc/arc/ConflictResolver.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <limits>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>

namespace ob = ompl::base;

ompl_parc::PlanSmoother::PlanSmoother(MultiRobotSpaceInformationPtr si, std::uint_fast32_t seed)
    : si_(std::move(si)), alone_(si_->getRobotCount())
{
    rng_.setLocalSeed(seed);
}

std::size_t ompl_parc::PlanSmoother::getStallLimit() const
{
    return std::max<std::size_t>(2000, 200 * si_->getRobotCount());
}

ompl_parc::SmoothingReport ompl_parc::PlanSmoother::smooth(MultiRobotPlan &plan,
                                                           const ob::PlannerTerminationCondition &ptc)
{
    const auto started = ompl::time::now();
    const std::size_t n = si_->getRobotCount();
    if (plan.getRobotCount() != n)
        throw ompl::Exception("PlanSmoother", "the plan is for a team of " + std::to_string(plan.getRobotCount()) +
                                                  " robots, not " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i)
        if (plan.getPath(i).empty())
            throw ompl::Exception("PlanSmoother", "robot " + si_->getRobot(i)->getName() + " has no path");
    SmoothingReport report;
    report.makespanBefore = plan.getMakespan();
    report.sumOfCostsBefore = plan.getSumOfCosts();
    const StopSignal::Scope scope(ptc);
    detector_.emplace(*si_);
    if (const auto conflict = detector_->findEarliest(plan))
        throw ompl::Exception("PlanSmoother", "only a conflict-free plan can be smoothed: robots " +
                                                  si_->getRobot(conflict->first)->getName() + " and " +
                                                  si_->getRobot(conflict->second)->getName() +
                                                  " collide at t=" + std::to_string(conflict->timestep));
    bound_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        bound_[i] = PlanQuality::straightLineSteps(*si_, plan, i);

    if (teamReplanTime_ > 0. && (replanner_ || teamSolver_))
    {
        const auto budget =
            ob::plannerOrTerminationCondition(ptc, ob::timedPlannerTerminationCondition(teamReplanTime_));
        std::vector<std::size_t> everyone(n);
        std::iota(everyone.begin(), everyone.end(), 0);
        if (teamSolver_ && teamSolver_->appliesTo(*si_, everyone))
        {
            const auto solveStarted = ompl::time::now();
            report.teamSolveTried = true;
            // At most half the team replan's time: where the lattice fails (its search does not finish), the
            // prioritised replan keeps the other half.
            const auto half =
                ob::plannerOrTerminationCondition(budget, ob::timedPlannerTerminationCondition(0.5 * teamReplanTime_));
            report.teamSolveKept = tryTeamSolve(plan, half, report.teamSolved);
            report.teamSolveSeconds = ompl::time::seconds(ompl::time::now() - solveStarted);
        }
        if (replanner_)
        {
            report.teamReplanned = true;
            report.teamReplanKept = tryTeamReplan(plan, budget, report.teamReplanDone);
        }
    }
    for (std::size_t stalled = 0; stalled < getStallLimit() && !ptc();)
    {
        const auto robot = pickRobot(plan);
        if (!robot)
            break;
        // A window of log-uniform length in [2, arrival] (a quarter of them ending at the arrival).
        const std::size_t arrival = plan.getArrival(*robot);
        const auto length = std::min<std::size_t>(
            arrival, static_cast<std::size_t>(std::exp(rng_.uniformReal(std::log(2.), std::log(arrival + 1.)))));
        const std::size_t t1 =
            rng_.uniform01() < 0.25
                ? arrival - length
                : std::min(arrival - length, static_cast<std::size_t>(rng_.uniformReal(0., arrival - length + 1.)));
        const std::size_t t2 = t1 + length;
        ++report.attempts;
        if (replanner_ && stalled % REPLAN_PERIOD == REPLAN_PERIOD - 1)
        {
            ++report.replans;
            const std::size_t from = rng_.uniform01() < 0.5 ? 0 : t1;
            if (tryReplan(plan, *robot, from, ptc))
            {
                ++report.replansKept;
                stalled = 0;
            }
            else
                ++stalled;
            continue;
        }
        std::size_t blocker = n;
        const std::size_t gain =
            t2 - t1 - std::min(t2 - t1, PlanQuality::straightLineSteps(*si_, plan, *robot, t1, t2));
        if (tryShortcut(plan, {*robot}, t1, t2, 0, &blocker))
            ++report.shortcuts;
        else if (blocker < n && tryShortcut(plan, {*robot, blocker}, t1, t2, 0, nullptr))
            ++report.compositeShortcuts;
        else if (gain > 0 && tryShortcut(plan, {*robot}, t1, t2, gain, nullptr))
            ++report.straightenings;
        else
        {
            ++stalled;
            continue;
        }
        stalled = 0;
    }
    report.makespanAfter = plan.getMakespan();
    report.sumOfCostsAfter = plan.getSumOfCosts();
    report.seconds = ompl::time::seconds(ompl::time::now() - started);
    return report;
}

std::optional<std::size_t> ompl_parc::PlanSmoother::pickRobot(const MultiRobotPlan &plan)
{
    std::vector<std::size_t> slow, last;
    const std::size_t makespan = plan.getMakespan();
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
        if (plan.getArrival(i) > bound_[i])
        {
            slow.push_back(i);
            if (plan.getArrival(i) == makespan)
                last.push_back(i);
        }
    if (slow.empty())
        return std::nullopt;
    const auto &from = !last.empty() && rng_.uniform01() < 0.5 ? last : slow;
    return from[static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(from.size()) - 1))];
}

bool ompl_parc::PlanSmoother::tryShortcut(MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::size_t t1,
                                          std::size_t t2, std::size_t wait, std::size_t *blocker)
{
    // The team's straight motions; the window takes as long as the slowest one, then the wait.
    from_.resize(team.size());
    to_.resize(team.size());
    std::vector<std::size_t> steps(team.size());
    std::size_t window = 0;
    for (std::size_t k = 0; k < team.size(); ++k)
    {
        const std::size_t r = team[k];
        from_[k].resize(plan.getDimension(r));
        to_[k].resize(plan.getDimension(r));
        plan.getConfig(r, t1, from_[k].data());
        plan.getConfig(r, t2, to_[k].data());
        steps[k] = MultiRobotPlan::stepsFor(distance(r, from_[k].data(), to_[k].data()), plan.getResolution());
        window = std::max(window, steps[k]);
    }
    window += wait;
    if (window > t2 - t1)
        return false;
    if (window == t2 - t1)
    {
        // No time saved: only a real shortening of the path counts (at least one timestep's motion less).
        const double straight = distance(team.front(), from_[0].data(), to_[0].data());
        if (team.size() != 1 || pathLength(plan, team.front(), t1, t2) - straight <= 1. / plan.getResolution())
            return false;
    }
    for (std::size_t k = 0; k < team.size(); ++k)
        if (!motionValid(team[k], from_[k].data(), to_[k].data()))
            return false;

    std::vector<TimedPath> changed;
    for (std::size_t k = 0; k < team.size(); ++k)
    {
        TimedPath segment(plan.getDimension(team[k]), from_[k].data());
        segment.appendMotion(from_[k].data(), to_[k].data(), steps[k]);
        segment.appendHold(to_[k].data(), window);
        changed.push_back(plan.getPath(team[k]));
        changed.back().splice(t1, t2, segment);
    }
    return keepIfClear(plan, team, std::move(changed), t1, blocker);
}

bool ompl_parc::PlanSmoother::keepIfClear(MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                          std::vector<TimedPath> changed, std::size_t t1, std::size_t *blocker)
{
    for (std::size_t k = 0; k < team.size(); ++k)
    {
        const std::size_t r = team[k];
        TimedPath old = plan.getPath(r);
        plan.setPath(r, std::move(changed[k]));
        changed[k] = std::move(old);
        detector_->restart(r, t1);
    }
    std::vector<Conflict> conflicts;
    bool clear = false;
    if (detector_->discoverPairs(plan))  // else the planning stopped: the change is not known to be clear
    {
        std::vector<std::size_t> pairs;
        for (std::size_t r : team)
            for (std::size_t p : detector_->getPairsOf(r))
            {
                const auto [i, j] = detector_->getPair(p);
                const std::size_t other = i == r ? j : i;
                if (std::find(team.begin(), team.end(), other) == team.end() || other > r)
                    pairs.push_back(p);
            }
        conflicts = detector_->scan(plan, pairs, t1, plan.getMakespan() + 1, true);
        clear = conflicts.empty() &&
                std::all_of(pairs.begin(), pairs.end(), [&](std::size_t p) { return detector_->isSettled(plan, p); });
    }
    if (clear)
        return true;
    for (std::size_t k = 0; k < team.size(); ++k)
    {
        plan.setPath(team[k], std::move(changed[k]));  // the old path
        detector_->restart(team[k], t1);               // the swept bounds were the rejected path's
    }
    if (blocker != nullptr && !conflicts.empty())
    {
        const Conflict &c = conflicts.front();
        *blocker = std::find(team.begin(), team.end(), c.first) == team.end() ? c.first : c.second;
    }
    return false;
}

bool ompl_parc::PlanSmoother::tryReplan(MultiRobotPlan &plan, std::size_t robot, std::size_t t1,
                                        const ob::PlannerTerminationCondition &ptc)
{
    const std::size_t arrival = plan.getArrival(robot);
    // The context keeps every other robot's body per timestep (DynamicObstacles): as ARC's resolver, no replan
    // over a window that long (a fine resolution).
    if (std::max(arrival, plan.getMakespan()) - t1 >= ConflictResolver::MAX_CONTEXT_TIMESTEPS)
        return false;
    Subproblem sub;
    sub.robots = {robot};
    sub.windowStart = t1;
    sub.windowEnd = std::max(arrival, plan.getMakespan());  // the others' whole paths from t1
    sub.starts.emplace_back(plan.getDimension(robot));
    plan.getConfig(robot, t1, sub.starts.back().data());
    sub.goals.emplace_back(plan.getDimension(robot));
    plan.getConfig(robot, arrival, sub.goals.back().data());
    sub.sampleCap = REPLAN_SAMPLES;
    sub.fillContext(*si_, plan);
    Patch patch;
    const auto seed = static_cast<std::uint_fast32_t>(rng_.uniformInt(1, std::numeric_limits<int>::max()));
    if (!replanner_->solve(*si_, sub, ptc, seed, patch) || t1 + patch.paths.front().getArrival() >= arrival)
        return false;
    std::vector<TimedPath> changed{plan.getPath(robot)};
    changed.front().splice(t1, arrival, patch.paths.front());
    return keepIfClear(plan, {robot}, std::move(changed), t1, nullptr);
}

ompl_parc::Subproblem ompl_parc::PlanSmoother::wholeTeam(const MultiRobotPlan &plan)
{
    Subproblem whole;
    whole.global = true;
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        whole.robots.push_back(i);
        whole.starts.emplace_back(plan.getDimension(i));
        plan.getConfig(i, 0, whole.starts.back().data());
        whole.goals.emplace_back(plan.getDimension(i));
        plan.getConfig(i, plan.getArrival(i), whole.goals.back().data());
    }
    whole.windowEnd = plan.getMakespan();
    return whole;
}

bool ompl_parc::PlanSmoother::keepIfBetter(MultiRobotPlan &plan, std::vector<TimedPath> paths)
{
    MultiRobotPlan candidate(*si_);
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
        candidate.setPath(i, paths[i]);
    if (objectiveKey(candidate, objective_) >= objectiveKey(plan, objective_))
        return false;
    std::vector<std::size_t> team(plan.getRobotCount());
    std::iota(team.begin(), team.end(), 0);
    return keepIfClear(plan, team, std::move(paths), 0, nullptr);
}

bool ompl_parc::PlanSmoother::tryTeamReplan(MultiRobotPlan &plan, const ob::PlannerTerminationCondition &ptc,
                                            bool &done)
{
    Subproblem whole = wholeTeam(plan);
    whole.sampleCap = TEAM_REPLAN_SAMPLES;
    Patch patch;
    const auto seed = static_cast<std::uint_fast32_t>(rng_.uniformInt(1, std::numeric_limits<int>::max()));
    const bool solved = replanner_->resume(*si_, whole, ptc, seed, patch, teamReplanMemory_);
    done = solved || !ptc();
    return solved && keepIfBetter(plan, std::move(patch.paths));
}

bool ompl_parc::PlanSmoother::tryTeamSolve(MultiRobotPlan &plan, const ob::PlannerTerminationCondition &ptc,
                                           bool &solved)
{
    // Each seed gives the solver another lattice origin, and where the lattice's points fall in doorways and gaps
    // decides how the team passes them: the best of a few tries is kept. A failed try has spent its time.
    const Subproblem whole = wholeTeam(plan);
    bool kept = false;
    solved = false;
    for (unsigned int k = 0; k < TEAM_SOLVE_TRIES && !ptc(); ++k)
    {
        Patch patch;
        const auto seed = static_cast<std::uint_fast32_t>(rng_.uniformInt(1, std::numeric_limits<int>::max()));
        if (!teamSolver_->solve(*si_, whole, ptc, seed, patch))
            break;
        solved = true;
        kept = keepIfBetter(plan, std::move(patch.paths)) || kept;
    }
    return kept;
}

bool ompl_parc::PlanSmoother::motionValid(std::size_t robot, const double *from, const double *to)
{
    if (!alone_[robot])
        alone_[robot] = std::make_shared<MultiRobotSpaceInformation>(std::vector<RobotPtr>{si_->getRobot(robot)},
                                                                     si_->getResolution());
    const auto &si = alone_[robot];
    ob::ScopedState<> a(si), b(si);
    const unsigned int d = si_->getRobot(robot)->getDimension();
    std::copy(from, from + d, si->getRobotValues(a.get(), 0));
    std::copy(to, to + d, si->getRobotValues(b.get(), 0));
    return si->isValid(b.get()) && si->checkMotion(a.get(), b.get());
}

double ompl_parc::PlanSmoother::distance(std::size_t robot, const double *a, const double *b) const
{
    return si_->getRobot(robot)->distance(a, b);
}

double ompl_parc::PlanSmoother::pathLength(const MultiRobotPlan &plan, std::size_t robot, std::size_t t1,
                                           std::size_t t2)
{
    // Between consecutive breakpoints the robot moves on a straight line.
    std::vector<std::size_t> times;
    plan.getPath(robot).appendBreakpoints(times);
    times.push_back(t1);
    times.push_back(t2);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    std::vector<double> a(plan.getDimension(robot)), b(a.size());
    double length = 0.;
    plan.getConfig(robot, t1, a.data());
    for (std::size_t t : times)
        if (t > t1 && t <= t2)
        {
            plan.getConfig(robot, t, b.data());
            length += distance(robot, a.data(), b.data());
            a.swap(b);
        }
    return length;
}
