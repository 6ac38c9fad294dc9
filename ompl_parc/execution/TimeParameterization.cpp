#include "ompl_parc/execution/TimeParameterization.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/validation/DisplacementBound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace
{
    constexpr double INF = std::numeric_limits<double>::infinity();

    double groupNorm(const double *values, unsigned int count)
    {
        double squared = 0.;
        for (unsigned int d = 0; d < count; ++d)
            squared += values[d] * values[d];
        return std::sqrt(squared);
    }

    /** Rounds of narrowing the windows where robots would touch before the last makes them sharp. */
    constexpr unsigned int NARROWING_PASSES = 4;

    /** Samples per timestep of the contact test of rounded corners. */
    constexpr unsigned int CONTACT_SAMPLES = 2;

    /** Caps on the team's rate (timesteps per second): at each timestep, and over each step between two. */
    struct RateCaps
    {
        std::vector<double> point, span;

        explicit RateCaps(std::size_t makespan) : point(makespan + 1, INF), span(makespan, INF) {}

        /** Cap the rate over plan times [lo, hi]: every timestep from floor(lo) to ceil(hi) and the steps between. */
        void limit(double lo, double hi, double cap)
        {
            const auto first = static_cast<std::size_t>(std::max(0., std::floor(lo)));
            const auto last = std::min(static_cast<std::size_t>(std::ceil(hi)), point.size() - 1);
            for (std::size_t k = first; k <= last; ++k)
            {
                point[k] = std::min(point[k], cap);
                if (k < last)
                    span[k] = std::min(span[k], cap);
            }
        }
    };
}  // namespace

ompl_parc::TimeParameterization::TimeParameterization(const MultiRobotProblem &problem, double maxDeviation)
    : problem_(problem), maxDeviation_(maxDeviation), check_(problem)
{
    if (!(maxDeviation >= 0.) || !std::isfinite(maxDeviation))
        throw std::invalid_argument("TimeParameterization: the largest deviation must be finite and >= 0");
    const auto &si = *problem.getSpaceInformation();
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        limits_.push_back(si.getRobot(i)->getMotionLimits());
        maxSpeed_ = std::max(maxSpeed_, ExecutionCheck::maxSpeed(limits_.back()));
    }
}

