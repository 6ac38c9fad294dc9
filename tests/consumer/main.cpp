// A user's program against the installed ompl_parc: build a team, check a state, set up the space-time planner
// in use, exit 0 on success.
#include <ompl_parc/robots/DiscRobot.h>
#include <ompl_parc/model/MultiRobotSpaceInformation.h>
#include <ompl_parc/planners/SpaceTime.h>
#include <ompl_parc/scenarios/Scenarios.h>
#include <ompl_parc/statespaces/CompositeStateSpace.h>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <iostream>

int main()
{
    const auto problem = ompl_parc::scenarios::createMobileCross(4);
    const auto &si = problem.getSpaceInformation();
    if (si->getRobotCount() != 4 || !problem.checkEndpoints().empty())
        return 1;
    std::cout << "consumer: " << si->getRobotCount() << " robots over " << si->getCompositeSpace()->getDimension()
              << "-D composite space" << std::endl;

    auto plane = std::make_shared<ompl::base::RealVectorStateSpace>(2);
    plane->setBounds(-1., 1.);
    const auto spaceTime = std::make_shared<ompl::base::SpaceInformation>(
        std::make_shared<ompl_parc::spacetime::SpaceTimeStateSpace>(plane));
    spaceTime->setStateValidityChecker([](const ompl::base::State *) { return true; });
    spaceTime->setup();
    ompl_parc::spacetime::STRRTstar planner(spaceTime);
    std::cout << "consumer: " << planner.getName() << " over "
              << (ompl_parc::spacetime::USES_OMPL_SPACE_TIME ? "OMPL's" : "ompl_parc's") << " space-time classes"
              << std::endl;
    return 0;
}
