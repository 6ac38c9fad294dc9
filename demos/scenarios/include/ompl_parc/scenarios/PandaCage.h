#ifndef OMPL_PARC_SCENARIOS_PANDA_CAGE_
#define OMPL_PARC_SCENARIOS_PANDA_CAGE_

#include "ompl_parc/model/MultiRobotProblem.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace ompl_parc
{
    namespace scenarios
    {
        /** \brief Number of tasks (start/goal sets) per team size of Panda Cage. */
        constexpr std::size_t PANDA_CAGE_TASKS = 5;

        /** \brief The team sizes of Panda Cage: 2, 4, 8 and 16. */
        const std::vector<std::size_t> &pandaCageTeamSizes();

        /** \brief The inside of the cage (the box whose edges are its bars): every end effector is in it at
            start and goal. */
        Eigen::AlignedBox3d pandaCageInterior();

        /** \brief Task \e task (0 .. PANDA_CAGE_TASKS - 1) of Panda Cage with \e robots (2, 4, 8 or 16) Pandas,
            as stored in demos/scenarios/panda_cage/panda_cage_<robots>_<task>.json (compiled into the library,
            so every run plans the same tasks); \e resolution replaces the file's timesteps per unit. Throws
            ompl::Exception for other sizes or tasks. */
        MultiRobotProblem createPandaCage(std::size_t robots, std::size_t task = 0, double resolution = 128.);

        /** \brief The stored scenario file of task \e task for \e robots Pandas (its JSON text); throws
            ompl::Exception if there is none. */
        const std::string &pandaCageTaskJson(std::size_t robots, std::size_t task);

        /** \brief Generates task \e task for \e robots Pandas afresh, as the stored ones were: the authors'
            layout (floor and ceiling Pandas beside a 1 x 2 x 1 m cage of 12 bars) and, from a seed fixed by
            \e robots and \e task, end effector targets drawn inside the cage within reach of each base and
            reached by position-only IK; every start and goal is valid alone and against the robots placed
            before it (greedy, starting the team over when a robot finds no room); a task the robots might solve
            without coordinating (countConflictingPairs() is 0 for one of ARC seeds 1, 2, 3) is drawn again. The
            random draws use the
            standard library's distributions, whose output differs between implementations: that is why the
            tasks are stored rather than regenerated. Throws ompl::Exception if no team fits or no task needs
           coordination. */
        MultiRobotProblem generatePandaCageTask(std::size_t robots, std::size_t task);

        /** \brief generatePandaCageTask()'s draw from the random seed \e seed, for a problem named \e name (task
            \e task of the stored tasks has seed 1000 * robots + task). */
        MultiRobotProblem generatePandaCageProblem(std::size_t robots, std::uint32_t seed, const std::string &name);
    }  // namespace scenarios
}  // namespace ompl_parc

#endif
