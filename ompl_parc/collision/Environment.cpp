#include "ompl_parc/collision/Environment.h"

#include <cmath>

#include "ompl_parc/meshes/BoxFit.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <ompl/util/Exception.h>

namespace
{
    bool positiveSize(const ompl_parc::Obstacle &o)
    {
        using Shape = ompl_parc::Obstacle::Shape;
        const auto positive = [](double v) { return v > 0. && std::isfinite(v); };
        if (o.shape == Shape::BOX)
            return positive(o.size.x()) && positive(o.size.y()) && positive(o.size.z());
        if (o.shape == Shape::SPHERE)
            return positive(o.size.x());
        if (o.shape == Shape::MESH)
            return o.mesh != nullptr;
        return positive(o.size.x()) && positive(o.size.z());
    }
}  // namespace

std::shared_ptr<fcl::CollisionGeometryd> ompl_parc::Environment::createGeometry(const Obstacle &o)
{
    using Shape = Obstacle::Shape;
    switch (o.shape)
    {
        case Shape::BOX:
            return std::make_shared<fcl::Boxd>(o.size.x(), o.size.y(), o.size.z());
        case Shape::SPHERE:
            return std::make_shared<fcl::Sphered>(o.size.x());
        case Shape::CYLINDER:
            return std::make_shared<fcl::Cylinderd>(o.size.x(), o.size.z());
        case Shape::MESH:
            return createMeshGeometry(*o.mesh);
    }
    return nullptr;
}

std::shared_ptr<fcl::CollisionGeometryd> ompl_parc::Environment::createMeshGeometry(const TriangleMesh &mesh)
{
    std::vector<fcl::Triangle> triangles;
    for (const auto &t : mesh.getTriangles())
        triangles.emplace_back(t[0], t[1], t[2]);
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(mesh.getVertices().size()));
    model->addSubModel(mesh.getVertices(), triangles);
    model->endModel();
    return model;
}

void ompl_parc::Environment::addObstacle(const Obstacle &obstacle)
{
    if (!positiveSize(obstacle))
        throw ompl::Exception("Environment", "obstacle '" + obstacle.name + "' has a non-positive or non-finite size");
    if (!obstacle.pose.matrix().allFinite())
        throw ompl::Exception("Environment", "obstacle '" + obstacle.name + "' has a non-finite pose");
    auto object = std::make_shared<fcl::CollisionObjectd>(createGeometry(obstacle), obstacle.pose);
    object->computeAABB();
    std::shared_ptr<const BoxFit> fit;
    if (obstacle.shape == Obstacle::Shape::MESH)
    {
        fit = std::make_shared<const BoxFit>(*obstacle.mesh, obstacle.fitResolution);
        for (const Eigen::AlignedBox3d &box : fit->getBoxes())
        {
            Obstacle part;
            part.name = obstacle.name;
            part.size = box.sizes();
            part.pose = obstacle.pose * Eigen::Translation3d(box.center());
            primitives_.add(part);
        }
    }
    else
        primitives_.add(obstacle);
    obstacles_.push_back(obstacle);
    objects_.push_back(std::move(object));
    fits_.push_back(std::move(fit));
}

void ompl_parc::Environment::addBox2D(const std::string &name, double centerX, double centerY, double sizeX,
                                      double sizeY, double yaw)
{
    Obstacle o;
    o.name = name;
    o.shape = Obstacle::Shape::BOX;
    o.size = Eigen::Vector3d(sizeX, sizeY, 2.);
    o.pose = Eigen::Translation3d(centerX, centerY, 0.) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    addObstacle(o);
}

bool ompl_parc::Environment::collidesFcl(const CollisionBody &body) const
{
    if (objects_.empty())
        return false;
    for (std::size_t i = 0; i < body.size(); ++i)
        if (findCollision(body, i) != nullptr)
            return true;
    return false;
}

const ompl_parc::Obstacle *ompl_parc::Environment::findCollision(const CollisionBody &body, std::size_t i) const
{
    const Eigen::Vector3d a(body.ax_[i], body.ay_[i], body.az_[i]), b(body.bx_[i], body.by_[i], body.bz_[i]);
    const double r = body.radius_[i];
    const fcl::AABBd box(a.cwiseMin(b) - Eigen::Vector3d::Constant(r), a.cwiseMax(b) + Eigen::Vector3d::Constant(r));
    const Eigen::Vector3d axis = b - a;
    const double length = axis.norm();
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = 0.5 * (a + b);
    if (length > 0.)
        tf.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
    const fcl::Capsuled capsule(r, length);
    const fcl::Sphered sphere(r);
    const fcl::CollisionGeometryd *geometry = length > 0. ? static_cast<const fcl::CollisionGeometryd *>(&capsule)
                                                          : static_cast<const fcl::CollisionGeometryd *>(&sphere);
    const fcl::CollisionRequestd request;
    for (std::size_t k = 0; k < objects_.size(); ++k)
    {
        const auto &object = objects_[k];
        if (!object->getAABB().overlap(box))
            continue;
        fcl::CollisionResultd result;
        if (fcl::collide(geometry, tf, object->collisionGeometry().get(), object->getTransform(), request, result) > 0)
            return &obstacles_[k];
    }
    return nullptr;
}
