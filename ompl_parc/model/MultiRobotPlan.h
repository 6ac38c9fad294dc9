#ifndef OMPL_PARC_MULTI_ROBOT_PLAN_
#define OMPL_PARC_MULTI_ROBOT_PLAN_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/model/TimedPath.h"

#include <ompl/geometric/PathGeometric.h>

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Time-parameterised paths of a robot team: robot i's configuration at every integer timestep,
        stored as timed waypoints (one TimedPath of straight pieces per robot), never as a dense grid.

        A robot's last timestep is its arrival; from then on it holds that state, so getConfig(i, t) is defined
        for every t >= 0. One timestep moves a robot at most 1/resolution in its space's distance (vmax = 1).
        Paths laid from OMPL paths (fromPathGeometric(), layTeamPath(), discretize()) give, at every timestep,
        bit for bit the state the dense grid of earlier versions held. */
    class MultiRobotPlan
    {
      public:
        /** \brief The latest timestep a plan may have (solution files, the validator; a team whose bounds need
            more to be crossed once is refused): 10^8, room for the largest teams the tools accept (Mobile
            Cross 256's makespan is 1.7 x 10^5 and grows linearly with the team), and a bound on what a crafted
            file can make the validator do (its time grows with the pieces and the timesteps in which robots
            move close to each other or to an obstacle). */
        static constexpr std::size_t MAX_TIMESTEP = 100000000;

        MultiRobotPlan() = default;
        /** \brief An empty plan (no states yet) for a team with these configuration sizes. */
        MultiRobotPlan(std::vector<unsigned int> dimensions, double resolution);
        /** \brief An empty plan for the team of \e si, at its resolution. */
        explicit MultiRobotPlan(const MultiRobotSpaceInformation &si);

        std::size_t getRobotCount() const { return paths_.size(); }
        unsigned int getDimension(std::size_t robot) const { return paths_.at(robot).getDimension(); }
        double getResolution() const { return resolution_; }

        /** \brief Number of timesteps with a state of \e robot's own (its arrival + 1; 0 if it has no path). */
        std::size_t getStateCount(std::size_t robot) const
        {
            return paths_.at(robot).empty() ? 0 : paths_[robot].getArrival() + 1;
        }
        /** \brief Timestep at which \e robot reaches its last state. Requires a path. */
        std::size_t getArrival(std::size_t robot) const { return paths_.at(robot).getArrival(); }

        /** \brief Robot \e robot's configuration at timestep \e t (its last state once arrived) into \e out
            (getDimension(robot) values). A binary search: scans over time use getPath(robot)'s Cursor. */
        void getConfig(std::size_t robot, std::size_t t, double *out) const { paths_[robot].getConfig(t, out); }

        const TimedPath &getPath(std::size_t robot) const { return paths_.at(robot); }
        /** \brief Replace a robot's path (of the robot's dimension). */
        void setPath(std::size_t robot, TimedPath path);

        /** \brief Replace a robot's path by the dense states \e flat (getDimension(robot) values per timestep). */
        void setRobotPath(std::size_t robot, const std::vector<double> &flat);

        /** \brief Empty if this plan is one for the team of \e si (as many robots, its resolution, each robot's
            configuration size, a path for every robot), else the first mismatch, e.g. "plan has 3 robots, problem
            has 2": what the validator and the solution writer refuse. */
        std::string checkTeam(const MultiRobotSpaceInformation &si) const;
        /** \brief Robot \e robot's states at timesteps 0..arrival, flat: for tests and small plans only. */
        std::vector<double> getRobotPath(std::size_t robot) const { return paths_.at(robot).toDense(); }

        /** \brief Replace robot \e robot's states at timesteps [from, to] by \e segment (a robot that arrived
            before \e from holds its goal until then); the states after \e to follow the segment, shifted in
            time by the difference in length. The arrival is then recomputed (trailing copies of the final
            state are dropped). O(pieces), whatever the number of timesteps. */
        void splice(std::size_t robot, std::size_t from, std::size_t to, const TimedPath &segment);

        /** \brief Largest arrival timestep over the team. */
        std::size_t getMakespan() const;
        /** \brief Sum of the robots' arrival timesteps. */
        std::size_t getSumOfCosts() const;
        /** \brief Total number of pieces over the team: what the plan's memory grows with. */
        std::size_t getPieceCount() const;

        /** \brief Up to \e maxCount timesteps spread evenly (rounded) over 0 .. makespan, both ends included
            (at least 2, so a plan that never moves still gives a start and an end): the frames pictures
            draw of a long plan. */
        std::vector<std::size_t> sampleTimesteps(std::size_t maxCount) const;

        /** \brief The union of the robots' breakpoints (TimedPath::appendBreakpoints), sorted, with 0 and the
            makespan: between two consecutive ones every robot moves on a straight line. */
        std::vector<std::size_t> getBreakpoints() const;

        /** \brief One composite state per breakpoint (getBreakpoints()): since OMPL interpolates a compound
            state per component, linearly, the path is the plan's motion (returned by pointer: OMPL's
            PathGeometric copies its states, so it is built once, in place). */
        ompl::geometric::PathGeometricPtr toPathGeometric(const MultiRobotSpaceInformationPtr &si) const;

        /** \brief Write the configurations at timesteps times[from, to) into the composite states
            \e states[0 .. to - from) (allocated, e.g. by CompositeStateSpace::allocStates()): the piece of
            toPathGeometric() that several threads can do at once on disjoint ranges. */
        void fillStates(const MultiRobotSpaceInformation &si, const std::vector<std::size_t> &times, std::size_t from,
                        std::size_t to, ompl::base::State *const *states) const;

        /** \brief Timesteps a straight motion of length \e distance takes at \e resolution (0 for none): how every
            path is laid on the grid. */
        static std::size_t stepsFor(double distance, double resolution);

        /** \brief Lay a composite path on the timestep grid: each segment takes ceil(length x resolution)
            timesteps with all robots moving synchronised; trailing states at a robot's goal are dropped so
            its arrival is when it stops moving. Dense paths (one state per timestep) are accepted too. */
        static MultiRobotPlan fromPathGeometric(const MultiRobotSpaceInformation &si,
                                                const ompl::geometric::PathGeometric &path);

        /** \brief Lay a composite path of the team of \e si on the grid without trimming: every robot gets
            the same number of timesteps (a synchronised patch for a subproblem). */
        static std::vector<TimedPath> layTeamPath(const MultiRobotSpaceInformation &si,
                                                  const ompl::geometric::PathGeometric &path);

        /** \brief Lay a single-robot path (over \e robot's own space) on the grid, as above. */
        static TimedPath discretize(const Robot &robot, const ompl::geometric::PathGeometric &path, double resolution);

      private:
        std::vector<TimedPath> paths_;
        double resolution_{128.};
    };
}  // namespace ompl_parc

#endif
