#include "ompl_parc/collision/CapsuleCollision.h"

#include "ompl_parc/collision/PrimitiveDistance.h"

#include <algorithm>

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
    constexpr std::size_t CHUNK = 16;

    /** The capsules of one chunk of a body whose bounding spheres reach into a given sphere: their spheres
        copied into local arrays (plain stack memory the pair loop can vectorise over) and their indices. */
    struct NearCapsules
    {
        std::size_t count{0};
        std::size_t index[CHUNK];
        double sx[CHUNK], sy[CHUNK], sz[CHUNK], sr[CHUNK];

        /** Capsules [base, base + m) of \e body reaching into the sphere (x, y, z, radius). */
        NearCapsules(const ompl_parc::CollisionBody &body, std::size_t base, std::size_t m, double x, double y,
                     double z, double radius)
        {
            const double *px = body.sphereX_.data() + base, *py = body.sphereY_.data() + base;
            const double *pz = body.sphereZ_.data() + base, *pr = body.sphereRadius_.data() + base;
            double clearance[CHUNK];
            for (std::size_t k = 0; k < m; ++k)  // a vectorised map
            {
                const double dx = px[k] - x, dy = py[k] - y, dz = pz[k] - z, rr = pr[k] + radius;
                clearance[k] = dx * dx + dy * dy + dz * dz - rr * rr;
            }
            // Branch-free compaction: every capsule is written to the next free slot, which only advances for
            // a near one (the signs are random, so a branch here would mispredict about every other time).
            for (std::size_t k = 0; k < m; ++k)
            {
                index[count] = base + k;
                sx[count] = px[k];
                sy[count] = py[k];
                sz[count] = pz[k];
                sr[count] = pr[k];
                count += clearance[k] < 0. ? 1 : 0;
            }
        }
    };

    /** True if a near capsule of \e a overlaps a near capsule of \e b: per capsule of \e a, a vectorised pass
        of sphere-sphere clearances over those of \e b, then the exact segment distance only where the capsule
        spheres overlap. */
    bool nearCapsulesCollide(const ompl_parc::CollisionBody &a, const NearCapsules &nearA,
                             const ompl_parc::CollisionBody &b, const NearCapsules &nearB)
    {
        double clearance[CHUNK];
        for (std::size_t n = 0; n < nearA.count; ++n)
        {
            const double x = nearA.sx[n], y = nearA.sy[n], z = nearA.sz[n], r = nearA.sr[n];
            for (std::size_t k = 0; k < nearB.count; ++k)
            {
                const double dx = nearB.sx[k] - x, dy = nearB.sy[k] - y, dz = nearB.sz[k] - z, rr = nearB.sr[k] + r;
                clearance[k] = dx * dx + dy * dy + dz * dz - rr * rr;
            }
            const std::size_t i = nearA.index[n];
            for (std::size_t k = 0; k < nearB.count; ++k)
            {
                if (clearance[k] >= 0.)
                    continue;
                const std::size_t j = nearB.index[k];
                const double rr = a.radius_[i] + b.radius_[j];
                if (ompl_parc::segmentSegmentDistanceSquared(a.ax_[i], a.ay_[i], a.az_[i], a.bx_[i], a.by_[i], a.bz_[i],
                                                             b.ax_[j], b.ay_[j], b.az_[j], b.bx_[j], b.by_[j],
                                                             b.bz_[j]) < rr * rr)
                    return true;
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
    if (a.size() == 1 && b.size() == 1 && a.spheresOnly_ && b.spheresOnly_)
        return true;  // two spheres are their own bounds (discs: the common case stops here)

    // Only capsules whose spheres reach into the other body's bounding sphere can touch it; chunk by chunk.
    const std::size_t na = a.size(), nb = b.size();
    for (std::size_t baseB = 0; baseB < nb; baseB += CHUNK)
    {
        const NearCapsules nearB(b, baseB, std::min(CHUNK, nb - baseB), a.centerX_, a.centerY_, a.centerZ_,
                                 a.boundRadius_);
        if (nearB.count == 0)
            continue;
        for (std::size_t baseA = 0; baseA < na; baseA += CHUNK)
        {
            const NearCapsules nearA(a, baseA, std::min(CHUNK, na - baseA), b.centerX_, b.centerY_, b.centerZ_,
                                     b.boundRadius_);
            if (nearCapsulesCollide(a, nearA, b, nearB))
                return true;
        }
    }
    return false;
}
