#include "ompl_parc/execution/ExecutionCheck.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace
{
    ompl_parc::ValidationOptions executionOptions(const ompl_parc::MultiRobotProblem &problem)
    {
        ompl_parc::ValidationOptions options;
        options.contactTolerance = 0.5 / problem.getSpaceInformation()->getResolution();
        return options;
    }
}  // namespace

ompl_parc::ExecutionCheck::ExecutionCheck(const MultiRobotProblem &problem)
    : problem_(problem), validator_(problem, executionOptions(problem))
{
}

double ompl_parc::ExecutionCheck::maxSpeed(const MotionLimits &limits)
{
    double squared = 0.;
    for (const auto &group : limits.groups)
        squared += group.velocity * group.velocity;
    return std::sqrt(squared);
}

ompl_parc::MultiRobotPlan ompl_parc::ExecutionCheck::sample(double start, double end, double maxSpeed,
                                                            const Motion &motion) const
{
    const auto &si = *problem_.getSpaceInformation();
    if (!(end >= start) || !std::isfinite(end - start) || !(maxSpeed > 0.) || !std::isfinite(maxSpeed))
        throw std::invalid_argument("ExecutionCheck: the motion's times or speed are not finite");
    const double dt = 0.999 / (si.getResolution() * maxSpeed);
    const auto steps = static_cast<std::size_t>(std::ceil((end - start) / dt));
    if (steps > MultiRobotPlan::MAX_TIMESTEP)
        throw std::invalid_argument("ExecutionCheck: the motion needs more samples than a plan may hold");
    // Samples where the motion is straight and steady (cruising, waiting) are merged into one piece: memory grows
    // with the motion's bends, not its length. A run goes on while each sample stays within EPSILON of the line its
    // first step sets, so the plan's grid states are within 2 EPSILON of the motion's: rounding, next to the
    // half-timestep tolerance of the check.
    const double epsilon = 1e-9 / si.getResolution();
    const auto at = [&](std::size_t s) { return s == steps ? end : start + static_cast<double>(s) * dt; };
    MultiRobotPlan plan(si);
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        const unsigned int dim = si.getRobot(i)->getDimension();
        std::vector<double> anchor(dim), first(dim), last(dim), current(dim);
        TimedPath path(dim);
        motion(i, start, anchor.data());
        path.appendHold(anchor.data(), 0);
        std::size_t anchorStep = 0, lastStep = 0;
        for (std::size_t s = 1; s <= steps; ++s)
        {
            motion(i, at(s), current.data());
            bool onLine = s > anchorStep + 1;
            for (unsigned int k = 0; k < dim && onLine; ++k)
                onLine = std::abs(anchor[k] + static_cast<double>(s - anchorStep) * (first[k] - anchor[k]) -
                                  current[k]) <= epsilon;
            if (!onLine && s > anchorStep + 1)
            {
                path.appendMotion(anchor.data(), last.data(), lastStep - anchorStep);
                anchor = last;
                anchorStep = lastStep;
            }
            if (s == anchorStep + 1)
                first = current;
            last = current;
            lastStep = s;
        }
        path.appendMotion(anchor.data(), last.data(), lastStep - anchorStep);
        plan.setPath(i, std::move(path));
    }
    return plan;
}

ompl_parc::ValidationReport ompl_parc::ExecutionCheck::check(double start, double end, double maxSpeed,
                                                             const Motion &motion) const
{
    auto report = validator_.validate(sample(start, end, maxSpeed, motion));
    if (report.time)
    {
        const double dt = 0.999 / (problem_.getSpaceInformation()->getResolution() * maxSpeed);
        report.time = std::min(end, start + *report.time * dt);
        // The validator counts samples: say the time in seconds instead.
        const auto colon = report.message.find(": ");
        std::ostringstream at;
        at << "at " << *report.time << " s";
        report.message = at.str() + (colon == std::string::npos ? ": " + report.message : report.message.substr(colon));
    }
    return report;
}
