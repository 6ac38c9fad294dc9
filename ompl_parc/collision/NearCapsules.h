#ifndef OMPL_PARC_NEAR_CAPSULES_
#define OMPL_PARC_NEAR_CAPSULES_

#include "ompl_parc/collision/CollisionBody.h"

#include <array>
#include <cstddef>

namespace ompl_parc
{
    /** \brief The capsules of one chunk of a body whose boxes overlap a given box (another body's, an obstacle's):
        their indices and boxes, gathered into local arrays for the pair loops that follow.

        The broad phase shared by the robot-robot test (bodiesCollide()) and the robot-environment test
        (ObstacleSet::collides()): one SIMD vector of capsule boxes (CollisionBody::boxes_) per step against the
        given box, a branch-free compaction of the few that overlap. Capsules are taken CHUNK at a time so that the
        lists live on the stack whatever the body's size. A body of one sphere (which keeps no boxes) is its own
        chunk of one. The body's boxes must be current (CollisionBody::hasBoxes()). */
    class NearCapsules
    {
      public:
        static constexpr std::size_t CHUNK = 64;

        /** \brief Capsules [\e base, \e base + CHUNK) of \e body (\e base a multiple of CHUNK) whose boxes overlap
            [\e boxLo, \e boxHi]. */
        NearCapsules(const CollisionBody &body, std::size_t base, const std::array<float, 3> &boxLo,
                     const std::array<float, 3> &boxHi);

        /** \brief True if near capsule \e k's box overlaps near capsule \e m's of \e other. */
        bool overlaps(std::size_t k, const NearCapsules &other, std::size_t m) const
        {
            return lo_[0][k] <= other.hi_[0][m] && other.lo_[0][m] <= hi_[0][k] && lo_[1][k] <= other.hi_[1][m] &&
                   other.lo_[1][m] <= hi_[1][k] && lo_[2][k] <= other.hi_[2][m] && other.lo_[2][m] <= hi_[2][k];
        }

        /** \brief How many capsules of the chunk overlap the box. */
        std::size_t size() const { return count_; }

        /** \brief The body's index of near capsule \e k. */
        std::size_t index(std::size_t k) const { return index_[k]; }

      private:
        std::size_t count_{0};
        std::size_t index_[CHUNK];
        float lo_[3][CHUNK], hi_[3][CHUNK];
    };
}  // namespace ompl_parc

#endif
