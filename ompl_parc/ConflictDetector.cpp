#include "ompl_parc/ConflictDetector.h"

#include "ompl_parc/CapsuleCollision.h"

#include <algorithm>
#include <limits>

ompl_parc::ConflictDetector::ConflictDetector(const MultiRobotSpaceInformation &si)
    : si_(si), robots_(si.getRobotCount())
{
    for (std::size_t i = 0; i < robots_; ++i)
        for (std::size_t j = i + 1; j < robots_; ++j)
            pairs_.emplace_back(i, j);
    frontier_.assign(pairs_.size(), 0);
    allPairs_.resize(pairs_.size());
    for (std::size_t p = 0; p < pairs_.size(); ++p)
        allPairs_[p] = p;
}

std::optional<ompl_parc::Conflict> ompl_parc::ConflictDetector::findEarliest(const MultiRobotPlan &plan)
{
    const auto conflicts = scan(plan, allPairs_, 0, plan.getMakespan() + 1, true);
    if (conflicts.empty())
        return std::nullopt;
    return conflicts.front();
}

std::vector<ompl_parc::Conflict> ompl_parc::ConflictDetector::scan(const MultiRobotPlan &plan,
                                                                   const std::vector<std::size_t> &pairs,
                                                                   std::size_t from, std::size_t to,
                                                                   bool firstTimestepOnly, const PairFilter &skip)
{
    // The pairs that still need checking in [from, to): the next timestep each needs and the last one.
    // Frontiers are tracked here and written back once at the end, so that workers scanning interleaved
    // pair subsets do not write to shared cache lines at every timestep.
    struct Active
    {
        std::size_t pair, next, end;
    };
    std::vector<Active> active, finished;
    std::size_t t = std::numeric_limits<std::size_t>::max();
    for (std::size_t p : pairs)
    {
        const auto [i, j] = pairs_[p];
        if (skip && skip(i, j))
            continue;
        const std::size_t end = std::min(std::max(plan.getArrival(i), plan.getArrival(j)), to - 1);
        // A pair whose frontier lies before \e from has a known conflict (or an unchecked gap) there: it
        // must not be resumed at \e from, which would declare that stretch conflict-free.
        if (frontier_[p] >= from && frontier_[p] <= end)
        {
            active.push_back({p, frontier_[p], end});
            t = std::min(t, frontier_[p]);
        }
    }

    // Bodies are computed once per robot and timestep, only for robots that some active pair needs.
    std::vector<CollisionBody> bodies(robots_);
    std::vector<std::size_t> stamp(robots_, std::numeric_limits<std::size_t>::max());
    const auto body = [&](std::size_t robot, std::size_t step) -> const CollisionBody &
    {
        if (stamp[robot] != step)
        {
            si_.getRobot(robot)->computeBody(plan.getConfig(robot, step), bodies[robot]);
            stamp[robot] = step;
        }
        return bodies[robot];
    };

    std::vector<Conflict> conflicts;
    for (; !active.empty() && !(firstTimestepOnly && !conflicts.empty()); ++t)
    {
        bool anyDone = false;
        for (Active &a : active)
        {
            if (a.next > t)
                continue;
            const auto [i, j] = pairs_[a.pair];
            if (bodiesCollide(body(i, t), body(j, t)))
            {
                conflicts.push_back({i, j, t});
                a.end = t;  // this pair is done: its frontier stays at the conflict
            }
            else
                a.next = t + 1;
            anyDone = anyDone || a.end <= t;
        }
        if (anyDone)  // retire finished pairs (rare: keep the per-timestep loop to one pass)
        {
            const auto split = std::partition(active.begin(), active.end(), [t](const Active &a) { return a.end > t; });
            finished.insert(finished.end(), split, active.end());
            active.erase(split, active.end());
        }
    }
    for (const auto *set : {&active, &finished})
        for (const Active &a : *set)
            frontier_[a.pair] = a.next;
    return conflicts;
}

std::size_t ompl_parc::ConflictDetector::firstUnvalidated(const MultiRobotPlan &plan) const
{
    std::size_t first = plan.getMakespan() + 1;
    for (std::size_t p = 0; p < pairs_.size(); ++p)
    {
        const auto [i, j] = pairs_[p];
        if (frontier_[p] <= std::max(plan.getArrival(i), plan.getArrival(j)))
            first = std::min(first, frontier_[p]);
    }
    return first;
}

void ompl_parc::ConflictDetector::invalidate(std::size_t robot, std::size_t timestep)
{
    for (std::size_t other = 0; other < robots_; ++other)
        if (other != robot)
        {
            auto &f = frontier_[pairIndex(std::min(robot, other), std::max(robot, other))];
            f = std::min(f, timestep);
        }
}
