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
        }

        bool reportsSortedResults() const override { return true; }

        void add(const T &data) override
        {
            const Query element = makeQuery(data);
            data_.push_back(data);
            coordinates_.insert(coordinates_.end(), element.q, element.q + dimension_);
            times_.push_back(element.time);
            const auto at = std::upper_bound(byTime_.begin(), byTime_.end(), element.time,
                                             [](double t, const Entry &e) { return t < e.time; });
            byTime_.insert(at, {element.time, data_.size() - 1});
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
                    byTime_.erase(
                        std::find_if(byTime_.begin(), byTime_.end(), [i](const Entry &e) { return e.index == i; }));
                    for (Entry &e : byTime_)
                        e.index -= e.index > i ? 1 : 0;
                    return true;
                }
            return false;
        }

        /** \brief The first of the nearest elements in insertion order (as NearestNeighborsLinear), found by
            walking out from the query's time in both directions: the time term alone bounds the distance from
            below (the space term is not negative, and rounding is monotonic), so a side ends once its next
            element is farther in time alone than the nearest distance found. */
        T nearest(const T &data) const override
        {
            if (data_.empty())
                throw ompl::Exception("No elements found in nearest neighbors data structure");
            const Query query = makeQuery(data);
            const auto split = std::lower_bound(byTime_.begin(), byTime_.end(), query.time,
                                                [](const Entry &e, double t) { return e.time < t; });
            std::size_t up = static_cast<std::size_t>(split - byTime_.begin()), down = up;  // next: up, down - 1
            std::size_t best = data_.size();
            double least = std::numeric_limits<double>::infinity();
            const auto bound = [&](std::size_t k)
            { return query.timeWeight * std::fabs(byTime_[k].time - query.time); };
            while (true)
            {
                const bool upOpen = up < byTime_.size() && !(bound(up) > least),
                           downOpen = down > 0 && !(bound(down - 1) > least);
                if (!upOpen && !downOpen)
                    break;
                const std::size_t k = upOpen && (!downOpen || bound(up) <= bound(down - 1)) ? up++ : --down;
                const std::size_t i = byTime_[k].index;
                if (const double d = distance(i, query); d < least || (d == least && i < best))
                {
                    best = i;
                    least = d;
                }
            }
            return data_[best];
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
        /** \brief An element's time and insertion index, in byTime_. */
        struct Entry
        {
            double time;
            std::size_t index;
        };

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

        /** \brief SpaceTimeStateSpace::distance(element i, query), with the same arithmetic. */
        double distance(std::size_t i, const Query &query) const
        {
            const double *c = coordinates_.data() + i * dimension_;
            double squared = 0.;
            for (std::size_t k = 0; k < dimension_; ++k)
            {
                const double diff = c[k] - query.q[k];
                squared += diff * diff;
            }
            const double deltaSpace = std::sqrt(squared);
            const double deltaTime = std::fabs(times_[i] - query.time);
            if (deltaSpace / query.vMax > deltaTime + query.epsilon)
                return std::numeric_limits<double>::infinity();
            return query.spaceWeight * deltaSpace + query.timeWeight * deltaTime;
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
        std::vector<T> data_;
        /** \brief Element i's space coordinates at [i * dimension_, (i + 1) * dimension_). */
        std::vector<double> coordinates_;
        std::vector<double> times_;
        /** \brief The elements ordered by time (equal times in insertion order). */
        std::vector<Entry> byTime_;
    };
}  // namespace ompl_parc

#endif
