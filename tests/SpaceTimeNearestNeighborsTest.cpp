#include "ompl_parc/planners/SpaceTime.h"
#include "ompl_parc/planners/SpaceTimeNearestNeighbors.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

using ompl_parc::SpaceTimeNearestNeighbors;
using ompl_parc::spacetime::SpaceTimeStateSpace;
namespace ob = ompl::base;

namespace
{
    struct Element
    {
        ob::State *state;
    };

    using Flat = SpaceTimeNearestNeighbors<const Element *>;

    /** \brief States of a space-time space on a coarse grid (so that equal times, equal distances and speed-test
        boundaries occur), freed with the space. */
    class Elements
    {
      public:
        Elements(std::shared_ptr<SpaceTimeStateSpace> space, std::size_t count, std::mt19937 &rng)
            : space_(std::move(space))
        {
            const unsigned int d = space_->getSubspace(0)->getDimension();
            std::uniform_int_distribution<int> cell(-8, 8), tick(0, 40);
            for (std::size_t i = 0; i < count; ++i)
            {
                auto *state = space_->allocState()->as<ob::CompoundState>();
                for (unsigned int k = 0; k < d; ++k)
                    state->as<ob::RealVectorStateSpace::StateType>(0)->values[k] = 0.5 * cell(rng);
                state->as<ob::TimeStateSpace::StateType>(1)->position = 0.25 * tick(rng);
                elements_.push_back(std::make_unique<Element>(Element{state}));
            }
        }

        ~Elements()
        {
            for (const auto &e : elements_)
                space_->freeState(e->state);
        }

        const Element *operator[](std::size_t i) const { return elements_[i].get(); }
        std::size_t size() const { return elements_.size(); }

      private:
        std::shared_ptr<SpaceTimeStateSpace> space_;
        std::vector<std::unique_ptr<Element>> elements_;
    };

    std::shared_ptr<SpaceTimeStateSpace> spaceOf(unsigned int dimension, double vMax, double timeWeight)
    {
        auto component = std::make_shared<ob::RealVectorStateSpace>(dimension);
        component->setBounds(-4., 4.);
        auto space = std::make_shared<SpaceTimeStateSpace>(component, vMax, timeWeight);
        space->setTimeBounds(0., 10.);
        space->updateEpsilon();
        return space;
    }

    /** \brief Both structures give the same answers, element for element and in the same order. */
    void expectSameAnswers(const ompl::NearestNeighbors<const Element *> &linear, const Flat &flat,
                           const Elements &queries)
    {
        ASSERT_EQ(linear.size(), flat.size());
        std::vector<const Element *> a, b;
        linear.list(a);
        flat.list(b);
        EXPECT_EQ(a, b);
        for (std::size_t q = 0; q < queries.size(); ++q)
        {
            EXPECT_EQ(linear.nearest(queries[q]), flat.nearest(queries[q])) << "query " << q;
            for (std::size_t k : {1, 5, 40, 1000})
            {
                linear.nearestK(queries[q], k, a);
                flat.nearestK(queries[q], k, b);
                EXPECT_EQ(a, b) << "query " << q << ", k " << k;
            }
            for (double r : {0., 0.5, 2., std::numeric_limits<double>::infinity()})
            {
                linear.nearestR(queries[q], r, a);
                flat.nearestR(queries[q], r, b);
                EXPECT_EQ(a, b) << "query " << q << ", radius " << r;
            }
        }
    }
}  // namespace

/* The flat structure must be a drop-in for NearestNeighborsLinear with the space-time distance: the same nearest
   element (the first of equally near ones, also when every distance is infinite), the same sorted neighbourhoods,
   through additions, removals and a clear, for several dimensions, speeds and weights. */
TEST(SpaceTimeNearestNeighbors, AnswersAsLinearSearchWithTheSpaceTimeDistance)
{
    std::mt19937 rng(7);
    for (const auto &[dimension, vMax, timeWeight] :
         {std::tuple{2u, 1., 0.5}, std::tuple{3u, 0.5, 0.2}, std::tuple{7u, 2., 0.8}, std::tuple{1u, 1., 1.}})
    {
        SCOPED_TRACE(dimension);
        const auto space = spaceOf(dimension, vMax, timeWeight);
        ASSERT_TRUE(Flat::supports(*space));
        const Elements elements(space, 300, rng), queries(space, 60, rng);
        ompl::NearestNeighborsLinear<const Element *> linear;
        linear.setDistanceFunction([&](const Element *a, const Element *b)
                                   { return space->distance(a->state, b->state); });
        Flat flat(*space, [](const Element *const &e) { return e->state; });

        EXPECT_THROW(flat.nearest(queries[0]), ompl::Exception);
        for (std::size_t i = 0; i < 150; ++i)
        {
            linear.add(elements[i]);
            flat.add(elements[i]);
        }
        flat.add(std::vector<const Element *>{elements[0], elements[1]});  // duplicates, as a tree may not hold
        linear.add(std::vector<const Element *>{elements[0], elements[1]});
        expectSameAnswers(linear, flat, queries);

        for (std::size_t i = 150; i < elements.size(); ++i)
        {
            linear.add(elements[i]);
            flat.add(elements[i]);
        }
        for (std::size_t i = 0; i < elements.size(); i += 3)
            EXPECT_EQ(linear.remove(elements[i]), flat.remove(elements[i]));
        EXPECT_TRUE(flat.remove(elements[0]));  // the second copy
        EXPECT_TRUE(linear.remove(elements[0]));
        EXPECT_FALSE(flat.remove(elements[0]));
        EXPECT_FALSE(linear.remove(elements[0]));
        expectSameAnswers(linear, flat, queries);

        // Time bounds moved (as ST-RRT* does between batches): the speed test's epsilon changes with them.
        space->setTimeBounds(0., 1e4);
        space->updateEpsilon();
        expectSameAnswers(linear, flat, queries);

        flat.clear();
        linear.clear();
        EXPECT_EQ(flat.size(), 0u);
        flat.add(elements[5]);
        linear.add(elements[5]);
        expectSameAnswers(linear, flat, queries);
    }
}

