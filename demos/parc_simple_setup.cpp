/* Using P-ARC from plain OMPL code: a team of four discs, OMPL's SimpleSetup, composite ScopedStates for
   the start and goal, PARC as the planner, and the validated per-robot plan read back. (README's API example.) */
#include <ompl_parc/robots/DiscRobot.h>
#include <ompl_parc/model/MultiRobotSpaceInformation.h>
#include <ompl_parc/validation/SolutionValidator.h>
#include <ompl_parc/planners/PARC.h>

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/SimpleSetup.h>

#include <iostream>

int main()
{
    // Four discs of radius 0.5 in a 20 x 20 room, crossing in pairs through its middle.
    auto env = std::make_shared<ompl_parc::Environment>();
    env->addBox2D("pillar", 0., 6., 1., 1.);
    ompl::base::RealVectorBounds room(2);
    room.setLow(-10.);
    room.setHigh(10.);
    std::vector<ompl_parc::RobotPtr> team;
    for (int i = 0; i < 4; ++i)
        team.push_back(std::make_shared<ompl_parc::DiscRobot>("r" + std::to_string(i), env, 0.5, room));
    auto si = std::make_shared<ompl_parc::MultiRobotSpaceInformation>(team);  // 128 timesteps per unit

    ompl::geometric::SimpleSetup setup(si);
    ompl::base::ScopedState<> start(si), goal(si);  // composite states: x0, y0, x1, y1, ...
    const double starts[4][2] = {{-8, -2}, {8, -2}, {-8, 2}, {8, 2}};
    for (int i = 0; i < 4; ++i)
    {
        start[2 * i] = starts[i][0];
        start[2 * i + 1] = starts[i][1];
        goal[2 * i] = -starts[i][0];  // everyone crosses to the other side
        goal[2 * i + 1] = starts[i][1];
    }
    setup.setStartAndGoalStates(start, goal);

    auto parc = std::make_shared<ompl_parc::PARC>(si);
    parc->params().setParam("workers", "2");
    parc->params().setParam("seed", "1");
    setup.setPlanner(parc);
    if (setup.solve(30.0) != ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        std::cerr << "not solved: " << parc->getStatusMessage() << std::endl;
        return 1;
    }
    // The composite path has one state per timestep; the per-robot plan is the planner's.
    const ompl_parc::MultiRobotPlan &plan = parc->getPlan();
    const ompl_parc::MultiRobotProblem problem(si, {{-8, -2}, {8, -2}, {-8, 2}, {8, 2}},
                                               {{8, -2}, {-8, -2}, {8, 2}, {-8, 2}});
    const auto report = ompl_parc::SolutionValidator(problem).validate(plan);
    std::cout << "solved: " << setup.getSolutionPath().getStateCount() << " composite states, makespan "
              << plan.getMakespan() << " timesteps, robot r0 arrives at t=" << plan.getArrival(0)
              << ", validated: " << (report.valid ? "yes" : report.message) << std::endl;
    return report.valid ? 0 : 1;
}
