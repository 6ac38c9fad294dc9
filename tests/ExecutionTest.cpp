/* Plans robots can execute: time parameterization within limits (every sample checked), the temporal plan graph,
   execution with delays, the trajectory file and the scenario files' "limits". */
#include "TestProblems.h"

#include "ompl_parc/execution/ExecutionCheck.h"
#include "ompl_parc/execution/ExecutionSimulator.h"
#include "ompl_parc/execution/TemporalPlanGraph.h"
#include "ompl_parc/execution/TimeParameterization.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/io/TrajectoryFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    MultiRobotPlan solveArc(const MultiRobotProblem &problem)
    {
        ARC arc(problem.getSpaceInformation());
        arc.setSeed(1);
        arc.setProblemDefinition(problem.createProblemDefinition());
        arc.setup();
        EXPECT_EQ(arc.solve(ob::timedPlannerTerminationCondition(120.)), ob::PlannerStatus::EXACT_SOLUTION);
        const MultiRobotPlan plan = arc.getPlan();
        const auto report = SolutionValidator(problem).validate(plan);
        EXPECT_TRUE(report.valid) << report.message;
        return plan;
    }

    /** Every group's velocity and acceleration norm within its limit, at \e samples times over the trajectory and at
        every break time and either side of it. */
    void expectWithinLimits(const TeamTrajectory &trajectory, const std::vector<MotionLimits> &limits,
                            std::size_t samples)
    {
        for (std::size_t i = 0; i < trajectory.getRobotCount(); ++i)
        {
            std::vector<double> times = trajectory.getBreakTimes(i);
            for (double t : std::vector<double>(times))
                times.insert(times.end(), {t - 1e-9, t + 1e-9});
            for (std::size_t s = 0; s <= samples; ++s)
                times.push_back(trajectory.getDuration() * static_cast<double>(s) / static_cast<double>(samples));
            std::vector<double> q(trajectory.getDimension(i)), v(q.size()), a(q.size());
            for (double t : times)
            {
                trajectory.evaluate(i, t, q.data(), v.data(), a.data());
                for (const auto &g : limits[i].groups)
                {
                    double vv = 0., aa = 0.;
                    for (unsigned int d = g.first; d < g.first + g.count; ++d)
                        vv += v[d] * v[d], aa += a[d] * a[d];
                    ASSERT_LE(std::sqrt(vv), g.velocity * (1. + 1e-6)) << "robot " << i << " at " << t << " s";
                    ASSERT_LE(std::sqrt(aa), g.acceleration * (1. + 1e-6)) << "robot " << i << " at " << t << " s";
                }
            }
        }
    }

    void expectStartsAndEnds(const MultiRobotProblem &problem, const TeamTrajectory &trajectory)
    {
        for (std::size_t i = 0; i < trajectory.getRobotCount(); ++i)
        {
            std::vector<double> q(trajectory.getDimension(i));
            trajectory.evaluate(i, trajectory.getStartTime(), q.data(), nullptr, nullptr);
            for (std::size_t d = 0; d < q.size(); ++d)
                EXPECT_NEAR(q[d], problem.getStart(i)[d], 1e-9);
            trajectory.evaluate(i, trajectory.getEndTime(), q.data(), nullptr, nullptr);
            for (std::size_t d = 0; d < q.size(); ++d)
                EXPECT_NEAR(q[d], problem.getGoal(i)[d], 1e-9);
        }
    }

    /** A trajectory that passed the validator, from the start to the goal, within the limits at every sample. */
    void expectExecutable(const MultiRobotProblem &problem, const TimeParameterization &timing,
                          const TimeParameterization::Result &result)
    {
        ASSERT_TRUE(result.valid) << result.message;
        expectStartsAndEnds(problem, result.trajectory);
        expectWithinLimits(result.trajectory, timing.getLimits(), 4000);
    }
}  // namespace

