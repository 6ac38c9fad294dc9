#include "TestProblems.h"

#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <climits>
#include <cstdint>
#include <optional>

using namespace ompl_parc;
using ompl_parc::test::validatePatch;
using ompl_parc::test::wholeProblem;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** Discs 'a' and 'b' in a corridor one disc wide along y = 0 (x from -10 to 10), with a gap below it at
        x = 0 that leads to an open area. */
    MultiRobotProblem corridor(std::vector<std::vector<double>> starts, std::vector<std::vector<double>> goals)
    {
        auto env = std::make_shared<Environment>();
        env->addBox2D("top", 0., 1., 20., 0.6);
        env->addBox2D("bottom_left", -5.4, -1., 9.2, 0.6);
        env->addBox2D("bottom_right", 5.4, -1., 9.2, 0.6);
        return test::discPair(env, std::move(starts), std::move(goals), 128., "corridor");
    }

    /** Disc 'a' (first priority) runs through the corridor from (-8, 0) to (8, 0); disc 'b' enters it from
        below through the gap and stops at (0, 0), on a's way. b could arrive after 4 s, but a passes there
        only after 8 s: b's goal counts only once a has gone by. */
    MultiRobotProblem corridor()
    {
        return corridor({{-8., 0.}, {0., -4.}}, {{8., 0.}, {0., 0.}});
    }

    /** The same with the priorities the wrong way round: 'a' (first) comes up through the gap and parks at (0, 0)
        for good, walling in 'b', which must pass there from (-8, 0) to (8, 0). Solvable with b first. */
    MultiRobotProblem walledIn()
    {
        return corridor({{0., -4.}, {-8., 0.}}, {{0., 0.}, {8., 0.}});
    }

    /** In a patch of walledIn(): b's x coordinate at the first timestep at which a stands at (0, 0). */
    double bWhereAParks(const Patch &patch)
    {
        std::vector<double> a(2), b(2);
        for (std::size_t t = 0; t <= patch.paths[0].getArrival(); ++t)
        {
            patch.paths[0].getConfig(t, a.data());
            if (a[0] == 0. && a[1] == 0.)
            {
                patch.paths[1].getConfig(t, b.data());
                return b[0];
            }
        }
        ADD_FAILURE() << "a never reaches (0, 0)";
        return 0.;
    }

    /** Solve \e problem with the PrioritizedSTRRT planner and validate its plan independently. */
    void expectPlannerSolves(const MultiRobotProblem &problem, const std::string &order)
    {
        PrioritizedSTRRT planner(problem.getSpaceInformation());
        planner.params().setParam("priority_order", order);
        planner.params().setParam("seed", "17");
        const auto pdef = problem.createProblemDefinition();
        planner.setProblemDefinition(pdef);
        planner.setup();
        ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(30.)), ob::PlannerStatus::EXACT_SOLUTION);
        const auto &plan = planner.getPlan();
        EXPECT_TRUE(test::pathFollowsPlan(*problem.getSpaceInformation(),
                                          *pdef->getSolutionPath()->as<og::PathGeometric>(), plan));
        const auto report = SolutionValidator(problem).validate(plan);
        EXPECT_TRUE(report.valid) << report.message;
    }
}  // namespace

TEST(PrioritizedSTRRT, SolvesMobileCross4And8AsAPlanner)
{
    expectPlannerSolves(scenarios::createMobileCross(4), "given");
    expectPlannerSolves(scenarios::createMobileCross(8), "shuffled");
}

TEST(PrioritizedSTRRTSolver, SolvesMobileCross4And8AsSubproblems)
{
    const PrioritizedSTRRTSolver solver;
    EXPECT_EQ(solver.getName(), "pp-st-rrt");
    for (std::size_t robots : {4, 8})
    {
        const auto problem = scenarios::createMobileCross(robots);
        const auto sub = wholeProblem(problem);
        Patch patch;
        ASSERT_TRUE(
            solver.solve(*problem.getSpaceInformation(), sub, ob::timedPlannerTerminationCondition(30.), 21, patch));
        ASSERT_EQ(patch.paths.size(), robots);
        for (const auto &path : patch.paths)
            EXPECT_EQ(path.getArrival(), patch.paths.front().getArrival());
        const auto report = validatePatch(problem, sub, patch);
        EXPECT_TRUE(report.valid) << report.message;
    }
}

