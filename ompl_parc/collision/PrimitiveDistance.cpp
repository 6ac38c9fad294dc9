#include "ompl_parc/collision/PrimitiveDistance.h"

namespace
{
    /** How far coordinate \e x lies outside [-h, h] (signed, 0 inside). */
    inline double excess(double x, double h)
    {
        return x - std::min(std::max(x, -h), h);
    }

    /** Half the derivative in t of the squared distance from p + t d to the box. */
    inline double slope(const double p[3], const double d[3], const double half[3], double t)
    {
        return d[0] * excess(p[0] + t * d[0], half[0]) + d[1] * excess(p[1] + t * d[1], half[1]) +
               d[2] * excess(p[2] + t * d[2], half[2]);
    }

    /** Squared distance from p + t d to the box. */
    inline double boxDistanceSquared(const double p[3], const double d[3], const double half[3], double t)
    {
        const double ex = excess(p[0] + t * d[0], half[0]), ey = excess(p[1] + t * d[1], half[1]);
        const double ez = excess(p[2] + t * d[2], half[2]);
        return ex * ex + ey * ey + ez * ez;
    }
}  // namespace

double ompl_parc::pointSegmentDistanceSquared(const double p[3], const double a[3], const double b[3])
{
    const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    const double rx = p[0] - a[0], ry = p[1] - a[1], rz = p[2] - a[2];
    const double length2 = dx * dx + dy * dy + dz * dz;
    const double t = length2 > 0. ? std::min(std::max((rx * dx + ry * dy + rz * dz) / length2, 0.), 1.) : 0.;
    const double ex = rx - t * dx, ey = ry - t * dy, ez = rz - t * dz;
    return ex * ex + ey * ey + ez * ez;
}

double ompl_parc::segmentBoxDistanceSquared(const double p[3], const double d[3], const double half[3])
{
    double lo = 0., hi = 1.;
    double slopeLo = slope(p, d, half, lo), slopeHi = slope(p, d, half, hi);
    if (slopeLo >= 0.)  // increasing from the start: the start is closest
        return boxDistanceSquared(p, d, half, lo);
    if (slopeHi <= 0.)
        return boxDistanceSquared(p, d, half, hi);
    // The derivative is monotone: every break inside (lo, hi) narrows the bracket of its root from one side.
    for (int k = 0; k < 3; ++k)
    {
        if (d[k] == 0.)
            continue;
        for (const double face : {-half[k], half[k]})
        {
            const double t = (face - p[k]) / d[k];
            if (!(t > lo && t < hi))
                continue;
            const double s = slope(p, d, half, t);
            if (s < 0.)
            {
                lo = t;
                slopeLo = s;
            }
            else
            {
                hi = t;
                slopeHi = s;
            }
        }
    }
    // No break left inside (lo, hi): the derivative is linear there, with slopeLo < 0 <= slopeHi.
    const double t = lo + (hi - lo) * (-slopeLo / (slopeHi - slopeLo));
    return boxDistanceSquared(p, d, half, t);
}
