#include "ompl_parc/collision/CapsuleCollision.h"

#include "ompl_parc/collision/NearCapsules.h"
#include "ompl_parc/collision/PrimitiveDistance.h"

#include <algorithm>
#include <cstdint>
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

    /** The groups of a body and their spheres (CollisionBody::setGroups()); a body without group bounds as one
        group, its bounding sphere. */
    struct BodyGroups
    {
        explicit BodyGroups(const ompl_parc::CollisionBody &body)
        {
            if (body.hasGroupBounds())
            {
                group = body.groups_.data();
                count = body.groupCount();
                return;
            }
            whole = {body.centerX_, body.centerY_, body.centerZ_, body.boundRadius_,
                     static_cast<std::uint32_t>(body.size())};
        }
        BodyGroups(const BodyGroups &) = delete;
        BodyGroups &operator=(const BodyGroups &) = delete;

        std::size_t begin(std::size_t g) const { return g == 0 ? 0 : group[g - 1].end; }
        std::size_t end(std::size_t g) const { return group[g].end; }

        /** True if the sphere of group \e g overlaps the sphere (\e sx, \e sy, \e sz, \e sr). */
        bool overlaps(std::size_t g, double sx, double sy, double sz, double sr) const
        {
            const ompl_parc::CollisionBody::Group &s = group[g];
            const double dx = s.x - sx, dy = s.y - sy, dz = s.z - sz, rr = s.radius + sr;
            return dx * dx + dy * dy + dz * dz < rr * rr;
        }

        ompl_parc::CollisionBody::Group whole{};
        const ompl_parc::CollisionBody::Group *group{&whole};
        std::size_t count{1};
    };

    /** True if a capsule of group \e ga of \e a overlaps one of group \e gb of \e b: each capsule of \e gb whose
        sphere reaches the sphere of \e ga against each capsule of \e ga, exactly (double precision). */
    bool groupCapsulesCollide(const ompl_parc::CollisionBody &a, const BodyGroups &groupsA, std::size_t ga,
                              const ompl_parc::CollisionBody &b, const BodyGroups &groupsB, std::size_t gb)
    {
        const std::size_t beginA = groupsA.begin(ga), endA = groupsA.end(ga);
        const bool spheres = a.spheresOnly_ && b.spheresOnly_;
        for (std::size_t j = groupsB.begin(gb); j < groupsB.end(gb); ++j)
        {
            if (!groupsA.overlaps(ga, b.sphereX_[j], b.sphereY_[j], b.sphereZ_[j], b.sphereRadius_[j]))
                continue;
            const double bx = b.ax_[j], by = b.ay_[j], bz = b.az_[j], radius = b.radius_[j];
            if (spheres)  // sphere against sphere: the distance of the centres (what the segment distance gives)
            {
                for (std::size_t i = beginA; i < endA; ++i)
                {
                    const double dx = a.ax_[i] - bx, dy = a.ay_[i] - by, dz = a.az_[i] - bz, rr = a.radius_[i] + radius;
                    if (dx * dx + dy * dy + dz * dz < rr * rr)
                        return true;
                }
                continue;
            }
            // A capsule of a mixed body (a sphere model holding a rod): the segment distance only where the two
            // capsules' spheres overlap (with room for their rounding), as the boxes rule pairs out elsewhere.
            const double sx = b.sphereX_[j], sy = b.sphereY_[j], sz = b.sphereZ_[j], sr = b.sphereRadius_[j];
            for (std::size_t i = beginA; i < endA; ++i)
            {
                const double dx = a.sphereX_[i] - sx, dy = a.sphereY_[i] - sy, dz = a.sphereZ_[i] - sz;
                const double rr = (a.sphereRadius_[i] + sr) * (1. + 0x1p-30) + 0x1p-30;
                if (dx * dx + dy * dy + dz * dz < rr * rr && ompl_parc::capsulesCollide(a, i, b, j))
                    return true;
            }
        }
        return false;
    }

    /** bodiesCollide() of bodies of which one at least has group bounds: the groups of each that reach the other
        body's sphere, then per pair of those whose spheres overlap the capsules (groupCapsulesCollide()). Kept out
        of line: inlined, its registers and stack would be set up before bodiesCollide()'s first test, which alone
        decides most pairs (discs: every pair). */
    __attribute__((noinline)) bool groupedBodiesCollide(const ompl_parc::CollisionBody &a,
                                                        const ompl_parc::CollisionBody &b)
    {
        const BodyGroups groupsA(a), groupsB(b);
        constexpr std::size_t CHUNK = 64;
        for (std::size_t baseB = 0; baseB < groupsB.count; baseB += CHUNK)
        {
            const std::size_t m = std::min(CHUNK, groupsB.count - baseB);
            std::size_t nearB[CHUNK], count = 0;
            for (std::size_t k = 0; k < m; ++k)  // branch-free compaction, as NearCapsules
            {
                nearB[count] = baseB + k;
                count += groupsB.overlaps(baseB + k, a.centerX_, a.centerY_, a.centerZ_, a.boundRadius_) ? 1 : 0;
            }
            for (std::size_t ga = 0; ga < groupsA.count && count > 0; ++ga)
            {
                if (!groupsA.overlaps(ga, b.centerX_, b.centerY_, b.centerZ_, b.boundRadius_))
                    continue;
                for (std::size_t k = 0; k < count; ++k)
                {
                    const std::size_t gb = nearB[k];
                    const ompl_parc::CollisionBody::Group &sphereB = groupsB.group[gb];
                    if (groupsA.overlaps(ga, sphereB.x, sphereB.y, sphereB.z, sphereB.radius) &&
                        groupCapsulesCollide(a, groupsA, ga, b, groupsB, gb))
                        return true;
                }
            }
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
    // Bodies with group bounds are tested group by group (the box loops below where both have boxes and at most
    // one has groups); a body without groups there needs its capsule spheres, which its boxes stand for.
    const bool groupsA = a.hasGroupBounds(), groupsB = b.hasGroupBounds(), boxes = a.hasBoxes() && b.hasBoxes();
    if ((groupsA && groupsB) || ((groupsA || groupsB) && !boxes))
    {
        const auto current = [](const CollisionBody &body)
        { return body.hasGroupBounds() || (body.hasBoxes() && body.sphereRadius_.size() == body.size()); };
        if (!current(a) || !current(b))
            throw std::logic_error("bodiesCollide: a body changed after updateBound() (call it after the last change)");
        return groupedBodiesCollide(a, b);
    }
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
