#include "ompl_parc/validation/BoxOverlaps.h"

#include <algorithm>
#include <cmath>

std::uint64_t ompl_parc::BoxOverlaps::pack(std::uint64_t x, std::uint64_t y, std::uint64_t z) const
{
    return (((x << axisBits_) | y) << axisBits_) | z;
}

std::uint64_t ompl_parc::BoxOverlaps::cellIndex(double coordinate, int axis) const
{
    return static_cast<std::uint64_t>(std::floor((coordinate - origin_[axis]) / cell_));
}

std::uint64_t ompl_parc::BoxOverlaps::cellOf(const std::array<double, 3> &point) const
{
    return pack(cellIndex(point[0], 0), cellIndex(point[1], 1), cellIndex(point[2], 2));
}

bool ompl_parc::BoxOverlaps::cellRange(const AxisBox &box, std::array<std::uint64_t, 3> &first,
                                       std::array<std::uint64_t, 3> &last) const
{
    std::uint64_t cells = 1;
    for (int d = 0; d < 3; ++d)
    {
        first[d] = cellIndex(box.lo[d], d);
        last[d] = cellIndex(box.hi[d], d);
        cells *= last[d] - first[d] + 1;
        if (cells > MAX_CELLS)
            return false;
    }
    return true;
}

void ompl_parc::BoxOverlaps::find(const AxisBox *boxes, const char *active, std::size_t n,
                                  const std::function<void(std::size_t, std::size_t)> &report)
{
    const auto test = [&](std::size_t i, std::size_t j)
    {
        if ((active[i] || active[j]) && boxes[i].overlaps(boxes[j]))
            report(std::min(i, j), std::max(i, j));
    };
    const auto everyPair = [&]
    {
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                test(i, j);
    };
    if (n < 16)  // a handful: every pair
    {
        everyPair();
        return;
    }
    // The grid: its origin at the boxes' low corner, its cell twice their median extent, and coarser if the boxes
    // spread over more cells than a key holds.
    std::array<double, 3> top{};
    extents_.resize(n);
    for (int d = 0; d < 3; ++d)
    {
        origin_[d] = boxes[0].lo[d];
        top[d] = boxes[0].hi[d];
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        double extent = 0.;
        for (int d = 0; d < 3; ++d)
        {
            origin_[d] = std::min(origin_[d], boxes[i].lo[d]);
            top[d] = std::max(top[d], boxes[i].hi[d]);
            extent = std::max(extent, boxes[i].hi[d] - boxes[i].lo[d]);
        }
        extents_[i] = extent;
    }
    // An entry is one 64-bit word, the cell's key above the box's index: the index takes the bits n needs, each axis
    // a third of the rest.
    indexBits_ = 1;
    while ((std::uint64_t{1} << indexBits_) < n)
        ++indexBits_;
    axisBits_ = (64 - indexBits_) / 3;
    const auto cellsPerAxis = static_cast<double>((std::uint64_t{1} << axisBits_) - 2);
    std::nth_element(extents_.begin(), extents_.begin() + static_cast<std::ptrdiff_t>(n / 2), extents_.end());
    cell_ = 2. * extents_[n / 2];
    for (int d = 0; d < 3; ++d)
        cell_ = std::max(cell_, (top[d] - origin_[d]) / cellsPerAxis);
    if (!(cell_ > 0.) || !std::isfinite(cell_))  // points, or boxes the grid cannot place: every pair
    {
        everyPair();
        return;
    }
    entries_.clear();
    big_.clear();
    isBig_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
        std::array<std::uint64_t, 3> first{}, last{};
        if (!cellRange(boxes[i], first, last))
        {
            big_.push_back(static_cast<std::uint32_t>(i));
            isBig_[i] = 1;
            continue;
        }
        for (std::uint64_t x = first[0]; x <= last[0]; ++x)
            for (std::uint64_t y = first[1]; y <= last[1]; ++y)
                for (std::uint64_t z = first[2]; z <= last[2]; ++z)
                    entries_.push_back((pack(x, y, z) << indexBits_) | i);
    }
    // Entries grouped by cell with a counting sort over hashed keys (linear; a comparison sort of the entries was a
    // fifth of the check at thousands of robots): a bucket may hold several cells, told apart by their keys.
    unsigned int bucketBits = 1;
    while ((std::size_t{1} << bucketBits) < 2 * entries_.size())
        ++bucketBits;
    const std::uint64_t indexMask = (std::uint64_t{1} << indexBits_) - 1;
    const auto bucketOf = [&](std::uint64_t entry)
    { return static_cast<std::size_t>(((entry >> indexBits_) * 0x9E3779B97F4A7C15ull) >> (64 - bucketBits)); };
    starts_.assign((std::size_t{1} << bucketBits) + 1, 0);
    for (const std::uint64_t entry : entries_)
        ++starts_[bucketOf(entry) + 1];
    for (std::size_t b = 1; b < starts_.size(); ++b)
        starts_[b] += starts_[b - 1];
    grouped_.resize(entries_.size());
    for (const std::uint64_t entry : entries_)
        grouped_[starts_[bucketOf(entry)]++] = entry;
    // starts_[b] is now the end of bucket b, the start of bucket b + 1.
    for (std::size_t b = 0, a = 0; b + 1 < starts_.size(); a = starts_[b++])
        for (std::size_t x = a; x < starts_[b]; ++x)
            for (std::size_t y = x + 1; y < starts_[b]; ++y)
            {
                const std::uint64_t key = grouped_[x] >> indexBits_;
                if (grouped_[y] >> indexBits_ != key)
                    continue;
                const std::size_t i = grouped_[x] & indexMask, j = grouped_[y] & indexMask;
                const AxisBox &p = boxes[i], &q = boxes[j];
                if (!(active[i] || active[j]) || !p.overlaps(q))
                    continue;
                // Reported by the cell of the intersection's low corner only (it lies in both boxes' cells).
                const std::array<double, 3> corner = {std::max(p.lo[0], q.lo[0]), std::max(p.lo[1], q.lo[1]),
                                                      std::max(p.lo[2], q.lo[2])};
                if (cellOf(corner) == key)
                    report(std::min(i, j), std::max(i, j));
            }
    for (const std::uint32_t b : big_)
        for (std::size_t i = 0; i < n; ++i)
            if (i != b && !(isBig_[i] && i < b))
                test(b, i);
}
