#ifndef OMPL_PARC_CONFLICT_RESOLVER_
#define OMPL_PARC_CONFLICT_RESOLVER_

#include "ompl_parc/arc/ArcSettings.h"
#include "ompl_parc/arc/SubproblemSolver.h"
#include "ompl_parc/model/MultiRobotPlan.h"

#include <optional>

namespace ompl_parc
{
    /** \brief A successful repair: the subproblem that was solved, its patch, and how it was found. */
    struct Repair
    {
        Subproblem subproblem;
        Patch patch;
        std::string solver;
        /** \brief Solver calls, and window expansions after the first window, until success. */
        unsigned int attempts{0}, expansions{0};
        bool global{false};
    };

    /** \brief ARC's conflict resolution for one conflict: windows around the conflict that grow until a
        solver in the hierarchy succeeds, up to the global problem.

        The window [t - h, t + h] is clipped to [0, latest arrival of the team]; an invalid local start
        (goal) side is first widened by ArcSettings::endpointStep until the team's states there are
        collision-free; local bounds follow ArcSettings. When a grown window equals the previous one, or
        covers the team's whole plan, the attempt becomes the global problem (global starts and goals, whole
        spaces, no sample cap), retried until success or termination. resolve() only reads the plan, so
        P-ARC runs several at once on disjoint teams. */
    class ConflictResolver
    {
      public:
        ConflictResolver(const MultiRobotSpaceInformation &si, ArcSettings settings,
                         std::vector<SubproblemSolverPtr> hierarchy);

        /** \brief Repair the conflict of \e team at \e timestep of \e plan; none if \e ptc fired first. */
        std::optional<Repair> resolve(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                      std::size_t timestep, const ompl::base::PlannerTerminationCondition &ptc,
                                      std::uint_fast32_t seed) const;

        /** \brief The subproblem of attempt \e attempt (0 = first window), before global promotion. */
        Subproblem makeSubproblem(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                  std::size_t timestep, unsigned int attempt) const;

        /** \brief The team's whole problem: global starts and goals, no bounds, no sample cap. */
        Subproblem makeGlobal(const MultiRobotPlan &plan, const std::vector<std::size_t> &team) const;

        const ArcSettings &getSettings() const { return settings_; }

      private:
        bool teamClear(const MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::size_t timestep) const;
        void fillEndpoints(const MultiRobotPlan &plan, Subproblem &sub) const;
        void fillBounds(const MultiRobotPlan &plan, Subproblem &sub) const;

        const MultiRobotSpaceInformation &si_;
        ArcSettings settings_;
        std::vector<SubproblemSolverPtr> hierarchy_;
    };
}  // namespace ompl_parc

#endif
