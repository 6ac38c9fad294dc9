#include "ompl_parc/collision/ObstacleSet.h"

#include "ompl_parc/collision/FloatBounds.h"
#include "ompl_parc/collision/NearCapsules.h"
#include "ompl_parc/collision/PrimitiveDistance.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <limits>

namespace
{
    constexpr std::size_t CHUNK = 16;

    /** Capsule \e i of \e body in the frame of an obstacle (rotation rows \e r, centre \e c): its first end
        point \e p and its axis \e d. */
    inline void toLocal(const ompl_parc::CollisionBody &body, std::size_t i, const double r[9], const double c[3],
                        double p[3], double d[3])
    {
        const double ax = body.ax_[i] - c[0], ay = body.ay_[i] - c[1], az = body.az_[i] - c[2];
        const double dx = body.bx_[i] - body.ax_[i], dy = body.by_[i] - body.ay_[i], dz = body.bz_[i] - body.az_[i];
        for (int row = 0; row < 3; ++row)
        {
            p[row] = r[3 * row] * ax + r[3 * row + 1] * ay + r[3 * row + 2] * az;
            d[row] = r[3 * row] * dx + r[3 * row + 1] * dy + r[3 * row + 2] * dz;
        }
    }

    inline double square(double v)
    {
        return v * v;
    }
}  // namespace

void ompl_parc::ObstacleSet::add(const Obstacle &obstacle)
{
    Frame f;
    const Eigen::Matrix3d r = obstacle.pose.linear();
    const Eigen::Vector3d c = obstacle.pose.translation();
    for (int row = 0; row < 3; ++row)
    {
        for (int col = 0; col < 3; ++col)
            f.rotation[3 * row + col] = r(col, row);  // R^T: world to local
        f.center[row] = c[row];
    }
    Eigen::Vector3d half = Eigen::Vector3d::Zero();  // every shape sets it below (the compiler cannot tell)
    switch (obstacle.shape)
    {
        case Obstacle::Shape::BOX:
            half = 0.5 * obstacle.size;
            break;
        case Obstacle::Shape::SPHERE:
            half = Eigen::Vector3d::Constant(obstacle.size.x());
            break;
        case Obstacle::Shape::CYLINDER:
            half = Eigen::Vector3d(obstacle.size.x(), obstacle.size.x(), 0.5 * obstacle.size.z());
            break;
        case Obstacle::Shape::MESH:
            throw ompl::Exception("ObstacleSet", "mesh obstacle '" + obstacle.name +
                                                     "' must be added as the boxes fitted around it (Environment)");
    }
    for (int k = 0; k < 3; ++k)
        f.half[k] = half[k];
    // World bounds of the local box (of a sphere: its cube, which rotation leaves alone), widened by the margin.
    const Eigen::Vector3d extent = r.cwiseAbs() * half + Eigen::Vector3d::Constant(MARGIN);
    loX_.push_back(c.x() - extent.x());
    loY_.push_back(c.y() - extent.y());
    loZ_.push_back(c.z() - extent.z());
    hiX_.push_back(c.x() + extent.x());
    hiY_.push_back(c.y() + extent.y());
    hiZ_.push_back(c.z() + extent.z());
    const Eigen::Vector3d scale = c.cwiseAbs() + extent;  // what the bounds were computed from
    boxes_.push_back({roundedDown(loX_.back(), scale.x()), roundedDown(loY_.back(), scale.y()),
                      roundedDown(loZ_.back(), scale.z()), roundedUp(hiX_.back(), scale.x()),
                      roundedUp(hiY_.back(), scale.y()), roundedUp(hiZ_.back(), scale.z())});
    shape_.push_back(obstacle.shape);
    frames_.push_back(f);
}

bool ompl_parc::ObstacleSet::collides(const CollisionBody &body) const
{
    if (shape_.empty() || body.size() == 0)
        return false;
    if (body.hasBoxes())
        return boxedBodyCollides(body);
    CollisionBody boxed = body;  // a body built by hand, without updateBound(): not on the planners' paths
    boxed.updateBoxes();
    return boxedBodyCollides(boxed);
}

