#include "ompl_parc/collision/CollisionBody.h"

#include "ompl_parc/collision/FloatBounds.h"

#include <xsimd/xsimd.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace
{
    /** The centre (\e cx, \e cy, \e cz) of the axis-aligned box around the axes of capsules [\e begin, \e end)
        (\e end > \e begin), whose end points are (ax, ay, az) and (bx, by, bz): where a bounding sphere is centred. */
    inline void axisBoxCentre(const double *ax, const double *ay, const double *az, const double *bx,
                              const double *by, const double *bz, std::size_t begin, std::size_t end, double &cx,
                              double &cy, double &cz)
    {
        double lo[3] = {ax[begin], ay[begin], az[begin]}, hi[3] = {ax[begin], ay[begin], az[begin]};
        for (std::size_t i = begin; i < end; ++i)
        {
            lo[0] = std::min(lo[0], std::min(ax[i], bx[i]));
            hi[0] = std::max(hi[0], std::max(ax[i], bx[i]));
            lo[1] = std::min(lo[1], std::min(ay[i], by[i]));
            hi[1] = std::max(hi[1], std::max(ay[i], by[i]));
            lo[2] = std::min(lo[2], std::min(az[i], bz[i]));
            hi[2] = std::max(hi[2], std::max(az[i], bz[i]));
        }
        cx = 0.5 * (lo[0] + hi[0]);
        cy = 0.5 * (lo[1] + hi[1]);
        cz = 0.5 * (lo[2] + hi[2]);
    }

    /** The single-precision bounds, rounded outwards, of the interval from min(a, b) - r to max(a, b) + r along
        one axis: a capsule's box (a sphere's when a == b). Inline, so the loop over capsules vectorises. */
    inline void roundedInterval(double a, double b, double r, float &lo, float &hi)
    {
        const double scale = std::max(std::fabs(a), std::fabs(b)) + std::fabs(r);
        lo = ompl_parc::roundedDown(std::min(a, b) - r, scale);
        hi = ompl_parc::roundedUp(std::max(a, b) + r, scale);
    }
}  // namespace

void ompl_parc::CollisionBody::clear()
{
    for (auto *v : {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &radius_})
        v->clear();
    spheresOnly_ = true;
    boxesCurrent_ = false;
    groupsCurrent_ = false;
    groups_.clear();
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
    boxesCurrent_ = false;
    groupsCurrent_ = false;
    groups_.clear();
}

void ompl_parc::CollisionBody::setGroups(const std::uint32_t *ends, std::size_t count)
{
    bool increasing = count > 0 && ends[count - 1] == size();
    for (std::size_t k = 0; k < count; ++k)
        increasing = increasing && ends[k] > (k == 0 ? 0u : ends[k - 1]);
    if (!increasing)
        throw std::invalid_argument("CollisionBody::setGroups: the group ends must increase up to size()");
    groups_.resize(count);
    for (std::size_t k = 0; k < count; ++k)
        groups_[k].end = ends[k];
    groupsCurrent_ = false;
    groupSpheresGiven_ = false;
    boxesCurrent_ = false;
}

void ompl_parc::CollisionBody::resizeArrays(std::size_t n)
{
    for (auto *v : {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &radius_, &sphereX_, &sphereY_, &sphereZ_, &sphereRadius_})
        v->resize(n);
}

