#include "TestProblems.h"

#include "ompl_parc/arc/ConflictResolver.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <mutex>
#include <thread>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    /** A solver that records what it is asked and never succeeds. */
    class RecordingSolver : public SubproblemSolver
    {
      public:
        std::string getName() const override { return "recording"; }
        bool usesContext() const override { return context_; }
        bool solve(const MultiRobotSpaceInformation &, const Subproblem &sub, const ob::PlannerTerminationCondition &,
                   std::uint_fast32_t, Patch &) const override
        {
            record(sub, 0);
            return false;
        }
        /** \brief A memory numbered from 1 in the order they are made. */
        class Numbered : public Memory
        {
          public:
            explicit Numbered(int number) : number_(number) {}
            const int number_;
        };
        std::unique_ptr<Memory> makeMemory() const override
        {
            std::lock_guard<std::mutex> lock(mutex_);
            return std::make_unique<Numbered>(++made_);
        }
        bool resume(const MultiRobotSpaceInformation &, const Subproblem &sub, const ob::PlannerTerminationCondition &,
                    std::uint_fast32_t, Patch &, Memory *memory) const override
        {
            record(sub, memory == nullptr ? 0 : dynamic_cast<Numbered &>(*memory).number_);
            return false;
        }
        /** \brief A call and its memory, under one lock (windows may be repaired concurrently). */
        void record(const Subproblem &sub, int memory) const
        {
            std::lock_guard<std::mutex> lock(mutex_);
            asked_.push_back(sub);
            memories_.push_back(memory);
        }
        mutable std::mutex mutex_;
        mutable std::vector<Subproblem> asked_;
        /** \brief Per call, the number of the memory it got (0: none). */
        mutable std::vector<int> memories_;
        mutable int made_{0};
        /** \brief Whether it claims to plan around the other robots (as PP-ST-RRT does). */
        bool context_{false};
    };

    /** Mobile Cross 4 with straight-line plans: robots 0 and 1 collide head-on in the middle. */
    struct HeadOn : testing::Test
    {
        MultiRobotProblem problem = scenarios::createMobileCross(4);
        MultiRobotPlan plan = test::straightLinePlan(problem);
    };
}  // namespace

TEST_F(HeadOn, WindowEndpointsAndLocalBoundsFollowTheSettings)
{
    ArcSettings settings;  // mobile: window 200, margin 2, min range 2
    auto solver = std::make_shared<RecordingSolver>();
    ConflictResolver resolver(*problem.getSpaceInformation(), settings, {solver});
    // Conflict at t = 2000: robots 0 and 1 are 2*(10 - 2000/128) ... overlapping; the window edges are clear.
    const auto sub = resolver.makeSubproblem(plan, {0, 1}, 2400, 0);
    EXPECT_EQ(sub.windowStart, 2200u);
    EXPECT_EQ(sub.windowEnd, 2560u);  // clipped to the team's latest arrival
    EXPECT_EQ(sub.starts[0], test::config(plan, 0, 2200));
    EXPECT_EQ(sub.goals[1], problem.getGoal(1));
    // Robot 0 moves along x from 10 - 2200/128 to -10 over the window: box widened by 2x its size per side.
    const double lo = -10., hi = 10. - 2200. / 128., size = hi - lo;
    EXPECT_NEAR(sub.bounds[0].low[0], std::max(lo - 2. * size, -11.), 1e-9);
    EXPECT_NEAR(sub.bounds[0].high[0], hi + 2. * size, 1e-9);
    // y never changes: the minimum range (2) centred on the line, inside the robot's bounds.
    EXPECT_NEAR(sub.bounds[0].low[1], -2.5 - 1., 1e-9);
    EXPECT_NEAR(sub.bounds[0].high[1], -2.5 + 1., 1e-9);
    EXPECT_EQ(sub.sampleCap, settings.sampleCap);
}

TEST(Subproblem, DoubledCapsGrowGeometricallyUpToTheLargestCap)
{
    EXPECT_EQ(Subproblem::doubledCap(50000, 0), 50000u);
    EXPECT_EQ(Subproblem::doubledCap(50000, 3), 400000u);
    EXPECT_EQ(Subproblem::doubledCap(0, 10), 0u);  // no cap stays no cap
    EXPECT_EQ(Subproblem::doubledCap(50000, 20), UINT_MAX);
    EXPECT_EQ(Subproblem::doubledCap(1, 4000000000u), UINT_MAX);  // rounds past any shift width
}

