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
    if (n == 1 && spheresOnly_)  // a disc or a single sphere bounds itself exactly
    {
        centerX_ = ax_[0];
        centerY_ = ay_[0];
        centerZ_ = az_[0];
        boundRadius_ = radius_[0];
        return;
    }
    // Centre of the axis-aligned box around all capsule axes; then the farthest capsule surface.
    double lo[3] = {ax_[0], ay_[0], az_[0]}, hi[3] = {ax_[0], ay_[0], az_[0]};
    for (std::size_t i = 0; i < n; ++i)
    {
        lo[0] = std::min({lo[0], ax_[i], bx_[i]});
        hi[0] = std::max({hi[0], ax_[i], bx_[i]});
        lo[1] = std::min({lo[1], ay_[i], by_[i]});
        hi[1] = std::max({hi[1], ay_[i], by_[i]});
        lo[2] = std::min({lo[2], az_[i], bz_[i]});
        hi[2] = std::max({hi[2], az_[i], bz_[i]});
    }
    centerX_ = 0.5 * (lo[0] + hi[0]);
    centerY_ = 0.5 * (lo[1] + hi[1]);
    centerZ_ = 0.5 * (lo[2] + hi[2]);
    double r = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double dax = ax_[i] - centerX_, day = ay_[i] - centerY_, daz = az_[i] - centerZ_;
        const double dbx = bx_[i] - centerX_, dby = by_[i] - centerY_, dbz = bz_[i] - centerZ_;
        const double far2 = std::max(dax * dax + day * day + daz * daz, dbx * dbx + dby * dby + dbz * dbz);
        r = std::max(r, std::sqrt(far2) + radius_[i]);
    }
    boundRadius_ = r;
}

void ompl_parc::CollisionBody::expandBox(std::array<double, 3> &lo, std::array<double, 3> &hi) const
{
    // One min/max reduction per coordinate over plain arrays: vectorises.
    const std::vector<double> *a[3] = {&ax_, &ay_, &az_}, *b[3] = {&bx_, &by_, &bz_};
    const double *r = radius_.data();
    for (int d = 0; d < 3; ++d)
    {
        const double *pa = a[d]->data(), *pb = b[d]->data();
        double l = lo[d], h = hi[d];
        for (std::size_t i = 0; i < size(); ++i)
        {
            l = std::min(l, std::min(pa[i], pb[i]) - r[i]);
            h = std::max(h, std::max(pa[i], pb[i]) + r[i]);
        }
        lo[d] = l;
        hi[d] = h;
    }
}