ompl_parc::TeamTrajectory ompl_parc::TimeParameterization::compute(const MultiRobotPlan &plan,
                                                                   const WindowCaps &caps) const
{
    const auto &si = *problem_.getSpaceInformation();
    if (const std::string mismatch = plan.checkTeam(si); !mismatch.empty())
        throw std::invalid_argument("TimeParameterization: " + mismatch);
    const std::size_t n = si.getRobotCount(), makespan = plan.getMakespan();
    if (!caps.empty() && caps.size() != n)
        throw std::invalid_argument("TimeParameterization: window caps must be given per robot");
    TeamTrajectory traj;
    traj.robots_.resize(n);

    // Each robot's path in plan time, cut where its slope changes; the team's top rate and its pace-change bound.
    double topRate = INF, paceChange = INF;
    for (std::size_t i = 0; i < n; ++i)
    {
        auto &path = traj.robots_[i];
        const TimedPath &timed = plan.getPath(i);
        const unsigned int dim = path.dimension = timed.getDimension();
        std::vector<std::size_t> steps{0, timed.getArrival()};
        timed.appendBreakpoints(steps);
        std::sort(steps.begin(), steps.end());
        steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
        std::vector<double> q(dim), slope(dim), before(dim, 0.), next(dim);
        for (std::size_t j = 0; j < steps.size(); ++j)
        {
            timed.getConfig(steps[j], q.data());
            if (j + 1 < steps.size())
            {
                timed.getConfig(steps[j + 1], next.data());
                for (unsigned int d = 0; d < dim; ++d)
                    slope[d] = (next[d] - q[d]) / static_cast<double>(steps[j + 1] - steps[j]);
            }
            else
                std::fill(slope.begin(), slope.end(), 0.);
            bool corner = false;
            for (unsigned int d = 0; d < dim; ++d)
                corner = corner || std::abs(slope[d] - before[d]) > 1e-12 * std::max(1., std::abs(before[d]));
            if (j > 0 && !corner && j + 1 < steps.size())
                continue;  // the same straight part goes on
            if (corner)
                path.corners.push_back(path.steps.size());
            path.steps.push_back(steps[j]);
            path.configs.insert(path.configs.end(), q.begin(), q.end());
            path.slopes.insert(path.slopes.end(), slope.begin(), slope.end());
            before = slope;
        }
        for (const auto &group : limits_[i].groups)
        {
            double steepest = 0.;
            for (std::size_t j = 0; j < path.steps.size(); ++j)
                steepest = std::max(steepest, groupNorm(&path.slopes[j * dim + group.first], group.count));
            if (steepest > 0.)
            {
                topRate = std::min(topRate, group.velocity / steepest);
                paceChange = std::min(paceChange, group.acceleration / 2. / steepest);
            }
        }
    }
    if (topRate == INF)  // nobody moves
        topRate = paceChange = 1.;

    // Windows of the corners, and the caps on the rate.
    RateCaps rateCaps(makespan);
    for (std::size_t i = 0; i < n; ++i)
    {
        auto &path = traj.robots_[i];
        const unsigned int dim = path.dimension;
        const MotionLimits &limits = limits_[i];
        path.windows.assign(path.steps.size(), 0.);
        for (std::size_t c : path.corners)
        {
            const std::size_t b = path.steps[c];
            if (b == 0 || b >= makespan)
                continue;
            const double gapBefore = static_cast<double>(b - path.steps[c - 1]);
            const double gapAfter = static_cast<double>((c + 1 < path.steps.size() ? path.steps[c + 1] : makespan) - b);
            double full = 0.;
            for (const auto &group : limits.groups)
            {
                std::vector<double> change(group.count);
                for (unsigned int d = 0; d < group.count; ++d)
                    change[d] = path.slopes[c * dim + group.first + d] - path.slopes[(c - 1) * dim + group.first + d];
                full = std::max(full, groupNorm(change.data(), group.count) * topRate * topRate / group.acceleration);
            }
            // The corner cut, |change of slope| x window / 4, within maxDeviation_.
            std::vector<double> change(dim);
            for (unsigned int d = 0; d < dim; ++d)
                change[d] = path.slopes[c * dim + d] - path.slopes[(c - 1) * dim + d];
            const double cut = 4. * maxDeviation_ / groupNorm(change.data(), dim);
            path.windows[c] = std::min({gapBefore / 2., gapAfter / 2., full, cut});
            if (!caps.empty())
                if (const auto cap = caps[i].find(b); cap != caps[i].end())
                    path.windows[c] = std::min(path.windows[c], cap->second);
        }
        for (std::size_t j = 0; j < path.steps.size(); ++j)
        {
            const double lo = static_cast<double>(path.steps[j]) - path.windows[j];
            // A straight part: the velocity limits over it and the windows at its ends.
            if (j + 1 < path.steps.size())
            {
                double cap = INF;
                for (const auto &group : limits.groups)
                    if (const double norm = groupNorm(&path.slopes[j * dim + group.first], group.count); norm > 0.)
                        cap = std::min(cap, group.velocity / norm);
                if (cap < INF)
                    rateCaps.limit(lo, static_cast<double>(path.steps[j + 1]) + path.windows[j + 1], cap);
            }
            // A rounded corner: its curvature times the rate squared within half the acceleration limit.
            const double w = path.windows[j];
            if (w > 0.)
            {
                double cap = INF;
                for (const auto &group : limits.groups)
                {
                    std::vector<double> change(group.count);
                    for (unsigned int d = 0; d < group.count; ++d)
                        change[d] =
                            path.slopes[j * dim + group.first + d] - path.slopes[(j - 1) * dim + group.first + d];
                    if (const double norm = groupNorm(change.data(), group.count); norm > 0.)
                        cap = std::min(cap, std::sqrt(group.acceleration * w / norm));
                }
                rateCaps.limit(lo, static_cast<double>(path.steps[j]) + w, cap);
            }
        }
        for (std::size_t c : path.corners)
            if (path.windows[c] == 0.)
                rateCaps.point[path.steps[c]] = 0.;
    }
    rateCaps.point.front() = rateCaps.point.back() = 0.;

    // The largest rate under the caps whose square changes by at most 2 x paceChange per timestep.
    auto &rate = traj.rates_;
    rate = rateCaps.point;
    rate.front() = 0.;
    for (std::size_t k = 0; k < makespan; ++k)
        rate[k + 1] = std::min(rate[k + 1], std::sqrt(rate[k] * rate[k] + 2. * paceChange));
    for (std::size_t k = makespan; k > 0; --k)
        rate[k - 1] = std::min(rate[k - 1], std::sqrt(rate[k] * rate[k] + 2. * paceChange));
    traj.times_.assign(1, 0.);
    traj.bangBang_.assign(makespan + 1, 0.);
    for (std::size_t k = 0; k < makespan; ++k)
    {
        const double sum = rate[k] + rate[k + 1];
        if (sum > 0.)
            traj.times_.push_back(traj.times_.back() + 2. / sum);
        else
        {
            // From rest to rest: accelerate, then brake, peaking within the step's caps.
            const double a = std::min(paceChange, rateCaps.span[k] * rateCaps.span[k]);
            traj.bangBang_[k] = a;
            traj.times_.push_back(traj.times_.back() + 2. / std::sqrt(a));
        }
    }
    return traj;
}

