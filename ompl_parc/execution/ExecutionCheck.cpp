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
    MultiRobotPlan plan(si);
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        const unsigned int dim = si.getRobot(i)->getDimension();
        std::vector<double> flat((steps + 1) * dim);
        for (std::size_t s = 0; s <= steps; ++s)
            motion(i, s == steps ? end : start + static_cast<double>(s) * dt, flat.data() + s * dim);
        plan.setRobotPath(i, flat);
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
