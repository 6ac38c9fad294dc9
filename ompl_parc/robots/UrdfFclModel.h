#ifndef OMPL_PARC_URDF_FCL_MODEL_
#define OMPL_PARC_URDF_FCL_MODEL_

#include "ompl_parc/robots/UrdfArm.h"

#include <fcl/narrowphase/collision_object.h>

#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief The exact collision model of a UrdfArm: FCL objects of its URDF primitives (boxes,
        cylinders, spheres), not of the capsules the planners use.

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

      private:
        std::shared_ptr<const UrdfArm> arm_;
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects_;
        std::vector<Eigen::Isometry3d> frames_;
    };
}  // namespace ompl_parc

#endif
