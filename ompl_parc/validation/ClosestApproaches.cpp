#include "ompl_parc/validation/ClosestApproaches.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollisionBody.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>

namespace
{
    using Point = std::array<double, 3>;

    double dot(const Point &a, const Point &b)
    {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    Point sub(const Point &a, const Point &b)
    {
        return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    Point along(const Point &p, const Point &d, double s)
    {
        return {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]};
    }

    /** The clearance of two bodies (smallest capsule-capsule distance less the radii) and the capsules that have it. */
    double clearance(const ompl_parc::CollisionBody &a, const ompl_parc::CollisionBody &b, std::size_t &ia,
                     std::size_t &ib)
    {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = 0; j < b.size(); ++j)
            {
                const double c = std::sqrt(ompl_parc::segmentDistanceSquared(a, i, b, j)) - a.radius_[i] - b.radius_[j];
                if (c < best)
                {
                    best = c;
                    ia = i;
                    ib = j;
                }
            }
        return best;
    }
}  // namespace

std::array<std::array<double, 3>, 2> ompl_parc::ClosestApproaches::closestPoints(const Point &p1, const Point &q1,
                                                                                 const Point &p2, const Point &q2)
{
    // Ericson, Real-Time Collision Detection, 5.1.9: the parameters s on the first segment and t on the second.
    const Point d1 = sub(q1, p1), d2 = sub(q2, p2), r = sub(p1, p2);
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
    constexpr double EPS = 1e-18;
    double s = 0., t = 0.;
    if (a <= EPS && e <= EPS)
        return {p1, p2};
    if (a <= EPS)
        t = std::clamp(f / e, 0., 1.);
    else
    {
        const double c = dot(d1, r);
        if (e <= EPS)
            s = std::clamp(-c / a, 0., 1.);
        else
        {
            const double b = dot(d1, d2), denom = a * e - b * b;
            s = denom > EPS ? std::clamp((b * f - c * e) / denom, 0., 1.) : 0.;
            t = (b * s + f) / e;
            if (t < 0.)
            {
                t = 0.;
                s = std::clamp(-c / a, 0., 1.);
            }
            else if (t > 1.)
            {
                t = 1.;
                s = std::clamp((b - c) / a, 0., 1.);
            }
        }
    }
    return {along(p1, d1, s), along(p2, d2, t)};
}

std::vector<ompl_parc::ClosestApproach> ompl_parc::ClosestApproaches::find(const MultiRobotSpaceInformation &si,
                                                                           const MultiRobotPlan &plan,
                                                                           const std::vector<std::size_t> &timesteps,
                                                                           std::size_t count)
{
    const std::size_t n = si.getRobotCount();
    if (plan.getRobotCount() != n)
        throw ompl::Exception("ClosestApproaches", "the plan has " + std::to_string(plan.getRobotCount()) +
                                                       " robots, the team " + std::to_string(n));
    if (count == 0 || n < 2)
        return {};
    std::vector<CollisionBody> bodies(n);
    std::vector<double> q;
    std::vector<std::size_t> byX(n);
    std::unordered_map<std::size_t, ClosestApproach> pairs;  // key: first * n + second
    std::vector<double> minima;
    double cutoff = std::numeric_limits<double>::infinity();  // the count-th smallest pair clearance so far
    const auto updateCutoff = [&]
    {
        if (pairs.size() < count)
            return;
        minima.clear();
        for (const auto &entry : pairs)
            minima.push_back(entry.second.clearance);
        std::nth_element(minima.begin(), minima.begin() + static_cast<std::ptrdiff_t>(count - 1), minima.end());
        cutoff = minima[count - 1];
    };
    for (std::size_t t : timesteps)
    {
        double largest = 0.;
        for (std::size_t r = 0; r < n; ++r)
        {
            q.resize(plan.getDimension(r));
            plan.getConfig(r, t, q.data());
            si.getRobot(r)->computeBody(q.data(), bodies[r]);
            largest = std::max(largest, bodies[r].boundRadius_);
        }
        std::iota(byX.begin(), byX.end(), 0);
        std::sort(byX.begin(), byX.end(),
                  [&](std::size_t a, std::size_t b) { return bodies[a].centerX_ < bodies[b].centerX_; });
        const auto consider = [&](std::size_t i, std::size_t j)
        {
            if (i > j)
                std::swap(i, j);
            std::size_t ci = 0, cj = 0;
            const double c = clearance(bodies[i], bodies[j], ci, cj);
            const auto found = pairs.find(i * n + j);
            if (c > cutoff || (found != pairs.end() && found->second.clearance <= c))
                return;
            ClosestApproach &approach = pairs[i * n + j];
            approach.first = i;
            approach.second = j;
            approach.timestep = t;
            approach.clearance = c;
            const CollisionBody &bi = bodies[i], &bj = bodies[j];
            const auto axes = closestPoints({bi.ax_[ci], bi.ay_[ci], bi.az_[ci]}, {bi.bx_[ci], bi.by_[ci], bi.bz_[ci]},
                                            {bj.ax_[cj], bj.ay_[cj], bj.az_[cj]}, {bj.bx_[cj], bj.by_[cj], bj.bz_[cj]});
            // From each axis point to its capsule's surface, towards the other body.
            const Point gap = sub(axes[1], axes[0]);
            const double length = std::sqrt(dot(gap, gap));
            approach.points = axes;
            if (length > 0.)
                approach.points = {along(axes[0], gap, bi.radius_[ci] / length),
                                   along(axes[1], gap, -bj.radius_[cj] / length)};
        };
        // The first time, neighbours along x give real clearances to prune the rest with.
        if (std::isinf(cutoff))
        {
            for (std::size_t u = 0; u + 1 < n; ++u)
                consider(byX[u], byX[u + 1]);
            updateCutoff();
        }
        for (std::size_t u = 0; u < n; ++u)
        {
            const CollisionBody &a = bodies[byX[u]];
            for (std::size_t v = u + 1; v < n; ++v)
            {
                const CollisionBody &b = bodies[byX[v]];
                if (b.centerX_ - a.centerX_ - a.boundRadius_ - largest > cutoff)
                    break;  // every later body is further along x
                const double dx = a.centerX_ - b.centerX_, dy = a.centerY_ - b.centerY_, dz = a.centerZ_ - b.centerZ_;
                if (std::sqrt(dx * dx + dy * dy + dz * dz) - a.boundRadius_ - b.boundRadius_ <= cutoff)
                    consider(byX[u], byX[v]);
            }
        }
        updateCutoff();
    }
    std::vector<ClosestApproach> closest;
    for (const auto &[key, approach] : pairs)
        closest.push_back(approach);
    std::sort(closest.begin(), closest.end(),
              [](const ClosestApproach &a, const ClosestApproach &b)
              { return std::tie(a.clearance, a.first, a.second) < std::tie(b.clearance, b.first, b.second); });
    closest.resize(std::min(closest.size(), count));
    return closest;
}
