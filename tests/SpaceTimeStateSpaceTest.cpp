#include "ompl_parc/planners/SpaceTime.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <limits>
#include <type_traits>

/* The space-time state space in use (spacetime::SpaceTimeStateSpace): ours against OMPL < 1.6, OMPL's own from
   OMPL 1.6 on. The same tests hold for both. */

using ompl_parc::spacetime::SpaceTimeStateSpace;
namespace ob = ompl::base;
namespace spacetime = ompl_parc::spacetime;

#if OMPL_PARC_OMPL_HAS_SPACE_TIME
static_assert(spacetime::USES_OMPL_SPACE_TIME, "OMPL >= 1.6 must use its own space-time classes");
static_assert(std::is_same_v<spacetime::SpaceTimeStateSpace, ob::SpaceTimeStateSpace>);
static_assert(std::is_same_v<spacetime::STRRTstar, ompl::geometric::STRRTstar>);
#else
static_assert(!spacetime::USES_OMPL_SPACE_TIME, "OMPL < 1.6 must use ompl_parc's space-time classes");
static_assert(std::is_same_v<spacetime::SpaceTimeStateSpace, ompl_parc::SpaceTimeStateSpace>);
static_assert(std::is_same_v<spacetime::STRRTstar, ompl_parc::STRRTstar>);
#endif

namespace
{
    std::shared_ptr<SpaceTimeStateSpace> plane(double vMax = 1., double timeWeight = 0.5)
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(-10., 10.);
        return std::make_shared<SpaceTimeStateSpace>(space, vMax, timeWeight);
    }

    ob::ScopedState<> at(const std::shared_ptr<SpaceTimeStateSpace> &space, double x, double y, double t)
    {
        ob::ScopedState<> state(space);
        state[0] = x;
        state[1] = y;
        state[2] = t;
        return state;
    }

    /** Whether moving 5 units (from (0, 0) to (3, 4)) in 5 - \e shortfall time units at vMax 1 counts as
        reachable: the speed test's round-off tolerance. */
    bool reachableWithShortfall(const std::shared_ptr<SpaceTimeStateSpace> &space, double shortfall)
    {
        return std::isfinite(space->distance(at(space, 0., 0., 0.).get(), at(space, 3., 4., 5. - shortfall).get()));
    }
}  // namespace

TEST(SpaceTimeStateSpace, DistanceIsTheWeightedSumWhenReachableAtVMax)
{
    const auto space = plane();
    const auto a = at(space, 0., 0., 0.), b = at(space, 3., 4., 10.);
    EXPECT_DOUBLE_EQ(space->distanceSpace(a.get(), b.get()), 5.);
    EXPECT_DOUBLE_EQ(space->distanceTime(a.get(), b.get()), 10.);
    EXPECT_DOUBLE_EQ(space->distance(a.get(), b.get()), 0.5 * 5. + 0.5 * 10.);
    EXPECT_DOUBLE_EQ(SpaceTimeStateSpace::getStateTime(b.get()), 10.);

    const auto weighted = plane(1., 0.2);
    EXPECT_DOUBLE_EQ(weighted->distance(at(weighted, 0., 0., 0.).get(), at(weighted, 3., 4., 10.).get()),
                     0.8 * 5. + 0.2 * 10.);
}

TEST(SpaceTimeStateSpace, DistanceIsInfiniteWhenFasterThanVMax)
{
    const auto space = plane();
    const auto a = at(space, 0., 0., 0.);
    EXPECT_TRUE(std::isinf(space->distance(a.get(), at(space, 3., 4., 4.9).get())));
    EXPECT_FALSE(std::isinf(space->distance(a.get(), at(space, 3., 4., 5.).get())));  // exactly vMax
    EXPECT_TRUE(std::isinf(space->distance(a.get(), at(space, 1., 0., 0.).get())));   // no time at all
    EXPECT_DOUBLE_EQ(space->distance(a.get(), at(space, 0., 0., 0.).get()), 0.);

    const auto fast = plane(2.);
    EXPECT_FALSE(std::isinf(fast->distance(at(fast, 0., 0., 0.).get(), at(fast, 3., 4., 2.5).get())));
    EXPECT_DOUBLE_EQ(fast->timeToCoverDistance(at(fast, 0., 0., 0.).get(), at(fast, 3., 4., 0.).get()), 2.5);
    EXPECT_DOUBLE_EQ(space->timeToCoverDistance(a.get(), at(space, 3., 4., 0.).get()), 5.);
}

TEST(SpaceTimeStateSpace, DistanceIgnoresTimeDirectionLikeOMPL)
{
    // OMPL's space-time distance is symmetric; motion validators and ST-RRT* forbid going back in time.
    const auto space = plane();
    const auto early = at(space, 0., 0., 0.), late = at(space, 3., 4., 10.);
    EXPECT_DOUBLE_EQ(space->distance(late.get(), early.get()), space->distance(early.get(), late.get()));
    EXPECT_FALSE(space->isMetricSpace());
    EXPECT_TRUE(std::isinf(space->getMaximumExtent()));
}

TEST(SpaceTimeStateSpace, TimeBoundsAndTheSpeedTestTolerance)
{
    const auto space = plane();
    EXPECT_FALSE(space->getTimeComponent()->isBounded());
    EXPECT_EQ(space->getSpaceComponent()->getDimension(), 2u);
    // The tolerance scales with the space's extent / vMax (about 28): float epsilon x 100.
    const double unbounded = std::numeric_limits<float>::epsilon() * 100.;
    space->updateEpsilon();
    EXPECT_TRUE(reachableWithShortfall(space, 0.9 * unbounded));
    EXPECT_FALSE(reachableWithShortfall(space, 1.1 * unbounded));

    // With bounded time, with the time extent (5000): float epsilon x 10000.
    space->setTimeBounds(0., 5000.);
    EXPECT_TRUE(space->getTimeComponent()->isBounded());
    EXPECT_DOUBLE_EQ(space->getTimeComponent()->getMaxTimeBound(), 5000.);
    space->updateEpsilon();
    EXPECT_TRUE(reachableWithShortfall(space, 90. * unbounded));
    EXPECT_FALSE(reachableWithShortfall(space, 110. * unbounded));

    space->setVMax(4.);
    EXPECT_DOUBLE_EQ(space->getVMax(), 4.);
    EXPECT_THROW(plane(1., 1.5), ompl::Exception);
}

#if !OMPL_PARC_OMPL_HAS_SPACE_TIME
// Ours only: OMPL's space-time space does not check vMax.
TEST(SpaceTimeStateSpace, OursRejectsANonPositiveVMax)
{
    EXPECT_THROW(plane(0.), ompl::Exception);
    EXPECT_THROW(plane()->setVMax(-1.), ompl::Exception);
}
#endif
