#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/FloatBounds.h"

#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <random>

using namespace ompl_parc;

namespace
{
    /** Brute-force squared segment distance by dense sampling of both segments. */
    double sampledDistanceSquared(const CollisionBody &a, const CollisionBody &b)
    {
        double best = 1e300;
        const int n = 400;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
            {
                const double s = double(i) / n, t = double(j) / n;
                const double dx = a.ax_[0] + s * (a.bx_[0] - a.ax_[0]) - b.ax_[0] - t * (b.bx_[0] - b.ax_[0]);
                const double dy = a.ay_[0] + s * (a.by_[0] - a.ay_[0]) - b.ay_[0] - t * (b.by_[0] - b.ay_[0]);
                const double dz = a.az_[0] + s * (a.bz_[0] - a.az_[0]) - b.az_[0] - t * (b.bz_[0] - b.az_[0]);
                best = std::min(best, dx * dx + dy * dy + dz * dz);
            }
        return best;
    }

    CollisionBody capsule(double ax, double ay, double az, double bx, double by, double bz, double r)
    {
        CollisionBody body;
        body.addCapsule(ax, ay, az, bx, by, bz, r);
        body.updateBound();
        return body;
    }
}  // namespace

TEST(CapsuleCollision, SegmentDistanceMatchesDenseSampling)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1., 1.);
    for (int k = 0; k < 200; ++k)
    {
        // Every fifth pair is degenerate (a point), every seventh parallel.
        const auto a = capsule(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), 0.1);
        CollisionBody b = capsule(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), 0.1);
        if (k % 5 == 0)
        {
            b.bx_[0] = b.ax_[0];
            b.by_[0] = b.ay_[0];
            b.bz_[0] = b.az_[0];
        }
        if (k % 7 == 0)
        {
            b.bx_[0] = b.ax_[0] + (a.bx_[0] - a.ax_[0]);
            b.by_[0] = b.ay_[0] + (a.by_[0] - a.ay_[0]);
            b.bz_[0] = b.az_[0] + (a.bz_[0] - a.az_[0]);
        }
        const double exact = segmentDistanceSquared(a, 0, b, 0);
        const double sampled = sampledDistanceSquared(a, b);
        EXPECT_LE(exact, sampled + 1e-12) << "pair " << k;
        EXPECT_NEAR(std::sqrt(exact), std::sqrt(sampled), 1e-2) << "pair " << k;
    }
}

TEST(CapsuleCollision, SpheresTouchExactlyAtSumOfRadii)
{
    CollisionBody a, b;
    a.addSphere(0, 0, 0, 0.5);
    a.updateBound();
    b.addSphere(1.0 + 1e-9, 0, 0, 0.5);
    b.updateBound();
    EXPECT_FALSE(bodiesCollide(a, b));
    b.clear();
    b.addSphere(1.0 - 1e-9, 0, 0, 0.5);
    b.updateBound();
    EXPECT_TRUE(bodiesCollide(a, b));
}

TEST(CapsuleCollision, CrossingCapsulesCollideAndParallelOnesDoNot)
{
    EXPECT_TRUE(bodiesCollide(capsule(-1, 0, 0, 1, 0, 0, 0.05), capsule(0, -1, 0, 0, 1, 0, 0.05)));
    EXPECT_FALSE(bodiesCollide(capsule(-1, 0, 0, 1, 0, 0, 0.05), capsule(-1, 0.11, 0, 1, 0.11, 0, 0.05)));
    EXPECT_TRUE(bodiesCollide(capsule(-1, 0, 0, 1, 0, 0, 0.05), capsule(-1, 0.09, 0, 1, 0.09, 0, 0.05)));
}

TEST(CapsuleCollision, BodyTestAgreesWithPairwiseCapsuleTest)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1., 1.), r(0.02, 0.2);
    int collisions = 0;
    for (int k = 0; k < 2000; ++k)
    {
        CollisionBody a, b;
        for (int c = 0; c < 3; ++c)
        {
            a.addCapsule(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), r(rng));
            b.addCapsule(u(rng) + 1., u(rng), u(rng), u(rng) + 1., u(rng), u(rng), r(rng));
        }
        a.updateBound();
        b.updateBound();
        // Reference: the closest capsule pair, one pair at a time (no early-outs, no vector loop).
        double pairMin = 1e300;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j)
            {
                const double rr = a.radius_[i] + b.radius_[j];
                pairMin = std::min(pairMin, std::sqrt(segmentDistanceSquared(a, i, b, j)) - rr);
            }
        const bool ours = bodiesCollide(a, b);
        if (std::abs(pairMin) > 1e-9)
            EXPECT_EQ(ours, pairMin < 0.) << "body pair " << k;
        collisions += ours;
    }
    EXPECT_GT(collisions, 100);
    EXPECT_LT(collisions, 1900);
}

