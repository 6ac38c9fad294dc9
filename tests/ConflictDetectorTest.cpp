#include "TestProblems.h"

#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/arc/RepairCache.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/util/StopSignal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

using namespace ompl_parc;

namespace
{
    /** The first conflict of each pair, in (t, i, j) order: what a non-ARC scan of all pairs must return. */
    std::vector<Conflict> firstPerPair(const std::vector<Conflict> &all)
    {
        std::vector<Conflict> first;
        for (const Conflict &c : all)
            if (std::none_of(first.begin(), first.end(),
                             [&c](const Conflict &f) { return f.first == c.first && f.second == c.second; }))
                first.push_back(c);
        return first;
    }

    /** All conflicts at the earliest conflicting timestep: what an ARC-mode scan of all pairs must return. */
    std::vector<Conflict> earliestTimestep(const std::vector<Conflict> &all)
    {
        std::vector<Conflict> earliest;
        for (const Conflict &c : all)
            if (c.timestep == all.front().timestep)
                earliest.push_back(c);
        return earliest;
    }

    /** Every pair \e detector tracks for \e plan (discovered first). */
    std::vector<std::size_t> allPairs(ConflictDetector &detector, const MultiRobotPlan &plan)
    {
        EXPECT_TRUE(detector.discoverPairs(plan));
        std::vector<std::size_t> pairs(detector.getPairCount());
        for (std::size_t p = 0; p < pairs.size(); ++p)
            pairs[p] = p;
        return pairs;
    }

    /** Both scan modes of a detector with segment length \e h against brute force on \e plan. */
    void expectScansMatchBruteForce(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan, std::size_t h)
    {
        const auto expected = test::allConflicts(si, plan);
        const std::size_t end = plan.getMakespan() + 1;
        ConflictDetector arcMode(si, h), workerMode(si, h);
        const auto pairs = allPairs(arcMode, plan);
        ASSERT_EQ(allPairs(workerMode, plan), pairs) << "H = " << h;
        EXPECT_EQ(arcMode.scan(plan, pairs, 0, end, true), expected.empty() ? expected : earliestTimestep(expected))
            << "H = " << h;
        EXPECT_EQ(workerMode.scan(plan, pairs, 0, end, false), firstPerPair(expected)) << "H = " << h;
        // Frontiers: at the pair's first conflict, or past its last timestep to check.
        for (std::size_t p = 0; p < pairs.size(); ++p)
        {
            const auto [i, j] = workerMode.getPair(p);
            const auto first = firstPerPair(expected);
            const auto c = std::find_if(first.begin(), first.end(),
                                        [i = i, j = j](const Conflict &f) { return f.first == i && f.second == j; });
            EXPECT_EQ(workerMode.getFrontier(i, j),
                      c != first.end() ? c->timestep : std::max(plan.getArrival(i), plan.getArrival(j)) + 1);
        }
    }

    /** \brief Two threads scan interleaved pair subsets of \e plan with one detector (segment length \e h):
        together they must find each pair's first conflict, as brute force does. */
    void expectConcurrentScansMatchBruteForce(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                              std::size_t h)
    {
        ConflictDetector detector(si, h);
        ASSERT_TRUE(detector.discoverPairs(plan));
        std::vector<std::size_t> subsets[2];
        for (std::size_t p = 0; p < detector.getPairCount(); ++p)
            subsets[p % 2].push_back(p);
        std::vector<Conflict> found[2];
        std::thread other([&] { found[1] = detector.scan(plan, subsets[1], 0, plan.getMakespan() + 1, false); });
        found[0] = detector.scan(plan, subsets[0], 0, plan.getMakespan() + 1, false);
        other.join();
        found[0].insert(found[0].end(), found[1].begin(), found[1].end());
        std::sort(found[0].begin(), found[0].end());
        EXPECT_EQ(found[0], firstPerPair(test::allConflicts(si, plan)));
    }
}  // namespace

