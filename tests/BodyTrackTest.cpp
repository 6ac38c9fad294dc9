#include "ompl_parc/collision/BodyTrack.h"
#include "ompl_parc/collision/CapsuleCollision.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace ompl_parc;

TEST(BodyTrack, LoadsBodiesBitForBitAndCollidesAsBodiesCollide)
{
    // Bodies of 1 to 20 capsules, spheres-only ones among them, as a robot's bodies over time would be.
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1., 1.), r(0.02, 0.3);
    std::uniform_int_distribution<int> count(1, 20);
    std::vector<CollisionBody> bodies(300);
    BodyTrack track;
    for (auto &body : bodies)
    {
        const bool spheres = u(rng) < 0;
        for (int c = count(rng); c > 0; --c)
            if (spheres)
                body.addSphere(u(rng), u(rng), u(rng), r(rng));
            else
                body.addCapsule(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), r(rng));
        body.updateBound();
        track.append(body);
    }
    ASSERT_EQ(track.size(), bodies.size());
    CollisionBody loaded, scratch, probe;
    int collisions = 0;
    for (std::size_t t = 0; t < bodies.size(); ++t)
    {
        track.load(t, loaded);
        const CollisionBody &body = bodies[t];
        EXPECT_EQ(loaded.ax_, body.ax_);
        EXPECT_EQ(loaded.bz_, body.bz_);
        EXPECT_EQ(loaded.radius_, body.radius_);
        EXPECT_EQ(loaded.sphereRadius_, body.sphereRadius_);
        EXPECT_EQ(loaded.spheresOnly_, body.spheresOnly_);
        EXPECT_EQ(loaded.boundRadius_, body.boundRadius_);
        EXPECT_EQ(loaded.centerY_, body.centerY_);
        probe.clear();
        probe.addCapsule(2. * u(rng), 2. * u(rng), 2. * u(rng), 2. * u(rng), 2. * u(rng), 2. * u(rng), r(rng));
        probe.updateBound();
        const bool expected = bodiesCollide(probe, body);
        EXPECT_EQ(track.collides(t, probe, scratch), expected) << "timestep " << t;
        collisions += expected;
    }
    EXPECT_GT(collisions, 30);
    EXPECT_LT(collisions, 270);
}
