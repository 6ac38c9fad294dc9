#ifndef OMPL_PARC_OBSTACLE_
#define OMPL_PARC_OBSTACLE_

#include "ompl_parc/meshes/TriangleMesh.h"

#include <Eigen/Geometry>

#include <string>

namespace ompl_parc
{
    /** \brief A static obstacle: a box (size = full extents), sphere (size.x = radius), cylinder
        (size.x = radius, size.z = length along its local z axis) or triangle mesh (\e mesh, in its own frame;
        planning checks boxes fitted around it, \e fitResolution cells along its longest side: see BoxFit),
        placed by a pose. */
    struct Obstacle
    {
        enum class Shape
        {
            BOX,
            SPHERE,
            CYLINDER,
            MESH
        };
        std::string name;
        Shape shape{Shape::BOX};
        Eigen::Vector3d size{Eigen::Vector3d::Zero()};
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
        TriangleMeshPtr mesh;
        unsigned int fitResolution{64};
    };
}  // namespace ompl_parc

#endif