TEST(ConflictDetector, EarliestConflictMatchesBruteForceOnRandomPlans)
{
    std::mt19937 rng(5);
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    int withConflicts = 0;
    for (int k = 0; k < 40; ++k)
    {
        const auto plan = test::randomWalkPlan(*problem.getSpaceInformation(), rng, 5. / 128.);
        const auto expected = test::allConflicts(si, plan);
        ConflictDetector detector(si);
        const auto found = detector.findEarliest(plan);
        ASSERT_EQ(found.has_value(), !expected.empty());
        if (found)
        {
            EXPECT_EQ(*found, expected.front());
            ++withConflicts;
        }
    }
    EXPECT_GT(withConflicts, 10);
}

TEST(ConflictDetector, BroadPhaseScansMatchBruteForceInBothModes)
{
    std::mt19937 rng(17);
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    for (int k = 0; k < 30; ++k)
    {
        const auto plan = test::randomWalkPlan(*problem.getSpaceInformation(), rng, 5. / 128.);
        for (std::size_t h : {0, 1, 5, 64, 1000})
            expectScansMatchBruteForce(si, plan, h);
    }
}

namespace
{
    /** Planar arms: capsules, several per body; random joint-space walks around the start configurations. */
    MultiRobotPlan armWalkPlan(const MultiRobotProblem &problem, std::mt19937 &rng)
    {
        const auto &si = *problem.getSpaceInformation();
        std::uniform_real_distribution<double> step(-0.05, 0.05);
        std::uniform_int_distribution<int> length(20, 300);
        MultiRobotPlan plan(si);
        for (std::size_t r = 0; r < si.getRobotCount(); ++r)
        {
            std::vector<double> q = problem.getStart(r), flat = q;
            for (int t = length(rng); t > 0; --t)
            {
                for (double &v : q)
                    v += step(rng);
                flat.insert(flat.end(), q.begin(), q.end());
            }
            plan.setRobotPath(r, flat);
        }
        return plan;
    }
}  // namespace

TEST(ConflictDetector, BroadPhaseMatchesBruteForceForArms)
{
    std::mt19937 rng(23);
    const auto problem = scenarios::createPlanarCross(8);
    for (int k = 0; k < 20; ++k)
    {
        const auto plan = armWalkPlan(problem, rng);
        for (std::size_t h : {0, 3, 64})
            expectScansMatchBruteForce(*problem.getSpaceInformation(), plan, h);
    }
}

/* reset() between two plans (a planner's next query): the second plan's earliest conflict is a fresh detector's,
   although the first plan's scan advanced frontiers, found conflicts and computed swept bounds (arms: the broad phase
   is in play). */
TEST(ConflictDetector, ResetForgetsFrontiersConflictsAndSweptBounds)
{
    std::mt19937 rng(29);
    const auto problem = scenarios::createPlanarCross(8);
    const auto &si = *problem.getSpaceInformation();
    ConflictDetector detector(si, 16);
    int conflicting = 0;
    for (int k = 0; k < 20; ++k)
    {
        const auto plan = armWalkPlan(problem, rng);
        detector.reset();
        ASSERT_EQ(detector.getPairCount(), 0u);  // every pair to be discovered again
        ConflictDetector fresh(si, 16);
        const auto expected = fresh.findEarliest(plan);
        EXPECT_EQ(detector.findEarliest(plan), expected);
        conflicting += expected ? 1 : 0;
        // The next plan starts from all of this.
        detector.scan(plan, allPairs(detector, plan), 0, plan.getMakespan() + 1, false);
    }
    EXPECT_GT(conflicting, 5);
}

TEST(ConflictDetector, InvalidationDropsStaleSweptBounds)
{
    // After a scan has computed the swept bounds, robot a's path is replaced from timestep t on by a copy
    // of robot b's: stale bounds would let the broad phase skip the new conflicts.
    std::mt19937 rng(31);
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    std::uniform_int_distribution<std::size_t> robot(0, si.getRobotCount() - 1);
    for (int k = 0; k < 20; ++k)
    {
        auto plan = test::randomWalkPlan(*problem.getSpaceInformation(), rng, 5. / 128.);
        ConflictDetector detector(si, 16);
        const auto pairs = allPairs(detector, plan);
        detector.scan(plan, pairs, 0, plan.getMakespan() + 1, false);
        const std::size_t a = robot(rng), b = (a + 1 + robot(rng) % (si.getRobotCount() - 1)) % si.getRobotCount();
        const std::size_t t = std::uniform_int_distribution<std::size_t>(0, plan.getArrival(a))(rng);
        test::followFrom(plan, a, b, t);
        detector.invalidate(a, t);
        ConflictDetector fresh(si, 16);
        EXPECT_EQ(detector.findEarliest(plan), fresh.findEarliest(plan));
        const auto expected = test::allConflicts(si, plan);
        ASSERT_FALSE(expected.empty());
        EXPECT_EQ(*fresh.findEarliest(plan), expected.front());
    }
}

