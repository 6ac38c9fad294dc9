#ifndef OMPL_PARC_URDF_ARM_
#define OMPL_PARC_URDF_ARM_

#include "ompl_parc/meshes/CapsuleFit.h"
#include "ompl_parc/robots/Robot.h"
#include "ompl_parc/robots/Srdf.h"
#include "ompl_parc/robots/UrdfMeshOptions.h"
#include "ompl_parc/robots/UrdfArmLanes.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief A serial arm of revolute and prismatic joints read from a URDF (urdfdom), for 3D multi-arm problems.

        The chain runs from \e baseLink to \e tipLink; fixed joints on it are folded into the next movable
        joint's offset, and links hanging off it by fixed joints (a hand, a flange) are folded into the link
        they hang from. Revolute and prismatic joints use their `<limit>`s (required, finite, lower < upper);
        continuous joints are bounded to [-pi, pi] (a configuration space must be bounded); planar and floating
        joints are rejected. A prismatic joint's coordinate is in metres, a revolute one's in radians: the state
        space's distance adds them up as they are, so a metre of travel counts like a radian of turn.

        A joint with `<mimic joint="j" multiplier="m" offset="o"/>` is not a planning coordinate: its value is
        m * q_j + o, composed through mimics of mimics down to a movable joint of the chain that mimics nothing
        (an unknown, fixed or off-chain joint there, or a loop of mimics, is refused). The coordinates are the
        chain's movable joints that mimic nothing (getCoordinateNames()). A mimic joint's own `<limit>` narrows
        the range of the coordinate it follows, so that every planned configuration keeps every joint within its
        limits (a mimic whose limits leave no range is refused); its `<limit velocity>` lowers that coordinate's
        velocity limit likewise. A movable joint off the chain that mimics a chain joint (a gripper's second finger
        on the hand, the chain running to the first) gives its child link a frame of its own, computed after the
        chain's, and its collision bodies move with it. Any other movable joint off the chain (the fingers, when
        the chain ends at the hand) is held still, as MoveIt holds the joints outside the planned group: at 0
        clamped into its `<limit>`, or where the joint it mimics is held.

        Collision geometry comes from the `<collision>` elements: a sphere stays a sphere, a cylinder becomes
        the capsule around it (same axis and radius), a box the capsule along its longest axis whose radius
        is the half-diagonal of its cross-section; both contain the primitive, so robot-robot checks on the
        capsules are conservative. A mesh (STL, OBJ, COLLADA; found by MeshOptions::locator) becomes the
        capsules of its CapsuleFit, which contain it, cached beside the mesh (CapsuleFitCache); getMeshes() says
        how tight each fit is. Capsule k of the body is primitive k of getPrimitives(), so exact checks (FCL on
        the primitives, and on the meshes themselves: UrdfFclModel) can be compared with ours.

        Self-collision is checked between primitives of links that are not adjacent (the same frame, or one
        frame the parent of the other), except for pairs that already overlap at the zero configuration (clamped
        into the joint limits): like an SRDF's "default"/"adjacent" disabled pairs, such overlaps are part of the
        mechanical design. An SRDF given with the arm removes the link pairs its `<disable_collisions>` name too
        (and must name links of the URDF only). */
    class UrdfArm : public Robot
    {
      public:
        /** \brief A collision primitive of the URDF: its shape (size and pose in frame \e frame, as an
            Obstacle) and the name of the URDF link it came from. */
        struct Primitive
        {
            std::size_t frame;
            Obstacle shape;
            /** \brief The index in getMeshes() of the mesh this capsule was fitted to (a cylinder standing for the
                capsule of its axis, or a sphere), or -1 for a primitive of the URDF. */
            int mesh{-1};
        };

        /** \brief A mesh of the URDF: the link it belongs to, its pose in chain frame \e frame, its file and
            scale, and the capsules fitted to it. */
        struct LinkMesh
        {
            std::string link;
            std::size_t frame;
            Eigen::Isometry3d pose;
            std::string file;
            Eigen::Vector3d scale;
            CapsuleFit fit;
        };

        using MeshOptions = UrdfMeshOptions;

        /** \brief The chain \e baseLink .. \e tipLink of the URDF document \e urdfXml, its base link placed at
            \e basePose in the world. Throws ompl::Exception naming the offending element for malformed
            URDF, missing links, unsupported joints or geometry, and a base pose that puts
            the base link (or a link fixed to it) into an obstacle of \e environment (as it is now). */
        UrdfArm(std::string name, EnvironmentPtr environment, const std::string &urdfXml, const std::string &baseLink,
                const std::string &tipLink, const Eigen::Isometry3d &basePose, SrdfPtr srdf = nullptr,
                const MeshOptions &meshOptions = {});

        /** \brief The contents of a URDF file; throws ompl::Exception if it cannot be read. */
        static std::string readFile(const std::string &path);

        /** \brief The base pose from a position and roll, pitch, yaw (URDF convention: R = Rz Ry Rx). */
        static Eigen::Isometry3d pose(double x, double y, double z, double roll, double pitch, double yaw);

        std::string getKind() const override { return "urdf_arm"; }
        void computeCapsules(const double *q, CollisionBody &body) const override;

        /** \brief Bounds one by one, then self-collision and the environment UrdfArmLanes::width()
            configurations at a time (single precision, conservative; see UrdfArmLanes). */
        bool allValid(const double *configs, std::size_t count) const override;

        const UrdfArmLanes *getLanes() const override { return lanes_.get(); }

        /** \brief A movable joint of the arm: what moves frame k (k >= 1, joint k - 1 of getJoints()) relative
            to its parent frame. Frames 1 .. getChainJointCount() are the chain's, each the parent of the next;
            the frames after them are the child links of mimic joints off the chain. */
        struct Joint
        {
            std::string name;
            /** \brief Translates along its axis (else turns about it). */
            bool prismatic{false};
            /** \brief The frame it hangs from (an earlier one). */
            std::size_t parent{0};
            /** \brief Pose of the joint at value 0 in its parent frame (fixed joints in between folded in). */
            Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};
            /** \brief Unit axis, in the joint's frame. */
            Eigen::Vector3d axis{Eigen::Vector3d::UnitZ()};
            /** \brief The joint's value is multiplier * q[coordinate] + offset (1 and 0 unless it mimics). */
            unsigned int coordinate{0};
            double multiplier{1.}, offset{0.};
        };

        /** \brief World poses of the frames at \e q: frames[0] is the base link, frames[k] the child link of
            joint k - 1 of getJoints() (the chain's first, then the mimic joints' off it); the tip is
            frames[getChainJointCount()] times getTipOffset(). */
        void computeFrames(const double *q, std::vector<Eigen::Isometry3d> &frames) const;

        /** \brief World pose of the tip link at \e q. */
        Eigen::Isometry3d computeTipPose(const double *q) const;

        /** \brief Position-only inverse kinematics: damped least squares from random configurations (up to
            \e restarts of them, drawn with \e rng) until the tip is within \e tolerance of \e target and the
            configuration isValid() (bounds, self-collision, environment). */
        bool solvePositionIk(const Eigen::Vector3d &target, std::mt19937 &rng, std::vector<double> &q,
                             unsigned int restarts = 50, double tolerance = 1e-4) const;

        const std::vector<Primitive> &getPrimitives() const { return primitives_; }
        /** \brief The URDF's meshes on the chain, with their fits (empty for a URDF of primitives). */
        const std::vector<LinkMesh> &getMeshes() const { return meshes_; }
        const MeshOptions &getMeshOptions() const { return meshOptions_; }
        const Eigen::Isometry3d &getBasePose() const { return basePose_; }
        /** \brief The URDF document and chain ends the arm was built from (so it can be written out again). */
        const std::string &getUrdfXml() const { return urdfXml_; }
        const std::string &getBaseLink() const { return baseLink_; }
        const std::string &getTipLink() const { return tipLink_; }
        /** \brief Pose of the tip link in the frame of the chain's last movable joint's child link. */
        const Eigen::Isometry3d &getTipOffset() const { return tipOffset_; }
        /** \brief The SRDF whose `<disable_collisions>` pairs are left out of the self-collision check (null if
            none). */
        const SrdfPtr &getSrdf() const { return srdf_; }
        /** \brief Names of the planning coordinates' joints (the chain's movable joints that mimic nothing), base
            to tip. */
        const std::vector<std::string> &getJointNames() const { return jointNames_; }
        /** \brief Every movable joint, mimic ones included: joint k moves frame k + 1. */
        const std::vector<Joint> &getJoints() const { return joints_; }
        /** \brief How many of getJoints() lie on the chain (the first ones). */
        std::size_t getChainJointCount() const { return chainJoints_; }
        /** \brief The largest |value| \e joint takes within the bounds: how far a prismatic joint can slide its
            child from its origin (bounds on motion need it). */
        double getLargestJointValue(const Joint &joint) const;
        std::vector<std::string> getCoordinateNames() const override { return jointNames_; }

      protected:
        /** \brief Per joint, the URDF's `<limit velocity=...>` (1 rad/s where it gives none) and three times that
            per second as the acceleration (URDF has no acceleration limit; for the Panda this stays below every
            joint's limit in Franka's data sheet). */
        MotionLimits defaultMotionLimits() const override;

      private:
        /** \brief A capsule of a primitive, in its frame's aligned frame. */
        struct LocalCapsule
        {
            std::size_t frame;
            Eigen::Vector3d a, b;
            double radius;
        };

        /** \brief What the URDF says about the chain: per coordinate its limits, joint name and velocity limit,
            the movable joints (the chain's, then the mimic joints off it), the tip offset and the primitives. */
        struct Chain
        {
            ompl::base::RealVectorBounds limits{0};
            std::vector<Joint> joints;
            std::size_t chainJoints{0};
            std::vector<std::string> names;
            std::vector<double> velocities;
            /** \brief Every link of the URDF (an SRDF may name only these). */
            std::set<std::string> linkNames;
            Eigen::Isometry3d tipOffset{Eigen::Isometry3d::Identity()};
            std::vector<Primitive> primitives;
            std::vector<LinkMesh> meshes;
        };

        /** \brief Parses the chain once, before the Robot base needs its bounds. */
        static Chain parseChain(const std::string &urdfXml, const std::string &baseLink, const std::string &tipLink,
                                const MeshOptions &options);

        UrdfArm(std::string name, EnvironmentPtr environment, Chain chain, const Eigen::Isometry3d &basePose,
                SrdfPtr srdf);

        /** \brief Joint-aligned frames at \e q, the one forward kinematics every query uses: frame k is link
            k's frame turned by alignment_[k] so that its joint turns about (or slides along) its z axis. A
            revolute joint then costs a rotation product and a 2D turn of two columns, not a general axis-angle
            rotation; a prismatic one a rotation product and a step along a column. \e rotations and
            \e translations get getJoints().size() + 1 entries (frame 0: the base). */
        void computeAlignedFrames(const double *q, std::vector<Eigen::Matrix3d> &rotations,
                                  std::vector<Eigen::Vector3d> &translations) const;

        /** \brief Self-collision pairs: primitives of frames that are neither the same nor parent and child, not
            overlapping in \e zeroBody (the body at the zero configuration), whose links the SRDF does not allow
            to touch. */
        void computeSelfCollisionPairs(const CollisionBody &zeroBody);

        /** \brief Throws ompl::Exception naming the link and the obstacle if a link that never moves (the base
            link and what is fixed to it) collides with the environment in \e body: no configuration could be
            valid, so the base pose is bad input, not a planning problem. */
        void checkFixedLinks(const CollisionBody &body) const;

        Eigen::Isometry3d basePose_;
        SrdfPtr srdf_;
        std::vector<double> velocities_;
        std::string urdfXml_, baseLink_, tipLink_;
        std::vector<Joint> joints_;
        std::size_t chainJoints_;
        /** \brief Per joint k, the offset from its parent's aligned frame to aligned frame k + 1 at value 0. */
        std::vector<Eigen::Matrix3d> offsetRotations_;
        std::vector<Eigen::Vector3d> offsetTranslations_;
        /** \brief Per frame k, the rotation from its URDF frame to its aligned frame (base: identity). */
        std::vector<Eigen::Matrix3d> alignment_;
        std::vector<std::string> jointNames_;
        Eigen::Isometry3d tipOffset_;
        std::vector<Primitive> primitives_;
        std::vector<LinkMesh> meshes_;
        MeshOptions meshOptions_;
        /** \brief The primitives' capsules, in their link's aligned frame; whether all are spheres. */
        std::vector<LocalCapsule> capsules_;
        bool spheresOnly_{false};
        /** \brief The ends of the runs of capsules of one frame, given to the bodies as their groups
            (CollisionBody::setGroups()) where the links carry several capsules each (a sphere model); empty
            otherwise. */
        std::vector<std::uint32_t> groupEnds_;
        /** \brief Per group, the sphere around its capsules in their frame's aligned frame: moved with the frame, it
            is the group's sphere (CollisionBody::keepGroupSpheres()) without a pass over the capsules. */
        struct LocalSphere
        {
            std::size_t frame;
            Eigen::Vector3d center;
            double radius;
        };
        std::vector<LocalSphere> groupSpheres_;
        /** \brief The same checks, several configurations per call. */
        std::unique_ptr<UrdfArmLanes> lanes_;
    };
}  // namespace ompl_parc

#endif
