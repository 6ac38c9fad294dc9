#ifndef OMPL_PARC_COLLISION_BODY_
#define OMPL_PARC_COLLISION_BODY_

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ompl_parc
{
    /** \brief The shape of a robot at one configuration, as a set of capsules (sphere-swept segments).

        A sphere is a capsule whose two end points coincide, so discs, planar-arm links and sphere
        models of 3D arms all share one representation and one robot-robot test. The data is stored
        structure-of-arrays so that the pairwise loops in bodiesCollide() vectorise. 2D robots use z = 0.
        updateBound() adds what the tests rule pairs out by: a bounding sphere around the whole body, one
        around each capsule (for self-collision), and each capsule's box in single precision rounded outwards
        (boxes_: the broad phase of the robot-robot and robot-environment tests), so that the exact distances
        in double precision run only for the few pairs that could touch.

        A body of many small capsules (a sphere model of an arm: several spheres per link) is better told its
        groups (setGroups(): a link's capsules): updateBound() then bounds each group by a sphere and leaves the
        capsule boxes out, since for such a body they cost more than the pair test they save. The robot-robot
        test rules group pairs out by their spheres and tests the capsules of the few close ones; readers of the
        boxes (the environment test) call updateBoxes() first where hasBoxes() is false. */
    class CollisionBody
    {
      public:
        /** \brief Remove all capsules (keeps the allocated memory, so bodies can be reused in hot loops). */
        void clear();

        /** \brief Add the capsule from (ax, ay, az) to (bx, by, bz) with the given radius. */
        void addCapsule(double ax, double ay, double az, double bx, double by, double bz, double radius);

        /** \brief Make the body \e n capsules long, for kinematics that write the arrays directly (cheaper than
            n addCapsule() calls in the hot loop); \e spheresOnly must say whether all of them will be spheres. */
        void resize(std::size_t n, bool spheresOnly)
        {
            spheresOnly_ = spheresOnly;
            boxesCurrent_ = false;
            groupsCurrent_ = false;
            groups_.clear();
            if (radius_.size() != n)  // inline and cheap when the size is unchanged: the case per timestep
                resizeArrays(n);
        }

        /** \brief Add a sphere (a capsule of zero length). */
        void addSphere(double x, double y, double z, double radius) { addCapsule(x, y, z, x, y, z, radius); }

        /** \brief Grow the axis-aligned box [\e lo, \e hi] to contain every capsule (swept bounds over time
            are unions of such boxes). */
        void expandBox(std::array<double, 3> &lo, std::array<double, 3> &hi) const;

        /** \brief Split the capsules into \e count consecutive groups, group k ending before capsule \e ends[k]
            (increasing, the last one size()): the capsules of one link, say. Call after the capsules are written
            (clear(), resize() and addCapsule() drop the groups); throws std::invalid_argument if the ends do not
            cover the body. */
        void setGroups(const std::uint32_t *ends, std::size_t count);

        /** \brief For kinematics that know each group's bounding sphere (a rigid link's, moved with the link): after
            setGroups(), write the spheres of groups_ (each containing its capsules with room for the rounding of
            both) and call this; updateBound() then keeps them instead of computing them from the capsules, a pass
            over every capsule. */
        void keepGroupSpheres() { groupSpheresGiven_ = true; }

        /** \brief Recompute the bounding spheres (of the body and of each capsule) and the boxes (updateBoxes());
            call after the last addCapsule(). A body with groups (setGroups()) gets its group spheres instead of
            the boxes (hasGroupBounds()). */
        void updateBound();

        /** \brief Recompute the single-precision capsule boxes and the body's box from the capsules (updateBound()
            does; a body whose arrays were copied in with their bounding spheres needs only this). A body of one
            sphere keeps none (boxStride_ 0): two such bodies are decided by their bounding spheres alone, and discs
            would pay for boxes at every state; getBox() gives its box when a pair test needs it. */
        void updateBoxes();

        /** \brief True once updateBoxes() (or updateBound()) ran after the last clear(), addCapsule() or resize(). */
        bool hasBoxes() const { return boxesCurrent_; }

        /** \brief True once updateBound() computed the group spheres of a body with groups (setGroups()), after the
            last change: bodiesCollide() then tests it group by group, without boxes. */
        bool hasGroupBounds() const { return groupsCurrent_; }

        /** \brief The number of groups (0: none set). */
        std::size_t groupCount() const { return groups_.size(); }

        /** \brief True for a body of exactly one sphere (a disc): it keeps no capsule boxes. */
        bool isSingleSphere() const { return spheresOnly_ && size() == 1; }

        /** \brief The body's box in single precision, rounded outwards: boxLo_ and boxHi_, or for a body of one sphere
            (isSingleSphere(), which keeps none) the sphere's, computed here. */
        void getBox(std::array<float, 3> &lo, std::array<float, 3> &hi) const;

        std::size_t size() const { return radius_.size(); }

        /** \brief Bounding sphere of all capsules. (The members the pair test reads first come first, so that they
            share a cache line: the sphere, then what tells a single sphere, which two discs need no more than.) */
        double centerX_{0.}, centerY_{0.}, centerZ_{0.}, boundRadius_{0.};

        /** \brief True while every capsule is a sphere: the pair test then skips the segment math. */
        bool spheresOnly_{true};

      private:
        /** \brief See hasBoxes(), hasGroupBounds() and keepGroupSpheres() (beside spheresOnly_: resize() writes all
            four, once per body and timestep). */
        bool boxesCurrent_{false}, groupsCurrent_{false}, groupSpheresGiven_{false};

      public:
        /** \brief Capsule radii (size() of them). */
        std::vector<double> radius_;

        /** \brief The body's box: the union of its capsule boxes (single precision, rounded outwards like them); not
            kept for a body of one sphere (read it with getBox()). */
        std::array<float, 3> boxLo_{}, boxHi_{};

        /** \brief Per capsule, its axis-aligned box (end points -/+ radius) in single precision, rounded outwards past
            the conversion's error: six arrays (low x, y, z, high x, y, z) of boxStride_ floats each, boxStride_ being
            size() rounded up to the library's SIMD width; the entries past size() are NaN (never overlapping).
            The broad phase of the robot-robot and robot-environment tests (bodiesCollide(), ObstacleSet::collides())
            reads these, a vector of capsules per instruction, and the double-precision arrays only for the
            pairs whose boxes overlap. */
        std::size_t boxStride_{0};
        std::vector<float> boxes_;

        /** \brief Capsule end points, one array per coordinate. */
        std::vector<double> ax_, ay_, az_, bx_, by_, bz_;

        /** \brief Bounding sphere of each capsule, one array per coordinate (set by updateBound()). */
        std::vector<double> sphereX_, sphereY_, sphereZ_, sphereRadius_;

        /** \brief A group of capsules (setGroups()): its bounding sphere (set by updateBound(), padded by a small
            multiple of the coordinates' rounding so that it contains its capsules whatever the rounding of its
            computation: ruling a pair of groups out never hides a collision of the exact test) and one past its
            last capsule. */
        struct Group
        {
            double x, y, z, radius;
            std::uint32_t end;
        };

        /** \brief The groups, read together (one vector: a body without groups, a disc's, stays small). */
        std::vector<Group> groups_;

      private:
        /** \brief Give every per-capsule array \e n entries. */
        void resizeArrays(std::size_t n);

        /** \brief The group spheres and, from them, the body's sphere (updateBound() of a body with groups). */
        void updateGroupBounds();

        /** \brief The group spheres from the capsules (where the kinematics gave none: keepGroupSpheres()). */
        void computeGroupSpheres();
    };
}  // namespace ompl_parc

#endif
