#ifndef OMPL_PARC_URDF_FCL_MODEL_
#define OMPL_PARC_URDF_FCL_MODEL_

#include "ompl_parc/robots/UrdfArm.h"

#include <fcl/narrowphase/collision_object.h>

#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief The exact collision model of a UrdfArm: FCL objects of its URDF primitives (boxes,
        cylinders, spheres) and meshes (bounding-volume hierarchies of their triangles, read again from their
        files), not of the capsules the planners use.

        It is the reference against which the capsule model's conservativeness and speed are measured
        (tests and PandaBenchmark). Not thread safe: setConfig() moves the objects. */
    class UrdfFclModel
    {
      public:
        explicit UrdfFclModel(std::shared_ptr<const UrdfArm> arm);

        /** \brief Place the primitives for configuration \e q (updates their transforms and AABBs). */
        void setConfig(const double *q);

        /** \brief True if any primitive of this arm touches any of \e other's (AABB test, then FCL). */
        bool collides(const UrdfFclModel &other) const;

        /** \brief True if any primitive of this arm touches an obstacle of \e environment (AABB test, then FCL on
            the obstacle's exact shape: a mesh obstacle's triangles, not its boxes). */
        bool collides(const Environment &environment) const;

      private:
        void add(std::shared_ptr<fcl::CollisionGeometryd> geometry, std::size_t frame, const Eigen::Isometry3d &pose);

        std::shared_ptr<const UrdfArm> arm_;
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects_;
        /** \brief Per object, its chain frame and its pose in that frame. */
        std::vector<std::pair<std::size_t, Eigen::Isometry3d>> placements_;
        std::vector<Eigen::Isometry3d> frames_;
    };
}  // namespace ompl_parc

#endif
