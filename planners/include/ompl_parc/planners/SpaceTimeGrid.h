#ifndef OMPL_PARC_PLANNERS_SPACE_TIME_GRID_
#define OMPL_PARC_PLANNERS_SPACE_TIME_GRID_

#include <ompl/base/spaces/RealVectorBounds.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ompl_parc
{
    /** \brief Space-time points (a time and Euclidean coordinates) indexed for exact nearest-point queries under
        OMPL's space-time distance, w_s |dq| + w_t |dt|, infinite where |dq| / vMax > |dt| + epsilon.
        Why: that distance is not a metric, so OMPL's only exact structure for it is a linear search, and ST-RRT*
        queries its trees once per extension: on dense teams (rooms, 24 discs) the trees grow to tens of thousands
        of states and the searches were two thirds of a PP-ST-RRT run even after SpaceTimeNearestNeighbors made
        each distance cheap.
        How: the points are kept in time slabs (in time order), each cut into cells over the first two
        coordinates (a fixed grid over the space's bounds, the outer cells open-ended). A query visits the slabs
        out from its time, ends a direction at the first slab whose time alone, on the far side of the query, is
        farther than the best distance found, and in a slab scans only the cells that a point could be near enough in:
       within the remaining distance budget and within the speed limit's reach (a point farther than vMax can travel in
       the slab's time span is at infinite distance). The answer is exactly a linear search's: the point of least
        distance, the first inserted among equals (the first point when all are infinite or the first one's
        distance is NaN); cells are skipped only on lower bounds with a margin far above rounding. Points with a
        time outside the slabs' range or a non-finite coordinate sit in a list that every query scans. */
    class SpaceTimeGrid
    {
      public:
        /** \brief A query point and the distance's constants at query time (they may change between queries). */
        struct Query
        {
            const double *q;
            double time, spaceWeight, timeWeight, vMax, epsilon;
        };

        /** \brief Points of \e dimension coordinates; \e bounds (of the space, in any case a hint: points outside
            are found too) and \e vMax size the cells. */
        SpaceTimeGrid(std::size_t dimension, const ompl::base::RealVectorBounds &bounds, double vMax);

        /** \brief Adds the point (\e time, \e q), insertion index size() - 1 afterwards; \e time must not be NaN. */
        void add(double time, const double *q);
        /** \brief Removes the point of insertion index \e i; those after it move down by one. */
        void remove(std::size_t i);
        void clear();
        std::size_t size() const { return points_.size() / stride(); }

        /** \brief The insertion index of the nearest point (see the class); size() must not be 0. */
        std::size_t nearest(const Query &query) const;
        /** \brief The distance of every point to \e query, by insertion index. */
        std::vector<double> distances(const Query &query) const;

      private:
        /** \brief Points of one time span: their insertion indices, times and coordinates, grouped by cell. */
        struct Slab
        {
            /** \brief Entries of cell c: [cellStart[c], cellStart[c + 1]). */
            std::vector<std::uint32_t> cellStart;
            std::vector<std::size_t> ids;
            /** \brief Per entry: its time, then its coordinates (stride() doubles). */
            std::vector<double> values;
            double earliest, latest;
        };

        /** \brief The nearest point found so far (its insertion index) and its distance. */
        struct Best
        {
            std::size_t index;
            double distance;
        };

        std::size_t stride() const { return dimension_ + 1; }
        /** \brief The slab of \e time, or none (SIZE_MAX) if it is outside the slabs' range. */
        std::size_t slabOf(double time) const;
        std::size_t cellOf(const double *q) const;
        /** \brief Files point \e i in its slab and cell, or in outside_. */
        void place(std::size_t i);
        /** \brief Makes point \e i (its time and coordinates at \e values) \e best if nearer, or as near and
            inserted earlier. */
        void consider(std::size_t i, const double *values, const Query &query, Best &best) const;
        /** \brief Scans the cells of \e slab a point nearer than \e best could be in; false if every slab beyond it
            in the walk's direction (\e later: to later times) is farther in time alone. */
        bool searchSlab(const Slab &slab, bool later, const Query &query, Best &best) const;
        /** \brief The distance's lower bound over cell (\e x, \e y) of a slab whose nearest time is \e nearTime. */
        double cellBound(std::size_t x, std::size_t y, double nearTime, const Query &query) const;
        double distanceOf(const double *values, const Query &query) const;

        std::size_t dimension_;
        /** \brief Gridded coordinates (the first two, or one) and each one's cells, low end and cell width. */
        std::size_t gridded_;
        std::size_t cells_[2]{1, 1};
        double low_[2]{0., 0.}, width_[2]{1., 1.};
        /** \brief How far cell edges are widened for the lower bounds (far above the rounding of a point's cell). */
        double edgeSlack_[2]{0., 0.};
        double slabWidth_;
        /** \brief Every point's time and coordinates by insertion index (stride() doubles each). */
        std::vector<double> points_;
        /** \brief The slabs by time, empty ones without storage; occupied_ lists the non-empty ones in order. */
        std::vector<Slab> slabs_;
        std::vector<std::size_t> occupied_;
        /** \brief Points outside the slabs (time out of range, or a non-finite coordinate). */
        std::vector<std::size_t> outside_;
    };
}  // namespace ompl_parc

#endif