bool ompl_parc::ObstacleSet::boxedBodyCollides(const CollisionBody &body) const
{
    std::array<float, 3> lo, hi;
    body.getBox(lo, hi);
    const std::size_t n = shape_.size();
    for (std::size_t base = 0; base < n; base += CHUNK)
    {
        const std::size_t m = std::min(CHUNK, n - base);
        // Body box against the obstacle boxes of this chunk: a vectorised map, then a branch-free compaction.
        bool overlap[CHUNK];
        for (std::size_t k = 0; k < m; ++k)
        {
            const auto &box = boxes_[base + k];
            overlap[k] = (box[0] <= hi[0]) & (box[3] >= lo[0]) & (box[1] <= hi[1]) & (box[4] >= lo[1]) &
                         (box[2] <= hi[2]) & (box[5] >= lo[2]);
        }
        std::size_t near[CHUNK], count = 0;
        for (std::size_t k = 0; k < m; ++k)
        {
            near[count] = base + k;
            count += overlap[k] ? 1 : 0;
        }
        // Per near obstacle: the capsules whose boxes reach its box, then the exact test of each.
        for (std::size_t g = 0; g < count; ++g)
        {
            const std::size_t o = near[g];
            const std::array<float, 3> obstacleLo{boxes_[o][0], boxes_[o][1], boxes_[o][2]},
                obstacleHi{boxes_[o][3], boxes_[o][4], boxes_[o][5]};
            for (std::size_t chunk = 0; chunk < std::max<std::size_t>(body.boxStride_, 1); chunk += NearCapsules::CHUNK)
            {
                const NearCapsules capsules(body, chunk, obstacleLo, obstacleHi);
                for (std::size_t k = 0; k < capsules.size(); ++k)
                    if (capsuleHits(body, capsules.index(k), o))
                        return true;
            }
        }
    }
    return false;
}

void ompl_parc::ObstacleSet::getBox(std::size_t k, double lo[3], double hi[3]) const
{
    lo[0] = loX_[k];
    lo[1] = loY_[k];
    lo[2] = loZ_[k];
    hi[0] = hiX_[k];
    hi[1] = hiY_[k];
    hi[2] = hiZ_[k];
}

bool ompl_parc::ObstacleSet::capsuleHits(const CollisionBody &body, std::size_t i, std::size_t k) const
{
    switch (shape_[k])
    {
        case Obstacle::Shape::BOX:
            return capsuleHitsBox(body, i, frames_[k]);
        case Obstacle::Shape::SPHERE:
            return capsuleHitsSphere(body, i, frames_[k]);
        case Obstacle::Shape::CYLINDER:
            return capsuleHitsCylinder(body, i, frames_[k]);
        case Obstacle::Shape::MESH:
            break;  // never added
    }
    return true;
}

bool ompl_parc::ObstacleSet::capsuleHitsBox(const CollisionBody &body, std::size_t i, const Frame &f)
{
    double p[3], d[3];
    toLocal(body, i, f.rotation, f.center, p, d);
    return segmentBoxDistanceSquared(p, d, f.half) <= square(body.radius_[i] + MARGIN);
}

bool ompl_parc::ObstacleSet::capsuleHitsSphere(const CollisionBody &body, std::size_t i, const Frame &f)
{
    const double a[3] = {body.ax_[i], body.ay_[i], body.az_[i]}, b[3] = {body.bx_[i], body.by_[i], body.bz_[i]};
    return pointSegmentDistanceSquared(f.center, a, b) <= square(body.radius_[i] + f.half[0] + MARGIN);
}

bool ompl_parc::ObstacleSet::capsuleHitsCylinder(const CollisionBody &body, std::size_t i, const Frame &f)
{
    double p[3], d[3];
    toLocal(body, i, f.rotation, f.center, p, d);
    const double r = body.radius_[i];
    if (segmentBoxDistanceSquared(p, d, f.half) > square(r + MARGIN))
        return false;
    return segmentSegmentDistanceSquared(p[0], p[1], p[2], p[0] + d[0], p[1] + d[1], p[2] + d[2], 0., 0., -f.half[2],
                                         0., 0., f.half[2]) <= square(r + f.half[0] + MARGIN);
}
