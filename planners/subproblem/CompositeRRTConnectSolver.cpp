#include "ompl_parc/planners/subproblem/CompositeRRTConnectSolver.h"

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

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
    for (std::size_t k = 0; k < subproblem.robots.size(); ++k)
    {
        std::copy(subproblem.starts[k].begin(), subproblem.starts[k].end(), local->getRobotValues(start.get(), k));
        std::copy(subproblem.goals[k].begin(), subproblem.goals[k].end(), local->getRobotValues(goal.get(), k));
    }
    if (!local->isValid(start.get()) || !local->isValid(goal.get()))
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

    auto &path = *pdef->getSolutionPath()->as<og::PathGeometric>();
    if (simplify_)
    {
        // Bounded like the initial paths: one pass of vertex reduction and of shortcutting (128 steps, stop after
        // 32 without improvement), each checked on the team's space (robots and environment).
        SeededPathSimplifier simplifier(local, mixSeed(seed, 0x5eed));
        simplifier.reduceVertices(path);
        compat::shortcutPath(simplifier, path, 128, 32);
    }
    patch.paths = MultiRobotPlan::layTeamPath(*local, path);
    return true;
}
