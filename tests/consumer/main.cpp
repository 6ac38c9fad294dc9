// A user's program against the installed ompl_parc: a team from the installed scenario library, per-robot starts
// and goals set by name through MultiRobotSetup, P-ARC by its registry name with typed parameters, its progress
// properties read, the solution validated; and the space-time planner in use set up. Exit 0 on success.
#include <ompl_parc/Version.h>
#include <ompl_parc/planners/SpaceTime.h>
#include <ompl_parc/planners/setup/MultiRobotSetup.h>
#include <ompl_parc/scenarios/Scenarios.h>
#include <ompl_parc/statespaces/CompositeStateSpace.h>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <iostream>

int main()
{
    const auto cross = ompl_parc::scenarios::createMobileCross(4);
    ompl_parc::MultiRobotSetup setup(cross.getSpaceInformation()->getRobots());
    for (std::size_t i = 0; i < setup.getRobotCount(); ++i)
    {
        const std::string &name = setup.getSpaceInformation()->getRobot(i)->getName();
        setup.setStart(name, cross.getStart(i));
        setup.setGoal(name, cross.getGoal(i));
    }
    setup.setPlanner("parc");
    setup.setPlannerParameter("workers", 2);
    setup.setPlannerParameter("seed", 7);
    setup.setPlannerParameter("smooth", 0.1);
    if (setup.solve(30.) != ompl::base::PlannerStatus::EXACT_SOLUTION || !setup.validate().valid)
        return 1;
    const auto progress = setup.getProgress();
    std::cout << "consumer: ompl_parc " << OMPL_PARC_VERSION << ", P-ARC solved " << setup.getRobotCount()
              << " robots, stage " << progress.at("stage INTEGER") << ", " << progress.at("conflicts resolved INTEGER")
              << " conflicts resolved, makespan " << setup.getPlan().getMakespan() << std::endl;
    if (progress.at("stage INTEGER") != "4" || progress.size() != 8)
        return 1;

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
