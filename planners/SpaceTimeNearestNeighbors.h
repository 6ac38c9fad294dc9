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
        found faster. The elements' times and coordinates sit in one flat buffer ordered by time, the distance is
        computed inline, and nearest() walks out from the query's time, stopping where the weighted time
        difference alone exceeds the nearest distance found.

        Why: ST-RRT* queries its trees once per extension, and a linear search through a distance function costs
        a std::function call, SpaceTimeStateSpace::distance and two more virtual distances per element: 85 % of a
        PP-ST-RRT run on a dense team (rooms, 24 robots) went there.

        Same answers as NearestNeighborsLinear with SpaceTimeStateSpace::distance, in the same order: the same
        distance arithmetic (the Euclidean space distance summed in coordinate order, the speed test with the
        space's vMax and epsilon read at each query, so moved time bounds count), the first of equally near
        elements in insertion order (the first element where its distance is NaN), the same sorts for nearestK()
        and nearestR(). Code that instantiates it should compile with -ffp-contract=off (as this project does),
        or a fused multiply-add may round differently from OMPL's library. Works with our space-time space and
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
            : space_(space), stateOf_(std::move(stateOf)), dimension_(space.getSubspace(0)->getDimension())
        {
            if (!supports(space))
                throw ompl::Exception("SpaceTimeNearestNeighbors",
                                      "needs the space-time space itself over a RealVectorStateSpace");
        }

        void clear() override
        {
            data_.clear();
            byTime_.clear();
            byTimeIndex_.clear();
            first_.clear();
        }

        bool reportsSortedResults() const override { return true; }

        /** \brief Throws ompl::Exception for a state whose time is NaN (it has no place in the time order). */
        void add(const T &data) override
        {
            const Query element = makeQuery(data);
            if (std::isnan(element.time))
                throw ompl::Exception("SpaceTimeNearestNeighbors", "a state's time is NaN");
            const std::size_t at = rankOf(element.time, true);
            byTimeIndex_.insert(byTimeIndex_.begin() + static_cast<std::ptrdiff_t>(at), data_.size());
            data_.push_back(data);
            const auto time =
                byTime_.insert(byTime_.begin() + static_cast<std::ptrdiff_t>(at * stride()), element.time);
            byTime_.insert(time + 1, element.q, element.q + dimension_);
            if (data_.size() == 1)
                keepFirst();
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
                    const auto at = std::find(byTimeIndex_.begin(), byTimeIndex_.end(), i) - byTimeIndex_.begin();
                    byTimeIndex_.erase(byTimeIndex_.begin() + at);
                    const auto entry = byTime_.begin() + at * static_cast<std::ptrdiff_t>(stride());
                    byTime_.erase(entry, entry + static_cast<std::ptrdiff_t>(stride()));
                    for (std::size_t &j : byTimeIndex_)
                        j -= j > i ? 1 : 0;
                    if (i == 0)
                        keepFirst();
                    return true;
                }
            return false;
        }

        /** \brief The first of the nearest elements in insertion order (as NearestNeighborsLinear). Starting from
            the first element (as Linear: where its distance is NaN, nothing compares below it), the others are searched
           in time order, up and then down from the query's time: the weighted time difference alone bounds the distance
           from below (the space term is not negative, and rounding is monotonic), so each direction ends at the first
           element farther in time alone than the nearest distance found. */
        T nearest(const T &data) const override
        {
            if (data_.empty())
                throw ompl::Exception("No elements found in nearest neighbors data structure");
            const Query query = makeQuery(data);
            Best best{0, distanceOf(first_.data(), query)};
            if (std::isnan(best.distance))
                return data_[0];  // Linear keeps its first element then: nothing compares below NaN
            const std::size_t split = rankOf(query.time, false);
            std::size_t up = split;
            while (up < data_.size() && consider(up, query, best))
                ++up;
            std::size_t down = split;
            while (down > 0 && consider(down - 1, query, best))
                --down;
            return data_[best.index];
        }

        void nearestK(const T &data, std::size_t k, std::vector<T> &nbh) const override
        {
            const std::vector<double> d = allDistances(makeQuery(data));
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
            const std::vector<double> d = allDistances(makeQuery(data));
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
        /** \brief A query's coordinates and time, and the space's distance constants at query time. */
        struct Query
        {
            const double *q;
            double time, spaceWeight, timeWeight, vMax, epsilon;
        };

        /** \brief The nearest element found so far (its insertion index) and its distance. */
        struct Best
        {
            std::size_t index;
            double distance;
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

        /** \brief Doubles per element in byTime_: its time, then its coordinates. */
        std::size_t stride() const { return dimension_ + 1; }

        /** \brief The number of elements whose time is below \e time (\e after: not above it). */
        std::size_t rankOf(double time, bool after) const
        {
            std::size_t low = 0, high = data_.size();
            while (low < high)
            {
                const std::size_t middle = low + (high - low) / 2;
                const double t = byTime_[middle * stride()];
                if (t < time || (after && t == time))
                    low = middle + 1;
                else
                    high = middle;
            }
            return low;
        }

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

        /** \brief SpaceTimeStateSpace::distance(element, query) with the same arithmetic, for an element's time
            and coordinates at \e entry. */
        double distanceOf(const double *entry, const Query &query) const
        {
            return combine(squaredSpace(entry + 1, query.q), std::fabs(entry[0] - query.time), query);
        }

        /** \brief Copies the first element's time and coordinates to first_ (none if empty). */
        void keepFirst()
        {
            first_.clear();
            if (data_.empty())
                return;
            const auto at = std::find(byTimeIndex_.begin(), byTimeIndex_.end(), std::size_t{0}) - byTimeIndex_.begin();
            const auto entry = byTime_.begin() + at * static_cast<std::ptrdiff_t>(stride());
            first_.assign(entry, entry + static_cast<std::ptrdiff_t>(stride()));
        }

        /** \brief The distance of every element to \e query, by insertion index. */
        std::vector<double> allDistances(const Query &query) const
        {
            std::vector<double> d(data_.size());
            for (std::size_t k = 0; k < data_.size(); ++k)
                d[byTimeIndex_[k]] = distanceOf(byTime_.data() + k * stride(), query);
            return d;
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
        std::size_t dimension_;
        /** \brief The elements in insertion order. */
        std::vector<T> data_;
        /** \brief The elements ordered by time (equal times in insertion order): each one's time and coordinates
            (stride() doubles), contiguous for the walks of nearest(). */
        std::vector<double> byTime_;
        /** \brief The insertion index of each element of byTime_. */
        std::vector<std::size_t> byTimeIndex_;
        /** \brief The first element's time and coordinates: nearest() starts from it, as Linear does. */
        std::vector<double> first_;
    };
}  // namespace ompl_parc

#endif
