#ifndef OMPL_PARC_SCENARIOS_PANDA_CAGE_
#define OMPL_PARC_SCENARIOS_PANDA_CAGE_

#include "ompl_parc/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    namespace scenarios
    {
        /** \brief The Franka Panda model of demos/resources/panda.urdf (compiled into the library). */
        const std::string &pandaUrdf();

        /** \brief Number of tasks (start/goal sets) per team size of Panda Cage. */
        constexpr std::size_t PANDA_CAGE_TASKS = 5;

        /** \brief \e robots (2, 4 or 8; 16 is not supported yet: the greedy task generator finds no room) Pandas on the
           floor and ceiling around a cage of thin vertical bars; task \e task (0 .. PANDA_CAGE_TASKS - 1) places every
           end effector inside the cage at start and goal. Tasks are generated from a fixed seed by position-only IK,
           each start and goal valid against the environment and the other robots. Throws ompl::Exception for other
           sizes or tasks. */
        MultiRobotProblem createPandaCage(std::size_t robots, std::size_t task = 0, double resolution = 128.);
    }  // namespace scenarios
}  // namespace ompl_parc

#endif
