#ifndef OMPL_PARC_PLANNERS_SPACE_TIME_NEAREST_NEIGHBORS_
#define OMPL_PARC_PLANNERS_SPACE_TIME_NEAREST_NEIGHBORS_

#include "ompl_parc/spacetime/SpaceTimeStateSpace.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/TimeStateSpace.h>
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <typeinfo>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief Exact nearest neighbours in a space-time space whose space component is a RealVectorStateSpace: the
        answers of OMPL's NearestNeighborsLinear (the only exact structure for a distance that is not a metric),
        found faster. Coordinates and times sit in flat buffers and the distance is computed inline; nearest()
        walks out from the query's time over the elements ordered by time and stops where the time difference
        alone exceeds the nearest distance found.

        Why: ST-RRT* queries its trees once per extension, and a linear search through a distance function costs
        a std::function call, SpaceTimeStateSpace::distance and two more virtual distances per element: 85 % of a
        PP-ST-RRT run on a dense team (rooms, 24 robots) went there.

        Same answers as NearestNeighborsLinear with SpaceTimeStateSpace::distance, in the same order: the same
        distance arithmetic (the Euclidean space distance summed in coordinate order, the speed test with the
        space's vMax and epsilon read at each query, so moved time bounds count), the first of equally near
        elements in insertion order, the same sorts for nearestK() and nearestR(). Works with our space-time
        space and OMPL's (>= 1.6). The distance function set on it is not used. Queries are const; only
        nearestK() and nearestR() allocate. */
    template <typename T>
    class SpaceTimeNearestNeighbors : public ompl::NearestNeighbors<T>
    {
      public:
        /** \brief The state of an element (called once per element added and once per query). */
        using StateOf = std::function<const ompl::base::State *(const T &)>;

        /** \brief Whether \e space's space component is a plain RealVectorStateSpace (Euclidean distance). */
        static bool supports(const spacetime::SpaceTimeStateSpace &space)
        {
            const auto &component = *space.getSubspace(0);
            return typeid(component) == typeid(ompl::base::RealVectorStateSpace);
        }

        /** \brief Elements of \e space (supports() must hold; throws ompl::Exception otherwise), whose states
            \e stateOf gives; \e space must outlive this structure. */
        SpaceTimeNearestNeighbors(const spacetime::SpaceTimeStateSpace &space, StateOf stateOf)
            : space_(space), stateOf_(std::move(stateOf)), dimension_(space.getSubspace(0)->getDimension())
        {
            if (!supports(space))
                throw ompl::Exception("SpaceTimeNearestNeighbors",
                                      "the space component must be a RealVectorStateSpace");
        }

        void clear() override
        {
            data_.clear();
            coordinates_.clear();
            times_.clear();
            byTime_.clear();
            byTimeIndex_.clear();
        }

        bool reportsSortedResults() const override { return true; }

        void add(const T &data) override
        {
            const Query element = makeQuery(data);
            data_.push_back(data);
            coordinates_.insert(coordinates_.end(), element.q, element.q + dimension_);
            times_.push_back(element.time);
            const auto at = static_cast<std::ptrdiff_t>(
                std::upper_bound(byTimeIndex_.begin(), byTimeIndex_.end(), element.time,
                                 [this](double t, std::size_t i) { return t < times_[i]; }) -
                byTimeIndex_.begin());
            byTimeIndex_.insert(byTimeIndex_.begin() + at, data_.size() - 1);
            const auto entry = byTime_.begin() + at * static_cast<std::ptrdiff_t>(stride());
            const auto time = byTime_.insert(entry, element.time);
            byTime_.insert(time + 1, element.q, element.q + dimension_);
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
                    times_.erase(times_.begin() + static_cast<std::ptrdiff_t>(i));
                    const auto first = coordinates_.begin() + static_cast<std::ptrdiff_t>(i * dimension_);
                    coordinates_.erase(first, first + static_cast<std::ptrdiff_t>(dimension_));
                    const auto at = std::find(byTimeIndex_.begin(), byTimeIndex_.end(), i) - byTimeIndex_.begin();
                    byTimeIndex_.erase(byTimeIndex_.begin() + at);
                    const auto entry = byTime_.begin() + at * static_cast<std::ptrdiff_t>(stride());
                    byTime_.erase(entry, entry + static_cast<std::ptrdiff_t>(stride()));
                    for (std::size_t &j : byTimeIndex_)
                        j -= j > i ? 1 : 0;
                    return true;
                }
            return false;
        }

        /** \brief The first of the nearest elements in insertion order (as NearestNeighborsLinear). The elements
            are searched in time order, up and then down from the query's time: the time term alone bounds the
            distance from below (the space term is not negative, and rounding is monotonic), so each direction
            ends at the first element farther in time alone than the nearest distance found. */
        T nearest(const T &data) const override
        {
            if (data_.empty())
                throw ompl::Exception("No elements found in nearest neighbors data structure");
            const Query query = makeQuery(data);
            const auto split =
                static_cast<std::size_t>(std::lower_bound(byTimeIndex_.begin(), byTimeIndex_.end(), query.time,
                                                          [this](std::size_t i, double t) { return times_[i] < t; }) -
                                         byTimeIndex_.begin());
            Best best{data_.size(), std::numeric_limits<double>::infinity()};
            // The element just before the query's time first: a near one found early shortens both walks.
            if (split > 0)
                consider(split - 1, query, best);
            for (std::size_t k = split; k < data_.size() && consider(k, query, best); ++k)
                ;
            for (std::size_t k = split; k-- > 0 && consider(k, query, best);)
                ;
            return data_[best.index];
        }

        void nearestK(const T &data, std::size_t k, std::vector<T> &nbh) const override
        {
            const Query query = makeQuery(data);
            std::vector<double> d(data_.size());
            for (std::size_t i = 0; i < data_.size(); ++i)
                d[i] = distance(i, query);
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
            const Query query = makeQuery(data);
            std::vector<double> d(data_.size());
            std::vector<std::size_t> within;
            for (std::size_t i = 0; i < data_.size(); ++i)
                if ((d[i] = distance(i, query)) <= radius)
                    within.push_back(i);
            std::sort(within.begin(), within.end(), [&d](std::size_t a, std::size_t b) { return d[a] < d[b]; });
            collect(within, nbh);
        }

        std::size_t size() const override { return data_.size(); }

        void list(std::vector<T> &data) const override { data = data_; }

      private:
        /** \brief A query's coordinates and time, and the space's distance constants at query time. */
        struct Query
        {
            const double *q;
            double time, spaceWeight, timeWeight, vMax, epsilon;
        };

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

        /** \brief The nearest element found so far (its insertion index) and its distance. */
        struct Best
        {
            std::size_t index;
            double distance;
        };

        /** \brief Doubles per element in byTime_: its time, then its coordinates. */
        std::size_t stride() const { return dimension_ + 1; }

        /** \brief Makes the element at \e k of the time order \e best if it is nearer, or as near and inserted
            earlier; false if it, and so every element beyond it in time, is farther in time alone than \e best.
            A far element skips the square root: a squared space term above the squared best distance (by a
            margin far above rounding) cannot give a distance as small. */
        bool consider(std::size_t k, const Query &query, Best &best) const
        {
            const double *entry = byTime_.data() + k * stride();
            const double deltaTime = std::fabs(entry[0] - query.time);
            if (query.timeWeight * deltaTime > best.distance)
                return false;
            const double squared = squaredSpace(entry + 1, query.q);
            if (query.spaceWeight * query.spaceWeight * squared > best.distance * best.distance * (1. + 1e-9))
                return true;
            const double d = combine(squared, deltaTime, query);
            const std::size_t i = byTimeIndex_[k];
            if (d < best.distance || (d == best.distance && i < best.index))
                best = {i, d};
            return true;
        }

        /** \brief The squared Euclidean distance of \e c and \e q, summed in coordinate order as
            RealVectorStateSpace::distance does. */
        double squaredSpace(const double *c, const double *q) const
        {
            double squared = 0.;
            for (std::size_t k = 0; k < dimension_; ++k)
            {
                const double diff = c[k] - q[k];
                squared += diff * diff;
            }
            return squared;
        }

        /** \brief SpaceTimeStateSpace::distance from the squared space distance and the time difference. */
        static double combine(double squared, double deltaTime, const Query &query)
        {
            const double deltaSpace = std::sqrt(squared);
            if (deltaSpace / query.vMax > deltaTime + query.epsilon)
                return std::numeric_limits<double>::infinity();
            return query.spaceWeight * deltaSpace + query.timeWeight * deltaTime;
        }

        /** \brief SpaceTimeStateSpace::distance(element i, query), with the same arithmetic. */
        double distance(std::size_t i, const Query &query) const
        {
            return combine(squaredSpace(coordinates_.data() + i * dimension_, query.q),
                           std::fabs(times_[i] - query.time), query);
        }

        void collect(const std::vector<std::size_t> &order, std::vector<T> &nbh) const
        {
            nbh.clear();
            nbh.reserve(order.size());
            for (std::size_t i : order)
                nbh.push_back(data_[i]);
        }

        const spacetime::SpaceTimeStateSpace &space_;
        StateOf stateOf_;
        std::size_t dimension_;
        /** \brief The elements in insertion order. */
        std::vector<T> data_;
        /** \brief Element i's space coordinates at [i * dimension_, (i + 1) * dimension_). */
        std::vector<double> coordinates_;
        std::vector<double> times_;
        /** \brief The elements ordered by time (equal times in insertion order): each one's time and coordinates
            (stride() doubles), contiguous for the walks of nearest(). */
        std::vector<double> byTime_;
        /** \brief The insertion index of each element of byTime_. */
        std::vector<std::size_t> byTimeIndex_;
    };
}  // namespace ompl_parc

#endif