TEST_F(HeadOn, InvalidEndpointsWidenOnlyTheirSide)
{
    ArcSettings settings;
    settings.window = 10;  // the window edges fall inside the collision
    settings.endpointStep = 50;
    ConflictResolver resolver(*problem.getSpaceInformation(), settings, {std::make_shared<RecordingSolver>()});
    const std::size_t t = 1280;  // the robots pass through each other at the centre
    const auto sub = resolver.makeSubproblem(plan, {0, 1}, t, 0);
    // Robots of radius 0.5 overlap while |x| < 0.5, i.e. for 64 timesteps either side of t.
    EXPECT_EQ(sub.windowStart, t - 10 - 50 - 50);
    EXPECT_EQ(sub.windowEnd, t + 10 + 50 + 50);
    for (const auto *side : {&sub.starts, &sub.goals})
        EXPECT_FALSE(problem.getSpaceInformation()->robotsCollide(0, (*side)[0].data(), 1, (*side)[1].data()));
}

TEST_F(HeadOn, FailedWindowsGrowUntilTheGlobalProblemOfTheTeamThenOfAllRobots)
{
    ArcSettings settings;
    settings.window = 100;
    settings.growthStep = 300;
    auto solver = std::make_shared<RecordingSolver>();
    solver->context_ = true;
    ConflictResolver resolver(*problem.getSpaceInformation(), settings, {solver});
    // Give up once the global problem has been tried three times.
    const auto ptc = ob::PlannerTerminationCondition(
        [&]
        {
            std::lock_guard<std::mutex> lock(solver->mutex_);
            std::size_t globals = 0;
            for (const auto &s : solver->asked_)
                globals += s.bounds.empty() ? 1 : 0;
            return globals >= 3;
        });
    EXPECT_FALSE(resolver.resolve(plan, {0, 1}, 1280, ptc, 1).has_value());
    const auto &asked = solver->asked_;
    ASSERT_GE(asked.size(), 4u);
    // Half-widths 100, 400, 700, ...: the window grows until it covers [0, 2560], which is the global problem.
    EXPECT_EQ(asked[0].windowStart, 1180u);
    EXPECT_EQ(asked[1].windowStart, 880u);
    EXPECT_EQ(asked[2].windowStart, 580u);
    const auto &last = asked.back();
    EXPECT_TRUE(last.bounds.empty());
    EXPECT_EQ(last.windowStart, 0u);
    EXPECT_EQ(last.windowEnd, 2560u);
    EXPECT_EQ(last.starts[0], problem.getStart(0));
    EXPECT_EQ(last.goals[1], problem.getGoal(1));
    // The global problem is retried with twice the effort each round: no call is ever uncapped.
    std::vector<unsigned int> globalCaps;
    for (const auto &s : asked)
        if (s.bounds.empty())
            globalCaps.push_back(s.sampleCap);
    EXPECT_EQ(globalCaps,
              (std::vector<unsigned int>{settings.sampleCap, 2 * settings.sampleCap, 4 * settings.sampleCap}));
    // The team's global problem came first; after it failed around the other robots' fixed paths, the whole team's.
    std::vector<std::vector<std::size_t>> globalTeams;
    for (const auto &s : asked)
        if (s.bounds.empty())
            globalTeams.push_back(s.robots);
    const std::vector<std::size_t> pair = {0, 1}, all = {0, 1, 2, 3};
    EXPECT_EQ(globalTeams, (std::vector<std::vector<std::size_t>>{pair, all, all}));
    EXPECT_TRUE(asked[0].robots == pair && asked[1].robots == pair) << "windows keep the team";
    // Windows are new problems each time; the global rounds of one team are one problem, whose calls share a memory
    // (SubproblemSolver::resume); the whole team's rounds get another.
    std::vector<int> globalMemories;
    for (std::size_t c = 0; c < asked.size(); ++c)
        if (asked[c].bounds.empty())
            globalMemories.push_back(solver->memories_[c]);
        else
            EXPECT_EQ(solver->memories_[c], 0) << "window call " << c;
    ASSERT_EQ(globalMemories.size(), 3u);
    EXPECT_NE(globalMemories[0], 0);
    EXPECT_NE(globalMemories[1], globalMemories[0]);
    EXPECT_EQ(globalMemories[2], globalMemories[1]);

    // Without a solver that plans around the others, their paths cannot be what failed it: the team keeps trying.
    auto blind = std::make_shared<RecordingSolver>();
    ConflictResolver blindResolver(*problem.getSpaceInformation(), settings, {blind});
    const auto blindStop = ob::PlannerTerminationCondition(
        [&]
        {
            std::lock_guard<std::mutex> lock(blind->mutex_);
            return std::count_if(blind->asked_.begin(), blind->asked_.end(),
                                 [](const Subproblem &s) { return s.bounds.empty(); }) >= 3;
        });
    EXPECT_FALSE(blindResolver.resolve(plan, {0, 1}, 1280, blindStop, 1).has_value());
    for (const auto &s : blind->asked_)
        EXPECT_EQ(s.robots, pair);
}