TEST(TimeParameterization, PandaCageTrajectoryIsWithinLimitsAndConflictFree)
{
    const auto problem = scenarios::createPandaCage(8, 0);
    const auto plan = solveArc(problem);
    const TimeParameterization timing(problem);
    const auto result = timing.computeConflictFree(plan);
    expectExecutable(problem, timing, result);
    // The Panda's own limits: the URDF's velocities, three times them per second as accelerations.
    EXPECT_DOUBLE_EQ(timing.getLimits()[0].groups[0].velocity, 2.175);
    EXPECT_DOUBLE_EQ(timing.getLimits()[0].groups[6].velocity, 2.61);
    EXPECT_DOUBLE_EQ(timing.getLimits()[0].groups[6].acceleration, 3. * 2.61);
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        EXPECT_LE(result.trajectory.getArrivalTime(i), result.trajectory.getDuration() + 1e-9);
        EXPECT_LE(result.trajectory.getMaxDeviation(i), TimeParameterization::DEFAULT_MAX_DEVIATION * (1. + 1e-12));
    }
    // No deviation allowed: every corner sharp, the team resting at each.
    const TeamTrajectory exact = TimeParameterization(problem, 0.).compute(plan);
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
        EXPECT_EQ(exact.getMaxDeviation(i), 0.);
    EXPECT_GT(exact.getDuration(), result.trajectory.getDuration());
    EXPECT_THROW(TimeParameterization(problem, -1.), std::invalid_argument);
}

TEST(TimeParameterization, DiscTeamTrajectoryIsWithinLimitsAndConflictFree)
{
    const auto problem = scenarios::createScenario("field", 16, 128., 2);
    const auto plan = solveArc(problem);
    const TimeParameterization timing(problem);
    const auto result = timing.computeConflictFree(plan);
    expectExecutable(problem, timing, result);
    EXPECT_EQ(timing.getLimits()[0].groups.size(), 1u);  // a disc's speed, whatever the heading
}

TEST(TimeParameterization, WithEveryCornerSharpTheTeamIsExactlyOnThePlan)
{
    const auto problem = scenarios::createScenario("mobile_cross", 8);
    const auto plan = solveArc(problem);
    const TimeParameterization timing(problem);
    TimeParameterization::WindowCaps sharp(plan.getRobotCount());
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
        for (std::size_t t = 0; t <= plan.getMakespan(); ++t)
            sharp[i][t] = 0.;
    const TeamTrajectory trajectory = timing.compute(plan, sharp);
    EXPECT_EQ(trajectory.getSharpCornerCount() > 0, true);
    expectWithinLimits(trajectory, timing.getLimits(), 2000);
    std::vector<double> q(2), a(2), b(2);
    for (std::size_t s = 0; s <= 500; ++s)
    {
        const double t = trajectory.getDuration() * static_cast<double>(s) / 500.;
        const double step = trajectory.planTimeAt(t);
        const auto k = static_cast<std::size_t>(std::floor(step));
        for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
        {
            trajectory.evaluate(i, t, q.data(), nullptr, nullptr);
            plan.getConfig(i, k, a.data());
            plan.getConfig(i, k + 1, b.data());
            for (std::size_t d = 0; d < 2; ++d)
                ASSERT_NEAR(q[d], a[d] + (step - static_cast<double>(k)) * (b[d] - a[d]), 1e-9);
        }
        EXPECT_NEAR(trajectory.timeAtPlanStep(step), t, 1e-6 * std::max(1., t));
    }
}

TEST(TimeParameterization, RefusesAPlanOfAnotherTeam)
{
    const auto problem = scenarios::createScenario("mobile_cross", 4);
    const auto other = scenarios::createScenario("mobile_cross", 8);
    EXPECT_THROW(TimeParameterization(problem).compute(test::straightLinePlan(other)), std::invalid_argument);
}

