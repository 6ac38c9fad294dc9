#include "ompl_parc/planners/subproblem/WholeTeamSolver.h"

#include "ompl_parc/planners/subproblem/LatticeMapfSolver.h"
#include "ompl_parc/planners/subproblem/SequentialRRTConnectSolver.h"

ompl_parc::WholeTeamSolver::WholeTeamSolver()
    : lattice_(LatticeMapfSolver::makeTeamSolver()), sequential_(std::make_shared<SequentialRRTConnectSolver>(true))
{
}

bool ompl_parc::WholeTeamSolver::appliesTo(const MultiRobotSpaceInformation &si,
                                           const std::vector<std::size_t> &robots) const
{
    return lattice_->appliesTo(si, robots) ||
           (!robots.empty() && robots.size() <= SequentialRRTConnectSolver::MAX_TEAM);
}

bool ompl_parc::WholeTeamSolver::solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                       const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                       Patch &patch) const
{
    if (lattice_->appliesTo(si, subproblem.robots))
        return lattice_->solve(si, subproblem, ptc, seed, patch);
    return appliesTo(si, subproblem.robots) && sequential_->solve(si, subproblem, ptc, seed, patch);
}