void ompl_parc::CollisionBody::updateBound()
{
    const std::size_t n = size();
    if (sphereRadius_.size() != n)  // after addCapsule(); resize() sized them already
        for (auto *v : {&sphereX_, &sphereY_, &sphereZ_, &sphereRadius_})
            v->resize(n);
    if (n == 0)
    {
        centerX_ = centerY_ = centerZ_ = boundRadius_ = 0.;
        updateBoxes();
        return;
    }
    if (n == 1 && spheresOnly_)  // a disc or a single sphere bounds itself (the common 2D case: keep it cheap)
    {
        sphereX_[0] = centerX_ = ax_[0];
        sphereY_[0] = centerY_ = ay_[0];
        sphereZ_[0] = centerZ_ = az_[0];
        sphereRadius_[0] = boundRadius_ = radius_[0];
        updateBoxes();  // nothing to compute: one sphere keeps no boxes
        return;
    }
    // Restricted plain pointers: distinct vectors never alias, which the compiler cannot prove by itself
    // (without it the loops stay scalar).
    const double *__restrict ax = ax_.data(), *__restrict ay = ay_.data(), *__restrict az = az_.data();
    const double *__restrict bx = bx_.data(), *__restrict by = by_.data(), *__restrict bz = bz_.data();
    const double *__restrict r = radius_.data();
    double *__restrict sx = sphereX_.data(), *__restrict sy = sphereY_.data(), *__restrict sz = sphereZ_.data();
    double *__restrict sr = sphereRadius_.data();
    for (std::size_t i = 0; i < n; ++i)  // capsule spheres: a pure map
    {
        const double dx = bx[i] - ax[i], dy = by[i] - ay[i], dz = bz[i] - az[i];
        sx[i] = 0.5 * (ax[i] + bx[i]);
        sy[i] = 0.5 * (ay[i] + by[i]);
        sz[i] = 0.5 * (az[i] + bz[i]);
        sr[i] = 0.5 * std::sqrt(dx * dx + dy * dy + dz * dz) + r[i];
    }
    if (!groups_.empty())
    {
        updateGroupBounds();
        return;
    }

    // Centre of the axis-aligned box around all capsule axes; then the farthest capsule surface, per chunk
    // a map of distances into a small buffer (vectorised square roots) and a scalar maximum of it.
    double cx, cy, cz;
    axisBoxCentre(ax, ay, az, bx, by, bz, 0, n, cx, cy, cz);
    constexpr std::size_t CHUNK = 16;
    double far[CHUNK], radius = 0.;
    for (std::size_t base = 0; base < n; base += CHUNK)
    {
        const std::size_t m = std::min(CHUNK, n - base);
        for (std::size_t k = 0; k < m; ++k)
        {
            const std::size_t i = base + k;
            const double dax = ax[i] - cx, day = ay[i] - cy, daz = az[i] - cz;
            const double dbx = bx[i] - cx, dby = by[i] - cy, dbz = bz[i] - cz;
            far[k] = std::sqrt(std::max(dax * dax + day * day + daz * daz, dbx * dbx + dby * dby + dbz * dbz)) + r[i];
        }
        for (std::size_t k = 0; k < m; ++k)
            radius = std::max(radius, far[k]);
    }
    centerX_ = cx;
    centerY_ = cy;
    centerZ_ = cz;
    boundRadius_ = radius;
    updateBoxes();
}

void ompl_parc::CollisionBody::updateGroupBounds()
{
    if (!groupSpheresGiven_)
        computeGroupSpheres();
    // The body's sphere around the group spheres: the centre of their box, the farthest group surface.
    double lo[3] = {groups_[0].x, groups_[0].y, groups_[0].z}, hi[3] = {lo[0], lo[1], lo[2]};
    for (const Group &g : groups_)
    {
        lo[0] = std::min(lo[0], g.x - g.radius);
        hi[0] = std::max(hi[0], g.x + g.radius);
        lo[1] = std::min(lo[1], g.y - g.radius);
        hi[1] = std::max(hi[1], g.y + g.radius);
        lo[2] = std::min(lo[2], g.z - g.radius);
        hi[2] = std::max(hi[2], g.z + g.radius);
    }
    centerX_ = 0.5 * (lo[0] + hi[0]);
    centerY_ = 0.5 * (lo[1] + hi[1]);
    centerZ_ = 0.5 * (lo[2] + hi[2]);
    double radius = 0.;
    for (const Group &g : groups_)
    {
        const double dx = g.x - centerX_, dy = g.y - centerY_, dz = g.z - centerZ_;
        radius = std::max(radius, std::sqrt(dx * dx + dy * dy + dz * dz) + g.radius);
    }
    boundRadius_ = radius;
    boxesCurrent_ = false;
    groupsCurrent_ = true;
}

