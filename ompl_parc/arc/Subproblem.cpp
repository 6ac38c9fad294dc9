#include "ompl_parc/arc/Subproblem.h"

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

std::string ompl_parc::Subproblem::check(const MultiRobotSpaceInformation &si) const
{
    if (robots.empty())
        return "subproblem has no robots";
    if (starts.size() != robots.size() || goals.size() != robots.size())
        return "subproblem needs one local start and goal per robot";
    if (!bounds.empty() && bounds.size() != robots.size())
        return "subproblem needs one bounds entry per robot, or none";
    if (windowEnd < windowStart)
        return "subproblem window ends before it starts";
    for (std::size_t k = 0; k < robots.size(); ++k)
    {
        if (robots[k] >= si.getRobotCount() || (k > 0 && robots[k] <= robots[k - 1]))
            return "subproblem robots must be increasing indices of the team";
        const unsigned int d = si.getRobot(robots[k])->getDimension();
        if (starts[k].size() != d || goals[k].size() != d)
            return "local start or goal of robot '" + si.getRobot(robots[k])->getName() + "' has the wrong size";
    }
    return "";
}

std::shared_ptr<ompl_parc::MultiRobotSpaceInformation> ompl_parc::Subproblem::createSpaceInformation(
    const MultiRobotSpaceInformation &si, std::uint_fast32_t seed) const
{
    if (!check(si).empty())
        return nullptr;
    std::vector<RobotPtr> team;
    for (std::size_t r : robots)
        team.push_back(si.getRobot(r));
    return std::make_shared<MultiRobotSpaceInformation>(team, si.getResolution(), bounds, seed);
}

ompl::base::PlannerTerminationCondition ompl_parc::Subproblem::cappedTermination(
    const ompl::base::PlannerTerminationCondition &ptc) const
{
    if (sampleCap == 0)
        return ptc;
    auto iterations = std::make_shared<unsigned int>(0);
    const unsigned int cap = sampleCap;
    return ompl::base::plannerOrTerminationCondition(
        ptc, ompl::base::PlannerTerminationCondition([iterations, cap] { return ++*iterations > cap; }));
}
