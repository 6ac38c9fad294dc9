#include "ompl_parc/statespaces/CompositeStateSpace.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <thread>
#include <vector>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    std::vector<ob::StateSpacePtr> spaces(std::size_t n, unsigned int dim, double extent)
    {
        std::vector<ob::StateSpacePtr> out;
        for (std::size_t i = 0; i < n; ++i)
        {
            auto s = std::make_shared<ob::RealVectorStateSpace>(dim);
            s->setBounds(-extent, extent);
            out.push_back(s);
        }
        return out;
    }
}  // namespace

TEST(CompositeStateSpace, DistanceIsTheLargestRobotDistance)
{
    auto space = std::make_shared<CompositeStateSpace>(spaces(3, 2, 10.));
    space->setup();
    ob::ScopedState<> a(space), b(space);
    for (unsigned int k = 0; k < 6; ++k)
        a[k] = b[k] = 0.;
    b[0] = 3.;  // robot 0 moves 3 + 4 -> 5
    b[1] = 4.;
    b[4] = 1.;  // robot 2 moves 1
    EXPECT_DOUBLE_EQ(space->distance(a.get(), b.get()), 5.);
    EXPECT_DOUBLE_EQ(space->getMaximumExtent(), std::sqrt(2.) * 20.);
}

namespace
{
    /** A real vector space that measures otherwise (a user's subclass): the composite must ask it. */
    class DoubledSpace : public ob::RealVectorStateSpace
    {
      public:
        using ob::RealVectorStateSpace::RealVectorStateSpace;
        double distance(const ob::State *a, const ob::State *b) const override
        {
            return 2. * ob::RealVectorStateSpace::distance(a, b);
        }
    };
}  // namespace

/* Robots of different dimensions, random states: the composite distance is the largest of the robots' own
   distances (RealVectorStateSpace::distance, or a subclass's override), up to rounding. */
TEST(CompositeStateSpace, DistanceMatchesTheRobotSpacesOwn)
{
    std::vector<ob::StateSpacePtr> team = spaces(3, 2, 10.);
    const auto seven = spaces(2, 7, 3.);
    team.insert(team.end(), seven.begin(), seven.end());
    auto doubled = team;
    doubled[1] = std::make_shared<DoubledSpace>(2);
    doubled[1]->as<ob::RealVectorStateSpace>()->setBounds(-10., 10.);
    for (const auto &robots : {team, doubled})
    {
        auto space = std::make_shared<CompositeStateSpace>(robots);
        space->setup();
        auto sampler = space->allocStateSampler();
        ob::ScopedState<> a(space), b(space);
        for (int k = 0; k < 200; ++k)
        {
            sampler->sampleUniform(a.get());
            sampler->sampleUniform(b.get());
            if (k % 4 == 0)  // robots 0..2 close: a 7-dimensional robot decides
                for (unsigned int v = 0; v < 6; ++v)
                    b[v] = a[v] + 1e-3 * v;
            double expected = 0.;
            for (unsigned int i = 0; i < robots.size(); ++i)
                expected = std::max(expected, robots[i]->distance(a->as<ob::CompoundState>()->components[i],
                                                                  b->as<ob::CompoundState>()->components[i]));
            EXPECT_NEAR(space->distance(a.get(), b.get()), expected, 1e-12 * expected);
        }
    }
    // As the robot spaces' largest distance (std::max): a NaN robot distance is passed over, an infinite one wins.
    auto space = std::make_shared<CompositeStateSpace>(team);
    space->setup();
    ob::ScopedState<> a(space), b(space);
    for (unsigned int v = 0; v < space->getDimension(); ++v)
        a[v] = b[v] = 0.;
    b[0] = std::nan("");
    b[2] = 2.;
    EXPECT_EQ(space->distance(a.get(), b.get()), 2.);
    b[8] = HUGE_VAL;
    EXPECT_EQ(space->distance(a.get(), b.get()), HUGE_VAL);
}

TEST(CompositeStateSpace, OneCompositeStepMovesNoRobotFurther)
{
    auto space = std::make_shared<CompositeStateSpace>(spaces(4, 3, 5.));
    space->setup();
    ob::ScopedState<> a(space), b(space), mid(space);
    a.random();
    b.random();
    const double d = space->distance(a.get(), b.get());
    const int steps = 50;
    for (int s = 1; s <= steps; ++s)
    {
        ob::ScopedState<> prev(space);
        space->interpolate(a.get(), b.get(), double(s - 1) / steps, prev.get());
        space->interpolate(a.get(), b.get(), double(s) / steps, mid.get());
        for (std::size_t r = 0; r < 4; ++r)
            EXPECT_LE(space->getRobotSpace(r)->distance(prev->as<ob::CompoundState>()->components[r],
                                                        mid->as<ob::CompoundState>()->components[r]),
                      d / steps + 1e-12);
    }
}

