#include "ompl_parc/collision/CapsuleCollision.h"

#include "ompl_parc/collision/NearCapsules.h"
#include "ompl_parc/collision/PrimitiveDistance.h"

#include <algorithm>
#include <stdexcept>

double ompl_parc::segmentDistanceSquared(const CollisionBody &a, std::size_t i, const CollisionBody &b, std::size_t j)
{
    return segmentSegmentDistanceSquared(a.ax_[i], a.ay_[i], a.az_[i], a.bx_[i], a.by_[i], a.bz_[i], b.ax_[j], b.ay_[j],
                                         b.az_[j], b.bx_[j], b.by_[j], b.bz_[j]);
}

bool ompl_parc::capsulesCollide(const CollisionBody &a, std::size_t i, const CollisionBody &b, std::size_t j)
{
    const double rr = a.radius_[i] + b.radius_[j];
    return segmentDistanceSquared(a, i, b, j) < rr * rr;
}

namespace
{
    /** True if a near capsule of \e a overlaps a near capsule of \e b: their boxes, then the exact segment
        distance in double precision only where the boxes overlap. */
    bool nearCapsulesCollide(const ompl_parc::CollisionBody &a, const ompl_parc::NearCapsules &nearA,
                             const ompl_parc::CollisionBody &b, const ompl_parc::NearCapsules &nearB)
    {
        for (std::size_t n = 0; n < nearA.size(); ++n)
            for (std::size_t k = 0; k < nearB.size(); ++k)
            {
                if (!nearA.overlaps(n, nearB, k))
                    continue;
                const std::size_t i = nearA.index(n), j = nearB.index(k);
                const double rr = a.radius_[i] + b.radius_[j];
                if (ompl_parc::segmentSegmentDistanceSquared(a.ax_[i], a.ay_[i], a.az_[i], a.bx_[i], a.by_[i], a.bz_[i],
                                                             b.ax_[j], b.ay_[j], b.az_[j], b.bx_[j], b.by_[j],
                                                             b.bz_[j]) < rr * rr)
                    return true;
            }
        return false;
    }
}  // namespace

bool ompl_parc::bodiesCollide(const CollisionBody &a, const CollisionBody &b)
{
    const double cx = a.centerX_ - b.centerX_, cy = a.centerY_ - b.centerY_, cz = a.centerZ_ - b.centerZ_;
    const double rb = a.boundRadius_ + b.boundRadius_;
    if (cx * cx + cy * cy + cz * cz >= rb * rb)
        return false;
    if (a.isSingleSphere() && b.isSingleSphere())
        return true;  // two spheres are their own bounds (discs: the common case stops here)
    if (!a.hasBoxes() || !b.hasBoxes())  // the capsule loops below run over the boxes: stale ones would misread
        throw std::logic_error("bodiesCollide: a body changed after updateBound() (call it after the last change)");

    // The capsule boxes are an allocation of their own: ask for both bodies' at once, so that their cache misses
    // overlap (less time per pair when the bodies are not in cache, no change when they are).
    for (const CollisionBody *body : {&a, &b})
        for (std::size_t k = 0; k < 6; ++k)
            __builtin_prefetch(body->boxes_.data() + k * body->boxStride_);

    // The bodies' boxes (kept beside their spheres: no further memory read) before the capsules'.
    std::array<float, 3> loA, hiA, loB, hiB;
    a.getBox(loA, hiA);
    b.getBox(loB, hiB);
    for (std::size_t d = 0; d < 3; ++d)
        if (loA[d] > hiB[d] || loB[d] > hiA[d])
            return false;

    // Only capsules whose boxes reach into the other body's box can touch it; chunk by chunk (a single sphere
    // keeps no boxes: one chunk of one capsule).
    const std::size_t slotsA = std::max<std::size_t>(a.boxStride_, 1), slotsB = std::max<std::size_t>(b.boxStride_, 1);
    constexpr std::size_t CHUNK = NearCapsules::CHUNK;
    for (std::size_t baseB = 0; baseB < slotsB; baseB += CHUNK)
    {
        const NearCapsules nearB(b, baseB, loA, hiA);
        if (nearB.size() == 0)
            continue;
        for (std::size_t baseA = 0; baseA < slotsA; baseA += CHUNK)
        {
            const NearCapsules nearA(a, baseA, loB, hiB);
            if (nearCapsulesCollide(a, nearA, b, nearB))
                return true;
        }
    }
    return false;
}