TEST(CapsuleCollision, BoundingSphereLevelsNeverChangeTheAnswer)
{
    // Bodies of 1 to 40 capsules (past the 16-capsule chunks of the gathered pass), spheres among them:
    // the early-outs on body and capsule bounding spheres must give exactly the all-pairs answer.
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(-1., 1.), r(0.01, 0.15);
    std::uniform_int_distribution<int> count(1, 40);
    int collisions = 0, bodies = 0;
    for (int k = 0; k < 3000; ++k)
    {
        CollisionBody a, b;
        for (CollisionBody *body : {&a, &b})
        {
            const double shift = body == &b ? 1.2 : 0.;
            for (int c = count(rng); c > 0; --c)
            {
                const double x = u(rng) + shift, y = u(rng), z = u(rng);
                if (c % 4 == 0)
                    body->addSphere(x, y, z, r(rng));
                else
                    body->addCapsule(x, y, z, x + 0.4 * u(rng), y + 0.4 * u(rng), z + 0.4 * u(rng), r(rng));
            }
            body->updateBound();
        }
        double pairMin = 1e300;
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = 0; j < b.size(); ++j)
                pairMin =
                    std::min(pairMin, std::sqrt(segmentDistanceSquared(a, i, b, j)) - a.radius_[i] - b.radius_[j]);
        if (std::abs(pairMin) < 1e-9)
            continue;
        ++bodies;
        const bool ours = bodiesCollide(a, b);
        EXPECT_EQ(ours, pairMin < 0.) << "body pair " << k << " with " << a.size() << " and " << b.size()
                                      << " capsules";
        EXPECT_EQ(bodiesCollide(b, a), ours) << "body pair " << k << " (swapped)";
        collisions += ours ? 1 : 0;
    }
    EXPECT_GT(collisions, bodies / 10);  // both answers are well represented
    EXPECT_LT(collisions, bodies - bodies / 10);
}

TEST(CapsuleCollision, SinglePrecisionBoxesNeverDropAPairTheExactTestFlags)
{
    // The broad phase rules capsule pairs out by single-precision boxes; they are rounded outwards, so every pair
    // whose double-precision test says "collide" must still reach that test. Stress the rounding: bodies far from
    // the origin (up to 1e7, where a float's spacing is 1), capsule pairs placed within 1e-9 of contact on either
    // side, bodies past the 64-capsule chunks, single spheres against bodies, and coordinates beyond the float range.
    // The answer must equal the all-pairs double test exactly (no tolerance band).
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1., 1.), r(0.005, 0.05), gap(-1e-9, 1e-9);
    std::uniform_int_distribution<int> count(1, 150);
    int collisions = 0;
    const double offsets[] = {0., 1e3, 1e7, -3e5, 1e39};
    for (int k = 0; k < 2500; ++k)
    {
        const double offset = offsets[k % 5];
        CollisionBody a, b;
        const int n = k < 40 ? 63 + k % 4 : count(rng);  // 63-66 capsules: both sides of the 64-capsule chunks
        const double spread = 1. + n / 4.;               // sparse enough that the near contact below often decides
        for (CollisionBody *body : {&a, &b})
            for (int c = body == &a ? n : count(rng); c > 0; --c)
            {
                const double x = spread * u(rng) + offset, y = spread * u(rng) - offset, z = u(rng);
                body->addCapsule(x, y, z, x + 0.4 * u(rng), y + 0.4 * u(rng), z + 0.4 * u(rng), r(rng));
            }
        if (k % 3 == 0)  // every third pair: a single sphere (a disc's body, which keeps no boxes) against a body
        {
            a.clear();
            a.addSphere(b.ax_[0] + u(rng), b.ay_[0] + u(rng), b.az_[0] + u(rng), r(rng));
        }
        // One capsule of b made a sphere rr (1 + gap) from the first capsule's axis start of a: a near contact. On
        // every other pair that capsule of a is a sphere too and the contact lies along a coordinate axis, where
        // the two boxes touch face to face within ~1e-11, far below a float's spacing at 1e7. (The rounding
        // contract itself is tested directly: FloatBoundsAreNeverInsideTheirValue.)
        const std::size_t j = b.size() - 1;
        double dx = u(rng), dy = u(rng), dz = u(rng);
        if (k % 2 == 1)
        {
            a.bx_[0] = a.ax_[0];
            a.by_[0] = a.ay_[0];
            a.bz_[0] = a.az_[0];
            const double sign = u(rng) < 0. ? -1. : 1.;
            dx = k % 6 == 1 ? sign : 0.;
            dy = k % 6 == 3 ? sign : 0.;
            dz = k % 6 == 5 ? sign : 0.;
        }
        const double norm = std::sqrt(dx * dx + dy * dy + dz * dz);
        const double reach = (a.radius_[0] + b.radius_[j]) * (1. + gap(rng)) / norm;
        b.ax_[j] = b.bx_[j] = a.ax_[0] + dx * reach;
        b.ay_[j] = b.by_[j] = a.ay_[0] + dy * reach;
        b.az_[j] = b.bz_[j] = a.az_[0] + dz * reach;
        a.updateBound();
        b.updateBound();
        bool pairwise = false, swapped = false;  // the reference in each order (rounding need not be symmetric)
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t m = 0; m < b.size(); ++m)
            {
                pairwise = pairwise || capsulesCollide(a, i, b, m);
                swapped = swapped || capsulesCollide(b, m, a, i);
            }
        EXPECT_EQ(bodiesCollide(a, b), pairwise) << "body pair " << k << " at offset " << offset;
        EXPECT_EQ(bodiesCollide(b, a), swapped) << "body pair " << k << " (swapped)";
        collisions += pairwise && offset < 1e38 ? 1 : 0;  // at 1e39 every capsule is the same point: all collide
    }
    EXPECT_GT(collisions, 400);  // both answers are well represented among the 2000 pairs at finite offsets
    EXPECT_LT(collisions, 1600);
    std::printf("[ info ] %d of 2000 body pairs collide\n", collisions);
}