TEST(PrioritizedSTRRTSolver, SolvesALocalSubproblemOfMobileCross8InsideItsBounds)
{
    // Robots 2 and 3 swap on their line (y = -2.5) inside a local band; the others are not in the team.
    const auto problem = scenarios::createMobileCross(8);
    Subproblem sub;
    sub.robots = {2, 3};
    sub.starts = {problem.getStart(2), problem.getStart(3)};
    sub.goals = {problem.getGoal(2), problem.getGoal(3)};
    for (std::size_t k = 0; k < 2; ++k)
    {
        ob::RealVectorBounds b = problem.getSpaceInformation()->getRobot(2)->getBounds();
        b.setLow(1, -4.);
        b.setHigh(1, -1.);
        sub.bounds.push_back(b);
    }
    Patch patch;
    ASSERT_TRUE(PrioritizedSTRRTSolver().solve(*problem.getSpaceInformation(), sub,
                                               ob::timedPlannerTerminationCondition(30.), 4, patch));
    for (const auto &timed : patch.paths)
    {
        const auto path = timed.toDense();
        for (std::size_t k = 1; k < path.size(); k += 2)
        {
            EXPECT_GE(path[k], -4.);
            EXPECT_LE(path[k], -1.);
        }
    }
    const auto report = validatePatch(problem, sub, patch);
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(PrioritizedSTRRTSolver, WaitsUntilItsGoalIsSafeToHold)
{
    const auto problem = corridor();
    const auto sub = wholeProblem(problem);
    Patch patch;
    ASSERT_TRUE(PrioritizedSTRRTSolver().solve(*problem.getSpaceInformation(), sub,
                                               ob::timedPlannerTerminationCondition(30.), 8, patch));
    const auto report = validatePatch(problem, sub, patch);
    EXPECT_TRUE(report.valid) << report.message;

    // b's arrival (its first timestep at the goal for good) is after a's last contact with b's goal.
    const auto a = patch.paths[0].toDense(), b = patch.paths[1].toDense();
    std::size_t arrival = b.size() / 2 - 1;
    while (arrival > 0 && b[2 * (arrival - 1)] == 0. && b[2 * (arrival - 1) + 1] == 0.)
        --arrival;
    std::size_t lastContact = 0;
    for (std::size_t t = 0; t < a.size() / 2; ++t)
        if (std::hypot(a[2 * t], a[2 * t + 1]) < 1.)
            lastContact = t;
    EXPECT_GT(lastContact, 4 * 128u) << "the naive arrival (4 s) would have been hit";
    EXPECT_GT(arrival, lastContact);
}

TEST(PrioritizedSTRRTSolver, EarliestHoldScansTheEarlierRobotsPaths)
{
    const auto problem = corridor();
    const auto &si = *problem.getSpaceInformation();
    DynamicObstacles obstacles(si.getRobot(1), 128.);
    obstacles.addPath(*si.getRobot(0), TimedPath::fromDense(2, test::straightLine({-8., 0.}, {8., 0.}, 128.)));
    const std::vector<double> goal = {0., 0.};
    // a touches b's goal while |x| < 1, i.e. until it has covered 9 of its 16 units.
    EXPECT_EQ(obstacles.earliestHold(goal.data()), std::optional<std::size_t>(9 * 128));
    const std::vector<double> far = {0., -4.};
    EXPECT_EQ(obstacles.earliestHold(far.data()), std::optional<std::size_t>(0));
    const std::vector<double> blocked = {7.5, 0.};  // next to a's goal, forever
    EXPECT_FALSE(obstacles.earliestHold(blocked.data()).has_value());
    const std::vector<double> inWall = {0., 1.};
    EXPECT_FALSE(obstacles.earliestHold(inWall.data()).has_value());
}

TEST(PrioritizedSTRRTSolver, APermanentlyBlockedGoalFailsAtOnce)
{
    // b's goal overlaps a's goal: after a arrives it can never be held. Fails without waiting for the limit.
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {0., -5.}, {5.5, 0.});
    Patch patch;
    const auto start = ompl::time::now();
    EXPECT_FALSE(PrioritizedSTRRTSolver().solve(*problem.getSpaceInformation(), wholeProblem(problem),
                                                ob::timedPlannerTerminationCondition(30.), 1, patch));
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 5.);

    // For a whole problem, a goal blocked for good by an earlier robot means the goals overlap.
    PrioritizedSTRRT planner(problem.getSpaceInformation());
    planner.setProblemDefinition(problem.createProblemDefinition());
    EXPECT_EQ(planner.solve(ob::timedPlannerTerminationCondition(30.)), ob::PlannerStatus::INVALID_GOAL);
}

