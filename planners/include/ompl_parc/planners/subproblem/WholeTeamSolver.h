#ifndef OMPL_PARC_WHOLE_TEAM_SOLVER_
#define OMPL_PARC_WHOLE_TEAM_SOLVER_

#include "ompl_parc/arc/SubproblemSolver.h"

namespace ompl_parc
{
    /** \brief The smoother's and the anytime phase's whole-team solver (PlanSmoother::setTeamSolver()): a plan made for
        the whole team at once, from its starts to its goals, without the chains of waits and detours that repairs
        leave. Teams of discs are solved on a lattice (LatticeMapfSolver::makeTeamSolver(): LaCAM, milliseconds where
        prioritised planning needs seconds), other teams of up to SequentialRRTConnectSolver::MAX_TEAM robots (arms) by
        moving the robots one at a time, each move shortened among the robots standing, the moves then overlapped in
        time wherever the robots stay apart (SequentialRRTConnectSolver with shortened patches, MoveScheduler): every
        robot on a short path of its own, waiting only for the robots in its way. */
    class WholeTeamSolver : public SubproblemSolver
    {
      public:
        WholeTeamSolver();

        std::string getName() const override { return "whole-team"; }

        /** \brief Teams the lattice applies to, and teams of at most SequentialRRTConnectSolver::MAX_TEAM robots. */
        bool appliesTo(const MultiRobotSpaceInformation &si, const std::vector<std::size_t> &robots) const override;

        bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                   Patch &patch) const override;

        /** \brief A new solver, as a factory for PlanSmoother::setTeamSolver()'s callers. */
        static SubproblemSolverPtr make() { return std::make_shared<WholeTeamSolver>(); }

      private:
        SubproblemSolverPtr lattice_, sequential_;
    };
}  // namespace ompl_parc

#endif
