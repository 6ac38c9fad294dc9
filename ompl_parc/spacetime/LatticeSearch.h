#ifndef OMPL_PARC_LATTICE_SEARCH_
#define OMPL_PARC_LATTICE_SEARCH_

#include "ompl_parc/model/TimedPath.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief Space-time A* for one translating robot among moving obstacles, on a lattice of configurations
        around its start: each step moves one lattice step along one axis, or waits, in the same number of
        timesteps; the goal is reached by one straight move from a lattice point near it.

        Prioritised planning asks a robot planned late to thread between the paths of all robots before it: wait
        at a door until a dozen others have passed, then go. A sampling planner (ST-RRT) has to draw such a
        timing; this search enumerates them. Its heuristic is the time to the goal among the static obstacles
        (a Dijkstra over the lattice; the lattice distance on lattices too large for it), weighted (2 by
        default), so the arrival is not the earliest but the search is short. It is complete on its lattice: once
        every obstacle has stopped moving and the goal can be held, a lattice point is one state whatever the
        time, so the search ends. Every motion is checked as the plan lays it (DynamicObstacles::isMotionClear),
        so the path is clear at every timestep. Applies to robots whose body's box follows from a box of
        configurations (Robot::expandBoxOver: translating discs), where a motion's check skips far obstacles
        blockwise; for others it would be as slow as checking every timestep against every obstacle. Memory:
        about 100 bytes per state generated (up to 2d + 1 per expansion), some 100 MB at the default cap in the
        worst case. */
    class LatticeSearch
    {
      public:
        /** \brief Search among \e obstacles (for their robot), over configurations in [\e low, \e high], with
            lattice step \e step (> 0). Throws ompl::Exception for a bad step, bounds of the wrong size, or a robot
            with more than MAX_DIMENSION degrees of freedom. */
        LatticeSearch(DynamicObstaclesPtr obstacles, std::vector<double> low, std::vector<double> high, double step);

        /** \brief Whether the search suits \e robot: a translating robot (Robot::expandBoxOver) of at most
            MAX_DIMENSION degrees of freedom. */
        static bool applies(const Robot &robot);

        /** \brief The default lattice step for \e robot at \e q: the radius of its body's bounding sphere, so that
            a passage one body and one step wide always has a lattice line through it. */
        static double defaultStep(const Robot &robot, const std::vector<double> &q);

        /** \brief Most states expanded per plan() (default 200000): a bound on time and memory where the lattice
            is large and the obstacles keep moving for long. */
        void setMaxExpansions(std::size_t expansions) { maxExpansions_ = expansions; }
        std::size_t getMaxExpansions() const { return maxExpansions_; }

        /** \brief The weight of the heuristic, in [1, MAX_WEIGHT] (default 2; throws outside). Above 1 the search goes
            as far towards the goal as the others let it and waits there, instead of trying every place and time
            to wait at on the way: a robot that must let a dozen others pass a door costs a few thousand
            expansions, not a hundred thousand. */
        void setHeuristicWeight(double weight);
        double getHeuristicWeight() const { return weight_; }

        /** \brief A timed path from \e start (clear at timestep 0) to \e goal, arriving no earlier than timestep
            \e hold (from which the goal can be held: DynamicObstacles::earliestHold()); empty if the lattice has
            none, after the expansion cap, once \e ptc fires, if one move would take more than MAX_MOVE timesteps,
            or if the bounds span more than MAX_STEPS lattice steps. */
        TimedPath plan(const std::vector<double> &start, const std::vector<double> &goal, std::size_t hold,
                       const ompl::base::PlannerTerminationCondition &ptc) const;

        /** \brief States expanded by the last plan(). */
        std::size_t getExpansions() const { return expansions_; }

        static constexpr unsigned int MAX_DIMENSION = 3;
        static constexpr double MAX_WEIGHT = 1000.;
        /** \brief The most timesteps of one lattice move; plan() finds no path at a resolution that needs more
            (at resolution 128 a move of one unit takes 128). */
        static constexpr std::size_t MAX_MOVE = 4096;
        /** \brief The most lattice steps across the bounds, per axis; plan() finds no path in wider ones. */
        static constexpr double MAX_STEPS = 1e8;

      private:
        DynamicObstaclesPtr obstacles_;
        std::vector<double> low_, high_;
        double step_;
        std::size_t maxExpansions_{200000};
        double weight_{2.};
        mutable std::size_t expansions_{0};
    };
}  // namespace ompl_parc

#endif
