#include "ompl_parc/mapf/LatticeGraph.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace
{
    /** The lattice coordinates c with low <= origin + step c <= high, as [first, first + extent). */
    std::pair<long, long> axisRange(double low, double high, double origin, double step)
    {
        const double a = std::ceil((low - origin) / step - 1e-9), b = std::floor((high - origin) / step + 1e-9);
        if (!(b >= a) || !std::isfinite(a) || !std::isfinite(b) || b - a > 1e12)
            return {0, b >= a ? -1 : 0};
        return {static_cast<long>(a), static_cast<long>(b - a) + 1};
    }
}  // namespace

std::size_t ompl_parc::LatticeGraph::countPoints(const std::vector<double> &low, const std::vector<double> &high,
                                                 const std::vector<double> &origin, double step)
{
    std::size_t count = 1;
    for (std::size_t d = 0; d < low.size() && d < high.size() && d < origin.size(); ++d)
    {
        const long extent = axisRange(low[d], high[d], origin[d], step).second;
        if (extent < 0)
            return std::numeric_limits<std::size_t>::max();
        if (extent == 0)
            return 0;
        const auto e = static_cast<std::size_t>(extent);
        if (count > std::numeric_limits<std::size_t>::max() / e)
            return std::numeric_limits<std::size_t>::max();
        count *= e;
    }
    return count;
}

ompl_parc::LatticeGraph::LatticeGraph(const std::vector<double> &low, const std::vector<double> &high,
                                      const std::vector<double> &origin, double step, const PointCheck &free,
                                      const MoveCheck &move, std::size_t maxPoints)
    : dimension_(static_cast<unsigned int>(low.size())), step_(step), origin_(origin)
{
    if (!(step > 0.) || !std::isfinite(step))
        throw ompl::Exception("LatticeGraph", "the lattice step must be positive and finite");
    if (low.empty() || low.size() > MAX_DIMENSION || high.size() != low.size() || origin.size() != low.size())
        throw ompl::Exception("LatticeGraph", "bounds and origin need the same size, 1 to 3 values");
    const std::size_t total = countPoints(low, high, origin, step);
    if (total > maxPoints)
        throw ompl::Exception("LatticeGraph", "the box holds more lattice points than the limit");
    for (unsigned int d = 0; d < dimension_; ++d)
    {
        const auto [first, extent] = axisRange(low[d], high[d], origin[d], step);
        first_.push_back(first);
        extent_.push_back(std::max(0L, extent));
    }
    index_.assign(total, NONE);
    std::vector<double> q(dimension_);
    std::vector<long> c(dimension_, 0);
    for (std::size_t cell = 0; cell < total; ++cell)
    {
        std::size_t rest = cell;
        for (unsigned int d = dimension_; d-- > 0;)
        {
            c[d] = first_[d] + static_cast<long>(rest % static_cast<std::size_t>(extent_[d]));
            rest /= static_cast<std::size_t>(extent_[d]);
            q[d] = origin_[d] + step_ * static_cast<double>(c[d]);
        }
        if (!free(q.data()))
            continue;
        index_[cell] = static_cast<Vertex>(points_.size() / dimension_);
        points_.insert(points_.end(), q.begin(), q.end());
        for (long v : c)
            coords_.push_back(static_cast<std::int32_t>(v));
    }
    // Edges to the axis neighbours, each move checked once (from the lower point) and stored both ways.
    const std::size_t vertices = points_.size() / dimension_;
    std::vector<std::vector<Vertex>> lists(vertices);
    std::size_t stride = 1;
    for (unsigned int d = dimension_; d-- > 0;)
    {
        for (std::size_t cell = 0; cell < total; ++cell)
        {
            const Vertex a = index_[cell];
            const auto along = static_cast<long>((cell / stride) % static_cast<std::size_t>(extent_[d]));
            if (a == NONE || along + 1 >= extent_[d])
                continue;
            const Vertex b = index_[cell + stride];
            if (b != NONE && move(getPoint(a), getPoint(b)))
            {
                lists[a].push_back(b);
                lists[b].push_back(a);
            }
        }
        stride *= static_cast<std::size_t>(extent_[d]);
    }
    offsets_.push_back(0);
    for (const auto &list : lists)
    {
        adjacency_.insert(adjacency_.end(), list.begin(), list.end());
        offsets_.push_back(adjacency_.size());
    }
}

