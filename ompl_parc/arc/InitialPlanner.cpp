#include "ompl_parc/arc/InitialPlanner.h"

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/robots/RakeMotionValidator.h"
#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <algorithm>
#include <limits>

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
        if (auto straight = straightPath(robot))
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

std::optional<ompl_parc::TimedPath> ompl_parc::InitialPlanner::straightPath(std::size_t robot) const
{
    const auto &mrsi = *problem_.getSpaceInformation();
    const Robot &body = *mrsi.getRobot(robot);
    const auto *validator =
        dynamic_cast<const RakeMotionValidator *>(body.getSpaceInformation()->getMotionValidator().get());
    const auto &s = problem_.getStart(robot), &g = problem_.getGoal(robot);
    if (validator == nullptr || !body.isValid(s.data()))
        return std::nullopt;
    const std::size_t steps = MultiRobotPlan::stepsFor(body.distance(s.data(), g.data()), mrsi.getResolution());
    // The robot's own motion check at the path's timesteps (swept where the kind can, else sampled in rake order).
    if (steps > std::numeric_limits<unsigned int>::max())
        return std::nullopt;
    const std::optional<bool> valid = validator->checkStraight(s, g, static_cast<unsigned int>(steps));
    if (!valid || !*valid)
        return std::nullopt;
    TimedPath path(body.getDimension(), s.data());
    path.appendMotion(s.data(), g.data(), steps);
    path.trimArrival();
    return path;
}
