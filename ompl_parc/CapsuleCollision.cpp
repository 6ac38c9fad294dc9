#include "ompl_parc/CapsuleCollision.h"

#include <algorithm>

namespace
{
    constexpr double TINY = 1e-18;

    inline double clamp01(double v)
    {
        return std::min(std::max(v, 0.), 1.);
    }

    /** Closest-point parameters of two segments p1 + s d1 and p2 + t d2, then their squared distance.
        The line-line optimum of s is clamped, t is optimised for it and clamped, and s re-optimised for
        that t: at the true optimum s is already optimal for t, so this equals the usual case analysis. */
    inline double segmentDistanceSquared(double p1x, double p1y, double p1z, double q1x, double q1y, double q1z,
                                         double p2x, double p2y, double p2z, double q2x, double q2y, double q2z)
    {
        const double d1x = q1x - p1x, d1y = q1y - p1y, d1z = q1z - p1z;
        const double d2x = q2x - p2x, d2y = q2y - p2y, d2z = q2z - p2z;
        const double rx = p1x - p2x, ry = p1y - p2y, rz = p1z - p2z;
        const double a = d1x * d1x + d1y * d1y + d1z * d1z;
        const double e = d2x * d2x + d2y * d2y + d2z * d2z;
        const double b = d1x * d2x + d1y * d2y + d1z * d2z;
        const double c = d1x * rx + d1y * ry + d1z * rz;
        const double f = d2x * rx + d2y * ry + d2z * rz;
        const double denom = a * e - b * b;
        // Divisions are unconditional (by a floored denominator) and only their results selected, so
        // the compiler can if-convert and vectorise without speculating a trapping division.
        const double s0 = denom > TINY ? clamp01((b * f - c * e) / std::max(denom, TINY)) : 0.;
        const double t = clamp01((b * s0 + f) / std::max(e, TINY));
        const double s = clamp01((b * t - c) / std::max(a, TINY));
        const double dx = rx + d1x * s - d2x * t;
        const double dy = ry + d1y * s - d2y * t;
        const double dz = rz + d1z * s - d2z * t;
        return dx * dx + dy * dy + dz * dz;
    }
}  // namespace

double ompl_parc::segmentDistanceSquared(const CollisionBody &a, std::size_t i, const CollisionBody &b, std::size_t j)
{
    return ::segmentDistanceSquared(a.ax_[i], a.ay_[i], a.az_[i], a.bx_[i], a.by_[i], a.bz_[i], b.ax_[j], b.ay_[j],
                                    b.az_[j], b.bx_[j], b.by_[j], b.bz_[j]);
}

bool ompl_parc::capsulesCollide(const CollisionBody &a, std::size_t i, const CollisionBody &b, std::size_t j)
{
    const double rr = a.radius_[i] + b.radius_[j];
    return segmentDistanceSquared(a, i, b, j) < rr * rr;
}

bool ompl_parc::bodiesCollide(const CollisionBody &a, const CollisionBody &b)
{
    const auto apart = [](double x1, double y1, double z1, double r1, double x2, double y2, double z2, double r2)
    {
        const double dx = x1 - x2, dy = y1 - y2, dz = z1 - z2, rr = r1 + r2;
        return dx * dx + dy * dy + dz * dz >= rr * rr;
    };
    if (apart(a.centerX_, a.centerY_, a.centerZ_, a.boundRadius_, b.centerX_, b.centerY_, b.centerZ_, b.boundRadius_))
        return false;
    if (a.size() == 1 && b.size() == 1 && a.spheresOnly_ && b.spheresOnly_)
        return true;  // two spheres are their own bounds (discs: the common case stops here)

    // b's capsules in chunks: those whose spheres reach a's bound are gathered into small local arrays
    // (a vectorised map, then a compaction); then per capsule of a that reaches b's bound, one vectorised
    // pass of sphere-sphere clearances over the gathered ones, and the exact segment distance only where
    // the capsule spheres overlap.
    constexpr std::size_t CHUNK = 16;
    double clearance[CHUNK], gx[CHUNK], gy[CHUNK], gz[CHUNK], gr[CHUNK];
    std::size_t index[CHUNK];
    const std::size_t na = a.size(), nb = b.size();
    for (std::size_t base = 0; base < nb; base += CHUNK)
    {
        const std::size_t m = std::min(CHUNK, nb - base);
        const double *sx = b.sphereX_.data() + base, *sy = b.sphereY_.data() + base;
        const double *sz = b.sphereZ_.data() + base, *sr = b.sphereRadius_.data() + base;
        for (std::size_t k = 0; k < m; ++k)
        {
            const double dx = sx[k] - a.centerX_, dy = sy[k] - a.centerY_, dz = sz[k] - a.centerZ_;
            const double rr = sr[k] + a.boundRadius_;
            clearance[k] = dx * dx + dy * dy + dz * dz - rr * rr;
        }
        std::size_t near = 0;
        for (std::size_t k = 0; k < m; ++k)
            if (clearance[k] < 0.)
            {
                gx[near] = sx[k];
                gy[near] = sy[k];
                gz[near] = sz[k];
                gr[near] = sr[k];
                index[near++] = base + k;
            }
        if (near == 0)
            continue;
        for (std::size_t i = 0; i < na; ++i)
        {
            const double x = a.sphereX_[i], y = a.sphereY_[i], z = a.sphereZ_[i], r = a.sphereRadius_[i];
            if (apart(x, y, z, r, b.centerX_, b.centerY_, b.centerZ_, b.boundRadius_))
                continue;
            for (std::size_t k = 0; k < near; ++k)
            {
                const double dx = gx[k] - x, dy = gy[k] - y, dz = gz[k] - z, rr = gr[k] + r;
                clearance[k] = dx * dx + dy * dy + dz * dz - rr * rr;
            }
            for (std::size_t k = 0; k < near; ++k)
                if (clearance[k] < 0. && capsulesCollide(a, i, b, index[k]))
                    return true;
        }
    }
    return false;
}
