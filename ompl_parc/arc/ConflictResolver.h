#ifndef OMPL_PARC_CONFLICT_RESOLVER_
#define OMPL_PARC_CONFLICT_RESOLVER_

#include "ompl_parc/arc/ArcSettings.h"
#include "ompl_parc/arc/SubproblemSolver.h"
#include "ompl_parc/model/MultiRobotPlan.h"

#include <ompl/util/Time.h>

#include <optional>
#include <utility>

namespace ompl_parc
{
    /** \brief A successful repair: the subproblem that was solved, its patch, and how it was found. */
    struct Repair
    {
        Subproblem subproblem;
        Patch patch;
        std::string solver;
    };

    /** \brief What one resolve() did, success or not: the statistics of a failed repair, and the longest
        single solver call (no call may hold the budget). */
    struct ResolveTrace
    {
        unsigned int calls{0}, expansions{0}, globalRounds{0};
        /** \brief Passes of the window schedule after the first (ArcSettings::minWindowGrowth above 1). */
        unsigned int passes{0};
        double longestCall{0.};
        /** \brief Seconds of solver calls on global rounds and on the windows of the later passes. */
        double globalSeconds{0.}, againSeconds{0.};
    };

    /** \brief ARC's conflict resolution for one conflict: windows around the conflict that grow until a
        solver in the hierarchy succeeds, up to the global problem.

        The window [t - h, t + h] is clipped to [0, latest arrival of the team]; an invalid local start
        (goal) side is first widened by ArcSettings::endpointStep until the team's states there are
        collision-free; local bounds follow ArcSettings. When ArcSettings::minWindowGrowth exceeds 1, windows less
        than that factor longer than the first of their size are tried WINDOW_TRIES times and the schedule's others
        skipped. When the schedule stops growing (ArcSettings::halfWidth), the window covers the team's whole plan or,
        without skipping, equals the failed one, the attempt becomes the global problem (global starts and goals,
        whole spaces), retried with fresh seeds until success or termination; with skipping, a failed global round is
        followed by the schedule again from the first window (fresh seeds; the global rounds' caps and memories kept)
        while these later passes have taken no longer than the global rounds. When a solver of the hierarchy plans
        around the other robots (PP-ST-RRT) and the team's global problem has failed once, the next rounds plan every
        robot of the problem (the paper's global problem): the others' fixed paths may wall the team in for good. Such
        a repair covers every robot (P-ARC splices it first and drops the batch's other repairs, RepairLoop). Every
        call is bounded: a local window by ArcSettings::sampleCap iterations, global round g by sampleCap x 2^g (a
        sample cap of 0 lifts these caps); and every call, whatever the iterations cost, by time: it may run as long
        as the solve had run before it started (at least MIN_CALL_SECONDS), since the resolver was made
        (RepairLoop::configure, at each solve). So no call ever holds more than half of the time spent when the solve
        stops, while the effort per call still grows geometrically. Only calls that reach the time cap make a seeded
        solve's result depend on the machine's speed. resolve() only reads the plan, so P-ARC runs several at once. */
    class ConflictResolver
    {
      public:
        /** \brief The longest window that gets a context: a solver keeps bodies of the context per timestep. */
        static constexpr std::size_t MAX_CONTEXT_TIMESTEPS = std::size_t{1} << 16;

        /** \brief The least time cap of one solver call, in seconds. */
        static constexpr double MIN_CALL_SECONDS = 0.05;

        /** \brief How often windows of one size (less than ArcSettings::minWindowGrowth times as long as the first of
            them) are tried in one pass of the schedule when that factor exceeds 1: a fresh seed sometimes finds what
            the first try missed, while more tries of one size held the budgets of the Panda cells ARC failed
            (docs/results.md). A window needing more gets them in the later passes. */
        static constexpr unsigned int WINDOW_TRIES = 2;

        ConflictResolver(const MultiRobotSpaceInformation &si, ArcSettings settings,
                         std::vector<SubproblemSolverPtr> hierarchy);

        /** \brief Repair the conflict of \e team at \e timestep of \e plan; none if \e ptc fired first. */
        std::optional<Repair> resolve(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                      std::size_t timestep, const ompl::base::PlannerTerminationCondition &ptc,
                                      std::uint_fast32_t seed, ResolveTrace *trace = nullptr) const;

        /** \brief The subproblem of attempt \e attempt (0 = first window), before global promotion. */
        Subproblem makeSubproblem(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                  std::size_t timestep, unsigned int attempt) const;

        /** \brief The team's whole problem for global round \e round (0 = the first): global starts and goals, no
            bounds, a sample cap of ArcSettings::sampleCap x 2^round (none when sampleCap is 0). */
        Subproblem makeGlobal(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                              unsigned int round) const;

        const ArcSettings &getSettings() const { return settings_; }

      private:
        /** \brief The window [start, end] of attempt \e attempt: [t - h, t + h] clipped to the team's plan, each
            invalid side widened by ArcSettings::endpointStep until the team is clear there. */
        std::pair<std::size_t, std::size_t> window(const MultiRobotPlan &plan, const std::vector<std::size_t> &team,
                                                   std::size_t timestep, unsigned int attempt) const;
        /** \brief The subproblem of \e team over [start, end]: endpoints, bounds, context and the window's cap. */
        Subproblem makeWindow(const MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::size_t start,
                              std::size_t end) const;
        bool teamClear(const MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::size_t timestep) const;
        void fillEndpoints(const MultiRobotPlan &plan, Subproblem &sub) const;
        void fillBounds(const MultiRobotPlan &plan, Subproblem &sub) const;
        /** \brief Subproblem::fillContext() when a solver of the hierarchy uses the context; none for a window of
            MAX_CONTEXT_TIMESTEPS or more. */
        void fillContext(const MultiRobotPlan &plan, Subproblem &sub) const;

        const MultiRobotSpaceInformation &si_;
        ArcSettings settings_;
        std::vector<SubproblemSolverPtr> hierarchy_;
        bool usesContext_{false};
        /** \brief When the resolver was made: the time cap of a call is the time since. */
        ompl::time::point made_;
    };
}  // namespace ompl_parc

#endif
