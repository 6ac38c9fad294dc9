#include "ompl_parc/arc/ConflictDetector.h"

#include "ompl_parc/arc/DiscPairScan.h"
#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/util/StopSignal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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
    robots_(si.getRobotCount()),
    reach_(robots_),
    hull_(robots_),
    changedFrom_(robots_, 0),
    robotPairs_(robots_)
{
    for (std::size_t r = 0; r < robots_; ++r)
        discs_.push_back(dynamic_cast<const DiscRobot *>(si.getRobot(r).get()));
}

void ompl_parc::ConflictDetector::reset()
{
    pairs_.clear();
    frontier_.clear();
    knownConflict_.clear();
    pairIndex_.clear();
    for (auto &pairs : robotPairs_)
        pairs.clear();
    std::fill(changedFrom_.begin(), changedFrom_.end(), 0);
    reachLength_ = 0;
    for (SweptBounds &reach : reach_)
        reach.segments.clear();
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

ompl_parc::BoundingBox ompl_parc::ConflictDetector::boxOver(const MultiRobotPlan &plan, std::size_t robot,
                                                            std::size_t from, std::size_t to, CollisionBody &scratch,
                                                            std::vector<double> &work) const
{
    const Robot &model = *si_.getRobot(robot);
    const std::size_t dimension = model.getDimension();
    work.resize(3 * dimension);
    double *lo = work.data(), *hi = lo + dimension, *q = hi + dimension;
    BoundingBox box;
    if (to <= from)
        return box;
    plan.getPath(robot).bounds(from, to - 1, lo, hi);
    if (model.expandBoxOver(lo, hi, box.lo, box.hi))  // kinds that bound their body from a box of configurations
        return box;
    TimedPath::Cursor cursor(plan.getPath(robot));
    for (std::size_t t = from; t < to; ++t)
    {
        cursor.get(t, q);
        model.computeBody(q, scratch);
        box.add(scratch);
    }
    return box;
}

const ompl_parc::ConflictDetector::SweptBounds &ompl_parc::ConflictDetector::sweptBounds(const MultiRobotPlan &plan,
                                                                                         std::size_t robot,
                                                                                         std::size_t last,
                                                                                         CollisionBody &scratch)
{
    std::lock_guard<std::mutex> lock(sweptMutex_[robot]);
    SweptBounds &bounds = swept_[robot];
    const std::size_t arrival = plan.getArrival(robot);
    std::vector<double> work;
    if (!bounds.current)  // the path changed: its length (segment count) and final body may have too
    {
        bounds.segments.resize(arrival / segmentLength_ + 1);
        bounds.valid = std::min(bounds.valid, bounds.segments.size());
        bounds.finalBox = boxOver(plan, robot, arrival, arrival + 1, scratch, work);
        bounds.current = true;
    }
    // Resizing happens only in the first call after an invalidation, before any scan reads the vector;
    // later calls only write segments at or after `valid`, which no scan has read yet.
    const std::size_t end = std::min(last + 1, bounds.segments.size());
    for (; bounds.valid < end; ++bounds.valid)
    {
        const std::size_t from = bounds.valid * segmentLength_;
        bounds.segments[bounds.valid] =
            boxOver(plan, robot, from, std::min(from + segmentLength_, arrival + 1), scratch, work);
    }
    return bounds;
}

void ompl_parc::ConflictDetector::computeReach(const MultiRobotPlan &plan, std::size_t robot, std::size_t first,
                                               CollisionBody &scratch, std::vector<double> &work)
{
    SweptBounds &reach = reach_[robot];
    const std::size_t arrival = plan.getArrival(robot);
    // Segments past the old end were not computed (the final box stood for them).
    first = std::min(first, reach.segments.size());
    reach.segments.resize(arrival / reachLength_ + 1);
    reach.finalBox = boxOver(plan, robot, arrival, arrival + 1, scratch, work);
    BoundingBox hull = reach.finalBox;
    for (std::size_t k = 0; k < reach.segments.size(); ++k)
    {
        if (k >= first)
            reach.segments[k] = boxOver(plan, robot, k * reachLength_,
                                        std::min((k + 1) * reachLength_, arrival + 1), scratch, work);
        hull.add(reach.segments[k]);
    }
    hull_[robot] = hull;
}

void ompl_parc::ConflictDetector::trackPair(std::size_t i, std::size_t j)
{
    const auto [entry, added] = pairIndex_.emplace(key(i, j), pairs_.size());
    if (!added)
        return;
    robotPairs_[i].push_back(entry->second);
    robotPairs_[j].push_back(entry->second);
    pairs_.emplace_back(i, j);
    // Before both robots' changes the pair was proven apart (or, never discovered, nothing is known: 0).
    frontier_.push_back(std::min(changedFrom_[i], changedFrom_[j]));
    knownConflict_.push_back(0);
}

bool ompl_parc::ConflictDetector::sweepAll(std::size_t firstSegment)
{
    // Per segment, a grid in x and y of cells twice the median box's extent along each axis (a team moving along
    // lines has long, thin boxes): each box is listed in the cells it covers, and robots sharing a cell are tested
    // (a pair sharing several cells is tracked once). Boxes over more than MAX_CELLS cells (or unbounded) are tested
    // against every robot instead (a team whose robots move along different axes has many: time, not memory).
    constexpr double MAX_CELLS = 16.;
    std::size_t segments = 0;
    for (const SweptBounds &reach : reach_)
        segments = std::max(segments, reach.segments.size());
    const auto needs = [&](std::size_t k, std::size_t i, std::size_t j)
    { return k >= std::min(changedFrom_[i], changedFrom_[j]) / reachLength_; };
    const auto test = [&](std::size_t k, std::size_t i, std::size_t j)
    {
        if (i != j && needs(k, i, j) && boxAt(reach_[i], k).overlaps(boxAt(reach_[j], k), BOX_MARGIN))
            trackPair(std::min(i, j), std::max(i, j));
    };
    std::vector<double> extents[2] = {std::vector<double>(robots_), std::vector<double>(robots_)};
    std::vector<std::pair<std::uint64_t, std::size_t>> cells;
    std::vector<std::size_t> large;
    for (std::size_t k = firstSegment; k <= segments; ++k)  // the last one: every robot at its final box
    {
        if (StopSignal::raised())
            return false;
        double cell[2];
        for (int d = 0; d < 2; ++d)
        {
            for (std::size_t r = 0; r < robots_; ++r)
                extents[d][r] = boxAt(reach_[r], k).hi[d] - boxAt(reach_[r], k).lo[d];
            std::nth_element(extents[d].begin(), extents[d].begin() + robots_ / 2, extents[d].end());
            cell[d] = std::max(2. * extents[d][robots_ / 2], 1e-6);
        }
        cells.clear();
        large.clear();
        for (std::size_t r = 0; r < robots_; ++r)
        {
            const BoundingBox &box = boxAt(reach_[r], k);
            const double x0 = std::floor(box.lo[0] / cell[0]), x1 = std::floor(box.hi[0] / cell[0]),
                         y0 = std::floor(box.lo[1] / cell[1]), y1 = std::floor(box.hi[1] / cell[1]);
            if (!((x1 - x0 + 1.) * (y1 - y0 + 1.) <= MAX_CELLS))  // NaN and infinities included
            {
                large.push_back(r);
                continue;
            }
            for (double x = x0; x <= x1; ++x)
                for (double y = y0; y <= y1; ++y)  // collisions of the hash only cost extra box tests
                    cells.emplace_back(static_cast<std::uint64_t>(static_cast<std::int64_t>(x)) *
                                               0x9E3779B97F4A7C15ULL +
                                           static_cast<std::uint64_t>(static_cast<std::int64_t>(y)),
                                       r);
        }
        std::sort(cells.begin(), cells.end());
        for (std::size_t first = 0, last; first < cells.size(); first = last)
        {
            for (last = first + 1; last < cells.size() && cells[last].first == cells[first].first; ++last)
                ;
            for (std::size_t a = first; a < last; ++a)
                for (std::size_t b = a + 1; b < last; ++b)
                    test(k, cells[a].second, cells[b].second);
        }
        for (std::size_t r : large)
        {
            if (StopSignal::raised())
                return false;
            for (std::size_t other = 0; other < robots_; ++other)
                test(k, r, other);
        }
    }
    return true;
}

bool ompl_parc::ConflictDetector::testEach(const std::vector<std::size_t> &changed)
{
    for (std::size_t r : changed)
    {
        if (StopSignal::raised())
            return false;
        const SweptBounds &reach = reach_[r];
        const std::size_t first = changedFrom_[r] / reachLength_;
        BoundingBox changedBox = reach.finalBox;  // the box of its changed segments
        for (std::size_t k = first; k < reach.segments.size(); ++k)
            changedBox.add(reach.segments[k]);
        for (std::size_t other = 0; other < robots_; ++other)
        {
            if (other == r || !changedBox.overlaps(hull_[other], BOX_MARGIN))
                continue;
            const std::size_t i = std::min(r, other), j = std::max(r, other);
            if (pairIndex_.count(key(i, j)) != 0)
                continue;
            const std::size_t last = std::max(reach.segments.size(), reach_[other].segments.size());
            for (std::size_t k = first; k <= last; ++k)
                if (boxAt(reach, k).overlaps(boxAt(reach_[other], k), BOX_MARGIN))
                {
                    trackPair(i, j);
                    break;
                }
        }
    }
    return true;
}

bool ompl_parc::ConflictDetector::discoverPairs(const MultiRobotPlan &plan)
{
    if (reachLength_ == 0)  // H times a power of two: REACH_SEGMENTS of them span the plan
    {
        reachLength_ = std::max<std::size_t>(segmentLength_, 1);
        while (reachLength_ * REACH_SEGMENTS < plan.getMakespan() + 1)
            reachLength_ *= 2;
    }
    std::vector<std::size_t> changed;
    std::size_t firstSegment = NONE, segments = 0;
    CollisionBody scratch;
    std::vector<double> work;
    for (std::size_t r = 0; r < robots_; ++r)
        if (changedFrom_[r] != NONE)
        {
            if (StopSignal::raised())
                return false;
            computeReach(plan, r, changedFrom_[r] / reachLength_, scratch, work);
            changed.push_back(r);
            firstSegment = std::min(firstSegment, changedFrom_[r] / reachLength_);
            segments = std::max(segments, reach_[r].segments.size());
        }
    if (changed.empty())
        return true;
    // Testing one changed robot costs about one box test per robot, a sweep some 16 per robot and segment (the
    // sort): a repair's few robots are tested each, a new plan's whole team swept.
    constexpr std::size_t SWEEP_COST = 16;
    const std::size_t swept = std::max(segments, firstSegment + 1) - firstSegment;
    if (!(changed.size() <= SWEEP_COST * swept ? testEach(changed) : sweepAll(firstSegment)))
        return false;
    for (std::size_t r : changed)
        changedFrom_[r] = NONE;
    return true;
}

std::optional<std::size_t> ompl_parc::ConflictDetector::findPair(std::size_t i, std::size_t j) const
{
    const auto entry = pairIndex_.find(key(i, j));
    if (entry == pairIndex_.end())
        return std::nullopt;
    return entry->second;
}

std::size_t ompl_parc::ConflictDetector::getFrontier(std::size_t i, std::size_t j) const
{
    const auto pair = findPair(i, j);
    return pair ? frontier_[*pair] : 0;
}

std::optional<ompl_parc::Conflict> ompl_parc::ConflictDetector::findEarliest(const MultiRobotPlan &plan)
{
    if (!discoverPairs(plan))
        return std::nullopt;
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
    // The stop is polled every PAIRS_PER_POLL pairs (a disc pair costs a few pieces) and, in the per-timestep
    // loop, every StopSignal::POLL_INTERVAL pair checks.
    constexpr std::size_t PAIRS_PER_POLL = 256;
    std::size_t considered = 0;
    bool stopped = false;  // the pairs left, and the active pairs' rest, stay unchecked
    for (std::size_t p : pairs)
    {
        if (++considered % PAIRS_PER_POLL == 0 && (stopped = StopSignal::raised()))
            break;
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
            if (const auto stoppedAt = scan.getStoppedAt())
            {
                frontier_[p] = *stoppedAt;  // clear before it; the rest waits for a later scan (the planning stopped)
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
    std::size_t checks = 0;
    while (!stopped && !active.empty() && !(firstTimestepOnly && conflicts.size() > discConflicts))
    {
        checks += active.size();
        if (checks >= StopSignal::POLL_INTERVAL)
        {
            checks = 0;
            if ((stopped = StopSignal::raised()))
                break;  // the active pairs' frontiers stay at their first unchecked timestep
        }
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
    for (std::size_t p : robotPairs_[robot])
        if (timestep <= frontier_[p])  // a conflict at the frontier may have changed
        {
            frontier_[p] = timestep;
            knownConflict_[p] = 0;
        }
    changedFrom_[robot] = std::min(changedFrom_[robot], timestep);
    SweptBounds &bounds = swept_[robot];
    bounds.current = false;
    if (segmentLength_ > 0)
        bounds.valid = std::min(bounds.valid, timestep / segmentLength_);
}

void ompl_parc::ConflictDetector::restart(std::size_t robot, std::size_t timestep)
{
    for (std::size_t p : robotPairs_[robot])
    {
        frontier_[p] = timestep;
        knownConflict_[p] = 0;
    }
    invalidate(robot, timestep);  // the swept bounds, and the discovery of its new pairs
}