TEST(PrioritizedSTRRTSolver, PromotesARobotThatTheOrderWallsIn)
{
    const auto problem = walledIn();
    const auto &si = *problem.getSpaceInformation();
    auto sub = wholeProblem(problem);
    sub.sampleCap = 20000;  // b's ST-RRT gives up after this many iterations instead of at the limit
    PrioritizedSTRRTSettings plain;
    plain.promote = false;
    plain.unblock = false;  // the given order, a first
    Patch patch;
    EXPECT_FALSE(PrioritizedSTRRTSolver(plain).solve(si, sub, ob::timedPlannerTerminationCondition(60.), 3, patch));

    PrioritizedSTRRTSettings promoting = plain;
    promoting.promote = true;
    ASSERT_TRUE(PrioritizedSTRRTSolver(promoting).solve(si, sub, ob::timedPlannerTerminationCondition(60.), 3, patch));
    const auto report = validatePatch(problem, sub, patch);
    EXPECT_TRUE(report.valid) << report.message;
    EXPECT_GT(bWhereAParks(patch), 1.) << "b went first: it is past the gap when a first reaches (0, 0)";
}

TEST(PrioritizedSTRRTSolver, OrdersTheTeamSoThatNobodyIsWalledIn)
{
    // a's goal (0, 0) lies on b's way alone: the unblocking order (the default) plans b first, at the first try.
    const auto problem = walledIn();
    const auto &si = *problem.getSpaceInformation();
    auto sub = wholeProblem(problem);
    sub.sampleCap = 20000;
    PrioritizedSTRRTSettings settings;
    settings.promote = false;
    ASSERT_TRUE(settings.unblock);
    Patch patch;
    ASSERT_TRUE(PrioritizedSTRRTSolver(settings).solve(si, sub, ob::timedPlannerTerminationCondition(60.), 3, patch));
    const auto report = validatePatch(problem, sub, patch);
    EXPECT_TRUE(report.valid) << report.message;
    EXPECT_GT(bWhereAParks(patch), 1.);
}

TEST(PrioritizedSTRRT, PlansInRoundsUntilTheStop)
{
    const auto problem = walledIn();
    const auto solve = [&](const std::string &promote, const std::string &cap, double limit)
    {
        PrioritizedSTRRT planner(problem.getSpaceInformation());
        planner.params().setParam("promote", promote);
        planner.params().setParam("unblock", "0");  // the given order, which walls b in
        planner.params().setParam("sample_cap", cap);
        planner.params().setParam("lattice", "0");  // the rounds of ST-RRT's cap are tested
        planner.params().setParam("seed", "5");
        const auto pdef = problem.createProblemDefinition();
        planner.setProblemDefinition(pdef);
        planner.setup();
        const auto status = planner.solve(ob::timedPlannerTerminationCondition(limit));
        if (status == ob::PlannerStatus::EXACT_SOLUTION)
        {
            const auto report = SolutionValidator(problem).validate(planner.getPlan());
            EXPECT_TRUE(report.valid) << report.message;
        }
        ob::PlannerData data(problem.getSpaceInformation());
        planner.getPlannerData(data);
        return std::make_pair(ob::PlannerStatus::StatusType(status), data.properties["rounds INTEGER"]);
    };
    // The given order alone: b is walled in and its ST-RRT runs until the stop (one round, no cap).
    EXPECT_EQ(solve("0", "0", 1.), std::make_pair(ob::PlannerStatus::TIMEOUT, std::string("1")));
    // Capped rounds with promotion: b is planned first within the first round.
    EXPECT_EQ(solve("1", "20000", 60.), std::make_pair(ob::PlannerStatus::EXACT_SOLUTION, std::string("1")));
    // A cap too small for b's way along the corridor: later rounds, with twice the cap each, get there.
    const auto [status, rounds] = solve("1", "50", 60.);
    EXPECT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_GT(std::stoi(rounds), 1) << "rounds " << rounds;
}