/* Cases the grid above does not reach: every distance infinite (the first element inserted wins, as in Linear),
   a speed test decided by the space's epsilon (read at each query, so moved time bounds count), NaN. */
TEST(SpaceTimeNearestNeighbors, AnswersAsLinearSearchAtTheEdges)
{
    const auto space = spaceOf(2, 1., 0.5);
    const auto state = [&](double x, double t)
    {
        auto *s = space->allocState()->as<ob::CompoundState>();
        s->as<ob::RealVectorStateSpace::StateType>(0)->values[0] = x;
        s->as<ob::RealVectorStateSpace::StateType>(0)->values[1] = 0.;
        s->as<ob::TimeStateSpace::StateType>(1)->position = t;
        return std::make_unique<Element>(Element{s});
    };
    // At the query's time but elsewhere, inserted latest time first: all unreachable from the query.
    std::vector<std::unique_ptr<Element>> elements;
    for (double t : {1.2, 1.1, 1.0})
        elements.push_back(state(3. + t, t));
    // 1e-4 farther than vMax reaches in the time between: infinite while epsilon is 1.2e-6 (time bounds 10),
    // finite once it is 1.2e-3 (time bounds 1e4).
    elements.push_back(state(1. + 1e-4, 2.));
    const auto query = state(0., 1.), nan = state(std::nan(""), 1.), nanTime = state(0., std::nan(""));

    ompl::NearestNeighborsLinear<const Element *> linear;
    linear.setDistanceFunction([&](const Element *a, const Element *b) { return space->distance(a->state, b->state); });
    Flat flat(*space, [](const Element *const &e) { return e->state; });
    for (std::size_t i = 0; i < 3; ++i)
    {
        linear.add(elements[i].get());
        flat.add(elements[i].get());
    }
    EXPECT_EQ(flat.nearest(query.get()), elements[0].get());
    EXPECT_EQ(linear.nearest(query.get()), elements[0].get());
    EXPECT_EQ(flat.nearest(nanTime.get()), elements[0].get());
    EXPECT_EQ(linear.nearest(nanTime.get()), elements[0].get());
    EXPECT_THROW(flat.add(nanTime.get()), ompl::Exception);  // no place in the time order

    linear.add(elements[3].get());
    flat.add(elements[3].get());
    const Element *shifted = elements.back().get();
    EXPECT_EQ(linear.nearest(query.get()), elements[0].get());  // 1e-4 too far: infinite, like the rest
    EXPECT_EQ(flat.nearest(query.get()), elements[0].get());
    space->setTimeBounds(0., 1e4);
    space->updateEpsilon();
    EXPECT_EQ(linear.nearest(query.get()), shifted);  // within epsilon now: the only finite distance
    EXPECT_EQ(flat.nearest(query.get()), shifted);

    // The query's own slab may end before the query's time while later slabs hold nearer points: the walk to later
    // times must not stop there (slabs 0.5 wide here; elements at times 1.0, 0.5, 1.0, the query at 0.95).
    flat.clear();
    linear.clear();
    const auto at = [&](double x, double y, double t)
    {
        auto held = state(x, t);
        held->state->as<ob::CompoundState>()->as<ob::RealVectorStateSpace::StateType>(0)->values[1] = y;
        return held;
    };
    const auto p0 = at(0., 0., 1.), p1 = at(3., 3., 0.5), p2 = at(0., 0.01, 1.), late = at(0., 0.01, 0.95);
    for (const Element *e : {p0.get(), p1.get(), p2.get()})
    {
        linear.add(e);
        flat.add(e);
    }
    EXPECT_EQ(linear.nearest(late.get()), p2.get());
    EXPECT_EQ(flat.nearest(late.get()), p2.get());
    for (const Element *e : {p0.get(), p1.get(), p2.get(), late.get()})
        space->freeState(e->state);

    // A NaN coordinate makes element 0's distance NaN when it is the query: Linear keeps element 0.
    flat.clear();
    linear.clear();
    linear.add(nan.get());
    flat.add(nan.get());
    linear.add(elements[3].get());
    flat.add(elements[3].get());
    EXPECT_EQ(linear.nearest(query.get()), nan.get());
    EXPECT_EQ(flat.nearest(query.get()), nan.get());

    for (const auto &e : elements)
        space->freeState(e->state);
    for (const Element *e : {query.get(), nan.get(), nanTime.get()})
        space->freeState(e->state);
}

