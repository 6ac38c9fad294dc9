#include "ompl_parc/arc/InitialPlanner.h"

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <algorithm>
#include <cmath>

namespace ob = ompl::base;
namespace og = ompl::geometric;

ompl_parc::InitialPlanner::InitialPlanner(const MultiRobotProblem &problem, bool simplify,
                                          ob::PlannerAllocator allocator, bool straightFirst)
    : problem_(problem), simplify_(simplify), straightFirst_(straightFirst), allocator_(std::move(allocator))
{
    if (!allocator_)
        allocator_ = [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::RRTConnect>(si); };
}

bool ompl_parc::InitialPlanner::plan(std::size_t robot, const ob::PlannerTerminationCondition &ptc,
                                     std::uint_fast32_t seed, TimedPath &path) const
{
    if (straightFirst_)
        if (auto straight = straightPath(robot, ptc))
        {
            path = std::move(*straight);
            return true;
        }
    const auto &mrsi = *problem_.getSpaceInformation();
    auto si = std::make_shared<MultiRobotSpaceInformation>(
        std::vector<RobotPtr>{mrsi.getRobot(robot)}, mrsi.getResolution(), std::vector<ob::RealVectorBounds>{}, seed);
    ob::ScopedState<> start(si), goal(si);
    const auto &s = problem_.getStart(robot), &g = problem_.getGoal(robot);
    std::copy(s.begin(), s.end(), si->getRobotValues(start.get(), 0));
    std::copy(g.begin(), g.end(), si->getRobotValues(goal.get(), 0));
    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    pdef->setStartAndGoalStates(start, goal, 1e-9);
    auto planner = allocator_(si);
    planner->setProblemDefinition(pdef);
    planner->setup();
    if (planner->solve(ptc) != ob::PlannerStatus::EXACT_SOLUTION)
        return false;
    auto &geometric = *pdef->getSolutionPath()->as<og::PathGeometric>();
    if (simplify_)
    {
        // The authors' bounded effort: one pass of vertex reduction, shortcutting (128 steps, stop after 32
        // without improvement) and one B-spline smoothing step.
        SeededPathSimplifier simplifier(si, mixSeed(seed, 0x51));
        simplifier.reduceVertices(geometric);
        compat::shortcutPath(simplifier, geometric, 128, 32);
        simplifier.smoothBSpline(geometric, 1);
    }
    path = MultiRobotPlan::fromPathGeometric(*si, geometric).getPath(0);
    return true;
}

std::optional<ompl_parc::TimedPath> ompl_parc::InitialPlanner::straightPath(std::size_t robot,
                                                                         const ob::PlannerTerminationCondition &ptc) const
{
    const auto &mrsi = *problem_.getSpaceInformation();
    const Robot &body = *mrsi.getRobot(robot);
    const unsigned int d = body.getDimension();
    const double *s = problem_.getStart(robot).data(), *g = problem_.getGoal(robot).data();
    double squared = 0.;  // a robot's space is a real vector space: its distance is Euclidean
    for (unsigned int k = 0; k < d; ++k)
        squared += (g[k] - s[k]) * (g[k] - s[k]);
    TimedPath path(d, s);
    path.appendMotion(s, g, MultiRobotPlan::stepsFor(std::sqrt(squared), mrsi.getResolution()));
    path.trimArrival();
    if (const std::optional<bool> swept = body.sweepValid(s, g))
        return *swept ? std::optional<TimedPath>(std::move(path)) : std::nullopt;
    // Every timestep of the path, as a planner's motions are checked, a batch at a time (the kinds with a
    // batch kernel check it at once).
    constexpr std::size_t BATCH = 64;
    std::vector<double> configs(BATCH * d);
    TimedPath::Cursor cursor(path);
    const std::size_t arrival = path.getArrival();
    for (std::size_t t = 1; t <= arrival; t += BATCH)
    {
        if (ptc)
            return std::nullopt;
        const std::size_t count = std::min(BATCH, arrival + 1 - t);
        for (std::size_t k = 0; k < count; ++k)
            cursor.get(t + k, configs.data() + k * d);
        if (!body.allValid(configs.data(), count))
            return std::nullopt;
    }
    return path;
}
