#include "ompl_parc/robots/DiscRobot.h"

#include <ompl/util/Exception.h>

#include <algorithm>

ompl_parc::DiscRobot::DiscRobot(std::string name, EnvironmentPtr environment, double radius,
                                const ompl::base::RealVectorBounds &bounds)
    : Robot(std::move(name), std::move(environment), bounds), radius_(radius)
{
    if (!(radius > 0.))
        throw ompl::Exception("DiscRobot", "robot '" + getName() + "' needs a positive radius");
    if (getDimension() != 2)
        throw ompl::Exception("DiscRobot", "robot '" + getName() + "' needs 2D bounds");
}

void ompl_parc::DiscRobot::computeCapsules(const double *q, CollisionBody &body) const
{
    body.resize(1, true);  // written in place: bodies are computed at every timestep the detector scans
    body.ax_[0] = body.bx_[0] = q[0];
    body.ay_[0] = body.by_[0] = q[1];
    body.az_[0] = body.bz_[0] = 0.;
    body.radius_[0] = radius_;
}

std::optional<bool> ompl_parc::DiscRobot::sweepValid(const double *from, const double *to) const
{
    if (!withinBounds(to, 1))
        return false;
    thread_local CollisionBody sweep;
    sweep.resize(1, from[0] == to[0] && from[1] == to[1]);
    sweep.ax_[0] = from[0];
    sweep.ay_[0] = from[1];
    sweep.bx_[0] = to[0];
    sweep.by_[0] = to[1];
    sweep.az_[0] = sweep.bz_[0] = 0.;
    sweep.radius_[0] = radius_;
    sweep.updateBoxes();
    return !getEnvironment()->collides(sweep);
}

bool ompl_parc::DiscRobot::expandBoxOver(const double *lo, const double *hi, std::array<double, 3> &boxLo,
                                         std::array<double, 3> &boxHi) const
{
    for (int d = 0; d < 2; ++d)
    {
        boxLo[d] = std::min(boxLo[d], lo[d] - radius_);
        boxHi[d] = std::max(boxHi[d], hi[d] + radius_);
    }
    boxLo[2] = std::min(boxLo[2], -radius_);
    boxHi[2] = std::max(boxHi[2], radius_);
    return true;
}
