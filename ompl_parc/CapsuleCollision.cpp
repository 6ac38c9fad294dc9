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
    const double cx = a.centerX_ - b.centerX_, cy = a.centerY_ - b.centerY_, cz = a.centerZ_ - b.centerZ_;
    const double rb = a.boundRadius_ + b.boundRadius_;
    if (cx * cx + cy * cy + cz * cz >= rb * rb)
        return false;

    // Per capsule of a: a pure map over chunks of b's capsules into a small buffer of clearances (a
    // loop the compiler vectorises: no early exit, no reduction), then a short scalar scan of it.
    constexpr std::size_t CHUNK = 16;
    double clearance[CHUNK];
    const std::size_t n = b.size();
    const double *bax = b.ax_.data(), *bay = b.ay_.data(), *baz = b.az_.data();
    const double *bbx = b.bx_.data(), *bby = b.by_.data(), *bbz = b.bz_.data(), *br = b.radius_.data();
    const bool spheres = a.spheresOnly_ && b.spheresOnly_;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        const double p1x = a.ax_[i], p1y = a.ay_[i], p1z = a.az_[i];
        const double q1x = a.bx_[i], q1y = a.by_[i], q1z = a.bz_[i], ri = a.radius_[i];
        for (std::size_t base = 0; base < n; base += CHUNK)
        {
            const std::size_t m = std::min(CHUNK, n - base);
            for (std::size_t j = 0; j < m; ++j)
            {
                const std::size_t k = base + j;
                const double rr = ri + br[k];
                if (spheres)
                {
                    const double dx = p1x - bax[k], dy = p1y - bay[k], dz = p1z - baz[k];
                    clearance[j] = dx * dx + dy * dy + dz * dz - rr * rr;
                }
                else
                    clearance[j] = ::segmentDistanceSquared(p1x, p1y, p1z, q1x, q1y, q1z, bax[k], bay[k], baz[k],
                                                            bbx[k], bby[k], bbz[k]) -
                                   rr * rr;
            }
            for (std::size_t j = 0; j < m; ++j)
                if (clearance[j] < 0.)
                    return true;
        }
    }
    return false;
}
