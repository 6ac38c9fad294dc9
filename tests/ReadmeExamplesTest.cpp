/* The C++ examples of the documentation (docs/cpp.md, docs/planners.md), verbatim between the markers
   (tests/readme_test.py checks that every cpp block of README.md and docs/ is part of a compiled source): here they
   compile, run, and their plans are validated. */
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/SimpleSetup.h>

#include <iostream>

TEST(ReadmeExamples, ParcInPlainOmpl)
{
    // README: begin
    auto env = std::make_shared<ompl_parc::Environment>();  // obstacles: addBox2D, addObstacle (FCL shapes)
    ompl::base::RealVectorBounds room(2);
    room.setLow(-10.);
    room.setHigh(10.);
    std::vector<ompl_parc::RobotPtr> team;  // robots sharing the environment
    for (int i = 0; i < 4; ++i)
        team.push_back(std::make_shared<ompl_parc::DiscRobot>("r" + std::to_string(i), env, 0.5, room));
    auto si = std::make_shared<ompl_parc::MultiRobotSpaceInformation>(team);  // composite space, 128 steps/unit

    ompl::geometric::SimpleSetup setup(si);
    ompl::base::ScopedState<> start(si), goal(si);  // the robots' values one after another: x0, y0, x1, y1, ...
    const double xs[4] = {-8., 8., -8., 8.}, ys[4] = {-2., -2., 2., 2.};
    for (int i = 0; i < 4; ++i)
    {
        start[2 * i] = xs[i];
        start[2 * i + 1] = ys[i];
        goal[2 * i] = -xs[i];  // everyone crosses to the other side
        goal[2 * i + 1] = ys[i];
    }
    setup.setStartAndGoalStates(start, goal);
    auto parc = std::make_shared<ompl_parc::PARC>(si);
    parc->params().setParam("workers", "2");
    parc->params().setParam("smooth", "1");  // 1 s of time-aware smoothing after the solution
    setup.setPlanner(parc);
    if (setup.solve(30.0) == ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        const ompl_parc::MultiRobotPlan &plan = parc->getPlan();  // per-robot timed waypoints: getConfig(i, t, q)
        std::cout << "makespan " << plan.getMakespan() << " timesteps; the composite path has "
                  << setup.getSolutionPath().getStateCount() << " states, one per breakpoint\n";
    }
    // README: end
    ASSERT_TRUE(setup.haveExactSolutionPath());
    const ompl_parc::MultiRobotProblem problem(si, {{-8., -2.}, {8., -2.}, {-8., 2.}, {8., 2.}},
                                               {{8., -2.}, {-8., -2.}, {8., 2.}, {-8., 2.}});
    const auto report = ompl_parc::SolutionValidator(problem).validate(parc->getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(ReadmeExamples, PrioritizedSTRRT)
{
    // README: begin
    auto problem = ompl_parc::scenarios::createMobileCross(8);
    ompl_parc::PrioritizedSTRRT planner(problem.getSpaceInformation());
    planner.params().setParam("priority_order", "shuffled");  // or "given"
    planner.params().setParam("seed", "7");                   // same seed, same plan
    auto pdef = problem.createProblemDefinition();
    planner.setProblemDefinition(pdef);
    planner.solve(30.0);  // pdef->getSolutionPath(): one composite state per breakpoint; planner.getPlan(): per robot
    // README: end
    ASSERT_TRUE(pdef->hasExactSolution());
    const auto report = ompl_parc::SolutionValidator(problem).validate(planner.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}
