#include "ompl_parc/validation/FclBodies.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>

fcl::CollisionGeometryd *ompl_parc::FclBodies::Part::geometry() const
{
    return sphere ? static_cast<fcl::CollisionGeometryd *>(sphere.get()) : capsule.get();
}

ompl_parc::FclBodies::FclBodies(const MultiRobotSpaceInformation &si, const std::vector<CollisionBody> &templates)
{
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        first_.push_back(parts_.size());
        const CollisionBody &body = templates[i];
        for (std::size_t c = 0; c < body.size(); ++c)
        {
            Part part;
            const Eigen::Vector3d a(body.ax_[c], body.ay_[c], body.az_[c]), b(body.bx_[c], body.by_[c], body.bz_[c]);
            if ((b - a).norm() > 1e-12)
                part.capsule = std::make_shared<fcl::Capsuled>(body.radius_[c], (b - a).norm());
            else
                part.sphere = std::make_shared<fcl::Sphered>(body.radius_[c]);
            parts_.push_back(std::move(part));
        }
        selfPairs_.push_back(&si.getRobot(i)->getSelfCollisionPairs());
    }
    first_.push_back(parts_.size());
    for (const auto &o : si.getEnvironment()->getObstacles())
    {
        Obstacle obstacle{Environment::createGeometry(o), o.pose, {}};
        fcl::CollisionObjectd object(obstacle.geometry, o.pose);
        object.computeAABB();
        obstacle.box = Eigen::AlignedBox3d(object.getAABB().min_, object.getAABB().max_);
        obstacles_.push_back(std::move(obstacle));
    }
    swept_.capsule = std::make_shared<fcl::Capsuled>(1., 1.);
}

void ompl_parc::FclBodies::setShape(Part &part, const Eigen::Vector3d &a, const Eigen::Vector3d &b, double radius)
{
    const double length = (b - a).norm();
    part.pose.setIdentity();
    part.pose.translation() = 0.5 * (a + b);
    if (part.sphere)
        part.sphere->radius = radius + 0.5 * length;  // a sphere shape stays a sphere: around the capsule
    else
    {
        part.capsule->radius = radius;
        part.capsule->lz = length;
        if (length > 0.)
            part.pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), b - a).toRotationMatrix();
    }
    part.geometry()->computeLocalAABB();
    const double reach = part.sphere ? part.sphere->radius : radius;
    part.box = Eigen::AlignedBox3d(a.cwiseMin(b) - Eigen::Vector3d::Constant(reach),
                                   a.cwiseMax(b) + Eigen::Vector3d::Constant(reach));
}

void ompl_parc::FclBodies::place(std::size_t robot, const CollisionBody &body, double shrink, double grow)
{
    for (std::size_t c = 0; c < body.size(); ++c)
        setShape(parts_[first_[robot] + c], {body.ax_[c], body.ay_[c], body.az_[c]},
                 {body.bx_[c], body.by_[c], body.bz_[c]}, std::max(body.radius_[c] - shrink, MIN_RADIUS) + grow);
}

bool ompl_parc::FclBodies::touch(const Part &p, const Part &q)
{
    if (!p.box.intersects(q.box))
        return false;
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    return fcl::collide(p.geometry(), p.pose, q.geometry(), q.pose, request, result) > 0;
}

bool ompl_parc::FclBodies::touch(const Part &p, const Obstacle &o)
{
    if (!p.box.intersects(o.box))
        return false;
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    return fcl::collide(p.geometry(), p.pose, o.geometry.get(), o.pose, request, result) > 0;
}

bool ompl_parc::FclBodies::robotsCollide(std::size_t i, std::size_t j) const
{
    for (std::size_t p = first_[i]; p < first_[i + 1]; ++p)
        for (std::size_t q = first_[j]; q < first_[j + 1]; ++q)
            if (touch(parts_[p], parts_[q]))
                return true;
    return false;
}

bool ompl_parc::FclBodies::hitsObstacle(std::size_t robot, std::size_t k) const
{
    for (std::size_t p = first_[robot]; p < first_[robot + 1]; ++p)
        if (touch(parts_[p], obstacles_[k]))
            return true;
    return false;
}

bool ompl_parc::FclBodies::selfCollides(std::size_t robot, std::pair<std::size_t, std::size_t> &links) const
{
    for (const auto &pair : *selfPairs_[robot])
        if (touch(parts_[first_[robot] + pair.first], parts_[first_[robot] + pair.second]))
        {
            links = pair;
            return true;
        }
    return false;
}

bool ompl_parc::FclBodies::sweptSphereHitsObstacle(const Eigen::Vector3d &a, const Eigen::Vector3d &b, double radius,
                                                   std::size_t k)
{
    setShape(swept_, a, b, radius);
    return touch(swept_, obstacles_[k]);
}
