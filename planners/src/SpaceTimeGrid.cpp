#include "ompl_parc/planners/SpaceTimeGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
    /** Cells along the space's longest gridded side. */
    constexpr double CELLS_ALONG_LONGEST = 16.;
    /** Slabs beyond this index (times above MAX_SLABS slab widths) are not made: such points are scanned. */
    constexpr std::size_t MAX_SLABS = std::size_t{1} << 14;
    /** Relative and absolute margins of the lower bounds that skip cells (far above rounding). */
    constexpr double RELATIVE_MARGIN = 1e-9, ABSOLUTE_MARGIN = 1e-12;
    /** Below this, squared distances may underflow: no squared shortcuts. */
    constexpr double TINY = 1e-100;

    /** floor(\e f) clamped to [0, n - 1]; 0 for NaN. */
    std::size_t clampIndex(double f, std::size_t n)
    {
        if (!(f > 0.))
            return 0;
        if (f >= static_cast<double>(n - 1))
            return n - 1;
        return static_cast<std::size_t>(f);
    }

    /** The squared Euclidean distance of a point's coordinates \e c and \e q, summed in coordinate order as
        RealVectorStateSpace::distance does. */
    double squaredSpace(const double *c, const double *q, std::size_t dimension)
    {
        double squared = 0.;
        for (std::size_t k = 0; k < dimension; ++k)
        {
            const double diff = c[k] - q[k];
            squared += diff * diff;
        }
        return squared;
    }

    /** SpaceTimeStateSpace::distance from the squared space distance and the time difference (its arithmetic). */
    double combine(double squared, double deltaTime, const ompl_parc::SpaceTimeGrid::Query &query)
    {
        const double deltaSpace = std::sqrt(squared);
        if (deltaSpace / query.vMax > deltaTime + query.epsilon)
            return std::numeric_limits<double>::infinity();
        return query.spaceWeight * deltaSpace + query.timeWeight * deltaTime;
    }

    /** Whether axis \e k of \e bounds has a finite, positive extent (it is gridded then). */
    bool griddable(const ompl::base::RealVectorBounds &bounds, std::size_t k)
    {
        const double extent = bounds.high[k] - bounds.low[k];
        return std::isfinite(extent) && extent > 0. && std::isfinite(bounds.low[k]);
    }

    /** Whether a cell whose distance is at least \e bound can hold a point nearer than (or as near as) \e best. */
    bool mayHold(double bound, double best)
    {
        return bound <= best * (1. + RELATIVE_MARGIN) + ABSOLUTE_MARGIN;
    }
}  // namespace

ompl_parc::SpaceTimeGrid::SpaceTimeGrid(std::size_t dimension, const ompl::base::RealVectorBounds &bounds, double vMax)
    : dimension_(dimension), gridded_(std::min<std::size_t>(dimension, 2))
{
    double side = 0.;
    for (std::size_t k = 0; k < gridded_ && k < bounds.low.size(); ++k)
        if (griddable(bounds, k))
            side = std::max(side, (bounds.high[k] - bounds.low[k]) / CELLS_ALONG_LONGEST);
    for (std::size_t k = 0; k < gridded_ && k < bounds.low.size() && side > 0.; ++k)
    {
        if (!griddable(bounds, k))
            continue;
        const double extent = bounds.high[k] - bounds.low[k];
        cells_[k] = static_cast<std::size_t>(std::min(CELLS_ALONG_LONGEST, std::max(1., std::ceil(extent / side))));
        low_[k] = bounds.low[k];
        width_[k] = extent / static_cast<double>(cells_[k]);
        edgeSlack_[k] = RELATIVE_MARGIN * (std::fabs(bounds.low[k]) + std::fabs(bounds.high[k]));
    }
    const double slab = side / vMax;
    slabWidth_ = slab > 0. && std::isfinite(slab) ? slab : 1.;
}

std::size_t ompl_parc::SpaceTimeGrid::slabOf(double time) const
{
    const double slab = time / slabWidth_;
    if (!(slab >= 0. && slab < static_cast<double>(MAX_SLABS)))
        return std::numeric_limits<std::size_t>::max();
    return static_cast<std::size_t>(slab);
}

std::size_t ompl_parc::SpaceTimeGrid::cellOf(const double *q) const
{
    std::size_t cell = 0;
    for (std::size_t k = 0; k < gridded_; ++k)
        cell = cell * cells_[k] + clampIndex(std::floor((q[k] - low_[k]) / width_[k]), cells_[k]);
    return cell;
}