TEST(TemporalPlanGraph, CoordinatedExecutionNeverCollidesWhereTimeIndexedDoes)
{
    for (const auto &problem : {scenarios::createPandaCage(8, 0), scenarios::createScenario("crossing", 16, 128., 1)})
    {
        const auto plan = solveArc(problem);
        const TimeParameterization timing(problem);
        const auto result = timing.computeConflictFree(plan);
        ASSERT_TRUE(result.valid) << result.message;
        const TemporalPlanGraph graph(problem, plan);
        for (const auto &e : graph.getEdges())
        {
            EXPECT_LT(e.from.phase, e.to.phase);  // forward in plan time: no cycle, no deadlock
            EXPECT_TRUE(graph.isMoving(e.from.robot, e.from.phase) && graph.isMoving(e.to.robot, e.to.phase));
        }
        const ExecutionSimulator simulator(problem, plan, result.trajectory, graph, timing.getMaxSpeed());
        // Undelayed, both ways execute the plan: on time, or (coordinated) sooner where a robot need not wait.
        const ExecutionSimulator::Disturbance none{std::vector<double>(plan.getRobotCount(), 0.),
                                                   std::vector<double>(plan.getRobotCount(), 1.)};
        for (auto mode : {ExecutionSimulator::Mode::TIME_INDEXED, ExecutionSimulator::Mode::COORDINATED})
        {
            const auto outcome = simulator.run(mode, none);
            EXPECT_TRUE(outcome.collisionFree) << outcome.message;
            if (mode == ExecutionSimulator::Mode::TIME_INDEXED)
                EXPECT_NEAR(outcome.makespan, simulator.getNominalMakespan(), 1e-6 * simulator.getNominalMakespan());
            else
                EXPECT_LE(outcome.makespan, simulator.getNominalMakespan() * (1. + 1e-6));
        }
        std::size_t timeIndexedCollisions = 0;
        for (std::uint64_t seed = 1; seed <= 10; ++seed)
        {
            const auto disturbance = ExecutionSimulator::Disturbance::random(plan.getRobotCount(), seed);
            const auto coordinated = simulator.run(ExecutionSimulator::Mode::COORDINATED, disturbance);
            EXPECT_TRUE(coordinated.collisionFree)
                << problem.getName() << " seed " << seed << ": " << coordinated.message;
            timeIndexedCollisions +=
                simulator.run(ExecutionSimulator::Mode::TIME_INDEXED, disturbance).collisionFree ? 0 : 1;
        }
        // The check can fail: run on their own clocks, delayed robots do collide.
        EXPECT_GT(timeIndexedCollisions, 0u) << problem.getName();
    }
}

TEST(TrajectoryFile, HoldsEachRobotsPointsInTimeOrderFromStartToGoal)
{
    const auto problem = scenarios::createPandaCage(8, 0);
    const auto plan = solveArc(problem);
    const TimeParameterization timing(problem);
    const auto result = timing.computeConflictFree(plan);
    const TemporalPlanGraph graph(problem, plan);
    const auto doc = TrajectoryFile::toJson(problem, result.trajectory, &graph);
    EXPECT_EQ(doc.at("format"), "ompl_parc.trajectory");
    ASSERT_EQ(doc.at("robots").size(), 8u);
    for (std::size_t i = 0; i < 8; ++i)
    {
        const auto &robot = doc.at("robots")[i];
        EXPECT_EQ(robot.at("joint_names").size(), 7u);
        const auto &points = robot.at("points");
        ASSERT_GE(points.size(), 2u);
        for (std::size_t p = 1; p < points.size(); ++p)
            EXPECT_LT(points[p - 1].at("time_from_start").get<double>(), points[p].at("time_from_start").get<double>());
        for (std::size_t d = 0; d < 7; ++d)
        {
            EXPECT_NEAR(points.front().at("positions")[d].get<double>(), problem.getStart(i)[d], 1e-9);
            EXPECT_NEAR(points.back().at("positions")[d].get<double>(), problem.getGoal(i)[d], 1e-9);
            EXPECT_NEAR(points.back().at("velocities")[d].get<double>(), 0., 1e-9);
        }
    }
    EXPECT_EQ(doc.at("temporal_plan_graph").at("edges").size(), graph.getEdges().size());
}

