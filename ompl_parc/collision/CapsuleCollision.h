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

        This is the robot-robot test on the hot path of conflict detection. Two levels of bounding spheres
        come before any exact test: the bodies' spheres, then each capsule's sphere against the other body's
        (those that reach it are gathered into small local arrays); per gathered capsule of \e a, one
        vectorised pass of sphere-sphere clearances over the gathered ones of \e b, and the exact segment
        distance only where two capsule spheres overlap. The answer is exactly that of testing all pairs. */
    bool bodiesCollide(const CollisionBody &a, const CollisionBody &b);
}  // namespace ompl_parc

#endif