ompl_parc::ValidationReport ompl_parc::TimeParameterization::check(const TeamTrajectory &trajectory) const
{
    return check_.check(trajectory.getStartTime(), trajectory.getEndTime(), maxSpeed_,
                        [&](std::size_t i, double t, double *out)
                        { trajectory.evaluate(i, t, out, nullptr, nullptr); });
}

std::vector<std::vector<std::size_t>> ompl_parc::TimeParameterization::nearContacts(const TeamTrajectory &traj) const
{
    const auto &si = *problem_.getSpaceInformation();
    const std::size_t n = traj.getRobotCount();
    // Per robot, half of how far any point of it moves in one timestep (its steepest slope per coordinate).
    std::vector<double> reach(n, 0.);
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto &path = traj.robots_[i];
        std::vector<double> steepest(path.dimension, 0.);
        for (std::size_t k = 0; k < path.slopes.size(); ++k)
            steepest[k % path.dimension] = std::max(steepest[k % path.dimension], std::abs(path.slopes[k]));
        reach[i] = DisplacementBound(*si.getRobot(i))(steepest.data()) / (2. * CONTACT_SAMPLES);
    }
    // The validator's tolerance between timesteps (ExecutionCheck), shared by the two bodies of a pair.
    const double slack = 0.25 / si.getResolution();
    // Every (sample, robot, corner) of a rounded window, in time order.
    struct Visit
    {
        std::size_t step, robot, corner;
    };
    std::vector<Visit> visits;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < traj.getCornerCount(i); ++c)
            if (const double w = traj.getCornerWindow(i, c); w > 0.)
            {
                const double b = static_cast<double>(traj.getCornerStep(i, c));
                const auto first = static_cast<std::size_t>(std::floor((b - w) * CONTACT_SAMPLES));
                const auto last = static_cast<std::size_t>(std::ceil((b + w) * CONTACT_SAMPLES));
                for (std::size_t s = first; s <= last; ++s)
                    visits.push_back({s, i, c});
            }
    std::sort(visits.begin(), visits.end(),
              [](const Visit &a, const Visit &b) { return std::tie(a.step, a.robot) < std::tie(b.step, b.robot); });

    std::vector<std::vector<std::size_t>> contacts(n);
    std::vector<CollisionBody> bodies(n);
    std::vector<double> q, dq, ddq;
    for (std::size_t v = 0; v < visits.size();)
    {
        const std::size_t step = visits[v].step;
        for (std::size_t j = 0; j < n; ++j)
        {
            q.resize(traj.getDimension(j)), dq.resize(q.size()), ddq.resize(q.size());
            traj.pathAt(j, static_cast<double>(step) / CONTACT_SAMPLES, q.data(), dq.data(), ddq.data());
            si.getRobot(j)->computeCapsules(q.data(), bodies[j]);
            for (auto &radius : bodies[j].radius_)
                radius = std::max(0., radius + reach[j] - slack);
            bodies[j].updateBound();
        }
        for (; v < visits.size() && visits[v].step == step; ++v)
        {
            const Visit &visit = visits[v];
            for (std::size_t j = 0; j < n; ++j)
                if (j != visit.robot && bodiesCollide(bodies[visit.robot], bodies[j]))
                {
                    contacts[visit.robot].push_back(visit.corner);
                    break;
                }
        }
    }
    for (auto &corners : contacts)
    {
        std::sort(corners.begin(), corners.end());
        corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    }
    return contacts;
}

