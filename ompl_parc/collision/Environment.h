#ifndef OMPL_PARC_ENVIRONMENT_
#define OMPL_PARC_ENVIRONMENT_

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/collision/Obstacle.h"
#include "ompl_parc/collision/ObstacleSet.h"

#include <Eigen/Geometry>
#include <fcl/geometry/collision_geometry.h>
#include <fcl/narrowphase/collision_object.h>

#include <memory>
#include <string>
#include <vector>

namespace ompl_parc
{
    class BoxFit;

    /** \brief The static world all robots share.

        Robots are tested through their CollisionBody (capsules). Planning asks collides(): analytic,
        conservative primitive distances on flat arrays (ObstacleSet), no FCL and no allocation. collidesFcl()
        and findCollision() convert the capsules to FCL capsules and spheres and ask FCL exactly (an AABB test
        skips far obstacles): the reference the analytic test is checked against, and the test that names the
        obstacle for error messages. A mesh obstacle is checked in planning as the boxes of its BoxFit (they
        contain it) and by FCL as its triangles (a bounding-volume hierarchy): exact where it counts, in the
        validator. All queries are const and thread safe. */
    class Environment
    {
      public:
        /** \brief Add an obstacle; throws ompl::Exception for non-positive sizes or a mesh obstacle without a
            mesh. */
        void addObstacle(const Obstacle &obstacle);

        /** \brief Convenience for 2D worlds: a box of the given footprint, extruded over z in [-1, 1]. */
        void addBox2D(const std::string &name, double centerX, double centerY, double sizeX, double sizeY,
                      double yaw = 0.);

        const std::vector<Obstacle> &getObstacles() const { return obstacles_; }

        /** \brief FCL objects of the obstacles (world poses set, AABBs computed). */
        const std::vector<std::shared_ptr<fcl::CollisionObjectd>> &getCollisionObjects() const { return objects_; }

        /** \brief A new FCL geometry for \e obstacle (in its local frame). */
        static std::shared_ptr<fcl::CollisionGeometryd> createGeometry(const Obstacle &obstacle);

        /** \brief A new FCL bounding-volume hierarchy (OBBRSS) of \e mesh's triangles. */
        static std::shared_ptr<fcl::CollisionGeometryd> createMeshGeometry(const TriangleMesh &mesh);

        /** \brief The boxes planning checks for obstacle \e k if it is a mesh, else null. */
        const std::shared_ptr<const BoxFit> &getBoxFit(std::size_t k) const { return fits_[k]; }

        /** \brief True if any capsule of \e body touches any obstacle, or comes within ObstacleSet::MARGIN of
            one, or passes the rim of a cylinder closely: conservative, never false where collidesFcl() is true. */
        bool collides(const CollisionBody &body) const { return primitives_.collides(body); }

        /** \brief The obstacles as flat arrays, for kernels that check several configurations at once. */
        const ObstacleSet &getObstacleSet() const { return primitives_; }

        /** \brief True if any capsule of \e body touches any obstacle, according to FCL (exact). */
        bool collidesFcl(const CollisionBody &body) const;

        /** \brief The first obstacle capsule \e capsule of \e body touches, or nullptr: lets error messages
            name the obstacle, where planning only needs collides(). */
        const Obstacle *findCollision(const CollisionBody &body, std::size_t capsule) const;

      private:
        std::vector<Obstacle> obstacles_;
        std::vector<std::shared_ptr<fcl::CollisionObjectd>> objects_;
        std::vector<std::shared_ptr<const BoxFit>> fits_;
        ObstacleSet primitives_;
    };

    using EnvironmentPtr = std::shared_ptr<Environment>;
}  // namespace ompl_parc

#endif