TEST(CompositeStateSpace, SubspaceSplitAndJoinRoundTrip)
{
    auto space = std::make_shared<CompositeStateSpace>(spaces(4, 2, 10.));
    space->setup();
    const std::vector<std::size_t> robots = {3, 1};
    auto sub = space->createSubspace(robots);
    sub->setup();
    EXPECT_EQ(sub->getRobotCount(), 2u);
    EXPECT_EQ(sub->getRobotSpace(0), space->getRobotSpace(3));
    ob::ScopedState<> full(space), part(sub);
    full.random();
    space->splitState(full.get(), robots, part.get());
    EXPECT_DOUBLE_EQ(part[0], full[6]);
    EXPECT_DOUBLE_EQ(part[3], full[3]);
    part[0] = 1.25;
    part[2] = -2.5;
    space->joinState(full.get(), robots, part.get());
    EXPECT_DOUBLE_EQ(full[6], 1.25);
    EXPECT_DOUBLE_EQ(full[2], -2.5);
}

TEST(CompositeStateSpace, RejectsBadInput)
{
    EXPECT_THROW(CompositeStateSpace(std::vector<ob::StateSpacePtr>{}), ompl::Exception);
    EXPECT_THROW(CompositeStateSpace(std::vector<ob::StateSpacePtr>{nullptr}), ompl::Exception);
    auto space = std::make_shared<CompositeStateSpace>(spaces(2, 2, 1.));
    EXPECT_THROW(space->createSubspace({0, 2}), ompl::Exception);
}

namespace
{
    /** Writes a value unique to (state, coordinate) into every state, then reads all back: states that overlap or
        share values would show here (and, for allocations below 512 KiB, which are not mapped on their own, under ASan
       as out-of-bounds writes). */
    void expectDisjointStates(const ob::StateSpace &space, const std::vector<ob::State *> &states)
    {
        const unsigned int dims = space.getDimension();
        for (std::size_t k = 0; k < states.size(); ++k)
            for (unsigned int d = 0; d < dims; ++d)
                *space.getValueAddressAtIndex(states[k], d) = static_cast<double>(k * dims + d);
        for (std::size_t k = 0; k < states.size(); ++k)
            for (unsigned int d = 0; d < dims; ++d)
                ASSERT_EQ(*space.getValueAddressAtIndex(states[k], d), static_cast<double>(k * dims + d));
    }
}  // namespace

TEST(CompositeStateSpace, SharedStatesAreDisjointAndFreedOneByOne)
{
    // 128 planar robots: 300 states of ~4 KB are past the 512 KiB from which the allocation is mapped on its own.
    for (const std::size_t robots : {1, 3, 128})
    {
        auto space = std::make_shared<CompositeStateSpace>(spaces(robots, 2, 10.));
        space->setup();
        for (const std::size_t count : {0, 1, 2, 7, 300})
        {
            std::vector<ob::State *> states(count, nullptr);
            space->allocStates(count, states.data());
            expectDisjointStates(*space, states);
            // A shared state behaves as any other: copied into, cloned, compared.
            if (count > 1)
            {
                ob::State *single = space->allocState();
                space->copyState(single, states[count - 1]);
                space->copyState(states[0], single);
                EXPECT_TRUE(space->equalStates(states[0], states[count - 1]));
                space->freeState(single);
            }
            // Freed in an order unrelated to the allocation's (odd ones first, then even ones backwards).
            for (std::size_t k = 1; k < count; k += 2)
                space->freeState(states[k]);
            for (std::size_t k = count; k-- > 0;)
                if (k % 2 == 0)
                    space->freeState(states[k]);
        }
    }
}

TEST(CompositeStateSpace, SharedStatesFreedFromManyThreads)
{
    // The last state freed frees the allocation, whichever thread frees it (TSan checks the count's ordering).
    auto space = std::make_shared<CompositeStateSpace>(spaces(64, 2, 10.));
    space->setup();
    for (int round = 0; round < 20; ++round)
    {
        std::vector<ob::State *> states(400, nullptr);
        space->allocStates(states.size(), states.data());
        expectDisjointStates(*space, states);
        std::vector<std::thread> threads;
        for (std::size_t t = 0; t < 4; ++t)
            threads.emplace_back(
                [&, t]
                {
                    for (std::size_t k = t; k < states.size(); k += 4)
                        space->freeState(states[k]);
                });
        for (auto &thread : threads)
            thread.join();
    }
}

TEST(CompositeStateSpace, OtherLayoutsAllocateStatesOneByOne)
{
    // A team with a non-vector robot space keeps OMPL's layout; allocStates still hands out independent states.
    auto so2 = std::make_shared<ob::SO2StateSpace>();
    auto space = std::make_shared<CompositeStateSpace>(std::vector<ob::StateSpacePtr>{spaces(1, 2, 10.)[0], so2});
    space->setup();
    std::vector<ob::State *> states(5, nullptr);
    space->allocStates(states.size(), states.data());
    expectDisjointStates(*space, states);
    for (ob::State *state : states)
        space->freeState(state);
}