namespace
{
    /** A RecordingSolver whose calls take time: \e window on a window, \e global on the global problem. */
    class SlowSolver : public RecordingSolver
    {
      public:
        SlowSolver(std::chrono::milliseconds window, std::chrono::milliseconds global)
            : window_(window), global_(global)
        {
        }
        bool resume(const MultiRobotSpaceInformation &si, const Subproblem &sub,
                    const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed, Patch &patch,
                    Memory *memory) const override
        {
            std::this_thread::sleep_for(sub.bounds.empty() ? global_ : window_);
            return RecordingSolver::resume(si, sub, ptc, seed, patch, memory);
        }
        const std::chrono::milliseconds window_, global_;
    };

    /** Resolves the head-on conflict at timestep 1280 with the planar profile and a least window growth of 1.25
        until its first window (start 1180) is asked for the third time, the start of the schedule's third pass, or
        after 2000 calls (a safety stop). */
    ResolveTrace resolveUntilTheThirdPass(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                          const std::shared_ptr<SlowSolver> &solver)
    {
        ArcSettings settings = ArcSettings::profile("planar");
        settings.minWindowGrowth = 1.25;
        const auto ptc = ob::PlannerTerminationCondition(
            [&solver]
            {
                std::lock_guard<std::mutex> lock(solver->mutex_);
                return std::count_if(solver->asked_.begin(), solver->asked_.end(),
                                     [](const Subproblem &s) { return s.windowStart == 1180; }) == 3 ||
                       solver->asked_.size() > 2000;
            });
        ResolveTrace trace;
        EXPECT_FALSE(ConflictResolver(si, settings, {solver}).resolve(plan, {0, 1}, 1280, ptc, 1, &trace).has_value());
        return trace;
    }
}  // namespace

TEST_F(HeadOn, WindowsHardlyWiderThanTheFirstOfTheirSizeAreTriedTwiceThenSkippedAndTheScheduleCycles)
{
    // The authors' planar schedule: half-widths 100 + ceil(1.05 * 2^(k-1)) = 100, 102, 103, 105, 109, 117, 134, 168,
    // 235, 369, 638, 1176, 2251. The first five grow the window [1180, 1380] by 2 to 34 timesteps: nearly the same
    // subproblem again, tried once more (102) and then skipped. A window at least 1.25 times as long as the first of
    // the size being tried starts a new size.
    // Global rounds of 50 ms, windows of no time: the later passes never have had more time than the global rounds.
    auto solver = std::make_shared<SlowSolver>(std::chrono::milliseconds(0), std::chrono::milliseconds(50));
    const ResolveTrace trace = resolveUntilTheThirdPass(*problem.getSpaceInformation(), plan, solver);
    std::vector<std::size_t> starts;
    for (const auto &s : solver->asked_)
        starts.push_back(s.windowStart);
    // Half-widths 100, 102, 134, 168, 235, 369, 638, 1176; then 2251 covers [0, 2560]: the global problem. It failed:
    // the schedule starts over (fresh seeds) and reaches the global problem again, whose cap has doubled; and again.
    const std::vector<std::size_t> cycle{1180, 1178, 1146, 1112, 1045, 911, 642, 104, 0};
    std::vector<std::size_t> expected = cycle;
    expected.insert(expected.end(), cycle.begin(), cycle.end());
    expected.push_back(1180);
    EXPECT_EQ(starts, expected);
    ASSERT_EQ(solver->asked_.size(), 19u);
    EXPECT_EQ(solver->asked_[8].windowEnd, 2560u);
    EXPECT_EQ(solver->asked_[8].sampleCap, ArcSettings::profile("planar").sampleCap);
    EXPECT_EQ(solver->asked_[17].sampleCap, 2 * ArcSettings::profile("planar").sampleCap);
    EXPECT_EQ(solver->memories_[17], solver->memories_[8]);  // the global problem goes on where it stopped
    EXPECT_NE(solver->memories_[8], 0);
    EXPECT_EQ(trace.expansions, 14u);
    EXPECT_EQ(trace.globalRounds, 2u);
    EXPECT_EQ(trace.passes, 2u);

    // With a least growth of 1 (the mobile and planar profiles') every window of the schedule is tried.
    const ArcSettings settings = ArcSettings::profile("planar");
    auto every = std::make_shared<RecordingSolver>();
    ConflictResolver everyResolver(*problem.getSpaceInformation(), settings, {every});
    EXPECT_FALSE(everyResolver
                     .resolve(plan, {0, 1}, 1280,
                              ob::PlannerTerminationCondition(
                                  [&]
                                  {
                                      std::lock_guard<std::mutex> lock(every->mutex_);
                                      return every->asked_.size() >= 6;
                                  }),
                              1)
                     .has_value());
    starts.clear();
    for (const auto &s : every->asked_)
        starts.push_back(s.windowStart);
    EXPECT_EQ(starts, (std::vector<std::size_t>{1180, 1178, 1177, 1175, 1171, 1163}));
}

