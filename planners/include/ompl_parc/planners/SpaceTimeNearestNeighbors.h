#ifndef OMPL_PARC_PLANNERS_SPACE_TIME_NEAREST_NEIGHBORS_
#define OMPL_PARC_PLANNERS_SPACE_TIME_NEAREST_NEIGHBORS_

#include "ompl_parc/planners/SpaceTimeGrid.h"
#include "ompl_parc/spacetime/SpaceTimeInUse.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/TimeStateSpace.h>
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numeric>
#include <typeinfo>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief Exact nearest neighbours in a space-time space whose space component is a RealVectorStateSpace: the
        answers of OMPL's NearestNeighborsLinear (the only exact structure for a distance that is not a metric),
        found faster: the elements' times and coordinates sit in a SpaceTimeGrid (time slabs cut into cells in
        space), the distance is computed inline, and nearest() searches only the slabs and cells a nearer element
        could be in.

        Why: ST-RRT* queries its trees once per extension, and a linear search through a distance function costs
        a std::function call, SpaceTimeStateSpace::distance and two more virtual distances per element, which was
        most of a PP-ST-RRT run on a dense team; a walk over the elements in time order with the distance inline
        still left most of it there (its trees reach tens of thousands of states).

        Same answers as NearestNeighborsLinear with SpaceTimeStateSpace::distance, in the same order: the same
        distance arithmetic (the Euclidean space distance summed in coordinate order, the speed test with the
        space's vMax and epsilon read at each query, so moved time bounds count), the first of equally near
        elements in insertion order (the first element where its distance is NaN), the same sorts for nearestK()
        and nearestR() (the arithmetic is SpaceTimeGrid's, compiled with -ffp-contract=off: a fused multiply-add
        would round differently from OMPL's library). Works with our space-time space and
        OMPL's (>= 1.6). The distance function set on it is not used. Queries are const; only nearestK() and
        nearestR() allocate. */
    template <typename T>
    class SpaceTimeNearestNeighbors : public ompl::NearestNeighbors<T>
    {
      public:
        /** \brief The state of an element (called once per element added and once per query). */
        using StateOf = std::function<const ompl::base::State *(const T &)>;

        /** \brief Whether \e space is the space-time space itself (not a subclass, which might change the
            distance) over a plain RealVectorStateSpace (Euclidean distance). */
        static bool supports(const spacetime::SpaceTimeStateSpace &space)
        {
            const auto &component = *space.getSubspace(0);
            return typeid(space) == typeid(spacetime::SpaceTimeStateSpace) &&
                   typeid(component) == typeid(ompl::base::RealVectorStateSpace);
        }

        /** \brief Elements of \e space (supports() must hold; throws ompl::Exception otherwise), whose states
            \e stateOf gives; \e space must outlive this structure. */
        SpaceTimeNearestNeighbors(const spacetime::SpaceTimeStateSpace &space, StateOf stateOf)
            : space_(space),
              stateOf_(std::move(stateOf)),
              grid_(space.getSubspace(0)->getDimension(), boundsOf(space), space.getVMax())
        {
        }

        void clear() override
        {
            data_.clear();
            grid_.clear();
        }

        bool reportsSortedResults() const override { return true; }

        /** \brief Throws ompl::Exception for a state whose time is NaN (it has no place in the time order). */
        void add(const T &data) override
        {
            const Query element = makeQuery(data);
            if (std::isnan(element.time))
                throw ompl::Exception("SpaceTimeNearestNeighbors", "a state's time is NaN");
            data_.push_back(data);
            grid_.add(element.time, element.q);
        }

        void add(const std::vector<T> &data) override
        {
            for (const T &d : data)
                add(d);
        }

        /** \brief Removes the last element equal to \e data, as NearestNeighborsLinear does. */
        bool remove(const T &data) override
        {
            for (std::size_t i = data_.size(); i-- > 0;)
                if (data_[i] == data)
                {
                    data_.erase(data_.begin() + static_cast<std::ptrdiff_t>(i));
                    grid_.remove(i);
                    return true;
                }
            return false;
        }

        /** \brief The first of the nearest elements in insertion order (as NearestNeighborsLinear), found by
            SpaceTimeGrid. */
        T nearest(const T &data) const override
        {
            if (data_.empty())
                throw ompl::Exception("No elements found in nearest neighbors data structure");
            return data_[grid_.nearest(makeQuery(data))];
        }

        void nearestK(const T &data, std::size_t k, std::vector<T> &nbh) const override
        {
            const std::vector<double> d = grid_.distances(makeQuery(data));
            std::vector<std::size_t> order(data_.size());
            std::iota(order.begin(), order.end(), 0);
            const auto nearer = [&d](std::size_t a, std::size_t b) { return d[a] < d[b]; };
            if (order.size() > k)
            {
                std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(), nearer);
                order.resize(k);
            }
            else
                std::sort(order.begin(), order.end(), nearer);
            collect(order, nbh);
        }

        void nearestR(const T &data, double radius, std::vector<T> &nbh) const override
        {
            const std::vector<double> d = grid_.distances(makeQuery(data));
            std::vector<std::size_t> within;
            for (std::size_t i = 0; i < data_.size(); ++i)
                if (d[i] <= radius)
                    within.push_back(i);
            std::sort(within.begin(), within.end(), [&d](std::size_t a, std::size_t b) { return d[a] < d[b]; });
            collect(within, nbh);
        }

        std::size_t size() const override { return data_.size(); }

        void list(std::vector<T> &data) const override { data = data_; }

      private:
        using Query = SpaceTimeGrid::Query;

        /** \brief The bounds of \e space's space component; throws ompl::Exception unless supports(). */
        static const ompl::base::RealVectorBounds &boundsOf(const spacetime::SpaceTimeStateSpace &space)
        {
            if (!supports(space))
                throw ompl::Exception("SpaceTimeNearestNeighbors",
                                      "needs the space-time space itself over a RealVectorStateSpace");
            return space.getSubspace(0)->template as<ompl::base::RealVectorStateSpace>()->getBounds();
        }

        /** \brief Reads the protected speed-test epsilon of either space-time space class (ours or OMPL's):
            neither has a getter, and it changes when the planner moves the time bounds. */
        struct EpsilonOf : spacetime::SpaceTimeStateSpace
        {
            static double get(const spacetime::SpaceTimeStateSpace &space) { return space.*(&EpsilonOf::eps_); }
        };

        /** \brief \e data's coordinates and time, with the space's distance constants now. */
        Query makeQuery(const T &data) const
        {
            const auto *state = stateOf_(data)->template as<ompl::base::CompoundState>();
            return {state->template as<ompl::base::RealVectorStateSpace::StateType>(0)->values,
                    state->template as<ompl::base::TimeStateSpace::StateType>(1)->position,
                    space_.getSubspaceWeight(0),
                    space_.getSubspaceWeight(1),
                    space_.getVMax(),
                    EpsilonOf::get(space_)};
        }

        /** \brief The elements of insertion indices \e order, in that order. */
        void collect(const std::vector<std::size_t> &order, std::vector<T> &nbh) const
        {
            nbh.clear();
            nbh.reserve(order.size());
            for (std::size_t i : order)
                nbh.push_back(data_[i]);
        }

        const spacetime::SpaceTimeStateSpace &space_;
        StateOf stateOf_;
        /** \brief The elements in insertion order. */
        std::vector<T> data_;
        /** \brief Their times and coordinates, indexed by insertion index. */
        SpaceTimeGrid grid_;
    };
}  // namespace ompl_parc

#endif
