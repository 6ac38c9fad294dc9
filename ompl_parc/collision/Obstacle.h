#ifndef OMPL_PARC_OBSTACLE_
#define OMPL_PARC_OBSTACLE_

#include <Eigen/Geometry>

#include <string>

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
}  // namespace ompl_parc

#endif
