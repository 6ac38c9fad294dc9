#ifndef OMPL_PARC_SCENARIOS_SCENARIOS_
#define OMPL_PARC_SCENARIOS_SCENARIOS_

#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief The paper's benchmark scenarios, built from their published formulas (docs/benchmarking.md).

        Each throws ompl::Exception for a robot count it cannot build (odd, or below 2). */
    namespace scenarios
    {
        /** \brief Disc radius, and the spacing of the 2D mobile scenarios. */
        constexpr double MOBILE_RADIUS = 0.5;
        constexpr double MOBILE_SPACING = 5.0;

        /** \brief Two lines of discs; the robots of each pair swap ends of a horizontal line. */
        MultiRobotProblem createMobileCross(std::size_t robots, double resolution = 128.);

        /** \brief Discs on a circle, each going to the diametrically opposite start. */
        MultiRobotProblem createMobileCircle(std::size_t robots, double resolution = 128.);

        /** \brief Two facing columns of 3-link planar arms between walls, swinging from +30 to -30 degrees. */
        MultiRobotProblem createPlanarCross(std::size_t robots, double resolution = 128.);

        /** \brief Build a scenario by name ("mobile_cross", "mobile_circle", "planar_cross", "panda_cage", or a
            generated family of ProblemFamilies.h); throws ompl::Exception listing the valid names for an unknown
            one. \e task picks one of the scenario's tasks: Panda Cage has PANDA_CAGE_TASKS
            (createPandaCage(robots, task), PandaCage.h), a family's task is the instance
            (generateFamilyInstance(name, robots, task)), the others have one (task 0); throws ompl::Exception
            for a task the scenario does not have. */
        MultiRobotProblem createScenario(const std::string &name, std::size_t robots, double resolution = 128.,
                                         std::size_t task = 0);

        /** \brief The names createScenario() accepts. */
        std::vector<std::string> scenarioNames();
    }  // namespace scenarios
}  // namespace ompl_parc

#endif
