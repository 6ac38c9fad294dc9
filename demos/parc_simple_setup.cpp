/* P-ARC from user code, the way OMPL's SimpleSetup is used: a team of four discs, per-robot starts and goals by
   name, the planner by name with typed parameters, live progress, then the per-robot plan, smoothed and checked by
   the independent validator. (The API example of README.md and docs/cpp.md; also run by the test suite.) */
#include <ompl_parc/planners/setup/MultiRobotSetup.h>
#include <ompl_parc/robots/DiscRobot.h>

#include <iostream>

int main()
{
    // Four discs of radius 0.5 in a 20 x 20 room with a pillar, crossing in pairs through its middle.
    auto env = std::make_shared<ompl_parc::Environment>();
    env->addBox2D("pillar", 0., 6., 1., 1.);
    ompl::base::RealVectorBounds room(2);
    room.setLow(-10.);
    room.setHigh(10.);
    std::vector<ompl_parc::RobotPtr> team;
    for (const char *name : {"left_low", "right_low", "left_high", "right_high"})
        team.push_back(std::make_shared<ompl_parc::DiscRobot>(name, env, 0.5, room));

    ompl_parc::MultiRobotSetup setup(team);  // 128 timesteps per unit of distance
    setup.setStart("left_low", {-8., -2.});
    setup.setGoal("left_low", {8., -2.});
    setup.setStart("right_low", {8., -2.});
    setup.setGoal("right_low", {-8., -2.});
    setup.setStart("left_high", {-8., 2.});
    setup.setGoal("left_high", {8., 2.});
    setup.setStart("right_high", {8., 2.});
    setup.setGoal("right_high", {-8., 2.});

    setup.setPlanner("parc");  // or "arc", "orparc", "pp-st-rrt", ... (ompl_parc::PlannerRegistry::names())
    setup.setPlannerParameter("workers", 2);
    setup.setPlannerParameter("seed", 1);
    if (setup.solve(30.) != ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        std::cerr << "not solved" << std::endl;
        return 1;
    }
    const auto progress = setup.getProgress();  // also readable from another thread while solve() runs
    std::cout << "solved in " << setup.getLastPlanComputationTime()
              << " s: " << progress.at("conflicts resolved INTEGER") << " conflicts resolved, makespan "
              << setup.getPlan().getMakespan() << " timesteps" << std::endl;

    const ompl_parc::SmoothingReport smoothing = setup.simplify(0.5);
    const ompl_parc::ValidationReport report = setup.validate();
    std::cout << "smoothed: makespan " << smoothing.makespanBefore << " -> " << setup.getPlan().getMakespan()
              << ", robot right_high arrives at t=" << setup.getPlan().getArrival(setup.getRobotIndex("right_high"))
              << ", validated: " << (report.valid ? "yes" : report.message) << std::endl;
    return report.valid ? 0 : 1;
}