TEST(CapsuleCollision, FloatBoundsAreNeverInsideTheirValue)
{
    // roundedDown(x) <= x <= roundedUp(x) as doubles, across zero, denormals, the float range's ends and beyond;
    // a bound computed from large numbers is widened by their magnitude; NaN stays NaN (never overlaps).
    const double values[] = {0.,
                             1e-45,
                             1e-40,
                             1e-30,
                             0.1,
                             1.,
                             1. / 3.,
                             1e7 + 0.3,
                             16777217.,
                             3.4e38,
                             3.5e38,
                             1e39,
                             1e300,
                             -1e-45,
                             -0.1,
                             -1e7,
                             -3.4e38,
                             -1e300,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};
    for (const double x : values)
    {
        EXPECT_LE(static_cast<double>(roundedDown(x, std::fabs(x))), x) << x;
        EXPECT_GE(static_cast<double>(roundedUp(x, std::fabs(x))), x) << x;
    }
    EXPECT_LE(static_cast<double>(roundedDown(1e-3, 1e7)), 1e-3 - 1e7 * 0x1p-21);  // widened by the scale
    EXPECT_GE(static_cast<double>(roundedUp(-1e-3, 1e7)), -1e-3 + 1e7 * 0x1p-21);
    EXPECT_TRUE(std::isnan(roundedDown(std::nan(""), 1.)));
}

TEST(CapsuleCollision, AStaleBodyIsRefusedNotMisread)
{
    CollisionBody a, b;
    a.addCapsule(0., 0., 0., 1., 0., 0., 0.1);
    b.addCapsule(0.5, 0.05, 0., 0.5, 1., 0., 0.1);
    a.updateBound();
    b.updateBound();
    EXPECT_TRUE(a.hasBoxes());
    EXPECT_TRUE(bodiesCollide(a, b));
    b.addCapsule(0.5, 0.05, 0., 0.5, 1., 0., 0.1);  // changed after updateBound(): its boxes are stale
    EXPECT_FALSE(b.hasBoxes());
    EXPECT_THROW(bodiesCollide(a, b), std::logic_error);
    b.updateBound();
    EXPECT_TRUE(bodiesCollide(a, b));
}

TEST(CapsuleCollision, SegmentDistanceMatchesFclDistance)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1., 1.);
    for (int k = 0; k < 300; ++k)
    {
        const Eigen::Vector3d p1(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng));
        const Eigen::Vector3d p2(u(rng) + 2., u(rng), u(rng)), q2(u(rng) + 2., u(rng), u(rng));
        const auto a = capsule(p1.x(), p1.y(), p1.z(), q1.x(), q1.y(), q1.z(), 0.1);
        const auto b = capsule(p2.x(), p2.y(), p2.z(), q2.x(), q2.y(), q2.z(), 0.1);
        auto place = [](const Eigen::Vector3d &p, const Eigen::Vector3d &q)
        {
            fcl::Transform3d tf = fcl::Transform3d::Identity();
            tf.translation() = 0.5 * (p + q);
            tf.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), q - p).toRotationMatrix();
            return tf;
        };
        const fcl::Capsuled ca(0.1, (q1 - p1).norm()), cb(0.1, (q2 - p2).norm());
        fcl::DistanceRequestd request;
        fcl::DistanceResultd result;
        fcl::distance(&ca, place(p1, q1), &cb, place(p2, q2), request, result);
        if (result.min_distance > 1e-6)
            EXPECT_NEAR(std::sqrt(segmentDistanceSquared(a, 0, b, 0)) - 0.2, result.min_distance, 1e-4) << k;
    }
}
