#ifndef OMPL_PARC_LINEAR_MOTION_
#define OMPL_PARC_LINEAR_MOTION_

#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief One robot's motion as the SolutionValidator sees it: timed breakpoints (timestep, configuration),
        straight between them.

        Piece k runs from breakpoint k to breakpoint k + 1; its configuration at time u is OMPL's RealVector
        interpolation q0 + s (q1 - q0) with s = (u - t0) / (t1 - t0). A dense plan (one state per timestep) is
        added state by state: a state on the line of the last piece extends it, so straight runs of equal
        per-timestep increments become one piece, and the validator bounds, sweeps and skips whole pieces
        instead of timesteps. Merging is exact up to MERGE_TOLERANCE: every state merged into a piece lies within
        it (per coordinate) of the piece's interpolation; the validator pads its radii by the resulting
        displacement, so checking the pieces is as strict as checking the states. */
    class LinearMotion
    {
      public:
        /** \brief Largest per-coordinate distance between a merged state and its piece's interpolation: far
            above the rounding of laid plans (coordinates of hundreds, ulp 1e-13), far below any tolerance. */
        static constexpr double MERGE_TOLERANCE = 1e-9;

        explicit LinearMotion(unsigned int dimension);

        /** \brief Append the configuration at timestep \e t (after the last breakpoint's): extends the last
            piece if every state merged into it stays within MERGE_TOLERANCE of the longer piece, else starts a
            new piece. Throws std::invalid_argument if \e t does not increase. */
        void addBreakpoint(std::size_t t, const double *q);

        unsigned int getDimension() const { return dimension_; }
        /** \brief Number of pieces (breakpoints - 1; 0 for a motion of one breakpoint). */
        std::size_t getPieceCount() const { return times_.empty() ? 0 : times_.size() - 1; }
        std::size_t getStartTime(std::size_t piece) const { return times_[piece]; }
        std::size_t getEndTime(std::size_t piece) const { return times_[piece + 1]; }
        const double *getStart(std::size_t piece) const { return &values_[piece * dimension_]; }
        const double *getEnd(std::size_t piece) const { return &values_[(piece + 1) * dimension_]; }
        /** \brief The first and the last breakpoint's configuration. */
        const double *getFirst() const { return values_.data(); }
        const double *getLast() const { return &values_[values_.size() - dimension_]; }
        /** \brief Timestep of the last breakpoint. */
        std::size_t getDuration() const { return times_.back(); }

        /** \brief True if the piece does not move at all (both ends equal). */
        bool isStill(std::size_t piece) const;

        /** \brief The last piece whose time span [t0, t1] contains \e time (clamped to the motion). */
        std::size_t findPiece(double time) const;

        /** \brief The configuration of \e piece at \e time (OMPL's interpolation; the start for a motion of
            one breakpoint). */
        void interpolate(std::size_t piece, double time, double *q) const;

      private:
        unsigned int dimension_;
        std::vector<std::size_t> times_;
        std::vector<double> values_;
        /** \brief Per coordinate, the per-timestep slopes of the last piece that keep its merged states within
            MERGE_TOLERANCE. */
        std::vector<double> slopeLow_, slopeHigh_;
    };
}  // namespace ompl_parc

#endif