TEST(ConflictDetector, ConcurrentScansOfDisjointPairSubsetsShareSweptBounds)
{
    std::mt19937 rng(41);
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    for (int k = 0; k < 10; ++k)
    {
        const auto plan = test::randomWalkPlan(*problem.getSpaceInformation(), rng, 5. / 128.);
        expectConcurrentScansMatchBruteForce(si, plan, 8);
    }
}

TEST(ConflictDetector, FrontiersResumeAndResetOnInvalidation)
{
    std::mt19937 rng(9);
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    for (int k = 0; k < 20; ++k)
    {
        auto plan = test::randomWalkPlan(*problem.getSpaceInformation(), rng, 5. / 128.);
        const auto expected = test::allConflicts(si, plan);
        if (expected.empty())
            continue;
        ConflictDetector detector(si);
        const Conflict c = *detector.findEarliest(plan);
        // Everything before the conflict is validated; the conflicting pair stops at the conflict.
        EXPECT_EQ(detector.getFrontier(c.first, c.second), c.timestep);
        // Scanning again finds the same conflict (the frontier does not skip it), also after a change of a path
        // after the conflict (which leaves it known).
        EXPECT_EQ(*detector.findEarliest(plan), c);
        detector.invalidate(c.first, c.timestep + 1);
        EXPECT_EQ(*detector.findEarliest(plan), c);
        // Move robot c.first away for good from the conflict on: the next earliest must again match brute force.
        auto path = plan.getRobotPath(c.first);
        for (std::size_t t = c.timestep; t < plan.getStateCount(c.first); ++t)
            path[2 * t] += 1000.;
        plan.setRobotPath(c.first, path);
        detector.invalidate(c.first, c.timestep);
        const auto after = test::allConflicts(si, plan);
        const auto next = detector.findEarliest(plan);
        ASSERT_EQ(next.has_value(), !after.empty());
        if (next)
            EXPECT_EQ(*next, after.front());
    }
}

TEST(ConflictDetector, ScanOfAPairSubsetReportsAllConflictsAtTheFirstConflictingTimestep)
{
    // Two head-on pairs meeting at the same time: a scan of all pairs returns both, in pair order.
    const auto problem = scenarios::createMobileCross(4);
    const auto &si = *problem.getSpaceInformation();
    MultiRobotPlan plan = test::straightLinePlan(problem);
    ConflictDetector detector(si);
    const auto all = allPairs(detector, plan);
    const auto conflicts = detector.scan(plan, all, 0, plan.getMakespan() + 1, true);
    ASSERT_EQ(conflicts.size(), 2u);
    EXPECT_EQ(conflicts[0].first, 0u);
    EXPECT_EQ(conflicts[0].second, 1u);
    EXPECT_EQ(conflicts[1].first, 2u);
    EXPECT_EQ(conflicts[1].second, 3u);
    EXPECT_EQ(conflicts[0].timestep, conflicts[1].timestep);
    // Skipping robot 0 leaves only the (2, 3) conflict; a horizon before it finds nothing.
    ConflictDetector fresh(si);
    ASSERT_EQ(allPairs(fresh, plan), all);
    const auto skipped = fresh.scan(plan, all, 0, plan.getMakespan() + 1, true,
                                    [](std::size_t i, std::size_t j) { return i == 0 || j == 0; });
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_EQ(skipped[0].first, 2u);
    ConflictDetector early(si);
    ASSERT_EQ(allPairs(early, plan), all);
    EXPECT_TRUE(early.scan(plan, all, 0, conflicts[0].timestep, true).empty());
    EXPECT_EQ(early.getFrontier(0, 1), conflicts[0].timestep);
}

