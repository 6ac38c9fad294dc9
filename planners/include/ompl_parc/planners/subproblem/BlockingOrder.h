#ifndef OMPL_PARC_BLOCKING_ORDER_
#define OMPL_PARC_BLOCKING_ORDER_

#include "ompl_parc/model/TimedPath.h"
#include "ompl_parc/robots/Robot.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief A priority order for prioritised planning in which robots get out of each other's way, from each
        robot's path planned alone.

        Prioritised planning fails when a robot planned early parks on the only way of a robot planned later, or
        sweeps through the start of a later robot before that one can leave. Both can be seen before planning:
        robot a goes \e before robot b when a's start lies on b's path alone (a leaves first), and \e after b when
        a's goal lies on b's path alone (a parks once b has passed). The order is a topological order of these
        constraints; ties, and the cycles that dense teams make, go by a base order (the given or shuffled one).

        The paths are walked once, in blocks of BLOCK timesteps whose bodies' box is tested against every start
        and goal body before any pair test: no bodies are kept beyond a block, and a path far from a robot costs
        one box test per block. */
    class BlockingOrder
    {
      public:
        /** \brief Robot team[k] planned alone along alone[k] (empty: not planned; its path then constrains nobody)
            from starts[k] to goals[k]. Once \e ptc fires the remaining paths are not looked at (the order is then
            built from fewer constraints). Throws ompl::Exception when the sizes differ. */
        BlockingOrder(
            const std::vector<RobotPtr> &team, const std::vector<TimedPath> &alone,
            const std::vector<std::vector<double>> &starts, const std::vector<std::vector<double>> &goals,
            const ompl::base::PlannerTerminationCondition &ptc = ompl::base::plannerNonTerminatingCondition());

        /** \brief \e base (a permutation of the team's positions) reordered by the constraints: among the robots
            that no unplaced robot must precede, the first in \e base; in a cycle, the robot with the fewest
            unplaced predecessors (then the first in \e base). Throws ompl::Exception if \e base is no
            permutation. */
        std::vector<std::size_t> order(const std::vector<std::size_t> &base) const;

        /** \brief Whether robot \e a must go before robot \e b. */
        bool before(std::size_t a, std::size_t b) const { return before_[a * size_ + b] != 0; }

        /** \brief Timesteps of a path tested together against a box. */
        static constexpr std::size_t BLOCK = 64;

      private:
        std::size_t size_;
        /** \brief before_[a * size_ + b]: robot a must go before robot b. */
        std::vector<char> before_;
    };
}  // namespace ompl_parc

#endif
