#ifndef OMPL_PARC_SEQUENTIAL_RRT_CONNECT_SOLVER_
#define OMPL_PARC_SEQUENTIAL_RRT_CONNECT_SOLVER_

#include "ompl_parc/arc/SubproblemSolver.h"

namespace ompl_parc
{
    /** \brief Subproblem solver that moves the team's robots one at a time: each robot's move is OMPL's RRTConnect
        in its own space (inside the local bounds), from its start to its goal, with the robots moved before it
        standing at their goals and the others at their starts.

        Why: neighbouring arms whose workspaces overlap (the Panda cell: four Pandas half a metre apart) make a
        coupled problem of 28 dimensions with narrow passages, where composite RRT-Connect and prioritised ST-RRT
        both run out of time, while most orders of one-arm moves are a few milliseconds each. Which orders work
        is not known before planning, so the orders are searched depth first over the set of robots already
        moved: a move depends only on that set, a failed move is not tried again in the same round, and a set
        from which no order completes is not entered again. Each round caps every move at twice the iterations
        of the round before (from 256), all moves of a call together at the subproblem's sample cap; a move found
        in one round is kept for the next. A window (not the team's global problem) gets the first round only: it
        starts and ends mid-motion with the team close together, where single moves seldom work, and the rounds
        would cost each failed window as much as composite RRT-Connect's call (docs/results.md). Each move is checked
        with the team's own checks as it is planned (and, with \e simplify, shortened among the same standing robots).
        The moves are then overlapped in time where the robots stay apart (MoveScheduler: a move that touches no
        robot moved before it starts at once, not when they have all arrived), the team path optionally shortened
        like composite RRT-Connect's (which lets robots move together again), and laid on the timestep grid.
        Teams of more than 16 robots are declined.
        ARC's global rounds of one team resume the search where the last round's call was cut. */
    class SequentialRRTConnectSolver : public SubproblemSolver
    {
      public:
        /** \brief \e simplify: shorten each move, and the team path as CompositeRRTConnectSolver does
            (ArcSettings::shortenPatches). */
        explicit SequentialRRTConnectSolver(bool simplify = false);

        std::string getName() const override { return "sequential-rrtc"; }

        bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                   Patch &patch) const override;

        /** \brief The search between calls: its moves (trees included), the round and the sets found dead in it. */
        std::unique_ptr<Memory> makeMemory() const override;

        /** \brief solve(), going on with the moves, round and order of the last call with \e memory (the team space
            and seed of its first call). */
        bool resume(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                    const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, Patch &patch,
                    Memory *memory) const override;

        /** \brief Largest team this solver plans for: the search keeps one bit per robot. */
        static constexpr std::size_t MAX_TEAM = 16;
        /** \brief Iterations of a single move in the first round. */
        static constexpr unsigned int FIRST_MOVE_CAP = 256;

      private:
        bool simplify_;
    };
}  // namespace ompl_parc

#endif
