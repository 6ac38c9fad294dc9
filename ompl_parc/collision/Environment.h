#ifndef OMPL_PARC_ENVIRONMENT_
#define OMPL_PARC_ENVIRONMENT_

#include "ompl_parc/collision/CollisionBody.h"

#include <Eigen/Geometry>
#include <fcl/geometry/collision_geometry.h>
#include <fcl/narrowphase/collision_object.h>

#include <memory>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief A static obstacle: a box (size = full extents), sphere (size.x = radius) or cylinder
        (size.x = radius, size.z = length along its local z axis), placed by a pose. */
    struct Obstacle
    {
        enum class Shape
        {
            BOX,
            SPHERE,
            CYLINDER
        };
        std::string name;
        Shape shape{Shape::BOX};
        Eigen::Vector3d size{Eigen::Vector3d::Zero()};
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
    };

    /** \brief The static world all robots share, checked exactly with FCL.

        Robots are tested through their CollisionBody (capsules), converted to FCL capsules and spheres;
        an AABB test skips obstacles that are far away. All queries are const and thread safe. */
    class Environment
    {
      public:
        /** \brief Add an obstacle; throws ompl::Exception for non-positive sizes. */
        void addObstacle(const Obstacle &obstacle);

        /** \brief Convenience for 2D worlds: a box of the given footprint, extruded over z in [-1, 1]. */
        void addBox2D(const std::string &name, double centerX, double centerY, double sizeX, double sizeY,
                      double yaw = 0.);

        const std::vector<Obstacle> &getObstacles() const { return obstacles_; }

        /** \brief FCL objects of the obstacles (world poses set, AABBs computed). */
        const std::vector<std::shared_ptr<fcl::CollisionObjectd>> &getCollisionObjects() const { return objects_; }

        /** \brief A new FCL geometry for \e obstacle (in its local frame). */
        static std::shared_ptr<fcl::CollisionGeometryd> createGeometry(const Obstacle &obstacle);

        /** \brief True if any capsule of \e body touches any obstacle. */
        bool collides(const CollisionBody &body) const;

        /** \brief The first obstacle capsule \e capsule of \e body touches, or nullptr: lets error messages
            name the obstacle, where planning only needs collides(). */
        const Obstacle *findCollision(const CollisionBody &body, std::size_t capsule) const;

      private:
        std::vector<Obstacle> obstacles_;
        std::vector<std::shared_ptr<fcl::CollisionObjectd>> objects_;
    };

    using EnvironmentPtr = std::shared_ptr<Environment>;
}  // namespace ompl_parc

#endif
