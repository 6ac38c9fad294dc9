#ifndef OMPL_PARC_SUBPROBLEM_SOLVER_
#define OMPL_PARC_SUBPROBLEM_SOLVER_

#include "ompl_parc/arc/Patch.h"
#include "ompl_parc/arc/Subproblem.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstdint>
#include <memory>
#include <string>

namespace ompl_parc
{
    /** \brief A multi-robot planner for ARC's local subproblems (prioritised ST-RRT, composite RRT-Connect).

        ARC tries solvers in a configurable hierarchy through this interface, and P-ARC calls them from
        several threads at once: solve() is const and keeps all its state local, and a given \e seed gives
        the same patch whatever else runs. */
    class SubproblemSolver
    {
      public:
        virtual ~SubproblemSolver() = default;

        /** \brief A short name for statistics ("pp-st-rrt", "composite-rrtc"). */
        virtual std::string getName() const = 0;

        /** \brief Whether the solver can plan for the robots \e robots of \e si at all (a lattice only for robots that
            translate): where it cannot, solve() declines at once, and a caller with a choice (PlanSmoother's team
            solve) need not try it. */
        virtual bool appliesTo(const MultiRobotSpaceInformation & /*si*/,
                               const std::vector<std::size_t> & /*robots*/) const
        {
            return true;
        }

        /** \brief Whether solve() avoids the subproblem's context (Subproblem::others), which is then worth
            filling. */
        virtual bool usesContext() const { return false; }

        /** \brief Solve \e subproblem for the robots of \e si; on success fill \e patch and return true.
            Returns false (never throws, never blocks past \e ptc) when it gives up. */
        virtual bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                           const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                           Patch &patch) const = 0;

        /** \brief What a solver keeps from one call to the next on the same problem. ARC's global rounds give each
            call a time cap as long as the solve has run so far (ConflictResolver): a solver that starts over in
            every round redoes what the rounds before it did, so a problem that needs T seconds in one call costs
            about twice that, or more, before it is solved. */
        class Memory
        {
          public:
            virtual ~Memory() = default;
        };

        /** \brief A fresh memory for calls of resume() on one problem; none (the default) if the solver cannot go
            on from where a call stopped. */
        virtual std::unique_ptr<Memory> makeMemory() const { return nullptr; }

        /** \brief solve(), going on from where the last call with \e memory (made by makeMemory(), used only on
            \e subproblem's team, starts, goals and context; its sample cap may grow) stopped, and leaving in it
            where this one stops. A null \e memory is a plain solve(). The caller keeps \e memory to one thread. */
        virtual bool resume(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                            const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, Patch &patch,
                            Memory * /*memory*/) const
        {
            return solve(si, subproblem, ptc, seed, patch);
        }
    };

    using SubproblemSolverPtr = std::shared_ptr<const SubproblemSolver>;
}  // namespace ompl_parc

#endif
