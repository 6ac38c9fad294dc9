#ifndef OMPL_PARC_PLAN_SMOOTHER_
#define OMPL_PARC_PLAN_SMOOTHER_

#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/arc/SubproblemSolver.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/quality/PlanObjective.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace ompl_parc
{
    /** \brief What one PlanSmoother::smooth() did. */
    struct SmoothingReport
    {
        std::size_t makespanBefore{0}, makespanAfter{0};
        std::size_t sumOfCostsBefore{0}, sumOfCostsAfter{0};
        /** \brief Shortcuts tried, and accepted: single-robot ones, composite ones (a robot and the robot that
            blocked its single shortcut), straightenings (a detour replaced by a straight motion and a wait). */
        std::size_t attempts{0}, shortcuts{0}, compositeShortcuts{0}, straightenings{0};
        /** \brief Replans tried and kept (PlanSmoother::setReplanner()). */
        std::size_t replans{0}, replansKept{0};
        /** \brief Whether the whole team was replanned (PlanSmoother::setTeamReplanTime()), and whether it was kept. */
        bool teamReplanned{false}, teamReplanKept{false};
        /** \brief Whether the team solver (PlanSmoother::setTeamSolver()) solved the whole team, and whether its plan
            was kept. */
        bool teamSolveTried{false}, teamSolved{false}, teamSolveKept{false};
        /** \brief Seconds the team solver took. */
        double teamSolveSeconds{0.};
        /** \brief Whether the team replan ended (solved, or failed in every order it tries) rather than being cut by
            its time: with a memory (PlanSmoother::setTeamReplanMemory()) a cut one goes on at the next smooth(). */
        bool teamReplanDone{false};
        /** \brief Changes kept, of every kind. */
        std::size_t kept() const
        {
            return shortcuts + compositeShortcuts + straightenings + replansKept + (teamReplanKept ? 1 : 0) +
                   (teamSolveKept ? 1 : 0);
        }
        double seconds{0.};
    };

    /** \brief Time-aware shortcutting of a conflict-free team plan: a post-processing step for any of our
        planners, which makes the plan shorter in time without ever making it invalid.

        A shortcut replaces a robot's motion over timesteps [t1, t2] by the straight motion from its state at t1 to
        its state at t2, at full speed, and moves the rest of its path earlier by the time saved (its goal hold
        starts earlier). It is kept only if the new path is valid on its own (the robot's motion validator on the
        straight motion: the same samples as planning) and touches no other robot at any timestep from t1 on,
        every other robot following its own timed path and holding its goal after arrival: the ConflictDetector's
        scan, the same per-timestep check that declared the plan conflict-free. So every plan it returns is
        conflict-free exactly as its input was, whatever the shortcuts.

        When a robot's shortcut is blocked by another robot, the pair is shortcut together over the same window
        (both straight, the later one's time saved by both): where two robots wait for each other in turn, neither
        can gain alone. When moving the rest earlier is what conflicts, the straight motion is kept with a wait at
        its end instead, if it shortens the robot's path (a detour becomes a straight move and a wait, and a later
        shortcut can remove the wait).

        Windows are drawn from a seeded generator: half the attempts on a robot that arrives last (the makespan),
        the others on any robot slower than its straight-line bound (PlanQuality); window lengths log-uniform
        between 2 timesteps and the robot's arrival, so both local detours and long waits are tried; a quarter of
        the windows end at the robot's arrival. It stops when the termination condition fires, when every robot
        meets its bound, or after getStallLimit() attempts in a row without gain. */
    class PlanSmoother
    {
      public:
        /** \brief A smoother for plans of the team of \e si, drawing its windows from \e seed. */
        PlanSmoother(MultiRobotSpaceInformationPtr si, std::uint_fast32_t seed);

        /** \brief Smooth \e plan (conflict-free, every robot with a path; throws ompl::Exception naming the first
            conflict otherwise) in place until \e ptc fires or no attempt gains any more. */
        SmoothingReport smooth(MultiRobotPlan &plan, const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief Also replan, after every REPLAN_PERIOD attempts in a row without gain, a robot's path from a
            timestep to its goal with \e solver (a time-aware SubproblemSolver: prioritised ST-RRT) among the other
            robots' timed paths, kept if it arrives earlier and is conflict-free: shortcuts only straighten what is
            there, a replan can take another way or another order through a crossing. Null: shortcuts only. */
        void setReplanner(SubproblemSolverPtr solver) { replanner_ = std::move(solver); }

        /** \brief First spend up to \e seconds replanning the whole team with the replanner, robot after robot
            among those planned before (prioritised planning from the plan's starts to its goals), and keep that
            plan if it is better by the objective (setObjective()) and conflict-free. A
            repair's detours and waits are not local: where a robot waited for a long chain of repairs, shortcuts
            and one-robot replans among the others' long paths cannot undo them, a fresh order can. 0 (the
            default): no team replan. */
        void setTeamReplanTime(double seconds) { teamReplanTime_ = seconds; }

        /** \brief Before the team replan, solve the whole team from the plan's starts to its goals with \e solver
            (the planners' WholeTeamSolver: for discs the whole team on one lattice, in milliseconds where prioritised
            planning needs seconds among dense teams; for arms one-arm moves overlapped in time), under half the team
            replan's time (setTeamReplanTime()); keep its plan as a team replan's, if better by the objective and
            conflict-free. The team replan then has to beat it. A repair's patch holds the robots of its window
            together for as long as the slowest needs; a plan made for the whole team at once has no such chain of
            waits. Not tried where the solver does not apply to the team (SubproblemSolver::appliesTo()). Null (the
            default): none. */
        void setTeamSolver(SubproblemSolverPtr solver) { teamSolver_ = std::move(solver); }

        /** \brief Let the team replan go on from where the last smooth() with \e memory (the replanner's
            SubproblemSolver::makeMemory(), kept to one thread and one team) left it when its time ran out: repeated
            short smoothings (PlanImprover's rounds) add up to one long team replan. Null (the default): each
            smooth() starts it afresh. */
        void setTeamReplanMemory(SubproblemSolver::Memory *memory) { teamReplanMemory_ = memory; }

        /** \brief Which plan a team replan must beat (objectiveKey()): by makespan (the default, also for FIRST), or by
            sum of costs. Shortcuts and one-robot replans make no robot arrive later, so they serve both. */
        void setObjective(PlanObjective objective) { objective_ = objective; }

        /** \brief Seeds the team solver tries (setTeamSolver()), within its time, the best plan kept. */
        static constexpr unsigned int TEAM_SOLVE_TRIES = 4;

        /** \brief Attempts in a row without gain before a replan (with a replanner). */
        static constexpr std::size_t REPLAN_PERIOD = 16;
        /** \brief The replanner's iteration cap per replan. */
        static constexpr unsigned int REPLAN_SAMPLES = 1000;
        /** \brief The team replan's iteration cap per robot (where the lattice has no path and ST-RRT plans it): as in
            PP-ST-RRT's rounds, a robot the order walls in then fails soon and is promoted to the front of another
            order, instead of holding the whole budget in one uncapped search. */
        static constexpr unsigned int TEAM_REPLAN_SAMPLES = 5000;

        /** \brief Attempts in a row without gain after which smooth() stops: 200 per robot, at least 2000. */
        std::size_t getStallLimit() const;

      private:
        /** \brief Try the straight motion of every robot of \e team from its state at t1 to its state at t2, the
            slowest at full speed, then \e wait timesteps at t2's states, the rest of each path moved earlier by the
            time saved; keep it if it saves time (or, for one robot and no time saved, shortens its path by a
            timestep's motion at least) and is valid and conflict-free. On a conflict, \e blocker (if given)
            receives the first robot outside the team hit. */
        bool tryShortcut(MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::size_t t1, std::size_t t2,
                         std::size_t wait, std::size_t *blocker);

        /** \brief Replan \e robot from timestep \e t1 to its goal (see setReplanner()); keep it if it arrives earlier
            and is conflict-free. */
        bool tryReplan(MultiRobotPlan &plan, std::size_t robot, std::size_t t1,
                       const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief Replan the whole team (setTeamReplanTime()) under \e ptc; keep it if better and conflict-free.
            \e done: whether the replan ended otherwise than by \e ptc (SmoothingReport::teamReplanDone). */
        bool tryTeamReplan(MultiRobotPlan &plan, const ompl::base::PlannerTerminationCondition &ptc, bool &done);

        /** \brief Solve the whole team with the team solver (setTeamSolver()) under \e ptc; \e solved receives
            whether it found a plan. Kept if better and conflict-free. */
        bool tryTeamSolve(MultiRobotPlan &plan, const ompl::base::PlannerTerminationCondition &ptc, bool &solved);

        /** \brief The whole team as one subproblem: every robot from the plan's start to its goal. */
        static Subproblem wholeTeam(const MultiRobotPlan &plan);

        /** \brief Keep \e paths (one per robot) as the plan if they are better by the objective (then by the other
            measure) and conflict-free. */
        bool keepIfBetter(MultiRobotPlan &plan, std::vector<TimedPath> paths);

        /** \brief Keep \e changed (new paths of the robots of \e team, the plan unchanged before \e t1) if it is
            conflict-free, else put the old paths back; on a conflict, \e blocker (if given) receives the first
            robot outside the team hit. */
        bool keepIfClear(MultiRobotPlan &plan, const std::vector<std::size_t> &team, std::vector<TimedPath> changed,
                         std::size_t t1, std::size_t *blocker);

        /** \brief True if \e robot's straight motion from \e from to \e to is valid (bounds, self, environment). */
        bool motionValid(std::size_t robot, const double *from, const double *to);

        /** \brief Length of \e robot's path over [t1, t2] in its space's distance. */
        double pathLength(const MultiRobotPlan &plan, std::size_t robot, std::size_t t1, std::size_t t2);

        /** \brief Distance between two configurations of \e robot in its space. */
        double distance(std::size_t robot, const double *a, const double *b) const;

        /** \brief A robot worth shortcutting (see the class description), or none if all meet their bounds. */
        std::optional<std::size_t> pickRobot(const MultiRobotPlan &plan);

        MultiRobotSpaceInformationPtr si_;
        SubproblemSolverPtr replanner_, teamSolver_;
        double teamReplanTime_{0.};
        PlanObjective objective_{PlanObjective::MAKESPAN};
        SubproblemSolver::Memory *teamReplanMemory_{nullptr};
        /** \brief The scans of the plan being smoothed (one per smooth(): its frontiers are that plan's). */
        std::optional<ConflictDetector> detector_;
        ompl::RNG rng_;
        /** \brief Per robot, its straight-line bound in the plan being smoothed. */
        std::vector<std::size_t> bound_;
        /** \brief Per robot, a one-robot SpaceInformation for its motion checks (made when first needed). */
        std::vector<MultiRobotSpaceInformationPtr> alone_;
        /** \brief Scratch: per team member, its states at t1 and t2. */
        std::vector<std::vector<double>> from_, to_;
    };
}  // namespace ompl_parc

#endif
