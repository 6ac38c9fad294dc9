#include "ompl_parc/validation/LinearMotion.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

ompl_parc::LinearMotion::LinearMotion(unsigned int dimension)
    : dimension_(dimension), slopeLow_(dimension), slopeHigh_(dimension)
{
}

void ompl_parc::LinearMotion::addBreakpoint(std::size_t t, const double *q)
{
    if (!times_.empty() && t <= times_.back())
        throw std::invalid_argument("LinearMotion: breakpoint at timestep " + std::to_string(t) +
                                    " does not follow timestep " + std::to_string(times_.back()));
    const std::size_t n = times_.size();
    if (n >= 2)
    {
        // Merging makes the current end an inner state of the piece: it constrains the slope, too.
        const double *start = &values_[(n - 2) * dimension_], *end = &values_[(n - 1) * dimension_];
        const auto inner = static_cast<double>(times_[n - 1] - times_[n - 2]);
        const auto span = static_cast<double>(t - times_[n - 2]);
        bool onLine = true;
        for (unsigned int d = 0; d < dimension_ && onLine; ++d)
        {
            const double slope = (q[d] - start[d]) / span;
            onLine = slope >= std::max(slopeLow_[d], (end[d] - start[d] - MERGE_TOLERANCE) / inner) &&
                     slope <= std::min(slopeHigh_[d], (end[d] - start[d] + MERGE_TOLERANCE) / inner);
        }
        if (onLine)
        {
            for (unsigned int d = 0; d < dimension_; ++d)
            {
                slopeLow_[d] = std::max(slopeLow_[d], (end[d] - start[d] - MERGE_TOLERANCE) / inner);
                slopeHigh_[d] = std::min(slopeHigh_[d], (end[d] - start[d] + MERGE_TOLERANCE) / inner);
            }
            times_.back() = t;
            std::copy(q, q + dimension_, values_.end() - dimension_);
            return;
        }
    }
    std::fill(slopeLow_.begin(), slopeLow_.end(), -std::numeric_limits<double>::infinity());
    std::fill(slopeHigh_.begin(), slopeHigh_.end(), std::numeric_limits<double>::infinity());
    times_.push_back(t);
    values_.insert(values_.end(), q, q + dimension_);
}

bool ompl_parc::LinearMotion::isStill(std::size_t piece) const
{
    return std::equal(getStart(piece), getStart(piece) + dimension_, getEnd(piece));
}

std::size_t ompl_parc::LinearMotion::findPiece(double time) const
{
    const auto after = std::upper_bound(times_.begin(), times_.end(), time,
                                        [](double u, std::size_t t) { return u < static_cast<double>(t); });
    const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - times_.begin() - 1, 0));
    return std::min(index, std::max<std::size_t>(getPieceCount(), 1) - 1);
}

void ompl_parc::LinearMotion::interpolate(std::size_t piece, double time, double *q) const
{
    const double *a = getStart(piece);
    if (getPieceCount() == 0)
    {
        std::copy(a, a + dimension_, q);
        return;
    }
    const double *b = getEnd(piece);
    const double s =
        (time - static_cast<double>(times_[piece])) / static_cast<double>(times_[piece + 1] - times_[piece]);
    for (unsigned int d = 0; d < dimension_; ++d)
        q[d] = a[d] + s * (b[d] - a[d]);
}