std::vector<ompl_parc::LatticeGraph::Vertex> ompl_parc::LatticeGraph::near(const double *q, double radius) const
{
    std::vector<std::pair<double, Vertex>> found;
    std::vector<long> lo(dimension_), hi(dimension_);
    for (unsigned int d = 0; d < dimension_; ++d)
    {
        lo[d] = std::max(first_[d], static_cast<long>(std::ceil((q[d] - radius - origin_[d]) / step_)));
        hi[d] =
            std::min(first_[d] + extent_[d] - 1, static_cast<long>(std::floor((q[d] + radius - origin_[d]) / step_)));
        if (hi[d] < lo[d])
            return {};
    }
    std::vector<long> c(lo);
    while (true)
    {
        std::size_t cell = 0;
        for (unsigned int d = 0; d < dimension_; ++d)
            cell = cell * static_cast<std::size_t>(extent_[d]) + static_cast<std::size_t>(c[d] - first_[d]);
        if (const Vertex v = index_[cell]; v != NONE)
        {
            double squared = 0.;
            for (unsigned int d = 0; d < dimension_; ++d)
                squared += (getPoint(v)[d] - q[d]) * (getPoint(v)[d] - q[d]);
            if (squared <= radius * radius)
                found.emplace_back(squared, v);
        }
        unsigned int d = dimension_;
        while (d-- > 0 && ++c[d] > hi[d])
            c[d] = lo[d];
        if (d > dimension_)  // wrapped past the first axis
            break;
    }
    std::sort(found.begin(), found.end());
    std::vector<Vertex> result;
    for (const auto &f : found)
        result.push_back(f.second);
    return result;
}

void ompl_parc::LatticeGraph::hopsTo(Vertex target, std::vector<std::uint32_t> &hops) const
{
    hops.assign(size(), UNREACHABLE);
    std::deque<Vertex> queue{target};
    hops[target] = 0;
    while (!queue.empty())
    {
        const Vertex v = queue.front();
        queue.pop_front();
        const auto [first, last] = getNeighbours(v);
        for (const Vertex *n = first; n != last; ++n)
            if (hops[*n] == UNREACHABLE)
            {
                hops[*n] = hops[v] + 1;
                queue.push_back(*n);
            }
    }
}

std::vector<std::uint32_t> ompl_parc::LatticeGraph::components() const
{
    std::vector<std::uint32_t> label(size(), UNREACHABLE);
    std::uint32_t next = 0;
    std::vector<Vertex> stack;
    for (Vertex seed = 0; seed < size(); ++seed)
    {
        if (label[seed] != UNREACHABLE)
            continue;
        label[seed] = next;
        stack.push_back(seed);
        while (!stack.empty())
        {
            const Vertex v = stack.back();
            stack.pop_back();
            const auto [first, last] = getNeighbours(v);
            for (const Vertex *n = first; n != last; ++n)
                if (label[*n] == UNREACHABLE)
                {
                    label[*n] = next;
                    stack.push_back(*n);
                }
        }
        ++next;
    }
    return label;
}

bool ompl_parc::LatticeGraph::straight(Vertex a, Vertex b, Vertex c) const
{
    for (unsigned int d = 0; d < dimension_; ++d)
        if (coords_[b * dimension_ + d] - coords_[a * dimension_ + d] !=
            coords_[c * dimension_ + d] - coords_[b * dimension_ + d])
            return false;
    return true;
}
