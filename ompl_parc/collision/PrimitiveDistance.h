#ifndef OMPL_PARC_PRIMITIVE_DISTANCE_
#define OMPL_PARC_PRIMITIVE_DISTANCE_

#include <algorithm>

namespace ompl_parc
{
    /** \brief The scalar select that segmentSegmentDistanceSquared() uses for doubles (SIMD types bring their
        own select, found by argument-dependent lookup). */
    inline double select(bool condition, double ifTrue, double ifFalse)
    {
        return condition ? ifTrue : ifFalse;
    }

    /** \brief Squared distance between the segments [p1, q1] and [p2, q2].

        The line-line optimum of the first parameter is clamped, the second optimised for it and clamped, and
        the first re-optimised for that: at the true optimum the first is already optimal for the second, so
        this equals the usual case analysis. Branch-free (clamps and selects only, divisions by floored
        denominators) and inline, so that loops over many capsule pairs vectorise. Handles degenerate segments
        (spheres) without special cases. \e T is double, or a SIMD batch (xsimd) that runs one pair of segments
        per lane: one formula for the scalar and the lane kernels. */
    template <typename T>
    inline T segmentSegmentDistanceSquared(T p1x, T p1y, T p1z, T q1x, T q1y, T q1z, T p2x, T p2y, T p2z, T q2x,
                                           T q2y, T q2z)
    {
        using std::max;
        using std::min;
        const T tiny(1e-18), zero(0.), one(1.);
        const auto clamp01 = [&](const T &v) { return min(max(v, zero), one); };
        const T d1x = q1x - p1x, d1y = q1y - p1y, d1z = q1z - p1z;
        const T d2x = q2x - p2x, d2y = q2y - p2y, d2z = q2z - p2z;
        const T rx = p1x - p2x, ry = p1y - p2y, rz = p1z - p2z;
        const T a = d1x * d1x + d1y * d1y + d1z * d1z;
        const T e = d2x * d2x + d2y * d2y + d2z * d2z;
        const T b = d1x * d2x + d1y * d2y + d1z * d2z;
        const T c = d1x * rx + d1y * ry + d1z * rz;
        const T f = d2x * rx + d2y * ry + d2z * rz;
        const T denom = a * e - b * b;
        const T s0 = select(denom > tiny, clamp01((b * f - c * e) / max(denom, tiny)), zero);
        const T t = clamp01((b * s0 + f) / max(e, tiny));
        const T s = clamp01((b * t - c) / max(a, tiny));
        const T dx = rx + d1x * s - d2x * t;
        const T dy = ry + d1y * s - d2y * t;
        const T dz = rz + d1z * s - d2z * t;
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
