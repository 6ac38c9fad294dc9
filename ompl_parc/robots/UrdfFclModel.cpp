#include "ompl_parc/robots/UrdfFclModel.h"

#include <fcl/narrowphase/collision.h>

ompl_parc::UrdfFclModel::UrdfFclModel(std::shared_ptr<const UrdfArm> arm) : arm_(std::move(arm))
{
    for (const auto &p : arm_->getPrimitives())
        objects_.push_back(std::make_unique<fcl::CollisionObjectd>(Environment::createGeometry(p.shape)));
}

void ompl_parc::UrdfFclModel::setConfig(const double *q)
{
    arm_->computeFrames(q, frames_);
    const auto &primitives = arm_->getPrimitives();
    for (std::size_t k = 0; k < objects_.size(); ++k)
    {
        objects_[k]->setTransform(frames_[primitives[k].frame] * primitives[k].shape.pose);
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