TEST_F(HeadOn, LaterPassesOfTheScheduleGetNoMoreTimeThanTheGlobalRounds)
{
    // Passes of 8 windows of 20 ms and global rounds of 2 ms: after the second pass (160 ms of windows) the global
    // problem gets rounds until it has had as much time, then the third pass starts.
    auto solver = std::make_shared<SlowSolver>(std::chrono::milliseconds(20), std::chrono::milliseconds(2));
    const ResolveTrace trace = resolveUntilTheThirdPass(*problem.getSpaceInformation(), plan, solver);
    ASSERT_GT(solver->asked_.size(), 18u);
    EXPECT_LE(solver->asked_.size(), 2000u);
    EXPECT_EQ(trace.passes, 2u);
    // Asks 0-8 are the first pass (its global round last), 9-17 the second; then global rounds only, until the third.
    const auto globals = std::count_if(solver->asked_.begin() + 17, solver->asked_.end() - 1,
                                       [](const Subproblem &s) { return s.bounds.empty(); });
    EXPECT_EQ(globals, static_cast<long>(solver->asked_.size()) - 18);
    EXPECT_GE(globals, 3);  // 160 ms of windows against rounds of 2 ms: dozens, unless sleeps overran 25-fold
    EXPECT_GE(trace.globalSeconds, 0.15);
}

namespace
{
    /** A solver that never succeeds and only returns when its termination condition fires. */
    class SpinningSolver : public SubproblemSolver
    {
      public:
        std::string getName() const override { return "spinning"; }
        bool solve(const MultiRobotSpaceInformation &, const Subproblem &, const ob::PlannerTerminationCondition &ptc,
                   std::uint_fast32_t, Patch &) const override
        {
            while (!ptc)
                std::this_thread::sleep_for(std::chrono::microseconds(100));
            return false;
        }
    };
}  // namespace

TEST_F(HeadOn, NoSolverCallHoldsTheBudget)
{
    // Sample caps bind on iterations; a call whose iterations are slow is stopped by its time cap: at most as
    // long as the solve had run before it (at least MIN_CALL_SECONDS). Slack for a loaded machine.
    ConflictResolver resolver(*problem.getSpaceInformation(), ArcSettings(), {std::make_shared<SpinningSolver>()});
    const auto start = ompl::time::now();
    ResolveTrace trace;
    EXPECT_FALSE(resolver.resolve(plan, {0, 1}, 1280, ob::timedPlannerTerminationCondition(2.), 1, &trace));
    const double elapsed = ompl::time::seconds(ompl::time::now() - start);
    EXPECT_GE(trace.calls, 3u);
    EXPECT_LE(trace.longestCall, std::max(ConflictResolver::MIN_CALL_SECONDS, 0.5 * elapsed) + 0.25);
}

namespace
{
    /** A RecordingSolver that asks for the subproblem's context. */
    class ContextSolver : public RecordingSolver
    {
      public:
        bool usesContext() const override { return true; }
    };
}  // namespace

