#include "ompl_parc/arc/Subproblem.h"

#include "ompl_parc/collision/BoundingBox.h"
#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <algorithm>
#include <climits>
#include <cmath>

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

unsigned int ompl_parc::Subproblem::doubledCap(unsigned int cap, unsigned int round)
{
    const double doubled = std::ldexp(static_cast<double>(cap), static_cast<int>(std::min(round, 64u)));
    return static_cast<unsigned int>(std::min(doubled, static_cast<double>(UINT_MAX)));
}

void ompl_parc::Subproblem::fillContext(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan)
{
    others.clear();
    otherPaths.clear();
    // A robot moves at most a quarter unit between two sampled bodies (vMax 1): boxes count as near within that and
    // more.
    constexpr double MARGIN = 0.5;
    const auto stride = static_cast<std::size_t>(std::max(1., std::round(0.25 * si.getResolution())));
    CollisionBody body;
    std::vector<double> q;
    const auto bodyAt = [&](std::size_t r, std::size_t t, CollisionBody &out)
    {
        q.resize(plan.getDimension(r));
        plan.getConfig(r, t, q.data());
        si.getRobot(r)->computeBody(q.data(), out);
    };
    const auto boxOf = [&](std::size_t r)
    {
        BoundingBox box;
        for (std::size_t t = windowStart;; t = std::min(t + stride, windowEnd))
        {
            bodyAt(r, t, body);
            box.add(body);
            if (t == windowEnd)
                break;
        }
        return box;
    };
    BoundingBox team;
    std::vector<CollisionBody> starts(robots.size()), goals(robots.size());
    for (std::size_t k = 0; k < robots.size(); ++k)
    {
        team.add(boxOf(robots[k]));
        bodyAt(robots[k], windowStart, starts[k]);
        bodyAt(robots[k], windowEnd, goals[k]);
    }
    CollisionBody first, last;
    for (std::size_t r = 0, k = 0; r < plan.getRobotCount(); ++r)
    {
        if (k < robots.size() && robots[k] == r)
        {
            ++k;
            continue;
        }
        if (!boxOf(r).overlaps(team, MARGIN))
            continue;
        bodyAt(r, windowStart, first);
        bodyAt(r, windowEnd, last);
        bool blocking = false;
        for (std::size_t j = 0; j < robots.size() && !blocking; ++j)
            blocking = bodiesCollide(first, starts[j]) || bodiesCollide(last, goals[j]);
        if (blocking)
            continue;
        others.push_back(r);
        otherPaths.emplace_back(plan.getDimension(r));
        plan.getPath(r).appendRange(windowStart, windowEnd, otherPaths.back());
    }
}
