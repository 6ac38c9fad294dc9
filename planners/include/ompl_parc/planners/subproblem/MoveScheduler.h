#ifndef OMPL_PARC_MOVE_SCHEDULER_
#define OMPL_PARC_MOVE_SCHEDULER_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief The moves of a team planned one robot at a time (SequentialRRTConnectSolver) made to overlap in time:
        each move starts as early as the moves before it allow, not when the last of them ends.

        Why: a team path with one robot moving at a time lasts as long as all moves together, and a patch that long
        delays every robot of the team and everything after it; where the team's robots get in each other's way for
        a moment only (arms side by side that cross one another's reach once), most moves could run at once.

        Each move keeps its path and runs at full speed; only its start time changes. The moves are placed in the
        order they were planned: a move starts at the first of a few candidate timesteps (0, the starts and ends of
        the moves placed, a sixteenth of the way between) at which, at every timestep, its robot's body touches none
        of the robots placed before it, each holding its start before its move and its goal after. The end of the
        last move placed is always such a timestep (the order's own premise: the earlier robots at their goals, the
        later ones at their starts). The team path then has a state wherever a robot's move starts or turns, and is
        kept only if the team's own motion validator accepts every segment of it: what a patch is must not depend
        on this pass. */
    class MoveScheduler
    {
      public:
        /** \brief One robot's move: the team position of the robot and its configurations from start to goal. */
        using Move = std::pair<std::size_t, const std::vector<std::vector<double>> *>;

        /** \brief A scheduler for moves of robots of \e team. */
        explicit MoveScheduler(std::shared_ptr<MultiRobotSpaceInformation> team);

        /** \brief \e moves (in the order planned, every team robot once, the team standing at \e start before them)
            overlapped as the class describes, into \e path (a path of the team's space, replaced); false, with
            \e path untouched, where they cannot start earlier, where the team's motion validator refuses the result,
            or once \e ptc fires. */
        bool schedule(
            const std::vector<Move> &moves, const ompl::base::State *start, ompl::geometric::PathGeometric &path,
            const ompl::base::PlannerTerminationCondition &ptc = ompl::base::plannerNonTerminatingCondition());

        /** \brief Timesteps the last schedule() lasts: as long as all moves one after another where it failed. */
        std::size_t getDuration() const { return duration_; }

        /** \brief The most robot bodies (one per timestep of each move) a schedule keeps; moves that last longer
            together are left one after another. */
        static constexpr std::size_t MAX_BODIES = std::size_t(1) << 18;

      private:
        /** \brief A placed move: its robot's configurations and bodies at each of its timesteps. */
        struct Timeline;

        /** \brief True if the robots of \e a and \e b, each moving from its begin, never touch. */
        static bool apart(const Timeline &a, const Timeline &b);

        std::shared_ptr<MultiRobotSpaceInformation> team_;
        std::size_t duration_{0};
    };
}  // namespace ompl_parc

#endif
