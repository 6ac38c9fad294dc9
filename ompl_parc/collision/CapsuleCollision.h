#ifndef OMPL_PARC_CAPSULE_COLLISION_
#define OMPL_PARC_CAPSULE_COLLISION_

#include "ompl_parc/collision/CollisionBody.h"

namespace ompl_parc
{
    /** \brief Squared distance between the axis segments of capsule \e i of \e a and capsule \e j of \e b.

        Branch-free (clamps and selects only) so that loops over many capsule pairs vectorise. Handles
        degenerate segments (spheres) without special cases. */
    double segmentDistanceSquared(const CollisionBody &a, std::size_t i, const CollisionBody &b, std::size_t j);

    /** \brief True if capsule \e i of \e a and capsule \e j of \e b overlap. */
    bool capsulesCollide(const CollisionBody &a, std::size_t i, const CollisionBody &b, std::size_t j);

    /** \brief True if any capsule of \e a overlaps any capsule of \e b.

        This is the robot-robot test on the hot path of conflict detection. The bodies' bounding spheres and
        boxes come first; then, a SIMD vector of capsules per instruction, the capsules of each body whose boxes
        overlap the other body's box (CollisionBody::boxes_, single precision rounded outwards: never tighter
        than the capsule); per pair of those, their boxes, and the exact segment distance in double precision
        only where the two boxes overlap. Bodies with group bounds (CollisionBody::setGroups()) are tested by
        their groups instead: the group spheres of each that reach the other body; per pair of those that overlap,
        each capsule of one group whose sphere reaches the other group against that group's capsules, by the
        distance of the centres for two spheres, else by the exact distance where the two capsules' spheres
        overlap. The boxes and spheres only rule pairs out that cannot touch, so the answer is that of testing
        every pair. Both bodies need current bounds (updateBound()): a stale one is refused with std::logic_error. */
    bool bodiesCollide(const CollisionBody &a, const CollisionBody &b);
}  // namespace ompl_parc

#endif
