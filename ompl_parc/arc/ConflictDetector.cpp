#include "ompl_parc/arc/ConflictDetector.h"

#include "ompl_parc/arc/DiscPairScan.h"
#include "ompl_parc/collision/CapsuleCollision.h"

#include <algorithm>
#include <numeric>
#include <limits>

namespace
{
    /** Boxes closer than this count as overlapping, so that rounding in the narrow phase can never report
        a collision the broad phase ruled out. */
    constexpr double BOX_MARGIN = 1e-9;
}  // namespace

ompl_parc::ConflictDetector::ConflictDetector(const MultiRobotSpaceInformation &si, std::size_t segmentLength)
    : si_(si),
      segmentLength_(segmentLength),
      swept_(si.getRobotCount()),
      sweptMutex_(new std::mutex[si.getRobotCount()]),
      robots_(si.getRobotCount())
{
    for (std::size_t r = 0; r < robots_; ++r)
        discs_.push_back(dynamic_cast<const DiscRobot *>(si.getRobot(r).get()));
    // Sized once (at 1024 robots the pair list alone is 8 MB of fresh pages; on huge pages, see HugePageMemory).
    pairs_.reserve(robots_ * (robots_ - 1) / 2);
    for (std::size_t i = 0; i < robots_; ++i)
        for (std::size_t j = i + 1; j < robots_; ++j)
            pairs_.emplace_back(i, j);
    frontier_.assign(pairs_.size(), 0);
    knownConflict_.assign(pairs_.size(), 0);
}

void ompl_parc::ConflictDetector::reset()
{
    std::fill(frontier_.begin(), frontier_.end(), 0);
    std::fill(knownConflict_.begin(), knownConflict_.end(), 0);
    for (SweptBounds &bounds : swept_)
    {
        bounds.valid = 0;
        bounds.current = false;
    }
}

void ompl_parc::ConflictDetector::setSegmentLength(std::size_t segmentLength)
{
    segmentLength_ = segmentLength;
    swept_.assign(robots_, SweptBounds());
}

const ompl_parc::ConflictDetector::SweptBounds &ompl_parc::ConflictDetector::sweptBounds(const MultiRobotPlan &plan,
                                                                                         std::size_t robot,
                                                                                         std::size_t last,
                                                                                         CollisionBody &scratch)
{
    std::lock_guard<std::mutex> lock(sweptMutex_[robot]);
    SweptBounds &bounds = swept_[robot];
    const Robot &model = *si_.getRobot(robot);
    const std::size_t arrival = plan.getArrival(robot);
    TimedPath::Cursor cursor(plan.getPath(robot));
    std::vector<double> q(model.getDimension()), lo(model.getDimension()), hi(model.getDimension());
    const auto boxOf = [&](std::size_t from, std::size_t to)  // timesteps [from, to)
    {
        BoundingBox box;
        if (to > from)  // kinds that bound their body from a box of configurations: from the plan's pieces
        {
            plan.getPath(robot).bounds(from, to - 1, lo.data(), hi.data());
            if (model.expandBoxOver(lo.data(), hi.data(), box.lo, box.hi))
                return box;
        }
        for (std::size_t t = from; t < to; ++t)
        {
            cursor.get(t, q.data());
            model.computeBody(q.data(), scratch);
            box.add(scratch);
        }
        return box;
    };
    if (!bounds.current)  // the path changed: its length (segment count) and final body may have too
    {
        bounds.segments.resize(arrival / segmentLength_ + 1);
        bounds.valid = std::min(bounds.valid, bounds.segments.size());
        bounds.finalBox = boxOf(arrival, arrival + 1);
        bounds.current = true;
    }
    // Resizing happens only in the first call after an invalidation, before any scan reads the vector;
    // later calls only write segments at or after `valid`, which no scan has read yet.
    const std::size_t end = std::min(last + 1, bounds.segments.size());
    for (; bounds.valid < end; ++bounds.valid)
    {
        const std::size_t from = bounds.valid * segmentLength_;
        bounds.segments[bounds.valid] = boxOf(from, std::min(from + segmentLength_, arrival + 1));
    }
    return bounds;
}

