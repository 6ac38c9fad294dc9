#ifndef OMPL_PARC_PRIMITIVE_DISTANCE_
#define OMPL_PARC_PRIMITIVE_DISTANCE_

#include <algorithm>

namespace ompl_parc
{
    /** \brief Squared distance between the segments [p1, q1] and [p2, q2].

        The line-line optimum of the first parameter is clamped, the second optimised for it and clamped, and
        the first re-optimised for that: at the true optimum the first is already optimal for the second, so
        this equals the usual case analysis. Branch-free (clamps and selects only, divisions by floored
        denominators) and inline, so that loops over many capsule pairs vectorise. Handles degenerate segments
        (spheres) without special cases. */
    inline double segmentSegmentDistanceSquared(double p1x, double p1y, double p1z, double q1x, double q1y, double q1z,
                                                double p2x, double p2y, double p2z, double q2x, double q2y, double q2z)
    {
        constexpr double TINY = 1e-18;
        const auto clamp01 = [](double v) { return std::min(std::max(v, 0.), 1.); };
        const double d1x = q1x - p1x, d1y = q1y - p1y, d1z = q1z - p1z;
        const double d2x = q2x - p2x, d2y = q2y - p2y, d2z = q2z - p2z;
        const double rx = p1x - p2x, ry = p1y - p2y, rz = p1z - p2z;
        const double a = d1x * d1x + d1y * d1y + d1z * d1z;
        const double e = d2x * d2x + d2y * d2y + d2z * d2z;
        const double b = d1x * d2x + d1y * d2y + d1z * d2z;
        const double c = d1x * rx + d1y * ry + d1z * rz;
        const double f = d2x * rx + d2y * ry + d2z * rz;
        const double denom = a * e - b * b;
        const double s0 = denom > TINY ? clamp01((b * f - c * e) / std::max(denom, TINY)) : 0.;
        const double t = clamp01((b * s0 + f) / std::max(e, TINY));
        const double s = clamp01((b * t - c) / std::max(a, TINY));
        const double dx = rx + d1x * s - d2x * t;
        const double dy = ry + d1y * s - d2y * t;
        const double dz = rz + d1z * s - d2z * t;
        return dx * dx + dy * dy + dz * dz;
    }

    /** \brief Squared distance between the point \e p and the segment [\e a, \e b] (exact; a capsule against a
        sphere). */
    double pointSegmentDistanceSquared(const double p[3], const double a[3], const double b[3]);

    /** \brief Squared distance between the segment \e p + t \e d, t in [0, 1], and the box [-\e half, \e half],
        all in the box's frame (exact; a capsule against an oriented box after moving it into the box's frame).

        The squared distance to a convex set is convex along the segment, and its derivative is continuous and
        piecewise linear with breaks only where a coordinate crosses a face plane (at most six). Evaluating
        the derivative at those breaks brackets its root between two neighbouring ones, where it is linear:
        the minimum follows in closed form, without iterating and without sorting the breaks. */
    double segmentBoxDistanceSquared(const double p[3], const double d[3], const double half[3]);
}  // namespace ompl_parc

#endif
