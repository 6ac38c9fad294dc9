#include "ompl_parc/statespaces/CompositeStateSpace.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

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