TEST(RepairCache, ExpansionIsTheTransitiveClosureOverOverlappingRepairs)
{
    RepairCache cache;
    cache.add({1, 2}, 100, 200);
    cache.add({2, 5}, 150, 300);
    cache.add({5, 7}, 1000, 1100);  // far in time: not pulled in
    cache.add({0, 9}, 100, 200);    // overlapping but unrelated robots
    EXPECT_EQ(cache.expand({1, 3, 180}, 20), (std::vector<std::size_t>{1, 2, 3, 5}));
    EXPECT_EQ(cache.expand({1, 3, 500}, 20), (std::vector<std::size_t>{1, 3}));
    EXPECT_EQ(cache.expand({5, 8, 1050}, 20), (std::vector<std::size_t>{5, 7, 8}));
    EXPECT_EQ(cache.expand({4, 6, 10}, 10000), (std::vector<std::size_t>{4, 6}));
}

TEST(ConflictDetector, ALaterScanNeverResumesAPairPastItsKnownConflict)
{
    // Robots 0 and 1 swap head-on; a P-ARC detection round finds their conflict, and the next round (a later
    // horizon, the conflict deferred) must not mark the stretch before it conflict-free.
    const auto problem = scenarios::createMobileCross(4);
    const auto &si = *problem.getSpaceInformation();
    MultiRobotPlan plan = test::straightLinePlan(problem);
    ConflictDetector detector(si);
    ASSERT_TRUE(detector.discoverPairs(plan));
    ASSERT_TRUE(detector.findPair(0, 1));
    const std::vector<std::size_t> pair = {*detector.findPair(0, 1)};
    const auto first = detector.scan(plan, pair, 0, 1400, false);
    ASSERT_EQ(first.size(), 1u);
    const std::size_t t = first.front().timestep;
    EXPECT_EQ(detector.getFrontier(0, 1), t);
    EXPECT_TRUE(detector.scan(plan, pair, 1400, 1800, false).empty());
    EXPECT_EQ(detector.getFrontier(0, 1), t);
}

namespace
{
    /** A team of discs (radius 0.25, one of 0.4) in an empty square, and optionally two planar arms reaching into
        it, whose pairs the detector scans timestep by timestep while the disc pairs are scanned from pieces. */
    MultiRobotSpaceInformationPtr discTeam(std::size_t discs, bool withArms)
    {
        auto env = std::make_shared<Environment>();
        ompl::base::RealVectorBounds bounds(2), joints(2);
        bounds.setLow(-10.);
        bounds.setHigh(10.);
        joints.setLow(-M_PI);
        joints.setHigh(M_PI);
        std::vector<RobotPtr> team;
        for (std::size_t r = 0; r < discs; ++r)
            team.push_back(std::make_shared<DiscRobot>("d" + std::to_string(r), env, r == 1 ? 0.4 : 0.25, bounds));
        if (withArms)
            for (double x : {-4., 4.})
                team.push_back(std::make_shared<PlanarArm>("arm" + std::to_string(team.size()), env, x, 0., 0.,
                                                           std::vector<double>{2., 2.}, 0.2, joints));
        return std::make_shared<MultiRobotSpaceInformation>(team, 128.);
    }

    /** Paths of a few long straight pieces between random waypoints (what the planners lay), with holds. */
    MultiRobotPlan piecewisePlan(const MultiRobotSpaceInformation &si, std::mt19937 &rng)
    {
        std::uniform_real_distribution<double> where(-3., 3.), angle(-3., 3.);
        std::uniform_int_distribution<std::size_t> steps(0, 600), pieces(1, 5);
        MultiRobotPlan plan(si);
        for (std::size_t r = 0; r < si.getRobotCount(); ++r)
        {
            const bool disc = si.getRobot(r)->getKind() == "disc";
            const auto draw = [&] {
                return disc ? std::vector<double>{where(rng), where(rng)} : std::vector<double>{angle(rng), angle(rng)};
            };
            std::vector<double> q = draw();
            TimedPath path(2, q.data());
            for (std::size_t k = pieces(rng); k > 0; --k)
            {
                const std::vector<double> next = k % 3 == 0 ? q : draw();  // some pieces hold still
                path.appendMotion(q.data(), next.data(), steps(rng));
                q = next;
            }
            plan.setPath(r, path);
        }
        return plan;
    }
}  // namespace