void ompl_parc::CollisionBody::computeGroupSpheres()
{
    const double *ax = ax_.data(), *ay = ay_.data(), *az = az_.data();
    const double *bx = bx_.data(), *by = by_.data(), *bz = bz_.data(), *r = radius_.data();
    // Per group, like the body's sphere without groups: the centre of the box around its capsule axes, the
    // farthest capsule surface from it; padded (see Group).
    std::size_t begin = 0;
    for (Group &group : groups_)
    {
        const std::size_t end = group.end;
        double cx, cy, cz;
        axisBoxCentre(ax, ay, az, bx, by, bz, begin, end, cx, cy, cz);
        double farthest = 0., radius = 0.;
        for (std::size_t i = begin; i < end; ++i)
        {
            const double dax = ax[i] - cx, day = ay[i] - cy, daz = az[i] - cz;
            const double dbx = bx[i] - cx, dby = by[i] - cy, dbz = bz[i] - cz;
            const double far = std::max(dax * dax + day * day + daz * daz, dbx * dbx + dby * dby + dbz * dbz);
            farthest = std::max(farthest, far);
            radius = std::max(radius, std::sqrt(far) + r[i]);
        }
        // The coordinates' rounding (about 2^-52 of their magnitude per operation) is far below 2^-40 of it.
        const double scale = std::max({std::fabs(cx), std::fabs(cy), std::fabs(cz), std::sqrt(farthest)}) + radius;
        group.x = cx;
        group.y = cy;
        group.z = cz;
        group.radius = radius + 0x1p-40 * scale;
        begin = end;
    }
}

void ompl_parc::CollisionBody::updateBoxes()
{
    boxesCurrent_ = true;
    if (isSingleSphere())
    {
        boxStride_ = 0;
        return;
    }
    constexpr std::size_t lanes = xsimd::batch<float>::size;
    const std::size_t n = size(), stride = (n + lanes - 1) / lanes * lanes;
    boxStride_ = stride;
    boxes_.resize(6 * stride);
    const std::vector<double> *a[3] = {&ax_, &ay_, &az_}, *b[3] = {&bx_, &by_, &bz_};
    constexpr float inf = std::numeric_limits<float>::infinity();
    for (std::size_t d = 0; d < 3; ++d)
    {
        float *lo = boxes_.data() + d * stride, *hi = boxes_.data() + (3 + d) * stride;
        const double *pa = a[d]->data(), *pb = b[d]->data(), *r = radius_.data();
        for (std::size_t i = 0; i < n; ++i)  // a map (vectorised), then the reductions
            roundedInterval(pa[i], pb[i], r[i], lo[i], hi[i]);
        float bodyLo = inf, bodyHi = -inf;
        for (std::size_t i = 0; i < n; ++i)
        {
            bodyLo = std::min(bodyLo, lo[i]);
            bodyHi = std::max(bodyHi, hi[i]);
        }
        // Padding: NaN, which fails every comparison, so it never overlaps anything (not even an infinite box).
        std::fill(lo + n, lo + stride, std::numeric_limits<float>::quiet_NaN());
        std::fill(hi + n, hi + stride, std::numeric_limits<float>::quiet_NaN());
        boxLo_[d] = bodyLo;
        boxHi_[d] = bodyHi;
    }
}

void ompl_parc::CollisionBody::getBox(std::array<float, 3> &lo, std::array<float, 3> &hi) const
{
    if (!isSingleSphere())
    {
        lo = boxLo_;
        hi = boxHi_;
        return;
    }
    const double center[3] = {ax_[0], ay_[0], az_[0]};
    for (std::size_t d = 0; d < 3; ++d)
        roundedInterval(center[d], center[d], radius_[0], lo[d], hi[d]);
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
