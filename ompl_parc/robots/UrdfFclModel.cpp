#include "ompl_parc/robots/UrdfFclModel.h"

#include <fcl/narrowphase/collision.h>

namespace
{
    /** Whether an object of \e a touches one of \e b (containers of pointers to placed FCL objects): boxes, then FCL. */
    template <typename As, typename Bs>
    bool anyTouch(const As &a, const Bs &b)
    {
        const fcl::CollisionRequestd request;
        for (const auto &p : a)
            for (const auto &q : b)
            {
                if (!p->getAABB().overlap(q->getAABB()))
                    continue;
                fcl::CollisionResultd result;
                if (fcl::collide(p.get(), q.get(), request, result) > 0)
                    return true;
            }
        return false;
    }
}  // namespace

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
    return anyTouch(objects_, other.objects_);
}

bool ompl_parc::UrdfFclModel::collides(const Environment &environment) const
{
    return anyTouch(objects_, environment.getCollisionObjects());
}
