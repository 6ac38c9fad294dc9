#include "ompl_parc/arc/DiscPairScan.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/util/StopSignal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
    /** Relative margin on the radius sum: the model's positions differ from the path's by a few units in the
        last place of the coordinates (about 1e-16 relative), the quadratic's evaluation by a few more, so
        1e-9 of the coordinates' magnitude is many orders above both and costs only a few extra exact checks. */
    constexpr double RELATIVE_MARGIN = 1e-9;
}  // namespace

ompl_parc::DiscPairScan::DiscPairScan(const DiscRobot &a, const TimedPath &pathA, const DiscRobot &b,
                                      const TimedPath &pathB, CollisionBody &bodyA, CollisionBody &bodyB)
    : a_(a), b_(b), pathA_(pathA), pathB_(pathB), bodyA_(bodyA), bodyB_(bodyB), cursorA_(pathA), cursorB_(pathB)
{
}

ompl_parc::DiscPairScan::Motion ompl_parc::DiscPairScan::motionAt(const TimedPath &path, TimedPath::Cursor &cursor,
                                                                  std::size_t t)
{
    constexpr std::size_t FOREVER = std::numeric_limits<std::size_t>::max();
    double q[2];
    const std::size_t arrival = path.getArrival();
    if (t >= arrival)  // held from the arrival on
    {
        path.getConfig(arrival, q);
        return {q[0], q[1], 0., 0., t, FOREVER};
    }
    const std::size_t piece = cursor.seek(t);
    const TimedPath::Piece &p = path.getPiece(piece);
    const std::size_t coverEnd = piece + 1 < path.getPieceCount() ? path.getPiece(piece + 1).start - 1 : arrival;
    const std::size_t local = p.offset + (t - p.start);
    const double *from = path.getFrom(piece), *to = path.getTo(piece);
    if (local >= p.steps)  // past the piece's motion: it holds its end
        return {to[0], to[1], 0., 0., t, coverEnd};
    TimedPath::interpolate(from, to, local, p.steps, 2, q);
    const double steps = static_cast<double>(p.steps);
    // The linear part ends where the local step reaches the piece's steps (its value there is `to`, which the
    // line reaches up to rounding).
    return {
        q[0], q[1], (to[0] - from[0]) / steps, (to[1] - from[1]) / steps, t, std::min(coverEnd, t + (p.steps - local))};
}

bool ompl_parc::DiscPairScan::collidesAt(std::size_t t)
{
    double qa[2], qb[2];
    cursorA_.get(t, qa);
    cursorB_.get(t, qb);
    a_.computeBody(qa, bodyA_);
    b_.computeBody(qb, bodyB_);
    return bodiesCollide(bodyA_, bodyB_);
}

std::optional<std::size_t> ompl_parc::DiscPairScan::firstContact(std::size_t from, std::size_t last)
{
    stoppedAt_.reset();
    const double radiusSum = a_.getRadius() + b_.getRadius();
    Motion ma{}, mb{};
    for (std::size_t t = from; t <= last;)
    {
        // A motion is renewed only when it ends: the other one carries on across the stretches it spans.
        if (t == from || t > ma.end)
            ma = motionAt(pathA_, cursorA_, t);
        if (t == from || t > mb.end)
            mb = motionAt(pathB_, cursorB_, t);
        const std::size_t end = std::min({ma.end, mb.end, last});
        const double length = static_cast<double>(end - t);
        // Relative position d(u) = d0 + dv u at timestep t + u, u in [0, length]; closest approach at u*.
        const double sa = static_cast<double>(t - ma.time), sb = static_cast<double>(t - mb.time);
        const double ax = ma.x + ma.vx * sa, ay = ma.y + ma.vy * sa, bx = mb.x + mb.vx * sb, by = mb.y + mb.vy * sb;
        const double dx = ax - bx, dy = ay - by, dvx = ma.vx - mb.vx, dvy = ma.vy - mb.vy;
        const double speed2 = dvx * dvx + dvy * dvy, along = dx * dvx + dy * dvy;
        const double u = speed2 > 0. ? std::clamp(-along / speed2, 0., length) : 0.;
        const double ex = dx + dvx * u, ey = dy + dvy * u, closest2 = ex * ex + ey * ey;
        const double scale =
            1. + std::max({std::abs(ma.x), std::abs(ma.y), std::abs(mb.x), std::abs(mb.y)}) +
            (std::abs(ma.vx) + std::abs(ma.vy) + std::abs(mb.vx) + std::abs(mb.vy)) * (length + sa + sb);
        const double reach = radiusSum + RELATIVE_MARGIN * scale;
        if (!(closest2 >= reach * reach))  // (NaN included) the discs may touch around u*: check exactly there
        {
            const double half = speed2 > 0. ? std::sqrt((reach * reach - closest2) / speed2) : length;
            std::size_t lo = 0, hi = end - t;
            if (std::isfinite(half))
            {
                if (u - half > 0.)
                    lo = static_cast<std::size_t>(std::floor(u - half));
                if (u + half < length)
                    hi = static_cast<std::size_t>(std::ceil(u + half));
            }
            for (std::size_t s = lo; s <= hi; ++s)
            {
                if ((s - lo) % StopSignal::POLL_INTERVAL == StopSignal::POLL_INTERVAL - 1 && StopSignal::raised())
                {
                    stoppedAt_ = t + s;
                    return std::nullopt;
                }
                if (collidesAt(t + s))
                    return t + s;
            }
        }
        if (end == last)
            break;
        t = end + 1;
    }
    return std::nullopt;
}
