#include "ompl_parc/robots/UrdfFclModel.h"

#include <fcl/narrowphase/collision.h>

ompl_parc::UrdfFclModel::UrdfFclModel(std::shared_ptr<const UrdfArm> arm) : arm_(std::move(arm))
{
    for (const auto &p : arm_->getPrimitives())
        if (p.mesh < 0)
            add(Environment::createGeometry(p.shape), p.frame, p.shape.pose);
    for (const auto &m : arm_->getMeshes())
        add(Environment::createMeshGeometry(*TriangleMesh::read(m.file, m.scale)), m.frame, m.pose);
}

void ompl_parc::UrdfFclModel::add(std::shared_ptr<fcl::CollisionGeometryd> geometry, std::size_t frame,
                                  const Eigen::Isometry3d &pose)
{
    objects_.push_back(std::make_unique<fcl::CollisionObjectd>(std::move(geometry)));
    placements_.emplace_back(frame, pose);
}

void ompl_parc::UrdfFclModel::setConfig(const double *q)
{
    arm_->computeFrames(q, frames_);
    for (std::size_t k = 0; k < objects_.size(); ++k)
    {
        objects_[k]->setTransform(frames_[placements_[k].first] * placements_[k].second);
        objects_[k]->computeAABB();
    }
}

bool ompl_parc::UrdfFclModel::collides(const UrdfFclModel &other) const
{
    const fcl::CollisionRequestd request;
    for (const auto &a : objects_)
        for (const auto &b : other.objects_)
        {
            if (!a->getAABB().overlap(b->getAABB()))
                continue;
            fcl::CollisionResultd result;
            if (fcl::collide(a.get(), b.get(), request, result) > 0)
                return true;
        }
    return false;
}

bool ompl_parc::UrdfFclModel::collides(const Environment &environment) const
{
    const fcl::CollisionRequestd request;
    for (const auto &a : objects_)
        for (const auto &b : environment.getCollisionObjects())
        {
            if (!a->getAABB().overlap(b->getAABB()))
                continue;
            fcl::CollisionResultd result;
            if (fcl::collide(a.get(), b.get(), request, result) > 0)
                return true;
        }
    return false;
}
