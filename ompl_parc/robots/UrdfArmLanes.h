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
        self-collision inflates radii by (n + 4) S 2^-20 (16 um for a Panda). The end points then move to the world frame (a rotation and the
        base translation B, a few more roundings of B + S), so the environment test inflates by
        getInflation() = that + (B + S) 2^-21 (19 um for a Panda two metres from the origin). Tests bisect to
        configurations a hair inside collisions and check none is missed. The width is the compiler's vector width for float (4 on baseline
        x86-64, 8 with AVX2 via OMPL_PARC_NATIVE), fixed at compile time. All state is per call (thread
        local scratch), so one kernel serves every thread. */
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
        bool anyCollides(const double *configs, std::size_t count, const ObstacleSet &obstacles) const;

        /** \brief How much every radius is inflated against obstacles to cover single-precision rounding
            (metres); less against the arm itself. */
        double getInflation() const { return inflation_; }

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
    };
}  // namespace ompl_parc

#endif