TEST(PrioritizedSTRRT, HonoursA10msTerminationCondition)
{
    const auto problem = scenarios::createMobileCross(8);
    PrioritizedSTRRT planner(problem.getSpaceInformation());
    planner.setProblemDefinition(problem.createProblemDefinition());
    planner.setup();
    auto start = ompl::time::now();
    planner.solve(ob::timedPlannerTerminationCondition(0.01));
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.2);

    // An impossible subproblem (both robots boxed into one thin strip, head-on) within 10 ms.
    auto sub = wholeProblem(scenarios::createMobileCross(4));
    sub.robots = {0, 1};
    sub.starts.resize(2);
    sub.goals.resize(2);
    for (std::size_t k = 0; k < 2; ++k)
    {
        ob::RealVectorBounds b(2);
        b.setLow(0, -10.);
        b.setHigh(0, 10.);
        b.setLow(1, -2.6);
        b.setHigh(1, -2.4);
        sub.bounds.push_back(b);
    }
    Patch patch;
    start = ompl::time::now();
    EXPECT_FALSE(PrioritizedSTRRTSolver().solve(*problem.getSpaceInformation(), sub,
                                                ob::timedPlannerTerminationCondition(0.01), 1, patch));
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.2);
}

TEST(PrioritizedSTRRTSolver, SameSeedGivesTheSamePatch)
{
    const auto problem = scenarios::createMobileCross(4);
    const auto sub = wholeProblem(problem);
    PrioritizedSTRRTSettings settings;
    settings.shuffle = true;
    const PrioritizedSTRRTSolver solver(settings);
    const auto &si = *problem.getSpaceInformation();
    Patch a, b, c;
    ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(30.), 11, a));
    ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(30.), 11, b));
    ASSERT_TRUE(solver.solve(si, sub, ob::timedPlannerTerminationCondition(30.), 12, c));
    EXPECT_EQ(a.paths, b.paths);
    EXPECT_NE(a.paths, c.paths);
    EXPECT_EQ(solver.priorityOrder(4, 11), solver.priorityOrder(4, 11));
    EXPECT_TRUE(validatePatch(problem, sub, a).valid);
}

namespace
{
    /** A termination condition that fires at its (\e budget + 1)-th evaluation and counts them in
        \e count: a cut at the same point of the work on every run, whatever the machine's speed. */
    ob::PlannerTerminationCondition afterEvaluations(std::size_t budget, std::size_t &count)
    {
        count = 0;
        return ob::PlannerTerminationCondition([budget, &count] { return ++count > budget; });
    }
}  // namespace

