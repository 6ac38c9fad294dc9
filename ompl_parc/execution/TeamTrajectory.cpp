#include "ompl_parc/execution/TeamTrajectory.h"

#include <algorithm>
#include <cmath>

void ompl_parc::TeamTrajectory::planMotionAt(double t, double &step, double &rate, double &acceleration) const
{
    rate = acceleration = 0.;
    const std::size_t last = times_.size() - 1;
    if (t <= 0. || last == 0)
    {
        step = 0.;
        return;
    }
    if (t >= times_.back())
    {
        step = static_cast<double>(last);
        return;
    }
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    const double tau = t - times_[k], r0 = rates_[k], r1 = rates_[k + 1];
    double s;
    if (r0 == 0. && r1 == 0.)
    {
        const double a = bangBang_[k], span = times_[k + 1] - times_[k];
        if (tau < span / 2.)
        {
            s = 0.5 * a * tau * tau;
            rate = a * tau;
            acceleration = a;
        }
        else
        {
            const double u = span - tau;
            s = 1. - 0.5 * a * u * u;
            rate = a * u;
            acceleration = -a;
        }
    }
    else
    {
        acceleration = (r1 * r1 - r0 * r0) / 2.;
        s = r0 * tau + 0.5 * acceleration * tau * tau;
        rate = r0 + acceleration * tau;
    }
    step = static_cast<double>(k) + std::clamp(s, 0., 1.);
}

void ompl_parc::TeamTrajectory::pathAt(std::size_t i, double s, double *q, double *dq, double *ddq) const
{
    const RobotPath &path = robots_[i];
    const unsigned int dim = path.dimension;
    const auto after =
        std::upper_bound(path.steps.begin(), path.steps.end(), s,
                         [](double value, std::size_t step) { return value < static_cast<double>(step); });
    // The breakpoint at or before s (the first one if s is before all), and the corner whose window holds s, if any.
    const std::size_t j = after == path.steps.begin() ? 0 : static_cast<std::size_t>(after - path.steps.begin()) - 1;
    std::size_t c = j;
    if (j + 1 < path.steps.size() && static_cast<double>(path.steps[j + 1]) - s < path.windows[j + 1])
        c = j + 1;
    const double offset = s - static_cast<double>(path.steps[c]), w = path.windows[c];
    const double *p = path.configs.data() + c * dim;
    const double *out = path.slopes.data() + c * dim;
    const double *in = c == 0 ? nullptr : path.slopes.data() + (c - 1) * dim;
    if (w > 0. && std::abs(offset) < w)
    {
        const double u = offset + w;
        for (unsigned int d = 0; d < dim; ++d)
        {
            const double mIn = in ? in[d] : 0., curvature = (out[d] - mIn) / (2. * w);
            q[d] = p[d] + mIn * offset + 0.5 * curvature * u * u;
            dq[d] = mIn + curvature * u;
            ddq[d] = curvature;
        }
        return;
    }
    // On a straight part: the one after breakpoint c, or before it (s before c), or before the first breakpoint.
    const bool before = offset < 0.;
    for (unsigned int d = 0; d < dim; ++d)
    {
        const double m = before ? (in ? in[d] : 0.) : out[d];
        q[d] = p[d] + m * offset;
        dq[d] = m;
        ddq[d] = 0.;
    }
}

void ompl_parc::TeamTrajectory::evaluate(std::size_t i, double t, double *position, double *velocity,
                                         double *acceleration) const
{
    double s, rate, planAcceleration;
    planMotionAt(t, s, rate, planAcceleration);
    const unsigned int dim = getDimension(i);
    double q[64], dq[64], ddq[64];
    std::vector<double> heap;
    double *buffer[3] = {q, dq, ddq};
    if (dim > 64)
    {
        heap.resize(3 * dim);
        for (int b = 0; b < 3; ++b)
            buffer[b] = heap.data() + b * dim;
    }
    pathAt(i, s, buffer[0], buffer[1], buffer[2]);
    for (unsigned int d = 0; d < dim; ++d)
    {
        if (position)
            position[d] = buffer[0][d];
        if (velocity)
            velocity[d] = buffer[1][d] * rate;
        if (acceleration)
            acceleration[d] = buffer[2][d] * rate * rate + buffer[1][d] * planAcceleration;
    }
}

