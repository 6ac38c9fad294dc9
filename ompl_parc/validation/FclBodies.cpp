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
    // The environment's own FCL objects (queries only read them): a mesh obstacle's hierarchy is built once.
    const auto &environment = *si.getEnvironment();
    for (std::size_t k = 0; k < environment.getObstacles().size(); ++k)
    {
        const fcl::CollisionObjectd &object = *environment.getCollisionObjects()[k];
        obstacles_.push_back({object.collisionGeometry(), environment.getObstacles()[k].pose,
                              Eigen::AlignedBox3d(object.getAABB().min_, object.getAABB().max_)});
    }
    swept_.capsule = std::make_shared<fcl::Capsuled>(1., 1.);
}

Eigen::Matrix3d ompl_parc::FclBodies::rotationFromZ(const Eigen::Vector3d &d)
{
    // Rodrigues' formula about Z x e for a unit e with e.z >= 0 (no division by a small 1 + e.z), and for d.z < 0 the
    // rotation to -d after a half turn about X (which takes Z to -Z).
    const bool flip = d.z() < 0.;
    const Eigen::Vector3d e = flip ? Eigen::Vector3d(-d) : d;
    const double k = 1. / (1. + e.z());
    Eigen::Matrix3d r;
    r << 1. - e.x() * e.x() * k, -e.x() * e.y() * k, e.x(),  //
        -e.x() * e.y() * k, 1. - e.y() * e.y() * k, e.y(),   //
        -e.x(), -e.y(), e.z();
    if (flip)
        r.rightCols<2>() *= -1.;
    return r;
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
            part.pose.linear() = rotationFromZ((b - a) / length);
    }
    part.geometry()->computeLocalAABB();
    const double reach = part.sphere ? part.sphere->radius : radius;
    part.box = Eigen::AlignedBox3d(a.cwiseMin(b) - Eigen::Vector3d::Constant(reach),
                                   a.cwiseMax(b) + Eigen::Vector3d::Constant(reach));
}

void ompl_parc::FclBodies::place(std::size_t robot, const CollisionBody &body, double shrink,
                                 const std::vector<double> &grow, const std::vector<char> &mask)
{
    for (std::size_t c = 0; c < body.size(); ++c)
        if (mask[c])
            setShape(parts_[first_[robot] + c], {body.ax_[c], body.ay_[c], body.az_[c]},
                     {body.bx_[c], body.by_[c], body.bz_[c]}, std::max(body.radius_[c] - shrink, MIN_RADIUS) + grow[c]);
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

bool ompl_parc::FclBodies::robotsCollide(std::size_t i, std::size_t j, const std::vector<char> &maskI,
                                         const std::vector<char> &maskJ) const
{
    for (std::size_t p = 0; p < maskI.size(); ++p)
        if (maskI[p])
            for (std::size_t q = 0; q < maskJ.size(); ++q)
                if (maskJ[q] && touch(parts_[first_[i] + p], parts_[first_[j] + q]))
                    return true;
    return false;
}

bool ompl_parc::FclBodies::hitsObstacle(std::size_t robot, std::size_t k, const std::vector<char> &mask) const
{
    for (std::size_t p = 0; p < mask.size(); ++p)
        if (mask[p] && touch(parts_[first_[robot] + p], obstacles_[k]))
            return true;
    return false;
}

bool ompl_parc::FclBodies::selfCollides(std::size_t robot, std::pair<std::size_t, std::size_t> &links,
                                        const std::vector<char> &mask) const
{
    for (const auto &pair : *selfPairs_[robot])
        if (mask[pair.first] && mask[pair.second] &&
            touch(parts_[first_[robot] + pair.first], parts_[first_[robot] + pair.second]))
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
