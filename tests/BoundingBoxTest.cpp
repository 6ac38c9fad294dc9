#include "ompl_parc/collision/BoundingBox.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ompl_parc;

namespace
{
    CollisionBody sphere(double x, double y, double radius)
    {
        CollisionBody body;
        body.addSphere(x, y, 0., radius);
        return body;
    }
}  // namespace

/* A box grows around the bodies and boxes added to it; an empty box overlaps no finite box, whatever the margin, nor
   another empty one. */
TEST(BoundingBox, GrowsAroundBodiesAndBoxesAndAnEmptyOneOverlapsNothing)
{
    BoundingBox empty, box;
    box.add(sphere(1., 2., 0.5));
    EXPECT_DOUBLE_EQ(box.lo[0], 0.5);
    EXPECT_DOUBLE_EQ(box.hi[1], 2.5);
    BoundingBox other;
    other.add(sphere(-3., 0., 1.));
    box.add(other);
    EXPECT_DOUBLE_EQ(box.lo[0], -4.);
    EXPECT_DOUBLE_EQ(box.hi[0], 1.5);
    EXPECT_DOUBLE_EQ(box.lo[1], -1.);
    EXPECT_DOUBLE_EQ(box.hi[1], 2.5);
    BoundingBox everything;
    everything.lo.fill(-HUGE_VAL);
    everything.hi.fill(HUGE_VAL);
    EXPECT_FALSE(empty.overlaps(empty));
    EXPECT_FALSE(empty.overlaps(box));
    EXPECT_FALSE(box.overlaps(empty));
    EXPECT_FALSE(empty.overlaps(box, 100.));
    EXPECT_TRUE(box.overlaps(everything));
}

/* Boxes overlap when they touch, or lie within the margin of each other along every axis; a NaN bound set on a box
   counts as overlapping. */
TEST(BoundingBox, OverlapWithinTheMarginAndOnNaN)
{
    BoundingBox a, b;
    a.add(sphere(0., 0., 1.));  // [-1, 1]^2
    b.add(sphere(3., 0., 1.));  // [2, 4] x [-1, 1]
    EXPECT_FALSE(a.overlaps(b));
    EXPECT_FALSE(b.overlaps(a));
    EXPECT_FALSE(a.overlaps(b, 0.999));
    EXPECT_TRUE(a.overlaps(b, 1.));
    EXPECT_TRUE(b.overlaps(a, 1.));
    BoundingBox touching;
    touching.add(sphere(2., 5., 1.));  // [1, 3] x [4, 6]: touches a's x range, far along y
    EXPECT_FALSE(a.overlaps(touching));
    EXPECT_TRUE(a.overlaps(touching, 3.));
    BoundingBox broken = b;
    broken.lo[0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(a.overlaps(broken));
    EXPECT_TRUE(broken.overlaps(a));
}