void ompl_parc::SpaceTimeGrid::add(double time, const double *q)
{
    points_.push_back(time);
    points_.insert(points_.end(), q, q + dimension_);
    place(size() - 1);
}

void ompl_parc::SpaceTimeGrid::place(std::size_t i)
{
    const double *values = points_.data() + i * stride();
    const std::size_t s = slabOf(values[0]);
    if (s == std::numeric_limits<std::size_t>::max() ||
        !std::all_of(values + 1, values + stride(), [](double v) { return std::isfinite(v); }))
    {
        outside_.push_back(i);
        return;
    }
    if (s >= slabs_.size())
        slabs_.resize(s + 1);
    Slab &slab = slabs_[s];
    if (slab.cellStart.empty())
    {
        slab.cellStart.assign(cells_[0] * cells_[1] + 1, 0);
        slab.earliest = slab.latest = values[0];
        occupied_.insert(std::lower_bound(occupied_.begin(), occupied_.end(), s), s);
    }
    slab.earliest = std::min(slab.earliest, values[0]);
    slab.latest = std::max(slab.latest, values[0]);

    const std::size_t cell = cellOf(values + 1), at = slab.cellStart[cell + 1];
    slab.ids.insert(slab.ids.begin() + static_cast<std::ptrdiff_t>(at), i);
    slab.values.insert(slab.values.begin() + static_cast<std::ptrdiff_t>(at * stride()), values, values + stride());
    for (std::size_t c = cell + 1; c < slab.cellStart.size(); ++c)
        ++slab.cellStart[c];
}

void ompl_parc::SpaceTimeGrid::remove(std::size_t i)
{
    if (i >= size())
        return;
    const auto at = points_.begin() + static_cast<std::ptrdiff_t>(i * stride());
    points_.erase(at, at + static_cast<std::ptrdiff_t>(stride()));
    slabs_.clear();
    occupied_.clear();
    outside_.clear();
    for (std::size_t j = 0; j < size(); ++j)
        place(j);
}

void ompl_parc::SpaceTimeGrid::clear()
{
    points_.clear();
    slabs_.clear();
    occupied_.clear();
    outside_.clear();
}

double ompl_parc::SpaceTimeGrid::distanceOf(const double *values, const Query &query) const
{
    return combine(squaredSpace(values + 1, query.q, dimension_), std::fabs(values[0] - query.time), query);
}

void ompl_parc::SpaceTimeGrid::consider(std::size_t i, const double *values, const Query &query, Best &best) const
{
    const double deltaTime = std::fabs(values[0] - query.time);
    if (query.timeWeight * deltaTime > best.distance)
        return;
    // A far point skips the square root: a squared space term above the squared best distance (by a margin far
    // above rounding) cannot give a distance as small.
    const double squared = squaredSpace(values + 1, query.q, dimension_);
    // (Only where the squares cannot underflow.)
    if (best.distance > TINY &&
        query.spaceWeight * query.spaceWeight * squared > best.distance * best.distance * (1. + RELATIVE_MARGIN))
        return;
    // Nor can a point beyond the speed limit's reach: its distance is infinite, and an infinite distance never
    // replaces the first point (the only one that can be best at infinity).
    const double reach = query.vMax * (deltaTime + query.epsilon);
    if (reach > TINY && squared > reach * reach * (1. + RELATIVE_MARGIN))
        return;
    const double d = combine(squared, deltaTime, query);
    if (d < best.distance || (d == best.distance && i < best.index))
        best = {i, d};
}

double ompl_parc::SpaceTimeGrid::cellBound(std::size_t x, std::size_t y, double nearTime, const Query &query) const
{
    const std::size_t index[2] = {x, y};
    double squared = 0.;
    for (std::size_t k = 0; k < gridded_; ++k)
    {
        // The outer cells are open-ended: they hold the points beyond the bounds too. The inner cells' edges are
        // widened by a slack far above the rounding of a point's cell (floor((x - low) / width)).
        const double low =
            index[k] == 0 ? -HUGE_VAL : low_[k] + width_[k] * static_cast<double>(index[k]) - edgeSlack_[k];
        const double high = index[k] + 1 == cells_[k]
                                ? HUGE_VAL
                                : low_[k] + width_[k] * static_cast<double>(index[k] + 1) + edgeSlack_[k];
        const double gap = std::max({0., low - query.q[k], query.q[k] - high});
        squared += gap * gap;
    }
    const double space = std::sqrt(squared);
    return query.spaceWeight * space + query.timeWeight * std::max(nearTime, space / query.vMax - query.epsilon);
}

