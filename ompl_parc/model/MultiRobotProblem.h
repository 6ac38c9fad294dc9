#ifndef OMPL_PARC_MULTI_ROBOT_PROBLEM_
#define OMPL_PARC_MULTI_ROBOT_PROBLEM_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/base/ProblemDefinition.h>

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief A robot team with one start and one goal configuration per robot.

        The scenarios build these; createProblemDefinition() turns one into an ordinary OMPL
        ProblemDefinition (composite start and goal states) for any planner. */
    class MultiRobotProblem
    {
      public:
        /** \brief Throws ompl::Exception if the numbers of starts/goals or their sizes do not match the team. */
        MultiRobotProblem(MultiRobotSpaceInformationPtr si, std::vector<std::vector<double>> starts,
                          std::vector<std::vector<double>> goals, std::string name = "");

        const MultiRobotSpaceInformationPtr &getSpaceInformation() const { return si_; }
        std::size_t getRobotCount() const { return starts_.size(); }
        const std::vector<double> &getStart(std::size_t i) const { return starts_.at(i); }
        const std::vector<double> &getGoal(std::size_t i) const { return goals_.at(i); }
        const std::string &getName() const { return name_; }

        /** \brief The same team, starts, goals and name over a new SpaceInformation with \e resolution timesteps
            per unit. */
        MultiRobotProblem withResolution(double resolution) const;

        /** \brief Empty if every start and goal is valid alone and the starts (and the goals) are pairwise
            collision-free; otherwise the first problem found, e.g. "goal of robot 'r3' is out of bounds". */
        std::string checkEndpoints() const;

        /** \brief A ProblemDefinition over the composite space with the team's start and goal states. */
        ompl::base::ProblemDefinitionPtr createProblemDefinition() const;

      private:
        std::string checkConfigurations(const std::vector<std::vector<double>> &configs, const std::string &what) const;

        MultiRobotSpaceInformationPtr si_;
        std::vector<std::vector<double>> starts_, goals_;
        std::string name_;
    };
}  // namespace ompl_parc

#endif