std::optional<ompl_parc::Conflict> ompl_parc::ConflictDetector::findEarliest(const MultiRobotPlan &plan)
{
    if (allPairs_.size() != pairs_.size())  // only the callers of findEarliest() need the list
    {
        allPairs_.resize(pairs_.size());
        std::iota(allPairs_.begin(), allPairs_.end(), std::size_t{0});
    }
    const auto conflicts = scan(plan, allPairs_, 0, plan.getMakespan() + 1, true);
    if (conflicts.empty())
        return std::nullopt;
    return conflicts.front();
}

std::vector<ompl_parc::Conflict> ompl_parc::ConflictDetector::scan(const MultiRobotPlan &plan,
                                                                   const std::vector<std::size_t> &pairs,
                                                                   std::size_t from, std::size_t to,
                                                                   bool firstTimestepOnly, const PairFilter &skip,
                                                                   std::size_t *resume)
{
    // The pairs that still need checking in [from, to): the next timestep each needs, the last one and
    // the end of the segment its swept bounds were last tested for. Frontiers are tracked here and written
    // back once at the end, so that workers scanning interleaved pair subsets do not write to shared cache
    // lines at every timestep.
    struct Active
    {
        std::size_t pair, next, end, boxedUntil;
    };
    std::vector<Active> active, finished;
    std::vector<Conflict> conflicts;
    std::size_t resumeAt = std::numeric_limits<std::size_t>::max();
    CollisionBody discA, discB;
    std::vector<std::size_t> arrival(robots_);
    for (std::size_t r = 0; r < robots_; ++r)
        arrival[r] = plan.getArrival(r);
    for (std::size_t p : pairs)
    {
        const auto [i, j] = pairs_[p];
        const std::size_t last = std::max(arrival[i], arrival[j]), f = frontier_[p];
        // A pair whose frontier lies before \e from has a known conflict (or an unchecked gap) there: it
        // must not be resumed at \e from, which would declare that stretch conflict-free.
        if (f < from || f > last)
            continue;
        if (f >= to)  // already known conflict-free up to a later timestep
        {
            resumeAt = std::min(resumeAt, f);
            continue;
        }
        if (skip && skip(i, j))
            continue;
        if (knownConflict_[p])  // found by an earlier scan, and neither path changed up to it since
        {
            conflicts.push_back({i, j, f});
            continue;
        }
        if (discs_[i] != nullptr && discs_[j] != nullptr)
        {
            // Two discs: straight to the pair's first conflict or its end, from the pieces (however far past
            // \e to: the frontier stops at the conflict, which a later window reports).
            DiscPairScan scan(*discs_[i], plan.getPath(i), *discs_[j], plan.getPath(j), discA, discB);
            const auto contact = scan.firstContact(f, last);
            if (const auto stopped = scan.getStoppedAt())
            {
                frontier_[p] = *stopped;  // clear before it; the rest waits for a later scan (the planning stopped)
                continue;
            }
            frontier_[p] = contact ? *contact : last + 1;
            knownConflict_[p] = contact.has_value();
            if (contact && *contact < to)
                conflicts.push_back({i, j, *contact});
            else if (contact)
                resumeAt = std::min(resumeAt, *contact);
            continue;
        }
        active.push_back({p, f, std::min(last, to - 1), 0});
    }
    // ARC's scan stops at the first timestep with a conflict: the per-timestep pairs need not look further
    // than the discs' earliest one.
    if (firstTimestepOnly && !conflicts.empty())
    {
        const std::size_t earliest = std::min_element(conflicts.begin(), conflicts.end())->timestep;
        for (Active &a : active)
            a.end = std::min(a.end, earliest);
    }
    std::size_t t = std::numeric_limits<std::size_t>::max();
    std::vector<const SweptBounds *> swept(active.empty() ? 0 : robots_, nullptr);
    std::vector<CollisionBody> bodies(active.empty() ? 0 : robots_);
    for (const Active &a : active)
    {
        t = std::min(t, a.next);
        if (segmentLength_ > 0)
            for (std::size_t r : {pairs_[a.pair].first, pairs_[a.pair].second})
                if (swept[r] == nullptr)
                    swept[r] = &sweptBounds(plan, r, (to - 1) / segmentLength_, bodies[r]);
    }

    // Bodies are computed once per robot and timestep, only for robots that some active pair needs; each robot's
    // configurations come from a cursor on its path (time only moves forward here) into its slot of `configs`.
    std::vector<std::size_t> stamp(robots_, std::numeric_limits<std::size_t>::max()), slot(robots_ + 1, 0);
    std::vector<TimedPath::Cursor> cursors;
    for (std::size_t r = 0; r < robots_ && !active.empty(); ++r)
    {
        cursors.emplace_back(plan.getPath(r));
        slot[r + 1] = slot[r] + plan.getDimension(r);
    }
    std::vector<double> configs(active.empty() ? 0 : slot.back());
    const auto body = [&](std::size_t robot, std::size_t step) -> const CollisionBody &
    {
        if (stamp[robot] != step)
        {
            double *q = configs.data() + slot[robot];
            cursors[robot].get(step, q);
            si_.getRobot(robot)->computeBody(q, bodies[robot]);
            stamp[robot] = step;
        }
        return bodies[robot];
    };

    // One pass over the active pairs per timestep that some pair needs; t then jumps to the next such one.
    const std::size_t discConflicts = conflicts.size();
    while (!active.empty() && !(firstTimestepOnly && conflicts.size() > discConflicts))
    {
        bool anyDone = false;
        std::size_t nextT = std::numeric_limits<std::size_t>::max();
        for (Active &a : active)
        {
            const auto [i, j] = pairs_[a.pair];
            if (a.next == t && segmentLength_ > 0 && t >= a.boxedUntil)
            {
                const std::size_t segment = t / segmentLength_;
                a.boxedUntil = (segment + 1) * segmentLength_;
                if (!boxAt(*swept[i], segment).overlaps(boxAt(*swept[j], segment), BOX_MARGIN))
                    a.next = std::min(a.boxedUntil, a.end + 1);  // the whole rest of the segment is clear
            }
            if (a.next == t)
            {
                if (bodiesCollide(body(i, t), body(j, t)))
                {
                    conflicts.push_back({i, j, t});
                    knownConflict_[a.pair] = 1;
                    a.end = t;  // this pair is done: its frontier stays at the conflict
                }
                else
                    a.next = t + 1;
            }
            if (a.next <= a.end && a.end > t)
                nextT = std::min(nextT, a.next);
            else
                anyDone = true;
        }
        if (anyDone)  // retire finished pairs (rare: keep the per-timestep loop to one pass)
        {
            const auto split = std::partition(active.begin(), active.end(),
                                              [t](const Active &a) { return a.next <= a.end && a.end > t; });
            finished.insert(finished.end(), split, active.end());
            active.erase(split, active.end());
        }
        t = nextT;
    }
    for (const auto *set : {&active, &finished})
        for (const Active &a : *set)
        {
            frontier_[a.pair] = a.next;
            const auto [i, j] = pairs_[a.pair];
            if (a.next <= std::max(arrival[i], arrival[j]))
                resumeAt = std::min(resumeAt, a.next);
        }
    if (resume != nullptr)
        *resume = resumeAt;
    std::sort(conflicts.begin(), conflicts.end());  // retiring pairs reorders them
    if (firstTimestepOnly && !conflicts.empty())
        conflicts.erase(std::find_if(conflicts.begin(), conflicts.end(),
                                     [&](const Conflict &c) { return c.timestep != conflicts.front().timestep; }),
                        conflicts.end());
    return conflicts;
}

void ompl_parc::ConflictDetector::invalidate(std::size_t robot, std::size_t timestep)
{
    for (std::size_t other = 0; other < robots_; ++other)
        if (other != robot)
        {
            const std::size_t p = pairIndex(std::min(robot, other), std::max(robot, other));
            if (timestep <= frontier_[p])  // a conflict at the frontier may have changed
            {
                frontier_[p] = timestep;
                knownConflict_[p] = 0;
            }
        }
    SweptBounds &bounds = swept_[robot];
    bounds.current = false;
    if (segmentLength_ > 0)
        bounds.valid = std::min(bounds.valid, timestep / segmentLength_);
}

void ompl_parc::ConflictDetector::restart(std::size_t robot, std::size_t timestep)
{
    for (std::size_t other = 0; other < robots_; ++other)
        if (other != robot)
        {
            const std::size_t p = pairIndex(std::min(robot, other), std::max(robot, other));
            frontier_[p] = timestep;
            knownConflict_[p] = 0;
        }
    invalidate(robot, timestep);  // the swept bounds
}