TEST(ConflictResolverContext, RobotsNearTheWindowAreTheContext)
{
    // Mobile Circle 4 with straight lines: all four discs cross the centre at the same time.
    const MultiRobotProblem problem = scenarios::createMobileCircle(4);
    const auto &si = *problem.getSpaceInformation();
    const MultiRobotPlan plan = test::straightLinePlan(problem);
    ArcSettings settings;
    settings.window = 200;
    const std::size_t t = plan.getArrival(0) / 2 - 100;  // before the discs touch: both window ends are clear
    const auto sub =
        ConflictResolver(si, settings, {std::make_shared<ContextSolver>()}).makeSubproblem(plan, {0, 2}, t, 0);
    ASSERT_EQ(sub.others, (std::vector<std::size_t>{1, 3}));
    std::vector<double> q(2), expected(2);
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t local : {std::size_t{0}, sub.windowEnd - sub.windowStart})
        {
            sub.otherPaths[k].getConfig(local, q.data());
            plan.getConfig(sub.others[k], sub.windowStart + local, expected.data());
            EXPECT_EQ(q, expected);
        }
    // A hierarchy that does not use the context gets none.
    EXPECT_TRUE(ConflictResolver(si, settings, {std::make_shared<RecordingSolver>()})
                    .makeSubproblem(plan, {0, 2}, t, 0)
                    .others.empty());
    // Far robots are not the context: Mobile Cross 4's rows are 5 apart.
    const MultiRobotProblem cross = scenarios::createMobileCross(4);
    const MultiRobotPlan rows = test::straightLinePlan(cross);
    EXPECT_TRUE(ConflictResolver(*cross.getSpaceInformation(), settings, {std::make_shared<ContextSolver>()})
                    .makeSubproblem(rows, {0, 1}, 1280, 0)
                    .others.empty());
}

TEST(ArcSettings, GrowthSchedulesAndProfiles)
{
    ArcSettings linear;
    EXPECT_EQ(linear.halfWidth(0), 200u);
    EXPECT_EQ(linear.halfWidth(3), 800u);
    const auto planar = ArcSettings::profile("planar");
    EXPECT_EQ(planar.halfWidth(0), 100u);
    EXPECT_EQ(planar.halfWidth(1), 102u);  // 100 + ceil(1.05)
    EXPECT_EQ(planar.halfWidth(5), 117u);  // 100 + ceil(1.05 * 16)
    // docs/results-arm-tail.md: Panda cells and Panda Cage 16
    EXPECT_EQ(ArcSettings::profile("panda").minWindowGrowth, 2.5);
    EXPECT_EQ(ArcSettings::profile("panda").sampleCap, 12500u);
    EXPECT_EQ(ArcSettings::profile("panda").solvers, ArcSettings::Solvers::COMPOSITE);
    EXPECT_TRUE(ArcSettings::profile("panda").sequential);  // docs/results.md: Panda cells, arms moved one at a time
    EXPECT_FALSE(ArcSettings::profile("planar").sequential);
    EXPECT_FALSE(ArcSettings::profile("mobile").sequential);
    EXPECT_EQ(planar.minWindowGrowth, 1.);  // every window
    EXPECT_EQ(planar.solvers, ArcSettings::Solvers::COMPOSITE_FIRST);
    EXPECT_EQ(ArcSettings::profile("mobile").minWindowGrowth, 1.);
    EXPECT_THROW(ArcSettings::profile("humanoid"), ompl::Exception);
    EXPECT_THROW(ArcSettings::growthFromString("cubic"), ompl::Exception);
    EXPECT_THROW(ArcSettings::solversFromString("magic"), ompl::Exception);
}

TEST(MultiRobotPlanSplice, LongerAndShorterPatchesShiftTheRest)
{
    MultiRobotPlan plan({1}, 1.);
    plan.setRobotPath(0, {0, 1, 2, 3, 4, 5, 6});
    auto longer = plan;
    longer.splice(0, 2, 4, TimedPath::fromDense(1, {2, 2.5, 3, 3.5, 4}));
    EXPECT_EQ(longer.getRobotPath(0), (std::vector<double>{0, 1, 2, 2.5, 3, 3.5, 4, 5, 6}));
    auto shorter = plan;
    shorter.splice(0, 1, 5, TimedPath::fromDense(1, {1, 5}));
    EXPECT_EQ(shorter.getRobotPath(0), (std::vector<double>{0, 1, 5, 6}));
    auto held = plan;  // the robot arrived at 6 before the window [8, 9]: it holds its goal until 8
    held.splice(0, 8, 9, TimedPath::fromDense(1, {6, 7, 6, 6}));
    EXPECT_EQ(held.getRobotPath(0), (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 6, 6, 7, 6}));
    EXPECT_EQ(held.getArrival(0), 10u);
}
