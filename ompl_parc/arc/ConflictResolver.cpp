#include "ompl_parc/arc/ConflictResolver.h"

#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace ob = ompl::base;

namespace
{
    std::size_t latestArrival(const ompl_parc::MultiRobotPlan &plan, const std::vector<std::size_t> &team)
    {
        std::size_t latest = 0;
        for (std::size_t r : team)
            latest = std::max(latest, plan.getArrival(r));
        return latest;
    }
}  // namespace

ompl_parc::ConflictResolver::ConflictResolver(const MultiRobotSpaceInformation &si, ArcSettings settings,
                                              std::vector<SubproblemSolverPtr> hierarchy)
    : si_(si), settings_(settings), hierarchy_(std::move(hierarchy)), made_(ompl::time::now())
{
    if (hierarchy_.empty())
        throw ompl::Exception("ConflictResolver", "needs at least one subproblem solver");
    usesContext_ = std::any_of(hierarchy_.begin(), hierarchy_.end(),
                               [](const SubproblemSolverPtr &solver) { return solver->usesContext(); });
}

bool ompl_parc::ConflictResolver::teamClear(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                            std::size_t timestep) const
{
    std::vector<std::vector<double>> q;
    for (std::size_t r : team)
    {
        q.emplace_back(plan.getDimension(r));
        plan.getConfig(r, timestep, q.back().data());
    }
    for (std::size_t a = 0; a < team.size(); ++a)
        for (std::size_t b = a + 1; b < team.size(); ++b)
            if (si_.robotsCollide(team[a], q[a].data(), team[b], q[b].data()))
                return false;
    return true;
}

void ompl_parc::ConflictResolver::fillEndpoints(const MultiRobotPlan &plan, Subproblem &sub) const
{
    sub.starts.clear();
    sub.goals.clear();
    for (std::size_t r : sub.robots)
    {
        sub.starts.emplace_back(plan.getDimension(r));
        sub.goals.emplace_back(plan.getDimension(r));
        plan.getConfig(r, sub.windowStart, sub.starts.back().data());
        plan.getConfig(r, sub.windowEnd, sub.goals.back().data());
    }
}

void ompl_parc::ConflictResolver::fillBounds(const MultiRobotPlan &plan, Subproblem &sub) const
{
    sub.bounds.clear();
    for (std::size_t r : sub.robots)
    {
        const auto &limits = si_.getRobot(r)->getBounds();
        const unsigned int dim = plan.getDimension(r);
        ob::RealVectorBounds b(dim);
        std::vector<double> low(dim), high(dim);
        plan.getPath(r).bounds(sub.windowStart, sub.windowEnd, low.data(), high.data());
        for (unsigned int d = 0; d < dim; ++d)
        {
            double lo = low[d], hi = high[d];
            const double pad = settings_.boundMargin * (hi - lo);
            lo -= pad;
            hi += pad;
            const double lack = settings_.minBoundRange - (hi - lo);
            if (lack > 0.)
            {
                lo -= 0.5 * lack;
                hi += 0.5 * lack;
            }
            b.setLow(d, std::max(lo, limits.low[d]));
            b.setHigh(d, std::min(hi, limits.high[d]));
        }
        sub.bounds.push_back(b);
    }
}

void ompl_parc::ConflictResolver::fillContext(const MultiRobotPlan &plan, Subproblem &sub) const
{
    sub.others.clear();
    sub.otherPaths.clear();
    if (usesContext_ && sub.windowEnd - sub.windowStart < MAX_CONTEXT_TIMESTEPS)
        sub.fillContext(si_, plan);
}

std::pair<std::size_t, std::size_t> ompl_parc::ConflictResolver::window(const MultiRobotPlan &plan,
                                                                        const std::vector<std::size_t> &team,
                                                                        std::size_t timestep,
                                                                        unsigned int attempt) const
{
    const std::size_t latest = latestArrival(plan, team), h = settings_.halfWidth(attempt);
    std::size_t start = timestep > h ? timestep - h : 0, end = std::min(timestep + h, latest);
    // Endpoints first: widen an invalid side until the team is clear there (always true at 0 and at the end).
    const std::size_t step = std::max(1u, settings_.endpointStep);
    // (Millions of steps at a resolution far above the usual: the search stops with the planning.)
    while (start > 0 && !teamClear(plan, team, start) && !StopSignal::raised())
        start = start > step ? start - step : 0;
    while (end < latest && !teamClear(plan, team, end) && !StopSignal::raised())
        end = std::min(end + step, latest);
    return {start, end};
}

ompl_parc::Subproblem ompl_parc::ConflictResolver::makeSubproblem(const MultiRobotPlan &plan,
                                                                  const std::vector<std::size_t> &team,
                                                                  std::size_t timestep, unsigned int attempt) const
{
    const auto [start, end] = window(plan, team, timestep, attempt);
    return makeWindow(plan, team, start, end);
}

ompl_parc::Subproblem ompl_parc::ConflictResolver::makeWindow(const MultiRobotPlan &plan,
                                                              const std::vector<std::size_t> &team, std::size_t start,
                                                              std::size_t end) const
{
    Subproblem sub;
    sub.robots = team;
    sub.windowStart = start;
    sub.windowEnd = end;
    fillEndpoints(plan, sub);
    fillBounds(plan, sub);
    fillContext(plan, sub);
    sub.sampleCap = settings_.sampleCap;
    return sub;
}