TEST(ConflictDetector, DiscPairsScannedFromPiecesMatchBruteForce)
{
    // Long straight pieces (up to 600 timesteps) and cuts of them (splices leave pieces with offsets), discs
    // alone and among arms: ARC's and the workers' scans, and the frontiers, against every timestep and pair.
    std::mt19937 rng(47);
    int withConflicts = 0;
    for (bool arms : {false, true})
    {
        const auto si = discTeam(6, arms);
        for (int k = 0; k < 25; ++k)
        {
            auto plan = piecewisePlan(*si, rng);
            const auto other = piecewisePlan(*si, rng);
            const std::size_t robot = k % si->getRobotCount(), cut = plan.getArrival(robot) / 2;
            plan.splice(robot, cut, cut + 40, other.getPath(robot));
            withConflicts += !test::allConflicts(*si, plan).empty();
            for (std::size_t h : {0, 64})
                expectScansMatchBruteForce(*si, plan, h);
        }
    }
    EXPECT_GT(withConflicts, 20);
}

TEST(ConflictDetector, GrazingDiscsAreDecidedExactlyAsAtEveryTimestep)
{
    // Two discs (radii 0.25 and 0.4) pass each other on parallel lines and on crossing ones, their closest
    // distance a hair above, at or below the sum of the radii: the piece scan must agree with the bodies' test
    // at every timestep, and the cases below and above must come out differently.
    const auto si = discTeam(2, false);
    int conflicting = 0, clear = 0;
    for (double gap : {-1e-6, -1e-12, 0., 1e-12, 1e-6})
        for (double slant : {0., 0.3})
        {
            const double y = 0.65 + gap;
            MultiRobotPlan plan(*si);
            const double a0[2] = {-5., 0.}, a1[2] = {5., 0.}, b0[2] = {5., y - slant}, b1[2] = {-5., y + slant};
            TimedPath pa(2, a0), pb(2, b0);
            pa.appendMotion(a0, a1, 1280);
            pb.appendMotion(b0, b1, 1280);
            plan.setPath(0, pa);
            plan.setPath(1, pb);
            const auto expected = test::allConflicts(*si, plan);
            ConflictDetector detector(*si);
            const auto found = detector.findEarliest(plan);
            ASSERT_EQ(found.has_value(), !expected.empty()) << "gap " << gap << ", slant " << slant;
            if (found)
                EXPECT_EQ(*found, expected.front());
            (found ? conflicting : clear)++;
        }
    EXPECT_GE(conflicting, 2);
    EXPECT_GE(clear, 2);
}

TEST(ConflictDetector, ConcurrentScansOfAMixedTeam)
{
    // Two threads scan interleaved pair subsets of discs among arms: disc pairs from pieces, arm pairs through
    // the shared swept bounds; together they find each pair's first conflict, as brute force does.
    std::mt19937 rng(53);
    const auto si = discTeam(5, true);
    for (int k = 0; k < 8; ++k)
    {
        const auto plan = piecewisePlan(*si, rng);
        expectConcurrentScansMatchBruteForce(*si, plan, 16);
    }
}

namespace
{
    /** \brief Every robot of \e problem on one straight piece from its start to its goal (a few bytes per robot
        whatever the distance, unlike test::straightLinePlan's dense states). */
    MultiRobotPlan straightPiecePlan(const MultiRobotProblem &problem)
    {
        const auto &si = *problem.getSpaceInformation();
        MultiRobotPlan plan(si);
        for (std::size_t r = 0; r < si.getRobotCount(); ++r)
        {
            const auto &s = problem.getStart(r), &g = problem.getGoal(r);
            TimedPath path(si.getRobot(r)->getDimension(), s.data());
            path.appendMotion(s.data(), g.data(),
                              MultiRobotPlan::stepsFor(si.getRobot(r)->distance(s.data(), g.data()),
                                                       si.getResolution()));
            path.trimArrival();
            plan.setPath(r, path);
        }
        return plan;
    }
}  // namespace

/* The pairs tracked for a well-separated team grow with the team, not with its square: of Mobile Cross 2000's
   1 999 000 pairs, those of discs on different lines never meet (the lines are 5 apart), so only the 1000 pairs of
   a line's two discs are tracked, and the earliest conflict is a line's head-on swap. */