/* The grid's cells and slabs cover the space's bounds and a range of times: points beyond them (outside the bounds,
   before time 0, after the last slab) must be found all the same, and a large tree is where cells are skipped. */
TEST(SpaceTimeNearestNeighbors, AnswersAsLinearSearchBeyondTheGrid)
{
    std::mt19937 rng(11);
    for (const auto &[dimension, vMax, timeWeight] : {std::tuple{2u, 1., 0.5}, std::tuple{3u, 2., 0.3}})
    {
        SCOPED_TRACE(dimension);
        const auto space = spaceOf(dimension, vMax, timeWeight);  // bounds [-4, 4], time bounds [0, 10]
        std::uniform_real_distribution<double> coordinate(-12., 12.), time(-5., 40.), unit(0., 1.);
        std::vector<ob::State *> states;
        const auto draw = [&]
        {
            auto *state = space->allocState()->as<ob::CompoundState>();
            for (unsigned int k = 0; k < dimension; ++k)
                state->as<ob::RealVectorStateSpace::StateType>(0)->values[k] =
                    unit(rng) < 0.7 ? 0.25 * std::round(coordinate(rng)) : coordinate(rng);
            const double u = unit(rng);
            state->as<ob::TimeStateSpace::StateType>(1)->position = u < 0.02  ? 1e7 * (1. + u)
                                                                    : u < 0.5 ? 0.5 * std::round(time(rng))
                                                                              : time(rng);
            states.push_back(state);
            return std::make_unique<Element>(Element{state});
        };
        std::vector<std::unique_ptr<Element>> elements, queries;
        for (int i = 0; i < 3000; ++i)
            elements.push_back(draw());
        for (int i = 0; i < 400; ++i)
            queries.push_back(draw());

        ompl::NearestNeighborsLinear<const Element *> linear;
        linear.setDistanceFunction([&](const Element *a, const Element *b)
                                   { return space->distance(a->state, b->state); });
        Flat flat(*space, [](const Element *const &e) { return e->state; });
        for (std::size_t i = 0; i < elements.size(); ++i)
        {
            linear.add(elements[i].get());
            flat.add(elements[i].get());
            if (i % 97 == 0 || i + 1 == elements.size())
                for (std::size_t q = 0; q < queries.size(); q += 7)
                    ASSERT_EQ(linear.nearest(queries[q].get()), flat.nearest(queries[q].get()))
                        << "query " << q << " among " << i + 1;
        }
        for (const auto &q : queries)
            EXPECT_EQ(linear.nearest(q.get()), flat.nearest(q.get()));
        for (std::size_t i = 0; i < elements.size(); i += 5)
            ASSERT_EQ(linear.remove(elements[i].get()), flat.remove(elements[i].get()));
        for (const auto &q : queries)
            EXPECT_EQ(linear.nearest(q.get()), flat.nearest(q.get()));
        // Small sparse trees, continuous times: few points per slab, so slabs end on either side of a query's time.
        std::uniform_real_distribution<double> near(-3., 3.), soon(0., 4.);
        for (int trial = 0; trial < 300; ++trial)
        {
            linear.clear();
            flat.clear();
            std::vector<std::unique_ptr<Element>> few;
            const auto place = [&]
            {
                auto *state = space->allocState()->as<ob::CompoundState>();
                for (unsigned int k = 0; k < dimension; ++k)
                    state->as<ob::RealVectorStateSpace::StateType>(0)->values[k] = near(rng);
                state->as<ob::TimeStateSpace::StateType>(1)->position = soon(rng);
                states.push_back(state);
                return std::make_unique<Element>(Element{state});
            };
            for (int i = 0; i < 3 + trial % 15; ++i)
            {
                few.push_back(place());
                linear.add(few.back().get());
                flat.add(few.back().get());
            }
            for (int q = 0; q < 20; ++q)
            {
                const auto query = place();
                ASSERT_EQ(linear.nearest(query.get()), flat.nearest(query.get())) << "trial " << trial;
            }
        }
        for (ob::State *state : states)
            space->freeState(state);
    }
}

TEST(SpaceTimeNearestNeighbors, NeedsAEuclideanSpaceComponent)
{
    const auto circle = std::make_shared<SpaceTimeStateSpace>(std::make_shared<ob::SO2StateSpace>());
    EXPECT_FALSE(Flat::supports(*circle));
    EXPECT_THROW(Flat(*circle, [](const Element *const &e) { return e->state; }), ompl::Exception);
}
