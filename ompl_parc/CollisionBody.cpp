#include "ompl_parc/CollisionBody.h"

#include <algorithm>
#include <cmath>

void ompl_parc::CollisionBody::clear()
{
    for (auto *v : {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &radius_})
        v->clear();
    spheresOnly_ = true;
}

void ompl_parc::CollisionBody::addCapsule(double ax, double ay, double az, double bx, double by, double bz,
                                          double radius)
{
    ax_.push_back(ax);
    ay_.push_back(ay);
    az_.push_back(az);
    bx_.push_back(bx);
    by_.push_back(by);
    bz_.push_back(bz);
    radius_.push_back(radius);
    spheresOnly_ = spheresOnly_ && ax == bx && ay == by && az == bz;
}

void ompl_parc::CollisionBody::updateBound()
{
    const std::size_t n = size();
    if (n == 0)
    {
        centerX_ = centerY_ = centerZ_ = boundRadius_ = 0.;
        return;
    }
    // Centre of the axis-aligned box around all capsule axes; then the farthest capsule surface.
    double lo[3] = {ax_[0], ay_[0], az_[0]}, hi[3] = {ax_[0], ay_[0], az_[0]};
    for (std::size_t i = 0; i < n; ++i)
    {
        const double xs[3][2] = {{ax_[i], bx_[i]}, {ay_[i], by_[i]}, {az_[i], bz_[i]}};
        for (int d = 0; d < 3; ++d)
            for (double v : xs[d])
            {
                lo[d] = std::min(lo[d], v);
                hi[d] = std::max(hi[d], v);
            }
    }
    centerX_ = 0.5 * (lo[0] + hi[0]);
    centerY_ = 0.5 * (lo[1] + hi[1]);
    centerZ_ = 0.5 * (lo[2] + hi[2]);
    double r = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double da = std::hypot(ax_[i] - centerX_, ay_[i] - centerY_, az_[i] - centerZ_);
        const double db = std::hypot(bx_[i] - centerX_, by_[i] - centerY_, bz_[i] - centerZ_);
        r = std::max(r, std::max(da, db) + radius_[i]);
    }
    boundRadius_ = r;
}
