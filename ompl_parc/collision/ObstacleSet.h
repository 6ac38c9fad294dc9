#ifndef OMPL_PARC_OBSTACLE_SET_
#define OMPL_PARC_OBSTACLE_SET_

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/collision/Obstacle.h"

#include <array>
#include <vector>

namespace ompl_parc
{
    /** \brief The static obstacles as flat arrays, for the robot-environment test on the planners' hot path
        (analytic distances, no FCL, no allocation).

        Built once, obstacle by obstacle. collides() is two broad-phase levels and one narrow one: the body's
        box against every obstacle's world box (single precision, rounded outwards; chunk by chunk, the near ones
        gathered by a branch-free compaction), then, per near obstacle, the capsule boxes of the body against the
        obstacle's box a SIMD vector of capsules at a time (NearCapsules, single precision rounded outwards: never
        tighter than the double-precision boxes), then the capsule's exact distance to the primitive: a sphere
        through the point-segment distance, a box through the segment-box distance in the box's frame. A cylinder
        is the intersection of its enclosing capsule (same axis and radius) and its bounding box, and both are
        tested: a capsule touching the cylinder touches both, so the test is conservative; it errs only where a
        capsule passes the rim, touching the enclosing capsule's cap and the box's corner but not the cylinder.
        Every distance is compared with a margin (MARGIN) that covers rounding and FCL's own tolerance, so a
        collision FCL reports is never missed. */
    class ObstacleSet
    {
      public:
        /** \brief Distance below which a capsule counts as touching an obstacle (metres). */
        static constexpr double MARGIN = 1e-6;

        /** \brief Add \e obstacle (its shape, size and pose; the caller checked the sizes). A primitive only:
            throws ompl::Exception for a mesh, which Environment adds as its fitted boxes. */
        void add(const Obstacle &obstacle);

        /** \brief True if any capsule of \e body comes within MARGIN of any obstacle (conservative). Uses the
            body's boxes (updateBound() or updateBoxes()); a body without current ones (CollisionBody::hasBoxes())
            is checked on a copy that gets them, slower but with the same answer. */
        bool collides(const CollisionBody &body) const;

        std::size_t size() const { return shape_.size(); }

        /** \brief World axis-aligned box of obstacle \e k, widened by MARGIN: kernels that check several
            configurations at once run their own broad phase on it, then capsuleHits(). */
        void getBox(std::size_t k, double lo[3], double hi[3]) const;

        /** \brief True if capsule \e i of \e body touches obstacle \e k (the narrow phase alone). */
        bool capsuleHits(const CollisionBody &body, std::size_t i, std::size_t k) const;

      private:
        /** \brief What the narrow phase needs of one obstacle: the world-to-local rotation (rows of R^T), the
            centre, and the half extents of its box (for a sphere: its radius in half[0]). */
        struct Frame
        {
            double rotation[9];
            double center[3];
            double half[3];
        };

        /** \brief Capsule \e i of \e body against the box of frame \e f. */
        static bool capsuleHitsBox(const CollisionBody &body, std::size_t i, const Frame &f);

        /** \brief Capsule \e i of \e body against the sphere of frame \e f. */
        static bool capsuleHitsSphere(const CollisionBody &body, std::size_t i, const Frame &f);

        /** \brief Capsule \e i of \e body against the cylinder of frame \e f (conservative, see the class). */
        static bool capsuleHitsCylinder(const CollisionBody &body, std::size_t i, const Frame &f);

        /** \brief True if a capsule of \e body (its boxes current) touches an obstacle. */
        bool boxedBodyCollides(const CollisionBody &body) const;

        /** \brief World axis-aligned bounds of each obstacle, one array per coordinate. */
        std::vector<double> loX_, loY_, loZ_, hiX_, hiY_, hiZ_;

        /** \brief The same bounds in single precision, rounded outwards, per obstacle (low x, y, z, high x, y, z). */
        std::vector<std::array<float, 6>> boxes_;

        std::vector<Obstacle::Shape> shape_;
        std::vector<Frame> frames_;
    };
}  // namespace ompl_parc

#endif
