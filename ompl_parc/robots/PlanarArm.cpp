#include "ompl_parc/robots/PlanarArm.h"

#include <ompl/util/Exception.h>

#include <cmath>

ompl_parc::PlanarArm::PlanarArm(std::string name, EnvironmentPtr environment, double baseX, double baseY,
                                double baseYaw, std::vector<double> linkLengths, double linkWidth,
                                const ompl::base::RealVectorBounds &jointLimits)
    : Robot(std::move(name), std::move(environment), jointLimits),
      baseX_(baseX),
      baseY_(baseY),
      baseYaw_(baseYaw),
      linkLengths_(std::move(linkLengths)),
      linkWidth_(linkWidth)
{
    if (linkLengths_.size() != getDimension())
        throw ompl::Exception("PlanarArm", "robot '" + getName() + "' needs one joint limit per link");
    for (double l : linkLengths_)
        if (!(l > 0.))
            throw ompl::Exception("PlanarArm", "robot '" + getName() + "' has a non-positive link length");
    if (!(linkWidth_ > 0.))
        throw ompl::Exception("PlanarArm", "robot '" + getName() + "' needs a positive link width");
    for (std::size_t i = 0; i < linkLengths_.size(); ++i)
        for (std::size_t j = i + 2; j < linkLengths_.size(); ++j)
            selfCollisionPairs_.emplace_back(i, j);
}

void ompl_parc::PlanarArm::computeCapsules(const double *q, CollisionBody &body) const
{
    body.clear();
    double x = baseX_, y = baseY_, angle = baseYaw_;
    const double radius = 0.5 * linkWidth_;
    for (std::size_t k = 0; k < linkLengths_.size(); ++k)
    {
        angle += q[k];
        const double nx = x + linkLengths_[k] * std::cos(angle), ny = y + linkLengths_[k] * std::sin(angle);
        body.addCapsule(x, y, 0., nx, ny, 0., radius);
        x = nx;
        y = ny;
    }
}
