#ifndef OMPL_PARC_MULTI_ROBOT_PLAN_
#define OMPL_PARC_MULTI_ROBOT_PLAN_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/geometric/PathGeometric.h>

#include <vector>

namespace ompl_parc
{
    /** \brief Time-parameterised paths of a robot team: robot i's configuration at every integer timestep.

        Timestep t of robot i is stored flat (getDimension(i) doubles each). A robot's last state is its
        arrival; from then on it holds that state, so getConfig(i, t) is defined for every t >= 0. One
        timestep moves a robot at most 1/resolution in its space's distance (vmax = 1). */
    class MultiRobotPlan
    {
      public:
        MultiRobotPlan() = default;
        /** \brief An empty plan (no states yet) for a team with these configuration sizes. */
        MultiRobotPlan(std::vector<unsigned int> dimensions, double resolution);
        /** \brief An empty plan for the team of \e si, at its resolution. */
        explicit MultiRobotPlan(const MultiRobotSpaceInformation &si);

        std::size_t getRobotCount() const { return paths_.size(); }
        unsigned int getDimension(std::size_t robot) const { return dimensions_.at(robot); }
        double getResolution() const { return resolution_; }

        /** \brief Number of timesteps stored for \e robot (its arrival + 1). */
        std::size_t getStateCount(std::size_t robot) const { return paths_.at(robot).size() / dimensions_.at(robot); }
        /** \brief Timestep at which \e robot reaches its last state. Requires at least one state. */
        std::size_t getArrival(std::size_t robot) const;

        /** \brief Robot \e robot's configuration at timestep \e t (its last state once arrived). */
        const double *getConfig(std::size_t robot, std::size_t t) const;

        const std::vector<double> &getRobotPath(std::size_t robot) const { return paths_.at(robot); }
        /** \brief Replace a robot's path by \e flat (getDimension(robot) values per timestep). */
        void setRobotPath(std::size_t robot, std::vector<double> flat);
        void appendConfig(std::size_t robot, const double *q);

        /** \brief Replace robot \e robot's states at timesteps [from, to] by \e segment (a robot that
            arrived before \e from holds its goal until then); the states after \e to follow the segment,
            shifted in time by the difference in length. The arrival is then recomputed (trailing copies of
            the final state are dropped). */
        void splice(std::size_t robot, std::size_t from, std::size_t to, const std::vector<double> &segment);

        /** \brief Largest arrival timestep over the team. */
        std::size_t getMakespan() const;
        /** \brief Sum of the robots' arrival timesteps. */
        std::size_t getSumOfCosts() const;

        /** \brief Up to \e maxCount timesteps spread evenly (rounded) over 0 .. makespan, both ends included
            (at least 2, so a plan that never moves still gives a start and an end): the frames pictures
            draw of a long plan. */
        std::vector<std::size_t> sampleTimesteps(std::size_t maxCount) const;

        /** \brief One composite state per timestep 0..makespan (returned by pointer: such paths are large and
            OMPL's PathGeometric copies its states, so it is built once, in place). */
        ompl::geometric::PathGeometricPtr toPathGeometric(const MultiRobotSpaceInformationPtr &si) const;

        /** \brief Allocate the composite states of timesteps [from, to) into \e out[0 .. to - from): the
            piece of toPathGeometric() that several threads can do at once on disjoint ranges. */
        void allocateStates(const MultiRobotSpaceInformation &si, std::size_t from, std::size_t to,
                            ompl::base::State **out) const;

        /** \brief Lay a composite path on the timestep grid: each segment takes ceil(length x resolution)
            timesteps with all robots moving synchronised; trailing states at a robot's goal are dropped so
            its arrival is when it stops moving. */
        static MultiRobotPlan fromPathGeometric(const MultiRobotSpaceInformation &si,
                                                const ompl::geometric::PathGeometric &path);

        /** \brief Lay a composite path of the team of \e si on the grid without trimming: every robot gets
            the same number of timesteps (a synchronised patch for a subproblem). */
        static std::vector<std::vector<double>> layTeamPath(const MultiRobotSpaceInformation &si,
                                                            const ompl::geometric::PathGeometric &path);

        /** \brief Lay a single-robot path (over \e robot's own space) on the grid, as above. */
        static std::vector<double> discretize(const Robot &robot, const ompl::geometric::PathGeometric &path,
                                              double resolution);

      private:
        /** \brief Drop trailing copies of the robot's final state: it arrives when it stops for good. */
        void trimArrival(std::size_t robot);

        std::vector<unsigned int> dimensions_;
        std::vector<std::vector<double>> paths_;
        double resolution_{128.};
    };
}  // namespace ompl_parc

#endif
