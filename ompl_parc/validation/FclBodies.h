#ifndef OMPL_PARC_FCL_BODIES_
#define OMPL_PARC_FCL_BODIES_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <Eigen/Geometry>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>

#include <memory>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief The SolutionValidator's own FCL shapes of a team's capsules and of the obstacles, and its narrow
        phase: robot-robot, robot-obstacle, self-collision, a sphere swept along a segment against an obstacle.

        Every capsule of every robot has one FCL shape (sphere or capsule, as in the robot's body at its start),
        which place() moves and resizes in place: no allocation per sample. An AABB test on each capsule skips
        FCL for far pairs. Placing mutates the shapes, so every thread uses its own FclBodies. */
    class FclBodies
    {
      public:
        /** \brief Smallest radius a shrunk capsule keeps (a segment or a point, for FCL). */
        static constexpr double MIN_RADIUS = 1e-9;

        /** \brief Shapes for the team of \e si, whose robots' bodies look like \e templates (one per robot). */
        FclBodies(const MultiRobotSpaceInformation &si, const std::vector<CollisionBody> &templates);

        std::size_t getObstacleCount() const { return obstacles_.size(); }
        const Eigen::AlignedBox3d &getObstacleBox(std::size_t k) const { return obstacles_[k].box; }

        /** \brief Put the shapes of \e robot's capsules c with mask[c] set at \e body, radii
            max(r - shrink, MIN_RADIUS) + grow[c]; the others keep where they were. The tests below read only the
            capsules their masks set: those a broad phase could not rule out. */
        void place(std::size_t robot, const CollisionBody &body, double shrink, const std::vector<double> &grow,
                   const std::vector<char> &mask);

        /** \brief Whether the placed shapes of two different robots touch (the capsules of \e maskI and
            \e maskJ). */
        bool robotsCollide(std::size_t i, std::size_t j, const std::vector<char> &maskI,
                           const std::vector<char> &maskJ) const;
        /** \brief Whether the placed shapes of \e robot (those of \e mask) touch obstacle \e k. */
        bool hitsObstacle(std::size_t robot, std::size_t k, const std::vector<char> &mask) const;
        /** \brief The first self-collision pair (capsule indices) of \e robot's placed shapes, both in \e mask, that
            touches, or nothing. */
        bool selfCollides(std::size_t robot, std::pair<std::size_t, std::size_t> &links,
                          const std::vector<char> &mask) const;

        /** \brief Whether a sphere of \e radius swept from \e a to \e b (a capsule) touches obstacle \e k. */
        bool sweptSphereHitsObstacle(const Eigen::Vector3d &a, const Eigen::Vector3d &b, double radius, std::size_t k);

      private:
        /** \brief One FCL shape (a sphere or a capsule; the other pointer is null) and where it is. */
        struct Part
        {
            std::shared_ptr<fcl::Sphered> sphere;
            std::shared_ptr<fcl::Capsuled> capsule;
            fcl::Transform3d pose{fcl::Transform3d::Identity()};
            Eigen::AlignedBox3d box;
            fcl::CollisionGeometryd *geometry() const;
        };

        struct Obstacle
        {
            std::shared_ptr<const fcl::CollisionGeometryd> geometry;
            fcl::Transform3d pose;
            Eigen::AlignedBox3d box;
        };

        /** \brief A rotation taking Z to the unit vector \e d (a capsule's axis; the turn about it is any, a capsule
            being round): closed form, where Eigen's FromTwoVectors takes an SVD for every axis pointing down. */
        static Eigen::Matrix3d rotationFromZ(const Eigen::Vector3d &d);

        /** \brief Give \e part the capsule (a, b, radius). */
        static void setShape(Part &part, const Eigen::Vector3d &a, const Eigen::Vector3d &b, double radius);
        static bool touch(const Part &p, const Part &q);
        static bool touch(const Part &p, const Obstacle &o);

        /** \brief Robot i's shapes are parts_[first_[i]] .. parts_[first_[i + 1] - 1]. */
        std::vector<Part> parts_;
        std::vector<std::size_t> first_;
        std::vector<const std::vector<std::pair<std::size_t, std::size_t>> *> selfPairs_;
        std::vector<Obstacle> obstacles_;
        /** \brief The swept sphere of sweptSphereHitsObstacle(). */
        Part swept_;
    };
}  // namespace ompl_parc

#endif
