#include "ompl_parc/execution/TimeParameterization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

ompl_parc::TimeParameterization::TimeParameterization(const MultiRobotProblem &problem)
    : problem_(problem), check_(problem)
{
    const auto &si = *problem.getSpaceInformation();
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        limits_.push_back(si.getRobot(i)->getMotionLimits());
        maxSpeed_ = std::max(maxSpeed_, ExecutionCheck::maxSpeed(limits_.back()));
    }
}

ompl_parc::TeamTrajectory ompl_parc::TimeParameterization::compute(
    const MultiRobotPlan &plan, const std::vector<std::vector<std::size_t>> &sharp) const
{
    const auto &si = *problem_.getSpaceInformation();
    if (const std::string mismatch = plan.checkTeam(si); !mismatch.empty())
        throw std::invalid_argument("TimeParameterization: " + mismatch);
    const std::size_t n = si.getRobotCount(), makespan = plan.getMakespan();
    if (!sharp.empty() && sharp.size() != n)
        throw std::invalid_argument("TimeParameterization: sharp corners must be given per robot");
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
    RateCaps caps(makespan);
    for (std::size_t i = 0; i < n; ++i)
    {
        auto &path = traj.robots_[i];
        const unsigned int dim = path.dimension;
        const MotionLimits &limits = limits_[i];
        path.windows.assign(path.steps.size(), 0.);
        for (std::size_t c : path.corners)
        {
            const std::size_t b = path.steps[c];
            if (b == 0 || b >= makespan || (!sharp.empty() && std::binary_search(sharp[i].begin(), sharp[i].end(), b)))
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
            path.windows[c] = std::min({gapBefore / 2., gapAfter / 2., full});
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
                    caps.limit(lo, static_cast<double>(path.steps[j + 1]) + path.windows[j + 1], cap);
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
                caps.limit(lo, static_cast<double>(path.steps[j]) + w, cap);
            }
        }
        for (std::size_t c : path.corners)
            if (path.windows[c] == 0.)
                caps.point[path.steps[c]] = 0.;
    }
    caps.point.front() = caps.point.back() = 0.;

    // The largest rate under the caps whose square changes by at most 2 x paceChange per timestep.
    auto &rate = traj.rates_;
    rate = caps.point;
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
            const double a = std::min(paceChange, caps.span[k] * caps.span[k]);
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

ompl_parc::TimeParameterization::Result ompl_parc::TimeParameterization::computeConflictFree(
    const MultiRobotPlan &plan, unsigned int maxChecks) const
{
    Result result;
    const std::size_t n = plan.getRobotCount();
    std::vector<std::vector<std::size_t>> sharp(n);
    bool allSharp = false;
    for (;;)
    {
        result.trajectory = compute(plan, sharp);
        const auto &traj = result.trajectory;
        const ValidationReport report = check(traj);
        ++result.checks;
        result.message = report.message;
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
                        sharp[i].push_back(traj.getCornerStep(i, c));
                        ++added;
                    }
                }
        allSharp = added == 0 || result.checks >= maxChecks;
        for (std::size_t i = 0; i < n; ++i)
        {
            if (allSharp)
                for (std::size_t c = 0; c < traj.getCornerCount(i); ++c)
                    sharp[i].push_back(traj.getCornerStep(i, c));
            std::sort(sharp[i].begin(), sharp[i].end());
            sharp[i].erase(std::unique(sharp[i].begin(), sharp[i].end()), sharp[i].end());
        }
        result.sharpened = 0;
        for (const auto &corners : sharp)
            result.sharpened += corners.size();
    }
}
