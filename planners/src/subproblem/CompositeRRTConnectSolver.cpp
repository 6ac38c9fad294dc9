#include "ompl_parc/planners/subproblem/CompositeRRTConnectSolver.h"

#include "ompl_parc/planners/subproblem/TeamPatch.h"

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

namespace ob = ompl::base;
namespace og = ompl::geometric;

ompl_parc::CompositeRRTConnectSolver::CompositeRRTConnectSolver(double range, bool simplify)
    : range_(range), simplify_(simplify)
{
}

bool ompl_parc::CompositeRRTConnectSolver::solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                                 const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                                 Patch &patch) const
{
    const auto local = subproblem.createSpaceInformation(si, seed);
    if (!local)
        return false;

    ob::ScopedState<> start(local), goal(local);
    if (!team_patch::fillEndpoints(*local, subproblem, start.get(), goal.get()))
        return false;

    auto pdef = std::make_shared<ob::ProblemDefinition>(local);
    pdef->setStartAndGoalStates(start, goal, 1e-9);
    og::RRTConnect planner(local);
    planner.setProblemDefinition(pdef);
    if (range_ > 0.)
        planner.setRange(range_);
    planner.setup();

    if (planner.solve(subproblem.cappedTermination(ptc)) != ob::PlannerStatus::EXACT_SOLUTION)
        return false;

    team_patch::lay(local, *pdef->getSolutionPath()->as<og::PathGeometric>(), seed, simplify_, patch);
    return true;
}
