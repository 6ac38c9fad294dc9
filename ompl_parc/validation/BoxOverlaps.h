#ifndef OMPL_PARC_BOX_OVERLAPS_
#define OMPL_PARC_BOX_OVERLAPS_

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace ompl_parc
{
    /** \brief An axis-aligned box (closed: boxes that share a face overlap). */
    struct AxisBox
    {
        std::array<double, 3> lo, hi;

        bool overlaps(const AxisBox &other) const
        {
            for (int d = 0; d < 3; ++d)
                if (lo[d] > other.hi[d] || other.lo[d] > hi[d])
                    return false;
            return true;
        }
    };

    /** \brief Every overlapping pair of a set of boxes, by a uniform grid: each box is entered in the cells it covers,
        and a pair is reported by one cell only, the one holding the low corner of the two boxes' intersection.

        The SolutionValidator's broad phase over a block of time, where the boxes are a team's bodies. A sweep along
        one axis costs O(n^2) when the boxes line up across that axis (a column of robots crossing a row: Mobile
        Cross at thousands of robots spent most of its check in the sweep); the grid costs O(n log n) plus the
        pairs whatever the layout. The cell is twice the boxes' median extent, so a typical box covers one to two
        cells per axis; the few boxes that would cover more than MAX_CELLS cells are tested against every box. */
    class BoxOverlaps
    {
      public:
        /** \brief Most cells a box is entered in; a larger box is tested against every box instead. */
        static constexpr std::size_t MAX_CELLS = 64;

        /** \brief Call \e report(i, j), i < j, once for every pair of the \e n \e boxes that overlap and of which
            one at least is \e active. */
        void find(const AxisBox *boxes, const char *active, std::size_t n,
                  const std::function<void(std::size_t, std::size_t)> &report);

      private:
        /** \brief Per box, its cell index range per axis; false if it covers more than MAX_CELLS cells. */
        bool cellRange(const AxisBox &box, std::array<std::uint64_t, 3> &first,
                       std::array<std::uint64_t, 3> &last) const;
        /** \brief The cell of \e coordinate along \e axis: one formula for entering boxes and for the cell that
            reports a pair, so that the intersection's corner always falls in a cell of both boxes. */
        std::uint64_t cellIndex(double coordinate, int axis) const;
        std::uint64_t cellOf(const std::array<double, 3> &point) const;
        std::uint64_t pack(std::uint64_t x, std::uint64_t y, std::uint64_t z) const;

        std::array<double, 3> origin_{};
        double cell_{1.};
        unsigned int indexBits_{1}, axisBits_{21};
        /** \brief Scratch: entries (cell key above box index) and the same grouped by bucket, where each bucket
            starts; the boxes tested against every box; extents for the median. */
        std::vector<std::uint64_t> entries_, grouped_;
        std::vector<std::size_t> starts_;
        std::vector<std::uint32_t> big_;
        std::vector<char> isBig_;
        std::vector<double> extents_;
    };
}  // namespace ompl_parc

#endif
