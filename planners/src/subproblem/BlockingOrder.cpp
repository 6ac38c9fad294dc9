#include "ompl_parc/planners/subproblem/BlockingOrder.h"

#include "ompl_parc/collision/BoundingBox.h"
#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollisionBody.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <limits>

namespace
{
    /** Whether \e body touches one of \e bodies from position \e first on. */
    bool touchesAny(const ompl_parc::CollisionBody &body, const std::vector<ompl_parc::CollisionBody> &bodies,
                    std::size_t first, std::size_t count)
    {
        for (std::size_t k = first; k < count; ++k)
            if (ompl_parc::bodiesCollide(body, bodies[k]))
                return true;
        return false;
    }
}  // namespace

ompl_parc::BlockingOrder::BlockingOrder(const std::vector<RobotPtr> &team, const std::vector<TimedPath> &alone,
                                        const std::vector<std::vector<double>> &starts,
                                        const std::vector<std::vector<double>> &goals,
                                        const ompl::base::PlannerTerminationCondition &ptc)
    : size_(team.size()), before_(team.size() * team.size(), 0)
{
    if (alone.size() != size_ || starts.size() != size_ || goals.size() != size_)
        throw ompl::Exception("BlockingOrder", "one path alone, one start and one goal per robot needed");
    std::vector<CollisionBody> startBodies(size_), goalBodies(size_);
    std::vector<BoundingBox> startBoxes(size_), goalBoxes(size_);
    for (std::size_t k = 0; k < size_; ++k)
    {
        if (starts[k].size() != team[k]->getDimension() || goals[k].size() != team[k]->getDimension() ||
            (!alone[k].empty() && alone[k].getDimension() != team[k]->getDimension()))
            throw ompl::Exception("BlockingOrder", "a start, goal or path is not of its robot's dimension");
        team[k]->computeBody(starts[k].data(), startBodies[k]);
        team[k]->computeBody(goals[k].data(), goalBodies[k]);
        startBoxes[k].add(startBodies[k]);
        goalBoxes[k].add(goalBodies[k]);
    }
    std::vector<CollisionBody> block(BLOCK);
    std::vector<double> q;
    for (std::size_t b = 0; b < size_; ++b)
    {
        if (alone[b].empty())
            continue;
        q.resize(team[b]->getDimension());
        TimedPath::Cursor cursor(alone[b]);
        const std::size_t arrival = alone[b].getArrival();
        for (std::size_t first = 0; first <= arrival && !ptc; first += BLOCK)
        {
            const std::size_t count = std::min(BLOCK, arrival + 1 - first);
            BoundingBox box;
            for (std::size_t k = 0; k < count; ++k)
            {
                cursor.get(first + k, q.data());
                team[b]->computeBody(q.data(), block[k]);
                box.add(block[k]);
            }
            for (std::size_t a = 0; a < size_; ++a)
            {
                if (a == b)
                    continue;
                // At timestep 0 robot b is at its own start, which touches no other start.
                if (!before(a, b) && box.overlaps(startBoxes[a]) &&
                    touchesAny(startBodies[a], block, first == 0 ? 1 : 0, count))
                    before_[a * size_ + b] = 1;
                if (!before(b, a) && box.overlaps(goalBoxes[a]) && touchesAny(goalBodies[a], block, 0, count))
                    before_[b * size_ + a] = 1;
            }
        }
    }
}

std::vector<std::size_t> ompl_parc::BlockingOrder::order(const std::vector<std::size_t> &base) const
{
    std::vector<char> seen(size_, 0);
    if (base.size() != size_)
        throw ompl::Exception("BlockingOrder", "the base order must hold every robot once");
    for (std::size_t k : base)
        if (k >= size_ || seen[k]++ != 0)
            throw ompl::Exception("BlockingOrder", "the base order must hold every robot once");
    // Kahn's topological sort (see the declaration for the choice among the robots left).
    std::vector<char> placed(size_, 0);
    std::vector<std::size_t> waiting(size_, 0), result;
    for (std::size_t a = 0; a < size_; ++a)
        for (std::size_t b = 0; b < size_; ++b)
            waiting[b] += before(a, b) ? 1 : 0;
    while (result.size() < size_)
    {
        std::size_t next = size_, fewest = std::numeric_limits<std::size_t>::max();
        for (std::size_t k : base)
            if (!placed[k] && waiting[k] < fewest)
            {
                next = k;
                fewest = waiting[k];
            }
        placed[next] = 1;
        result.push_back(next);
        for (std::size_t b = 0; b < size_; ++b)
            if (before(next, b) && !placed[b])
                --waiting[b];
    }
    return result;
}