double ompl_parc::TeamTrajectory::timeAtPlanStep(double step) const
{
    const std::size_t last = times_.size() - 1;
    if (step <= 0. || last == 0)
        return 0.;
    if (step >= static_cast<double>(last))
        return times_.back();
    const auto k = static_cast<std::size_t>(std::floor(step));
    const double f = step - static_cast<double>(k), r0 = rates_[k], r1 = rates_[k + 1];
    if (f == 0.)
        return times_[k];
    if (r0 == 0. && r1 == 0.)
    {
        const double a = bangBang_[k], span = times_[k + 1] - times_[k];
        return times_[k] + (f <= 0.5 ? std::sqrt(2. * f / a) : span - std::sqrt(2. * (1. - f) / a));
    }
    const double acceleration = (r1 * r1 - r0 * r0) / 2.;
    // r0 tau + a tau^2 / 2 = f, in the form that stays exact for a -> 0.
    return times_[k] + 2. * f / (r0 + std::sqrt(std::max(0., r0 * r0 + 2. * acceleration * f)));
}

double ompl_parc::TeamTrajectory::planTimeAt(double t) const
{
    double s, rate, acceleration;
    planMotionAt(t, s, rate, acceleration);
    return s;
}

double ompl_parc::TeamTrajectory::getArrivalTime(std::size_t i) const
{
    const RobotPath &path = robots_[i];
    if (path.corners.empty())
        return 0.;
    const std::size_t c = path.corners.back();
    return timeAtPlanStep(static_cast<double>(path.steps[c]) + path.windows[c]);
}

double ompl_parc::TeamTrajectory::getMaxDeviation(std::size_t i) const
{
    const RobotPath &path = robots_[i];
    double deviation = 0.;
    for (std::size_t c : path.corners)
        if (path.windows[c] > 0.)
        {
            double squared = 0.;
            for (unsigned int d = 0; d < path.dimension; ++d)
                squared += std::pow(path.slopes[c * path.dimension + d] - path.slopes[(c - 1) * path.dimension + d], 2);
            deviation = std::max(deviation, std::sqrt(squared) * path.windows[c] / 4.);
        }
    return deviation;
}

std::size_t ompl_parc::TeamTrajectory::getSharpCornerCount() const
{
    const std::size_t last = times_.size() - 1;
    std::size_t sharp = 0;
    for (const auto &path : robots_)
        for (std::size_t c : path.corners)
            sharp += path.windows[c] == 0. && path.steps[c] > 0 && path.steps[c] < last ? 1 : 0;
    return sharp;
}

std::vector<double> ompl_parc::TeamTrajectory::getBreakTimes(std::size_t i) const
{
    const RobotPath &path = robots_[i];
    if (path.corners.empty())
        return {0.};
    const std::size_t first = path.corners.front(), lastCorner = path.corners.back();
    const double from = static_cast<double>(path.steps[first]) - path.windows[first];
    const double to = static_cast<double>(path.steps[lastCorner]) + path.windows[lastCorner];
    std::vector<double> steps{from, to};
    for (std::size_t c : path.corners)
        if (path.windows[c] > 0.)
        {
            steps.push_back(static_cast<double>(path.steps[c]) - path.windows[c]);
            steps.push_back(static_cast<double>(path.steps[c]) + path.windows[c]);
        }
    // The team changes pace where its acceleration differs from the step before (and mid-way through a step
    // crossed from rest to rest).
    const auto accelerationOf = [&](std::size_t k)
    { return (rates_[k + 1] * rates_[k + 1] - rates_[k] * rates_[k]) / 2.; };
    const auto lo = static_cast<std::size_t>(std::max(0., std::floor(from)));
    const auto hi = std::min(static_cast<std::size_t>(std::ceil(to)), times_.size() - 1);
    for (std::size_t k = std::max<std::size_t>(lo, 1); k < hi; ++k)
    {
        if (rates_[k] == 0. && rates_[k + 1] == 0.)
            steps.push_back(static_cast<double>(k) + 0.5);
        if (accelerationOf(k) != accelerationOf(k - 1) || rates_[k] == 0.)
            steps.push_back(static_cast<double>(k));
    }
    std::vector<double> times;
    for (double s : steps)
        times.push_back(timeAtPlanStep(s));
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}