TEST(PrioritizedSTRRTSolver, CallsCutOneAfterAnotherGoOnWhereTheyStopped)
{
    // 16 robots in generated rooms (ARC's global rounds cut such solves by time): with the lattice, the unblocking
    // order and promotions, where calls cut one after the other find the uncut call's patch; and with ST-RRT planning
    // every robot in a shuffled order, where a resumed call draws its space samples afresh but still gets there.
    const auto problem = scenarios::generateFamilyInstance("rooms", 16, 1);
    const auto &si = *problem.getSpaceInformation();
    const auto sub = wholeProblem(problem);
    PrioritizedSTRRTSettings sampled;
    sampled.lattice = false;
    sampled.shuffle = true;
    for (const auto &settings : {PrioritizedSTRRTSettings(), sampled})
    {
        SCOPED_TRACE(settings.lattice ? "lattice" : "ST-RRT, shuffled");
        const PrioritizedSTRRTSolver solver(settings);
        const std::size_t unlimited = 50000000;  // far above what either takes
        std::size_t count = 0;
        Patch uncut;
        ASSERT_TRUE(solver.solve(si, sub, afterEvaluations(unlimited, count), 7, uncut));
        const std::size_t total = count;
        ASSERT_TRUE(validatePatch(problem, sub, uncut).valid);

        // Each call may do a part of that: starting over, no call gets there; going on, a few do, whatever seeds the
        // later calls bring (the robots planned before a cut are kept, alone for the order or in it; the one being
        // planned is planned again). A robot planned again starts over: ST-RRT's hardest robot alone takes over a
        // third of the sampled solve, so its calls get half.
        const unsigned int parts = settings.lattice ? 4 : 2;
        const std::size_t budget = total / parts;
        Patch patch;
        EXPECT_FALSE(solver.solve(si, sub, afterEvaluations(budget, count), 7, patch));
        EXPECT_FALSE(solver.resume(si, sub, afterEvaluations(budget, count), 7, patch, nullptr)) << "no memory";
        const auto memory = solver.makeMemory();
        ASSERT_NE(memory, nullptr);
        unsigned int calls = 0;
        bool solved = false;
        while (!solved && calls < 40)
        {
            solved = solver.resume(si, sub, afterEvaluations(budget, count), 7 + 100 * calls, patch, memory.get());
            ++calls;
        }
        ASSERT_TRUE(solved) << "in " << calls << " calls";
        EXPECT_GE(calls, parts);
        EXPECT_TRUE(validatePatch(problem, sub, patch).valid);
        if (settings.lattice)
            EXPECT_TRUE(patch.paths == uncut.paths) << "the first call's seed decides, as in one uncut call";

        // A solved call leaves the memory fresh: the next call is a whole solve of its own (here uncut, seed 7).
        Patch again;
        ASSERT_TRUE(solver.resume(si, sub, afterEvaluations(unlimited, count), 7, again, memory.get()));
        EXPECT_TRUE(again.paths == uncut.paths);
        EXPECT_EQ(count, total);
    }
}

TEST(PrioritizedSTRRT, RejectsBadInputsClearly)
{
    const auto plain = std::make_shared<ob::SpaceInformation>(std::make_shared<ob::RealVectorStateSpace>(2));
    EXPECT_THROW(PrioritizedSTRRT{plain}, ompl::Exception);

    // Overlapping starts name the robots; a goal in the wall names the robot.
    const auto clash = test::twoDiscs({0., 0.}, {5., 5.}, {0.5, 0.}, {-5., -5.});
    PrioritizedSTRRT planner(clash.getSpaceInformation());
    planner.setProblemDefinition(clash.createProblemDefinition());
    EXPECT_EQ(planner.solve(ob::timedPlannerTerminationCondition(1.)), ob::PlannerStatus::INVALID_START);
    const auto wall = test::twoDiscs({-5., 0.}, {0., 0.}, {5., 0.}, {5., 5.}, true);
    PrioritizedSTRRT walled(wall.getSpaceInformation());
    walled.setProblemDefinition(wall.createProblemDefinition());
    EXPECT_EQ(walled.solve(ob::timedPlannerTerminationCondition(1.)), ob::PlannerStatus::INVALID_GOAL);

    EXPECT_THROW(planner.setPriorityOrder("random"), ompl::Exception);
    EXPECT_THROW(planner.setRewiring("sometimes"), ompl::Exception);
    EXPECT_THROW(planner.setTimeBoundFactorIncrease(0.5), ompl::Exception);
    for (const char *name : {"range", "priority_order", "seed", "rewiring", "batch_size", "initial_time_bound_factor",
                             "time_bound_factor_increase", "promote", "unblock", "sample_cap"})
        EXPECT_TRUE(planner.params().hasParam(name)) << name;
}