TEST(ConflictDetector, TracksPairsInProportionToAWellSeparatedTeam)
{
    const auto problem = scenarios::createMobileCross(2000);
    const auto plan = straightPiecePlan(problem);
    ConflictDetector detector(*problem.getSpaceInformation());
    ASSERT_TRUE(detector.discoverPairs(plan));
    EXPECT_EQ(detector.getPairCount(), 1000u);
    for (std::size_t r = 0; r < 2000; r += 2)
        ASSERT_TRUE(detector.findPair(r, r + 1)) << "line " << r / 2;
    const auto earliest = detector.findEarliest(plan);
    ASSERT_TRUE(earliest);
    EXPECT_EQ(earliest->second, earliest->first + 1);
    EXPECT_EQ(earliest->first % 2, 0u);
}

/* Discovery is sound on a spread team whose plans change: every pair brute force finds in conflict is tracked, and
   the earliest conflict is brute force's, after a new plan (the sweep over the whole team) and after robot a copies
   far robot b's path from timestep t on (the changed robot alone tested against the team). */
TEST(ConflictDetector, TracksEveryConflictingPairAcrossInvalidations)
{
    std::mt19937 rng(71);
    const auto problem = scenarios::createMobileCross(40, 8.);  // 1600 timesteps: brute force stays quick
    const auto &si = *problem.getSpaceInformation();
    std::uniform_int_distribution<std::size_t> robot(0, si.getRobotCount() - 1);
    const auto expectTracked = [&](ConflictDetector &detector, const MultiRobotPlan &plan)
    {
        ASSERT_TRUE(detector.discoverPairs(plan));
        const auto all = test::allConflicts(si, plan);
        for (const Conflict &c : all)
            ASSERT_TRUE(detector.findPair(c.first, c.second)) << c.first << ", " << c.second;
        const auto found = detector.findEarliest(plan);
        ASSERT_EQ(found.has_value(), !all.empty());
        if (found)
            EXPECT_EQ(*found, all.front());
        EXPECT_LT(detector.getPairCount(), si.getRobotCount() * (si.getRobotCount() - 1) / 2);
    };
    for (int k = 0; k < 10; ++k)
    {
        auto plan = straightPiecePlan(problem);
        ConflictDetector detector(si, 16);
        expectTracked(detector, plan);
        const std::size_t a = robot(rng), b = (a + 7 + robot(rng) % 20) % si.getRobotCount();
        const std::size_t t = std::uniform_int_distribution<std::size_t>(0, plan.getArrival(a))(rng);
        test::followFrom(plan, a, b, t);
        detector.invalidate(a, t);
        expectTracked(detector, plan);
    }
}

/* A scan over a large team honours the planning's stop: with the thread's termination condition fired, a scan of
   Mobile Cross 2000's pairs checks at most one poll interval of them and leaves the rest unchecked (frontier 0),
   and a discovery stops before its sweep; a later scan without the stop finds the earliest conflict as usual. */
TEST(ConflictDetector, ScansAndDiscoveryOfALargeTeamStopOnceTheTerminationConditionFires)
{
    const auto problem = scenarios::createMobileCross(2000);
    const auto plan = straightPiecePlan(problem);
    const ompl::base::PlannerTerminationCondition fired([] { return true; });
    ConflictDetector detector(*problem.getSpaceInformation());
    {
        const StopSignal::Scope scope(fired);
        EXPECT_FALSE(detector.discoverPairs(plan));
        EXPECT_FALSE(detector.findEarliest(plan));
    }
    ASSERT_TRUE(detector.discoverPairs(plan));
    const auto pairs = allPairs(detector, plan);
    {
        const StopSignal::Scope scope(fired);
        EXPECT_TRUE(detector.scan(plan, pairs, 0, plan.getMakespan() + 1, false).size() < 256u);
    }
    std::size_t checked = 0;
    for (std::size_t p = 0; p < detector.getPairCount(); ++p)
        checked += detector.getFrontier(detector.getPair(p).first, detector.getPair(p).second) > 0 ? 1 : 0;
    EXPECT_LT(checked, 256u);
    const auto earliest = detector.findEarliest(plan);
    ASSERT_TRUE(earliest);
    EXPECT_EQ(earliest->second, earliest->first + 1);
}
