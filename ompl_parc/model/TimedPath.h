#ifndef OMPL_PARC_TIMED_PATH_
#define OMPL_PARC_TIMED_PATH_

#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief One robot's configuration at every integer timestep 0, 1, ..., held after its arrival, stored as
        straight pieces rather than one state per timestep.

        A piece is a straight motion laid on the grid the way the planners lay paths: from anchor \e from to
        anchor \e to in \e steps timesteps, the configuration at local step s being \e to itself for s >= steps
        and from + (to - from) x (s / steps) otherwise, which is exactly the arithmetic of OMPL's
        RealVectorStateSpace::interpolate, so the configuration at every timestep is bit-for-bit the state the
        dense grid held. A piece covers the timesteps from its \e start to the next piece's start (the last
        one to the arrival); its first covered timestep is local step \e offset. Cutting a piece (a splice
        keeps part of it) only moves its start and offset and keeps its anchors, which is why the anchors
        are stored rather than the configurations at the cut: interpolating from a cut point would round
        differently. Memory and splicing cost grow with the number of pieces, not of timesteps.

        Readers that walk over time use a Cursor: O(1) amortised per timestep for a forward scan. */
    class TimedPath
    {
      public:
        /** \brief One straight piece (see the class description). */
        struct Piece
        {
            std::size_t start, offset, steps;
        };

        /** \brief An empty path (no timesteps yet) of a robot with \e dimension degrees of freedom. */
        explicit TimedPath(unsigned int dimension = 0) : dimension_(dimension) {}

        /** \brief The path holding \e q from timestep 0. */
        TimedPath(unsigned int dimension, const double *q);

        /** \brief The path through the states of \e flat (getDimension() values per timestep, one state per
            timestep from 0); runs of equal states become one piece. */
        static TimedPath fromDense(unsigned int dimension, const std::vector<double> &flat);

        /** \brief The configuration at local step \e s of a piece from \e from to \e to of \e steps steps. */
        static void interpolate(const double *from, const double *to, std::size_t s, std::size_t steps,
                                unsigned int dimension, double *out);

        unsigned int getDimension() const { return dimension_; }
        bool empty() const { return pieces_.empty(); }
        /** \brief The last timestep with a state of its own (the arrival); throws if empty. */
        std::size_t getArrival() const;

        std::size_t getPieceCount() const { return pieces_.size(); }
        const Piece &getPiece(std::size_t k) const { return pieces_[k]; }
        const double *getFrom(std::size_t k) const { return anchors_.data() + 2 * k * dimension_; }
        const double *getTo(std::size_t k) const { return anchors_.data() + (2 * k + 1) * dimension_; }

        /** \brief The configuration at timestep \e t (the arrival's once arrived) into \e out. */
        void getConfig(std::size_t t, double *out) const;

        /** \brief All states 0..arrival, flat: for tests, small plans and version 1 files only. */
        std::vector<double> toDense() const;

        /** \brief Append the motion laid from the current end, which is \e from, to \e to in \e steps timesteps
            (nothing for 0 steps): the grid states from + (to - from) x s / steps for s < steps, then \e to. */
        void appendMotion(const double *from, const double *to, std::size_t steps);

        /** \brief Append a piece (as read from a file or cut from another path) starting at timestep
            getArrival() + 1 (0 if empty) and covering through \e last; throws if it does not fit. */
        void appendPiece(const Piece &piece, const double *from, const double *to, std::size_t last);

        /** \brief Hold \e q at timesteps getArrival() + 1 .. \e last (\e q copied as is). */
        void appendHold(const double *q, std::size_t last);

        /** \brief Append this path's timesteps [\e from, \e to] to \e out, shifted to start at
            out.getArrival() + 1 (0 if \e out is empty); timesteps past the arrival hold it. */
        void appendRange(std::size_t from, std::size_t to, TimedPath &out) const;

        /** \brief Replace the states at timesteps [from, to] by \e segment (timesteps 0..segment's arrival; a
            path that arrived before \e from holds until then); the states after \e to follow, shifted by the
            difference in length; then the arrival is trimmed (trimArrival()). O(pieces). */
        void splice(std::size_t from, std::size_t to, const TimedPath &segment);

        /** \brief Drop the trailing timesteps equal (==) to the final state: the arrival is when it stops for
            good. Whole pieces that do not move are skipped in one step. */
        void trimArrival();

        /** \brief Per-dimension minimum and maximum over the timesteps [from, to] into \e lo, \e hi, exactly
            those of the states there, from a few states per piece (a piece is monotone before its last step). */
        void bounds(std::size_t from, std::size_t to, double *lo, double *hi) const;

        /** \brief Append to \e times the timesteps at which the motion may change direction: 0, the first and
            last timestep of each piece where it does not continue the previous piece's line, where it stops
            within a piece, and the arrival. Between consecutive ones the path moves on a straight line. */
        void appendBreakpoints(std::vector<std::size_t> &times) const;

        /** \brief Same pieces, anchors (==) and arrival. */
        bool operator==(const TimedPath &other) const;
        bool operator!=(const TimedPath &other) const { return !(*this == other); }

        /** \brief Index of the piece covering timestep \e t (t <= arrival). */
        std::size_t locate(std::size_t t) const;

        /** \brief Sequential reader: get(t) costs O(1) amortised over increasing t (a step back searches).
            Valid while the path is not modified. */
        class Cursor
        {
          public:
            Cursor() = default;
            explicit Cursor(const TimedPath &path) : path_(&path) {}
            void get(std::size_t t, double *out);
            /** \brief Index of the piece covering timestep \e t (the last piece from the arrival on). */
            std::size_t seek(std::size_t t);

          private:
            const TimedPath *path_{nullptr};
            std::size_t piece_{0};
        };

      private:
        /** \brief The configuration at timestep \e t (within piece \e k's coverage) into \e out. */
        void evaluate(std::size_t k, std::size_t t, double *out) const;
        /** \brief True if every timestep piece \e k covers has the same configuration (==). */
        bool isStill(std::size_t k) const;
        /** \brief True if piece \e k's value at timestep \e t is its \e to anchor copied. */
        bool atTo(std::size_t k, std::size_t t) const
        {
            return pieces_[k].offset + (t - pieces_[k].start) >= pieces_[k].steps;
        }
        void push(const Piece &piece, const double *from, const double *to);

        unsigned int dimension_;
        std::vector<Piece> pieces_;
        /** \brief Two configurations per piece: from, to. */
        std::vector<double> anchors_;
        std::size_t arrival_{0};
    };
}  // namespace ompl_parc

#endif
