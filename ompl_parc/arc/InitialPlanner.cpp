#include "ompl_parc/arc/InitialPlanner.h"

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

namespace ob = ompl::base;
namespace og = ompl::geometric;

ompl_parc::InitialPlanner::InitialPlanner(const MultiRobotProblem &problem, bool simplify,
                                          ob::PlannerAllocator allocator)
    : problem_(problem), simplify_(simplify), allocator_(std::move(allocator))
{
    if (!allocator_)
        allocator_ = [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::RRTConnect>(si); };
}

bool ompl_parc::InitialPlanner::plan(std::size_t robot, const ob::PlannerTerminationCondition &ptc,
                                     std::uint_fast32_t seed, TimedPath &path) const
{
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