ompl_parc::Subproblem ompl_parc::ConflictResolver::makeGlobal(const MultiRobotPlan &plan,
                                                              const std::vector<std::size_t> &team,
                                                              unsigned int round) const
{
    Subproblem sub;
    sub.robots = team;
    sub.windowStart = 0;
    sub.windowEnd = latestArrival(plan, team);
    fillEndpoints(plan, sub);
    fillContext(plan, sub);
    sub.sampleCap = Subproblem::doubledCap(settings_.sampleCap, round);
    sub.global = true;
    return sub;
}

std::optional<ompl_parc::Repair> ompl_parc::ConflictResolver::resolve(
    const MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::size_t timestep,
    const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, ResolveTrace *trace) const
{
    ResolveTrace local;
    ResolveTrace &t = trace != nullptr ? *trace : local;
    t = ResolveTrace();
    Repair repair;
    bool global = false;  // the rounds pose the team's global problem (a window before)
    std::vector<std::size_t> members = team;
    std::size_t lastStart = 0, lastEnd = 0;
    double sizeLength = 0.;  // the length of the first window of the size being tried
    unsigned int triesOfSize = 0;
    // The global rounds of one team are one problem (only the sample cap grows): each solver goes on from where its
    // last round's call was cut instead of starting over (SubproblemSolver::resume).
    std::vector<std::unique_ptr<SubproblemSolver::Memory>> memories(hierarchy_.size());
    const auto forget = [&]
    {
        std::transform(hierarchy_.begin(), hierarchy_.end(), memories.begin(),
                       [](const SubproblemSolverPtr &solver) { return solver->makeMemory(); });
    };
    const bool skipping = settings_.minWindowGrowth > 1.;
    for (unsigned int k = 0; !ptc; ++k)
    {
        Subproblem sub;
        if (global)
            sub = makeGlobal(plan, members, t.globalRounds);
        else
        {
            const auto [start, end] = window(plan, team, timestep, k);
            // The schedule stopped growing, the window covers the team's whole plan or, when every window is tried,
            // it is the failed one again: the global problem.
            const bool stuck = k > 0 && (settings_.halfWidth(k) <= settings_.halfWidth(k - 1) ||
                                         (!skipping && start == lastStart && end == lastEnd));
            // A window hardly longer than the first of its size poses nearly the same subproblem again: tried once
            // more (a fresh seed), then skipped for a wider one.
            const bool sameSize =
                skipping && k > 0 && static_cast<double>(end - start) < settings_.minWindowGrowth * sizeLength;
            if (stuck || (start == 0 && end == latestArrival(plan, team)))
            {
                global = true;
                sub = makeGlobal(plan, members, t.globalRounds);
                if (t.globalRounds == 0)  // later passes go on with the memories of the earlier global rounds
                    forget();
            }
            else if (sameSize && triesOfSize >= WINDOW_TRIES)
                continue;
            else
            {
                if (!sameSize)
                {
                    sizeLength = static_cast<double>(end - start);
                    triesOfSize = 0;
                }
                ++triesOfSize;
                sub = makeWindow(plan, team, start, end);
                t.expansions += k > 0 ? 1 : 0;
            }
        }
        t.globalRounds += global ? 1 : 0;
        lastStart = sub.windowStart;
        lastEnd = sub.windowEnd;
        const auto posed = ompl::time::now();
        for (std::size_t s = 0; s < hierarchy_.size(); ++s)
        {
            const auto &solver = hierarchy_[s];
            if (ptc)
                break;
            ++t.calls;
            const auto start = ompl::time::now();
            const double cap = std::max(MIN_CALL_SECONDS, ompl::time::seconds(start - made_));
            const auto capped = ob::plannerOrTerminationCondition(
                ptc, ob::PlannerTerminationCondition([start, cap]
                                                     { return ompl::time::seconds(ompl::time::now() - start) > cap; }));
            const StopSignal::Scope scope(capped);
            // Memories belong to the team's global problem: a window (of a later pass) is posed afresh.
            const bool solved = solver->resume(si_, sub, capped, mixSeed(seed, t.calls), repair.patch,
                                               global ? memories[s].get() : nullptr);
            t.longestCall = std::max(t.longestCall, ompl::time::seconds(ompl::time::now() - start));
            if (solved)
            {
                repair.subproblem = std::move(sub);
                repair.solver = solver->getName();
                return repair;
            }
        }
        const double spent = ompl::time::seconds(ompl::time::now() - posed);
        t.globalSeconds += global ? spent : 0.;
        t.againSeconds += !global && t.passes > 0 ? spent : 0.;
        // The team's global problem failed around the other robots' fixed paths (a solver planned around them):
        // the next rounds plan every robot.
        if (global && usesContext_ && members.size() < si_.getRobotCount())
        {
            members.resize(si_.getRobotCount());
            std::iota(members.begin(), members.end(), 0);
            forget();  // another team
        }
        // With skipping, a failed global round sends the schedule back to the first window (fresh seeds) while its
        // later passes have had no more time than the global rounds: a window that needed more than WINDOW_TRIES
        // seeds gets them, and the global problem, whose cap keeps doubling and whose solvers resume, at least half of
        // the time after the first pass.
        if (global && skipping && t.againSeconds <= t.globalSeconds)
        {
            ++t.passes;
            global = false;
            k = std::numeric_limits<unsigned int>::max();  // ++k: the first window again (a new size)
        }
    }
    return std::nullopt;
}
