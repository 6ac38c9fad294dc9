#include "ompl_parc/collision/CollidingPairSweep.h"

#include "ompl_parc/collision/CapsuleCollision.h"

#include <algorithm>
#include <array>
#include <cmath>

void ompl_parc::CollidingPairSweep::sort(const std::vector<CollisionBody> &bodies)
{
    const std::size_t n = bodies.size();
    boxes_.assign(n, BoundingBox());
    double extent = 0.;
    std::array<double, 3> low{HUGE_VAL, HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::size_t i = 0; i < n; ++i)
    {
        boxes_[i].add(bodies[i]);  // never NaN (see BoundingBox): the order below is a strict weak one
        for (int d = 0; d < 3; ++d)
        {
            for (double v : {boxes_[i].lo[d], boxes_[i].hi[d]})
                if (std::isfinite(v))
                    extent = std::max(extent, std::fabs(v));
            if (std::isfinite(boxes_[i].lo[d]))
            {
                low[d] = std::min(low[d], boxes_[i].lo[d]);
                high[d] = std::max(high[d], boxes_[i].lo[d]);
            }
        }
    }
    // Relative to the coordinates, as DiscPairScan's: rounding in the boxes never hides a touching pair.
    margin_ = 1e-9 * (1. + extent);
    // The axis along which the lower ends spread furthest (teams often stand in rows or columns).
    int axis = 0;
    double spread = -1.;
    for (int d = 0; d < 3; ++d)
        if (high[d] - low[d] > spread)
        {
            axis = d;
            spread = high[d] - low[d];
        }
    order_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        order_[i] = {boxes_[i].lo[axis], boxes_[i].hi[axis], i};
    std::sort(order_.begin(), order_.end(), [](const Extent &a, const Extent &b) { return a.lo < b.lo; });
}

template <typename Visit>
bool ompl_parc::CollidingPairSweep::sweep(Visit &&visit) const
{
    const std::size_t n = order_.size();
    for (std::size_t a = 0; a < n; ++a)
    {
        const double reach = order_[a].hi + margin_;
        for (std::size_t b = a + 1; b < n && order_[b].lo <= reach; ++b)
        {
            const auto [i, j] = std::minmax(order_[a].body, order_[b].body);
            if (boxes_[i].overlaps(boxes_[j], margin_) && visit(i, j))
                return true;
        }
    }
    return false;
}

std::optional<std::pair<std::size_t, std::size_t>> ompl_parc::CollidingPairSweep::first(
    const std::vector<CollisionBody> &bodies)
{
    sort(bodies);
    std::optional<std::pair<std::size_t, std::size_t>> found;
    sweep(
        [&](std::size_t i, std::size_t j)
        {
            const std::pair<std::size_t, std::size_t> pair{i, j};
            if ((!found || pair < *found) && bodiesCollide(bodies[i], bodies[j]))
                found = pair;
            return false;  // an earlier pair may come later in the sweep
        });
    return found;
}

bool ompl_parc::CollidingPairSweep::any(const std::vector<CollisionBody> &bodies)
{
    sort(bodies);
    return sweep([&](std::size_t i, std::size_t j) { return bodiesCollide(bodies[i], bodies[j]); });
}
