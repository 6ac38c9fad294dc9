#include "ompl_parc/planners/subproblem/BlockingOrder.h"

#include <ompl/util/Exception.h>

#include <limits>

ompl_parc::BlockingOrder::BlockingOrder(std::vector<std::shared_ptr<const BodyTrack>> tracks,
                                        std::vector<CollisionBody> starts, std::vector<CollisionBody> goals)
    : size_(tracks.size()), tracks_(std::move(tracks)), before_(size_ * size_, 0)
{
    if (starts.size() != size_ || goals.size() != size_)
        throw ompl::Exception("BlockingOrder", "one start and one goal body per robot needed");
    CollisionBody scratch;
    for (std::size_t a = 0; a < size_; ++a)
        for (std::size_t b = 0; b < size_; ++b)
        {
            if (a == b)
                continue;
            // At timestep 0 robot b is at its own start, which touches no other start.
            if (onPath(starts[a], b, 1, scratch))
                before_[a * size_ + b] = 1;
            if (onPath(goals[a], b, 0, scratch))
                before_[b * size_ + a] = 1;
        }
}

bool ompl_parc::BlockingOrder::onPath(const CollisionBody &body, std::size_t k, std::size_t first,
                                      CollisionBody &scratch) const
{
    const auto &track = tracks_[k];
    if (!track)
        return false;
    for (std::size_t t = first; t < track->size(); ++t)
        if (track->collides(t, body, scratch))
            return true;
    return false;
}

std::vector<std::size_t> ompl_parc::BlockingOrder::order(const std::vector<std::size_t> &base) const
{
    std::vector<char> seen(size_, 0);
    if (base.size() != size_)
        throw ompl::Exception("BlockingOrder", "the base order must hold every robot once");
    for (std::size_t k : base)
        if (k >= size_ || seen[k]++ != 0)
            throw ompl::Exception("BlockingOrder", "the base order must hold every robot once");
    // Kahn's topological sort, taking among the robots that nothing unplaced must precede the first in base
    // order; in a cycle, the robot with the fewest unplaced predecessors (then the first in base order).
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