bool ompl_parc::SpaceTimeGrid::searchSlab(const Slab &slab, bool later, const Query &query, Best &best) const
{
    const double toEarliest = std::fabs(slab.earliest - query.time), toLatest = std::fabs(slab.latest - query.time);
    const double nearTime = query.time < slab.earliest ? toEarliest : query.time > slab.latest ? toLatest : 0.;
    // Beyond this slab in the walk's direction, time differences are at least this slab's on that side (slabs
    // are in time order; the query's own slab may hold points on both sides of its time).
    const double onward =
        later ? (query.time < slab.earliest ? toEarliest : 0.) : (query.time > slab.latest ? toLatest : 0.);
    if (query.timeWeight * onward > best.distance)
        return false;
    if (query.timeWeight * nearTime > best.distance)
        return true;
    // A point of the slab is within reach (speed limit) and within the distance left (budget) in space; the
    // margins cover the rounding of the distance (relative to it) and of the cells' edges (relative to the grid).
    const double reach = query.vMax * (std::max(toEarliest, toLatest) + query.epsilon) * (1. + RELATIVE_MARGIN);
    const double budget =
        query.spaceWeight > 0.
            ? (best.distance * (1. + RELATIVE_MARGIN) + ABSOLUTE_MARGIN - query.timeWeight * nearTime) /
                  query.spaceWeight
            : HUGE_VAL;
    double radius = std::min(reach, budget);
    if (!(radius >= 0.))
        radius = HUGE_VAL;
    std::size_t from[2] = {0, 0}, to[2] = {0, 0};
    for (std::size_t k = 0; k < gridded_; ++k)
    {
        const double reachK = radius + edgeSlack_[k] + RELATIVE_MARGIN * std::fabs(query.q[k]);
        from[k] = clampIndex(std::floor((query.q[k] - reachK - low_[k]) / width_[k]), cells_[k]);
        to[k] = clampIndex(std::floor((query.q[k] + reachK - low_[k]) / width_[k]), cells_[k]);
    }
    // A sparse slab is cheaper to scan whole than cell by cell.
    if (slab.ids.size() <= (to[0] - from[0] + 1) * (to[1] - from[1] + 1))
    {
        for (std::size_t e = 0; e < slab.ids.size(); ++e)
            consider(slab.ids[e], slab.values.data() + e * stride(), query, best);
        return true;
    }
    for (std::size_t x = from[0]; x <= to[0]; ++x)
        for (std::size_t y = from[1]; y <= to[1]; ++y)
        {
            const std::size_t cell = x * cells_[1] + y;
            const std::size_t begin = slab.cellStart[cell], end = slab.cellStart[cell + 1];
            if (begin == end || !mayHold(cellBound(x, y, nearTime, query), best.distance))
                continue;
            for (std::size_t e = begin; e < end; ++e)
                consider(slab.ids[e], slab.values.data() + e * stride(), query, best);
        }
    return true;
}

std::size_t ompl_parc::SpaceTimeGrid::nearest(const Query &query) const
{
    // As a linear search: the first point is the one to beat, and nothing beats a NaN distance.
    Best best{0, distanceOf(points_.data(), query)};
    if (std::isnan(best.distance))
        return 0;
    const bool gridded = std::isfinite(query.time) &&
                         std::all_of(query.q, query.q + dimension_, [](double v) { return std::isfinite(v); });
    if (!gridded)
    {
        for (std::size_t i = 1; i < size(); ++i)
            consider(i, points_.data() + i * stride(), query, best);
        return best.index;
    }
    for (std::size_t i : outside_)
        consider(i, points_.data() + i * stride(), query, best);
    const std::size_t slab = query.time < 0. ? 0 : std::min(slabOf(query.time), slabs_.size());
    const auto split = std::lower_bound(occupied_.begin(), occupied_.end(), slab);
    for (auto s = split; s != occupied_.end() && searchSlab(slabs_[*s], true, query, best); ++s)
        ;
    for (auto s = split; s != occupied_.begin() && searchSlab(slabs_[*(s - 1)], false, query, best); --s)
        ;
    return best.index;
}

std::vector<double> ompl_parc::SpaceTimeGrid::distances(const Query &query) const
{
    std::vector<double> d(size());
    for (std::size_t i = 0; i < d.size(); ++i)
        d[i] = distanceOf(points_.data() + i * stride(), query);
    return d;
}