TEST(MotionLimitsInScenarioFiles, AreReadCheckedAndWrittenBack)
{
    const std::string doc =
        R"({"format": "ompl_parc.scenario", "version": 1, "name": "limits", "obstacles": [], "robots": [
        {"name": "a", "kind": "disc", "radius": 0.5, "bounds": {"low": [-5, -5], "high": [5, 5]},
         "limits": {"velocity": 0.5, "acceleration": [0.25]}, "start": [-2, 0], "goal": [2, 0]},
        {"name": "b", "kind": "disc", "radius": 0.5, "bounds": {"low": [-5, -5], "high": [5, 5]},
         "start": [0, -2], "goal": [0, 2]}]})";
    const auto problem = ScenarioFile::fromJson(doc, "");
    const auto &a = *problem.getSpaceInformation()->getRobot(0);
    EXPECT_DOUBLE_EQ(a.getMotionLimits().groups[0].velocity, 0.5);
    EXPECT_DOUBLE_EQ(a.getMotionLimits().groups[0].acceleration, 0.25);
    EXPECT_FALSE(problem.getSpaceInformation()->getRobot(1)->hasOwnMotionLimits());
    const auto again = ScenarioFile::fromJson(ScenarioFile::toJson(problem), "");
    EXPECT_DOUBLE_EQ(again.getSpaceInformation()->getRobot(0)->getMotionLimits().groups[0].acceleration, 0.25);
    for (const std::string bad :
         {R"("velocity": 0)", R"("velocity": [1, 2])", R"("speed": 1)", R"("acceleration": -1)"})
    {
        std::string text = doc;
        text.replace(text.find(R"("velocity": 0.5, "acceleration": [0.25])"),
                     std::string(R"("velocity": 0.5, "acceleration": [0.25])").size(), bad);
        EXPECT_THROW(ScenarioFile::fromJson(text, ""), ompl::Exception) << bad;
    }
}

TEST(ExecutionCheck, SteadyStretchesAreOnePieceAndEveryTimestepKeepsTheMotion)
{
    // Two discs: one cruising at a constant velocity, then waiting; one on a parabola (every sample bends).
    const auto problem = scenarios::createScenario("mobile_cross", 2);
    const ExecutionCheck check(problem);
    const auto motion = [](std::size_t i, double t, double *out)
    {
        if (i == 0)
        {
            const double s = std::min(t, 4.);
            out[0] = -3. + 0.5 * s;
            out[1] = 0.25 * s;
            return;
        }
        out[0] = 0.1 * t * t - 3.;
        out[1] = -1.;
    };
    const MultiRobotPlan plan = check.sample(0., 6., 1., motion);
    const double dt = 0.999 / problem.getSpaceInformation()->getResolution();
    ASSERT_EQ(plan.getMakespan(), static_cast<std::size_t>(std::ceil(6. / dt)));
    // The cruise and the wait: a few pieces, whatever the duration (the start, the cruise, the sample where it
    // stops, the wait); the parabola bends at every sample: a piece each.
    EXPECT_LE(plan.getPath(0).getPieceCount(), 4u);
    EXPECT_GE(plan.getPath(1).getPieceCount(), plan.getMakespan() / 2);
    std::vector<double> q(2), expected(2);
    for (std::size_t t = 0; t <= plan.getMakespan(); ++t)
        for (std::size_t i = 0; i < 2; ++i)
        {
            plan.getConfig(i, t, q.data());
            motion(i, std::min(6., static_cast<double>(t) * dt), expected.data());
            EXPECT_NEAR(q[0], expected[0], 1e-9) << i << " " << t;
            EXPECT_NEAR(q[1], expected[1], 1e-9) << i << " " << t;
        }
}
