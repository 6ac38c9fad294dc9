// A user's program against the installed ompl_parc: build a team, check a state, exit 0 on success.
#include <ompl_parc/robots/DiscRobot.h>
#include <ompl_parc/model/MultiRobotSpaceInformation.h>
#include <ompl_parc/scenarios/Scenarios.h>
#include <ompl_parc/statespaces/CompositeStateSpace.h>

#include <iostream>

int main()
{
    const auto problem = ompl_parc::scenarios::createMobileCross(4);
    const auto &si = problem.getSpaceInformation();
    if (si->getRobotCount() != 4 || !problem.checkEndpoints().empty())
        return 1;
    std::cout << "consumer: " << si->getRobotCount() << " robots over " << si->getCompositeSpace()->getDimension()
              << "-D composite space" << std::endl;
    return 0;
}
