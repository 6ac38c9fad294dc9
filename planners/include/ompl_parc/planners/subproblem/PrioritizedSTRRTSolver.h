#ifndef OMPL_PARC_PRIORITIZED_STRRT_SOLVER_
#define OMPL_PARC_PRIORITIZED_STRRT_SOLVER_

#include "ompl_parc/arc/SubproblemSolver.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Settings of PP-ST-RRT's ST-RRT; the defaults are the P-ARC authors' (range = vMax = 1 in space-time,
        batches of 4096, time bound factors 2 and 2, no rewiring, first solution returned). */
    struct PrioritizedSTRRTSettings
    {
        /** \brief Longest tree edge in the space-time distance. */
        double range{1.};
        /** \brief Priority order: the team's order, or shuffled with the solve's seed. */
        bool shuffle{false};
        /** \brief Plan around the subproblem's context too (the other robots near the window, as moving
            obstacles), so that a patch seldom collides with robots outside the team. */
        bool avoidOthers{true};
        /** \brief When a robot cannot be planned (its ST-RRT runs out of samples, or a robot before it ends on its
            goal for good), plan the team again with that robot first: the classic remedy for an order in which a robot
           is walled in by the paths of those before it (rooms, 24 robots: most failures were one robot late in the
           order, which then held the whole budget). At most as many orders as the team has robots are tried per call.
         */
        bool promote{true};
        /** \brief Refine the priority order from each robot's path planned alone (BlockingOrder): a robot whose
            start lies on another's way goes before it, one whose goal lies on another's way after it. */
        bool unblock{true};
        /** \brief Plan each translating robot (LatticeSearch::applies) by space-time A* on a lattice first, and by
            ST-RRT only if the lattice has no path: the lattice finds the waits and timings of a robot planned
            late among many (a door, a crossing) that sampling seldom draws. The orders a solve tries alternate
            between this and ST-RRT alone (the first uses the lattice): a lattice path that waits where the others
            let the robot get furthest can wall in a later robot that ST-RRT's path would not. */
        bool lattice{true};
        /** \brief The lattice step; 0: LatticeSearch::defaultStep (the robot's bounding radius). */
        double latticeStep{0.};
        /** \brief "off", "radius" or "knearest". */
        std::string rewiring{"off"};
        unsigned int batchSize{4096};
        double initialTimeBoundFactor{2.};
        double timeBoundFactorIncrease{2.};
    };

    /** \brief Decoupled subproblem solver (PP-ST-RRT): the team's robots are planned one after another in
        priority order, each with ST-RRT (our STRRTstar, for its minimum goal time, which OMPL's lacks) in its
        own (local-bounded) space x time, the robots planned before it and the subproblem's context (robots
        outside the team near the window, when avoidOthers is set) being moving obstacles.

        A robot's goal counts only from the earliest timestep from which it can stay there forever without
        being hit by an earlier robot (the goal hold); if an earlier robot ends on the goal for good, the
        robot is promoted at once (settings.promote; without it the solve fails). Each space-time path is laid on the
       timestep grid (the checked interpolations at integer timesteps, arrival rounded up) and all paths are padded with
       their goals to the same length. Cheap when the team's robots can mostly yield to each other; incomplete, as
       prioritised planning is (the promotion of a robot that failed, settings.promote, recovers from many bad orders).
     */
    class PrioritizedSTRRTSolver : public SubproblemSolver
    {
      public:
        /** \brief Throws ompl::Exception for settings STRRTstar rejects. */
        explicit PrioritizedSTRRTSolver(PrioritizedSTRRTSettings settings = PrioritizedSTRRTSettings());

        /** \brief The solver PlanSmoother replans with (one robot's tail, or the whole team): PP-ST-RRT's defaults,
            the lattice for translating robots (discs) first; with \e shuffle the priority order is shuffled with
            each call's seed (PlanImprover's workers and rounds try different orders). Its axis-aligned paths are seldom
           shorter than a straight piece, but among the waits and detours a repair leaves they often arrive much
           earlier, and the shortcuts that follow straighten them. */
        static std::shared_ptr<PrioritizedSTRRTSolver> makeReplanner(bool shuffle = false);

        std::string getName() const override { return "pp-st-rrt"; }
        bool usesContext() const override { return settings_.avoidOthers; }
        const PrioritizedSTRRTSettings &getSettings() const { return settings_; }

        bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                   Patch &patch) const override;

        /** \brief solve(), saying on failure in \e retry whether another call (more samples, other draws) could
            succeed: not after the stop, nor when nothing would change (a start not clear at timestep 0, a path too
            long to plan around). */
        bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, Patch &patch,
                   bool &retry) const;

        /** \brief A memory of where a solve stopped: the order it was trying (after unblocking and promotions),
            that order's attempt and the robots of it already planned. */
        std::unique_ptr<Memory> makeMemory() const override;

        /** \brief solve(), going on with the order, attempt and planned robots where the last call with \e memory
            was cut by its termination condition (a robot being planned then is planned again), with the first
            call's seed; the robots planned alone for the unblocking order are kept too. Where the lattice plans every
            robot, calls cut one after the other find the patch one uncut call would; an ST-RRT run draws its space
            samples from the call's own local space, so a resumed call's ST-RRT runs draw afresh. A call that ends
            otherwise (solved, or every order of its attempts failed) leaves \e memory fresh: the next call starts
            over with its own seed. */
        bool resume(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                    const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, Patch &patch,
                    Memory *memory) const override;

        /** \brief The base order (positions in the team) of a solve with \e seed for a team of \e size: the given
            or shuffled one, before settings.unblock refines it and promotion changes it. */
        std::vector<std::size_t> priorityOrder(std::size_t size, std::uint_fast32_t seed) const;

      private:
        using Tracks = std::vector<std::shared_ptr<const BodyTrack>>;
        class Progress;

        /** \brief solve() and resume(): from \e progress, leaving in it where this call stopped. */
        bool solveFrom(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                       const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, Patch &patch,
                       bool &retry, Progress &progress) const;

        /** \brief \e order refined by BlockingOrder from each robot of \e local's team planned alone (the path of
            a robot that cannot be planned alone constrains nobody), planned into \e progress from the first robot
            not yet planned there; none if \e ptc fired first. */
        std::optional<std::vector<std::size_t>> unblockedOrder(const MultiRobotSpaceInformation &si,
                                                               const Subproblem &subproblem,
                                                               const MultiRobotSpaceInformation &local,
                                                               const std::vector<std::size_t> &order,
                                                               const ompl::base::PlannerTerminationCondition &ptc,
                                                               Progress &progress) const;

        /** \brief Plans the robots of \e local's team in \e progress's order into its paths, from its first robot not
            yet planned on (robots planned earlier and \e context as moving obstacles): the team position of the robot
            that could not be planned, or none if all were; \e hopeless is set when planning again in another order
            cannot help (the stop, a start that is not clear at timestep 0, or a path too long to plan around). */
        std::optional<std::size_t> planInOrder(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                               const MultiRobotSpaceInformation &local, const Tracks &context,
                                               const ompl::base::PlannerTerminationCondition &ptc,
                                               std::uint_fast32_t seed, bool lattice, Progress &progress,
                                               bool &hopeless) const;

        /** \brief One robot's timestep path from \e start to \e goal among \e obstacles, arriving no earlier
            than timestep \e hold, in \e space: on the lattice first if \e lattice is set and the robot translates
            (until \e ptc or its own expansion cap), else (or if the lattice has no path) by ST-RRT, capped by
            \e subproblem's sample cap; empty on failure. */
        TimedPath planRobot(const ompl::base::StateSpacePtr &space, const DynamicObstaclesPtr &obstacles,
                            const std::vector<double> &start, const std::vector<double> &goal, std::size_t hold,
                            const Subproblem &subproblem, const ompl::base::PlannerTerminationCondition &ptc,
                            std::uint_fast32_t seed, bool lattice) const;

        PrioritizedSTRRTSettings settings_;
    };
}  // namespace ompl_parc

#endif