ompl_parc::TimeParameterization::Result ompl_parc::TimeParameterization::computeConflictFree(
    const MultiRobotPlan &plan, unsigned int maxChecks) const
{
    Result result;
    const std::size_t n = plan.getRobotCount();
    // Narrow the windows where robots would touch (a quarter each time, then sharp), until they do not.
    WindowCaps caps(n);
    result.trajectory = compute(plan, caps);
    for (unsigned int pass = 0; pass < NARROWING_PASSES; ++pass)
    {
        const auto contacts = nearContacts(result.trajectory);
        bool any = false;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t c : contacts[i])
            {
                const double w = result.trajectory.getCornerWindow(i, c);
                caps[i][result.trajectory.getCornerStep(i, c)] = pass + 1 < NARROWING_PASSES && w >= 1. ? w / 4. : 0.;
                any = true;
            }
        if (!any)
            break;
        result.trajectory = compute(plan, caps);
    }
    // The validator decides; a corner whose window holds a violation it finds is made sharp.
    for (bool allSharp = false;;)
    {
        const auto &traj = result.trajectory;
        const ValidationReport report = check(traj);
        ++result.checks;
        result.message = report.message;
        result.sharpened = traj.getSharpCornerCount();
        if (report.valid || !report.time || allSharp)
        {
            result.valid = report.valid;
            return result;
        }
        // The rounded corners whose windows (widened by a timestep) hold the violation; else the nearest ones.
        const double s = traj.planTimeAt(*report.time);
        std::size_t added = 0;
        for (int nearest = 0; nearest < 2 && added == 0; ++nearest)
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t c = 0; c < traj.getCornerCount(i); ++c)
                {
                    const double b = static_cast<double>(traj.getCornerStep(i, c)), w = traj.getCornerWindow(i, c);
                    const bool next = c + 1 < traj.getCornerCount(i);
                    const bool holds =
                        nearest ? (b <= s && (!next || static_cast<double>(traj.getCornerStep(i, c + 1)) > s)) ||
                                      (b > s && (c == 0 || static_cast<double>(traj.getCornerStep(i, c - 1)) <= s))
                                : std::abs(b - s) <= w + 1.;
                    if (w > 0. && holds)
                    {
                        caps[i][traj.getCornerStep(i, c)] = 0.;
                        ++added;
                    }
                }
        allSharp = added == 0 || result.checks >= maxChecks;
        if (allSharp)
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t c = 0; c < traj.getCornerCount(i); ++c)
                    caps[i][traj.getCornerStep(i, c)] = 0.;
        result.trajectory = compute(plan, caps);
    }
}
