#ifndef OMPL_PARC_URDF_ARM_LANES_
#define OMPL_PARC_URDF_ARM_LANES_

#include "ompl_parc/collision/ObstacleSet.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief The collision check of a URDF arm for several configurations at once: one SIMD lane per
        configuration (the samples of one edge), in single precision.

        A state at a time, the check is a chain of short dependent steps (a joint's rotation, a capsule, a pair
        of capsules); here every step runs on width() configurations in one vector instruction: the forward
        kinematics (sin/cos included), the capsule end points, the self-collision pairs (a bounding-sphere
        clearance per pair, then the exact segment distance of segmentSegmentDistanceSquared() only for pairs
        where some lane is close), and the environment broad phase (each capsule's box against each obstacle's
        box). The few (capsule, obstacle, lane) triples that pass the broad phase go through ObstacleSet's
        exact narrow phase in double precision.

        Single precision is safe because every radius is inflated: a float operation rounds by at most 2^-24
        relative. The kinematics run in the base frame, where coordinates are bounded by the arm's reach S (joint
        offsets, prismatic joints' travel and capsule extents); each of the n joints adds a few roundings of
        rotation entries and of S (sin/cos of a rounded angle included), about 10 n S 2^-24 in all, so
        self-collision inflates radii by (n + 4) S 2^-20 (16 um for a Panda). The end points then move to the world
        frame (a rotation and the base translation B, a few more roundings of B + S), so the environment test
        inflates by getInflation() = that + (B + S) 2^-21 (19 um for a Panda two metres from the origin). Tests
        bisect to configurations a hair inside collisions and check none is missed. The width is the compiler's
        vector width for float (4 on baseline x86-64, 8 with AVX2 via OMPL_PARC_NATIVE), fixed at compile time. All
        state is per call (thread local scratch), so one kernel serves every thread. Two arms placed in the world
        (place(), or anyCollides() with a Placed) are compared by nearLanes(), which the team checks use. */
    class UrdfArmLanes
    {
      public:
        /** \brief A movable joint: it moves frame k + 1 (joint k) from aligned frame \e parent (an earlier one),
            turning about or sliding along its z axis by multiplier * q[coordinate] + offset. */
        struct Joint
        {
            std::size_t parent;
            unsigned int coordinate;
            double multiplier, offset;
            bool prismatic;
            /** \brief A prismatic joint's largest |value| within the bounds (0 for a revolute one). */
            double travel;
        };

        /** \brief A capsule in aligned frame \e frame. */
        struct Capsule
        {
            std::size_t frame;
            Eigen::Vector3d a, b;
            double radius;
        };

        /** \brief The arm's kinematics as UrdfArm keeps them: the base pose, the number of coordinates, the
            joints and per joint k the offset from its parent's aligned frame to aligned frame k + 1 at value 0,
            the capsules and the self-collision pairs. */
        UrdfArmLanes(const Eigen::Isometry3d &basePose, unsigned int dimension, std::vector<Joint> joints,
                     const std::vector<Eigen::Matrix3d> &offsetRotations,
                     const std::vector<Eigen::Vector3d> &offsetTranslations, std::vector<Capsule> capsules,
                     std::vector<std::pair<std::size_t, std::size_t>> selfPairs);

        /** \brief Configurations checked per call (the float SIMD width). */
        static std::size_t width();

        /** \brief True if any of the \e count (1 .. width()) configurations \e configs (flat, dimension doubles
            each, within the joint bounds) collides with itself or with \e obstacles. Conservative: never false
            where the double-precision check finds a collision. */
        bool anyCollides(const double *configs, std::size_t count, const ObstacleSet &obstacles) const
        {
            return anyCollides(configs, count, obstacles, nullptr);
        }

        /** \brief How much every radius is inflated against obstacles to cover single-precision rounding
            (metres); less against the arm itself. */
        double getInflation() const { return inflation_; }

        /** \brief Up to width() configurations of the arm placed in the world, one lane each: what nearLanes()
            compares between two arms, in rows of width() floats (one per lane); a lane's coordinates are within
            getInflation() of the double-precision ones. */
        struct Placed
        {
            /** \brief Per capsule its end points (6 rows) and their midpoint (3 rows); per frame its sphere's
                centre (3 rows). */
            std::vector<float> ends, mids, frameCenters;
            /** \brief Per lane, a box around the arm (low x, y, z rows, then high). */
            std::vector<float> box;
            std::size_t count{0};
        };

        /** \brief Place \e count (1 .. width()) configurations \e configs (flat, dimension doubles each). */
        void place(const double *configs, std::size_t count, Placed &placed) const;

        /** \brief anyCollides(), and where none collides, the configurations placed into \e placed as place() would
            (one pass of kinematics for both: the team check's robots alone, then their pairs). */
        bool anyCollides(const double *configs, std::size_t count, const ObstacleSet &obstacles, Placed *placed) const;

        /** \brief The lanes (bit l: configuration l) where arm \e a placed as \e pa and arm \e b placed as \e pb may
            touch and only the exact test can tell; 0 once \e touching is set. Conservative both ways: a lane left
            out of both is one where the double-precision capsules of the two arms are apart (by more than both
            inflations twice over), and \e touching (bits too, set when some lane is found) is only set for lanes
            where they overlap by more than that. Arms whose bases are farther apart than their reaches answer 0 at
            once. */
        static unsigned int nearLanes(const UrdfArmLanes &a, const Placed &pa, const UrdfArmLanes &b, const Placed &pb,
                                      unsigned int &touching);

      private:
        unsigned int dimension_;
        std::vector<Joint> joints_;
        /** \brief Base rotation (row-major) and translation. */
        float baseRotation_[9], baseTranslation_[3];
        /** \brief Per joint: offset rotation (row-major, 9 each) and translation (3 each). */
        std::vector<float> offsetRotations_, offsetTranslations_;
        /** \brief Per capsule: frame, local end points, radius inflated against obstacles and against the arm
            itself, bounding-sphere radius (for self-collision). */
        std::vector<std::size_t> frame_;
        std::vector<float> localA_, localB_, radius_, selfRadius_, sphereRadius_;
        std::vector<std::pair<std::size_t, std::size_t>> selfPairs_;
        /** \brief The self pairs grouped by their frames: a group's pairs are selfPairs_[begin, end), all between
            capsules of frames \e a and \e b, and each frame has a sphere around all its capsules' spheres. A group
            whose frame spheres are apart in every lane is skipped whole: a link covered by many spheres (a URDF of
            spheres, as VAMP and cuRobo make them) costs a test per pair of links, not per pair of spheres. */
        struct FramePairs
        {
            std::size_t a, b, begin, end;
        };
        std::vector<FramePairs> framePairs_;
        /** \brief Per frame: the local centre (3 each) of its sphere, and its radius against the arm itself and
            against obstacles (0: no capsule). Against an obstacle, a frame whose sphere's box misses the obstacle's
            in every lane has its capsules skipped. */
        std::vector<float> frameCenter_, frameRadius_, frameObstacleRadius_;
        /** \brief The capsules by frame: those of frame f are byFrame_[frameBegin_[f], frameBegin_[f + 1]). */
        std::vector<std::size_t> byFrame_, frameBegin_;
        bool hasCapsules(std::size_t f) const { return frameBegin_[f] != frameBegin_[f + 1]; }
        double selfInflation_, inflation_;
        /** \brief The base's position and a radius around it containing the arm at every configuration (for
            nearLanes()). */
        double basePosition_[3], reach_;
        /** \brief Frame \e f's sphere as nearLanes() compares it: grown by twice the inflation more than against
            obstacles, so that it contains the float capsules within the pair test's reach. */
        float pairFrameRadius(std::size_t f) const
        {
            return frameObstacleRadius_[f] + static_cast<float>(2. * inflation_);
        }
        /** \brief Per capsule, the radii nearLanes() uses: the capsule's grown by twice the inflation (apart beyond
            it), and shrunk by as much (touching within it). */
        std::vector<float> pairRadius_, pairCoreRadius_;
        /** \brief Per capsule, half its length grown by the inflation (its float end points lie within that of their
            midpoint), and whether it is a sphere (equal end points, computed alike in every lane). */
        std::vector<float> pairHalfLength_;
        std::vector<bool> sphere_;

        /** \brief The forward kinematics of \e count configurations into the thread's scratch (base frame). */
        void computeKinematics(const double *configs, std::size_t count) const;
        /** \brief Move the scratch's capsule end points and frame centres to the world frame. */
        void moveScratchToWorld() const;
        /** \brief Into \e lo and \e hi, the box around every frame's obstacle sphere in every lane of the scratch's
            world-frame lanes (moveScratchToWorld()), in the floats anyCollides() compares with obstacle boxes. */
        void armBox(float lo[3], float hi[3]) const;
        /** \brief Copy the scratch's world-frame lanes (moveScratchToWorld()) into \e placed. */
        void storePlaced(std::size_t count, Placed &placed) const;
    };
}  // namespace ompl_parc

#endif
