#include "TestProblems.h"

#include "ompl_parc/arc/BatchDetector.h"
#include "ompl_parc/arc/ConflictResolver.h"
#include "ompl_parc/arc/RepairLoop.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/statespaces/HugePageMemory.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    bool shares(const Conflict &a, const Conflict &b)
    {
        return a.first == b.first || a.first == b.second || a.second == b.first || a.second == b.second;
    }
}  // namespace

class BatchDetection : public testing::TestWithParam<std::tuple<unsigned int, unsigned int, unsigned int, bool>>
{
};

/* For any W, batch capacity (conflicts per worker) and H: the batch starts with the sequential earliest conflict, is
   robot-disjoint, holds only real conflicts, and each accepted conflict meets the paper's definition (strict: nothing
   earlier shares a robot; optimistic: every earlier conflict sharing a robot has its other robot in an earlier accepted
   conflict). */
TEST_P(BatchDetection, MatchesTheSequentialScanAndTheDefinitions)
{
    const auto [workers, perWorker, horizon, optimistic] = GetParam();
    const std::size_t capacity = std::size_t{workers} * perWorker;
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    WorkerPool pool(workers);
    std::mt19937 rng(21);
    int batches = 0;
    std::size_t largest = 0;
    for (int k = 0; k < 20; ++k)
    {
        const auto plan = test::randomWalkPlan(si, rng, 0.04);
        // Every other plan with earlier repairs on record: robot sets then grow, so conflicts get deferred
        // while their own robots stay out of the batch (their pairs keep being scanned).
        RepairCache cache;
        if (k % 2 == 1)
        {
            cache.add({0, 1}, 0, 1000);
            cache.add({2, 5}, 0, 1000);
        }
        const auto all = test::allConflicts(si, plan);
        ConflictDetector detector(si);
        const auto detected = BatchDetector(detector, pool, horizon, capacity, optimistic)
                                  .detect(plan, cache, 200, ob::plannerNonTerminatingCondition());
        const auto &batch = detected.entries;
        ASSERT_EQ(batch.empty(), all.empty());
        if (batch.empty())
            continue;
        ++batches;
        EXPECT_LE(batch.size(), capacity);
        largest = std::max(largest, batch.size());
        EXPECT_EQ(batch.front().conflict, all.front());
        std::vector<int> used(8, 0);
        for (const auto &entry : batch)
        {
            EXPECT_NE(std::find(all.begin(), all.end(), entry.conflict), all.end());
            for (std::size_t r : entry.team)
                EXPECT_EQ(used[r]++, 0) << "robot " << r << " in two batch conflicts";
            if (entry.team.size() > 2)
                continue;  // the definitions below are checked for pair teams (no cached repairs involved)
            for (const auto &earlier : all)
            {
                if (!(earlier < entry.conflict) || !shares(earlier, entry.conflict))
                    continue;
                ASSERT_TRUE(optimistic) << "strict batch accepted a conflict with an earlier one sharing a robot";
                const std::size_t other =
                    (earlier.first == entry.conflict.first || earlier.first == entry.conflict.second) ? earlier.second
                                                                                                      : earlier.first;
                const bool explained = std::any_of(
                    batch.begin(), batch.end(),
                    [&](const BatchEntry &e)
                    { return e.conflict < earlier && (e.conflict.first == other || e.conflict.second == other); });
                EXPECT_TRUE(explained) << "conflict at " << entry.conflict.timestep
                                       << " not optimistically independent";
            }
        }
        EXPECT_GE(detected.projectedSeconds, 0.);
        // Frontiers are sound: no pair is marked conflict-free past one of its conflicts, also after the
        // detection rounds that followed a conflict (a second call must resume correctly too).
        const auto sound = [&]
        {
            for (const auto &c : all)
                ASSERT_LE(detector.getFrontier(c.first, c.second), c.timestep)
                    << "pair (" << c.first << ", " << c.second << ") passed its conflict at " << c.timestep;
        };
        sound();
        BatchDetector(detector, pool, horizon, capacity, optimistic)
            .detect(plan, cache, 200, ob::plannerNonTerminatingCondition());
        sound();
    }
    EXPECT_GT(batches, 5);
    if (capacity > 1)
        EXPECT_GE(largest, 2u) << "no batch held more than one conflict";
}

/* One detector kept across calls, as the repair loop keeps it: pairs found conflict-free to their end leave the
   workers' lists, and an invalidation of one of their robots must bring them back. Robot a's path is replaced
   from timestep t on by a copy of robot b's (so a and b now collide), after a call settled their pair. */
TEST(BatchDetection, SettledPairsAreScannedAgainAfterAnInvalidation)
{
    const auto problem = scenarios::createMobileCircle(8);
    const auto &si = *problem.getSpaceInformation();
    WorkerPool pool(2);
    std::mt19937 rng(61);
    std::uniform_int_distribution<std::size_t> robot(0, 7);
    for (int k = 0; k < 20; ++k)
    {
        auto plan = test::randomWalkPlan(si, rng, 0.04);
        ConflictDetector detector(si);
        BatchDetector batches(detector, pool, 50, 2, true);
        const RepairCache cache;
        batches.detect(plan, cache, 200, ob::plannerNonTerminatingCondition());
        const std::size_t a = robot(rng), b = (a + 1 + robot(rng) % 7) % 8;
        const std::size_t t = std::uniform_int_distribution<std::size_t>(0, plan.getArrival(a))(rng);
        test::followFrom(plan, a, b, t);
        batches.invalidate(a, t);
        const auto all = test::allConflicts(si, plan);
        ASSERT_FALSE(all.empty());
        const auto after = batches.detect(plan, cache, 200, ob::plannerNonTerminatingCondition()).entries;
        ASSERT_FALSE(after.empty());
        EXPECT_EQ(after.front().conflict, all.front());
    }
}

TEST(BatchDetection, ChunkedScansFindTheSameBatchWithAnyWorkerCount)
{
    // 80 robots have 3160 pairs: W = 2 and 3 workers claim 8 and 13 chunks of them in the first round, W = 1 scans
    // one. A round's candidates are each pair's first conflict in the window (with capacity 1: the conflicts at the
    // earliest timestep), however the pairs are shared, so the batch must not depend on W (same capacity and
    // horizon); with capacity 1 it is the earliest conflict.
    const auto problem = scenarios::createMobileCircle(80);
    const auto &si = *problem.getSpaceInformation();
    std::vector<std::unique_ptr<WorkerPool>> pools;
    for (unsigned int w : {1u, 2u, 3u})
        pools.push_back(std::make_unique<WorkerPool>(w));
    std::mt19937 rng(83);
    for (int k = 0; k < 6; ++k)
    {
        const auto plan = test::randomWalkPlan(si, rng, 0.04);
        const auto all = test::allConflicts(si, plan);
        ASSERT_FALSE(all.empty());
        for (const std::size_t capacity : {1, 12})
        {
            std::vector<std::vector<BatchEntry>> batches;
            for (const auto &pool : pools)
            {
                ConflictDetector detector(si);
                const RepairCache cache;
                batches.push_back(BatchDetector(detector, *pool, 100, capacity, true)
                                      .detect(plan, cache, 200, ob::plannerNonTerminatingCondition())
                                      .entries);
            }
            ASSERT_FALSE(batches[0].empty());
            EXPECT_EQ(batches[0].front().conflict, all.front());
            EXPECT_EQ(batches[0].size() == 1, capacity == 1);
            for (std::size_t w = 1; w < batches.size(); ++w)
            {
                ASSERT_EQ(batches[w].size(), batches[0].size()) << "W = " << w + 1 << ", capacity " << capacity;
                for (std::size_t e = 0; e < batches[0].size(); ++e)
                {
                    EXPECT_EQ(batches[w][e].conflict, batches[0][e].conflict) << "W = " << w + 1;
                    EXPECT_EQ(batches[w][e].team, batches[0][e].team) << "W = " << w + 1;
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(WorkersHorizons, BatchDetection,
                         testing::Combine(testing::Values(1u, 2u, 3u, 4u), testing::Values(1u, 4u),
                                          testing::Values(1u, 7u, 50u, 400u), testing::Bool()),
                         [](const auto &info)
                         {
                             return "W" + std::to_string(std::get<0>(info.param)) + "_B" +
                                    std::to_string(std::get<1>(info.param)) + "_H" +
                                    std::to_string(std::get<2>(info.param)) +
                                    (std::get<3>(info.param) ? "_optimistic" : "_strict");
                         });

TEST(Parc, OneWorkerComputesWhatArcComputes)
{
    for (const auto &[scenario, profile] :
         {std::make_pair("mobile_cross", "mobile"), std::make_pair("planar_cross", "planar")})
    {
        const auto problem = scenarios::createScenario(scenario, 8);
        ARC arc(problem.getSpaceInformation());
        PARC parc(problem.getSpaceInformation());
        for (ArcPlannerBase *p : {static_cast<ArcPlannerBase *>(&arc), static_cast<ArcPlannerBase *>(&parc)})
        {
            p->setProfile(profile);
            p->setSeed(9);
            ASSERT_EQ(test::solveWith(*p, problem), ob::PlannerStatus::EXACT_SOLUTION) << p->getName();
        }
        EXPECT_TRUE(SolutionValidator(problem).validate(parc.getPlan()).valid);
        // A seed fixes the plan only while no solver call reaches its time cap (ConflictResolver.h), which is at
        // least MIN_CALL_SECONDS: here calls take milliseconds. Under ThreadSanitizer (10-20x slower, two tests
        // at once) one may reach it in one run and not the other; there the equality is checked only if neither
        // run had a call that long. Elsewhere the premise itself is asserted.
        const bool uncapped = arc.getStatistics().longestSolverCall < ConflictResolver::MIN_CALL_SECONDS &&
                              parc.getStatistics().longestSolverCall < ConflictResolver::MIN_CALL_SECONDS;
#ifndef OMPL_PARC_SANITIZED
        ASSERT_TRUE(uncapped) << scenario;
#endif
        if (!uncapped)
            continue;
        for (std::size_t r = 0; r < 8; ++r)
            EXPECT_EQ(arc.getPlan().getRobotPath(r), parc.getPlan().getRobotPath(r)) << scenario << " robot " << r;
        EXPECT_EQ(arc.getStatistics().conflicts, parc.getStatistics().conflicts);
    }
}

class ParcSolves : public testing::TestWithParam<std::tuple<std::string, std::size_t, unsigned int, bool>>
{
};

TEST_P(ParcSolves, AndTheIndependentValidatorAgrees)
{
    const auto [scenario, robots, workers, optimistic] = GetParam();
    const auto problem = scenarios::createScenario(scenario, robots);
    PARC parc(problem.getSpaceInformation());
    parc.setProfile(scenario == "planar_cross" ? "planar" : "mobile");
    parc.setWorkers(workers);
    parc.setOptimistic(optimistic);
    parc.setSeed(4);
    // Typically 0.05 s (1 s under TSan), but under TSan 2 of 320 runs of planar_cross16_W4 took 52-56 s (the
    // interleaving of 4 workers on 2 cores changes the batches, and one team's PP-ST-RRT repairs ran into their
    // sample caps): the limit is far above that, as this test checks the plan, not the speed.
    ASSERT_EQ(test::solveWith(parc, problem, 240.), ob::PlannerStatus::EXACT_SOLUTION) << parc.getStatusMessage();
    const auto report = SolutionValidator(problem).validate(parc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
    const auto &s = parc.getParallelStatistics();
    EXPECT_GT(s.batches, 0u);
    EXPECT_LE(s.firstBatchSize, workers * parc.getBatchPerWorker());
    EXPECT_GT(s.projectedInitial + s.projectedDetection + s.projectedResolution, 0.);
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, ParcSolves,
    testing::Values(std::make_tuple("mobile_cross", 16, 2, true), std::make_tuple("mobile_cross", 16, 4, false),
                    std::make_tuple("mobile_circle", 8, 2, true), std::make_tuple("mobile_circle", 8, 3, true),
                    std::make_tuple("planar_cross", 8, 2, true), std::make_tuple("planar_cross", 16, 4, true)),
    [](const auto &info)
    {
        return std::get<0>(info.param) + std::to_string(std::get<1>(info.param)) + "_W" +
               std::to_string(std::get<2>(info.param)) + (std::get<3>(info.param) ? "" : "_strict");
    });

/* P-ARC's workers allocate and fill their shares of the solution path (at 256 robots a share is over
   HugePageMemory::LARGE: mapped on its own, and kept for reuse when freed). Three solves, the third after the first's
   path was freed while the second's is held, so that it may take the first's kept mappings: every path is exactly
   the plan as handed to OMPL, and every plan validates. */
TEST(Parc, SolutionPathsOfALargeTeamFollowThePlanWhenTheirMemoryIsReused)
{
    const auto problem = scenarios::createScenario("mobile_cross", 256);
    std::vector<ob::PathPtr> held;
    for (unsigned int solve = 0; solve < 3; ++solve)
    {
        PARC parc(problem.getSpaceInformation());
        parc.setWorkers(2);
        parc.setSeed(1 + solve);
        ASSERT_EQ(test::solveWith(parc, problem, 240.), ob::PlannerStatus::EXACT_SOLUTION) << parc.getStatusMessage();
        const auto report = SolutionValidator(problem).validate(parc.getPlan());
        EXPECT_TRUE(report.valid) << report.message;
        held.push_back(parc.getProblemDefinition()->getSolutionPath());
        const auto &path = *held.back()->as<ompl::geometric::PathGeometric>();
        EXPECT_GT(path.getStateCount() * problem.getSpaceInformation()->getStateSpace()->getSerializationLength(),
                  2 * HugePageMemory::LARGE);
        EXPECT_TRUE(test::pathFollowsPlan(*problem.getSpaceInformation(), path, parc.getPlan())) << "solve " << solve;
        if (solve == 1)
            held.erase(held.begin());
    }
}

TEST(Parc, StopsPromptlyWithEveryWorkerJoinedThenContinues)
{
    // Mobile Circle 16 takes P-ARC-3 0.10-0.36 s here, so the 30 ms stop comes mid-solve (Mobile Circle 12, 0.04-0.09
    // s since the worker-pool change, finished first in about one run in thirty).
    const auto problem = scenarios::createMobileCircle(16);
    PARC parc(problem.getSpaceInformation());
    parc.setWorkers(3);
    parc.setSeed(2);
    parc.setProblemDefinition(problem.createProblemDefinition());
    const auto start = ompl::time::now();
    EXPECT_EQ(parc.solve(ob::timedPlannerTerminationCondition(0.03)), ob::PlannerStatus::TIMEOUT);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.03 + test::promptReturn());
    ASSERT_EQ(parc.solve(ob::timedPlannerTerminationCondition(120.)), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(SolutionValidator(problem).validate(parc.getPlan()).valid);
}

TEST(Parc, BadWorkerAndHorizonSettingsAreClearErrors)
{
    const auto problem = scenarios::createMobileCross(4);
    PARC parc(problem.getSpaceInformation());
    EXPECT_THROW(parc.setWorkers(0), ompl::Exception);
    EXPECT_THROW(parc.setHorizon(0), ompl::Exception);
    EXPECT_THROW(parc.params().setParam("workers", "0"), ompl::Exception);  // OMPL passes setter errors on
    EXPECT_THROW(parc.params().setParam("batch_per_worker", "0"), ompl::Exception);
    for (const char *name : {"workers", "horizon", "batch_per_worker", "optimistic", "local_or", "window", "seed"})
        EXPECT_TRUE(parc.params().hasParam(name)) << name;
}

/* A batch holds up to batch_per_worker x W conflicts (8 by default), and W with batch_per_worker = 1, the paper's
   batch: Mobile Cross 32 has many robot-disjoint conflicts around its middle, so the default's first batch holds more
   than W. Without grow_batches no batch holds more; with it (the default) Mobile Cross's crossing pairs, whose
   repairs do not meet, fill batches of twice and four times W. */
TEST(Parc, BatchesHoldUpToBatchPerWorkerTimesWConflicts)
{
    const auto problem = scenarios::createMobileCross(32);
    for (const bool grow : {false, true})
        for (unsigned int perWorker : {8u, 1u})
        {
            PARC parc(problem.getSpaceInformation());
            parc.setWorkers(2);
            parc.setBatchPerWorker(perWorker);
            parc.setGrowBatches(grow);
            parc.setSeed(3);
            ASSERT_EQ(test::solveWith(parc, problem), ob::PlannerStatus::EXACT_SOLUTION) << parc.getStatusMessage();
            EXPECT_TRUE(SolutionValidator(problem).validate(parc.getPlan()).valid);
            const auto &s = parc.getParallelStatistics();
            EXPECT_LE(s.firstBatchSize, 2 * perWorker);
            if (perWorker > 1)
                EXPECT_GT(s.firstBatchSize, 2u);
            if (!grow)
                EXPECT_LE(s.largestBatch, 2 * perWorker);
            else if (perWorker == 1)
                EXPECT_GE(s.largestBatch, 8u);
        }
}

/* The growth rule on its own: twice as many after a full batch none of whose conflicts pairs robots of two different
   repairs of the batch before, up to 8 x the base; the same after a batch that was not full; back to the base after
   a conflict between two repairs' robots (a conflict within one repair's team, or with a robot no repair moved, is
   not a meeting). */
TEST(Parc, BatchCapacityGrowsWhileTheRepairsOfABatchDoNotMeet)
{
    // The batch before: robots 0 and 1 repaired together, 2 and 3 together; robots 4 to 63 not repaired.
    std::vector<int> lastRepair(64, -1);
    lastRepair[0] = lastRepair[1] = 0;
    lastRepair[2] = lastRepair[3] = 1;
    const auto batch = [](std::vector<std::pair<std::size_t, std::size_t>> pairs)
    {
        std::vector<BatchEntry> entries;
        for (const auto &[a, b] : pairs)
            entries.push_back({Conflict{a, b, 10}, {a, b}});
        return entries;
    };
    // n conflicts of robots no repair moved.
    const auto fresh = [&batch](std::size_t n)
    {
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        for (std::size_t k = 0; k < n; ++k)
            pairs.emplace_back(4 + 2 * k, 5 + 2 * k);
        return batch(pairs);
    };
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 2, batch({{0, 4}, {1, 5}}), lastRepair), 4u);
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 2, batch({{0, 1}, {4, 5}}), lastRepair), 4u);
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 8, batch({{0, 4}, {1, 5}}), lastRepair), 8u);  // not full
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 8, fresh(8), lastRepair), 16u);
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 16, fresh(16), lastRepair), 16u);  // 8 x 2: the most
    EXPECT_EQ(RepairLoop::nextBatchCapacity(3, 12, fresh(12), lastRepair), 24u);
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 2, batch({{0, 2}, {4, 5}}), lastRepair), 2u);  // repairs 0 and 1 met
    EXPECT_EQ(RepairLoop::nextBatchCapacity(2, 8, batch({{3, 1}}), lastRepair), 2u);
}

/* A repair that grew to every robot (the team's global problem failed around the others' paths) shares robots with
   the batch's other repairs; a patch continues the plan it was made from, so only one of them may be spliced (the
   other would jump: before the fix, a robot moved 0.11 in one timestep, and this test failed 5 runs of 5). On
   crossing 24 instance 2 most P-ARC-2 runs meet such a batch (18 of 20 demo runs; which batches do depends on the
   repairs' time caps, so on the machine's speed). One seed under the sanitizers, which run several times slower. */
TEST(Parc, ARepairOfEveryRobotIsNotSplicedOverByItsBatch)
{
    const auto problem = scenarios::createScenario("crossing", 24, 128., 2);
#ifdef OMPL_PARC_SANITIZED
    const std::vector<unsigned int> seeds = {1};
#else
    const std::vector<unsigned int> seeds = {1, 2};
#endif
    for (unsigned int seed : seeds)
    {
        PARC parc(problem.getSpaceInformation());
        parc.setWorkers(2);
        parc.setSeed(seed);
        ASSERT_EQ(test::solveWith(parc, problem, 120.), ob::PlannerStatus::EXACT_SOLUTION) << parc.getStatusMessage();
        const auto report = SolutionValidator(problem).validate(parc.getPlan());
        EXPECT_TRUE(report.valid) << "seed " << seed << ": " << report.message;
    }
}

class OrParcSolves : public testing::TestWithParam<std::tuple<std::string, std::size_t, unsigned int, unsigned int>>
{
};

TEST_P(OrParcSolves, TheWinnerIsValidated)
{
    const auto [scenario, robots, instances, workers] = GetParam();
    const auto problem = scenarios::createScenario(scenario, robots);
    ORPARC orparc(problem.getSpaceInformation());
    ASSERT_TRUE(orparc.params().setParam("profile", scenario == "planar_cross" ? "planar" : "mobile"));
    orparc.setInstances(instances);
    orparc.setWorkers(workers);
    orparc.setSeed(6);
    ASSERT_EQ(test::solveWith(orparc, problem), ob::PlannerStatus::EXACT_SOLUTION) << orparc.getStatusMessage();
    const auto report = SolutionValidator(problem).validate(orparc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
    ob::PlannerData data(problem.getSpaceInformation());
    orparc.getPlannerData(data);
    EXPECT_EQ(data.properties["winner STRING"].rfind("ORPARC#", 0), 0u);
    // The solution in the ProblemDefinition is the winner's plan.
    auto *path = orparc.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    EXPECT_TRUE(test::pathFollowsPlan(*problem.getSpaceInformation(), *path, orparc.getPlan()));
}

INSTANTIATE_TEST_SUITE_P(Scenarios, OrParcSolves,
                         testing::Values(std::make_tuple("mobile_cross", 8, 2, 1),
                                         std::make_tuple("mobile_circle", 8, 2, 2),
                                         std::make_tuple("planar_cross", 8, 3, 1)),
                         [](const auto &info)
                         {
                             return std::get<0>(info.param) + std::to_string(std::get<1>(info.param)) + "_" +
                                    std::to_string(std::get<2>(info.param)) + "x" +
                                    std::to_string(std::get<3>(info.param));
                         });

TEST(OrParc, OddInstancesRepairEagerlyUnlessDiversifyIsOff)
{
    // A portfolio: on mobile robots the odd instances get a quarter of the sample cap and twice the window growth,
    // the even ones the prototype's settings; with diversify off, every instance is the prototype, as in the paper's
    // OR. The panda profile's schedule is eager already: its odd instances keep it (other seeds only).
    const auto mobile = scenarios::createMobileCross(4);
    ORPARC orparc(mobile.getSpaceInformation());
    EXPECT_TRUE(orparc.getDiversify());
    orparc.setProblemDefinition(mobile.createProblemDefinition());
    const auto even = orparc.createInstance(0, 9), odd = orparc.createInstance(1, 9),
               third = orparc.createInstance(3, 9);
    EXPECT_EQ(even->getSampleCap(), 5000u);
    EXPECT_DOUBLE_EQ(even->getMinWindowGrowth(), 1.);
    for (const auto &eager : {odd, third})
    {
        EXPECT_EQ(eager->getSampleCap(), 1250u);
        EXPECT_DOUBLE_EQ(eager->getMinWindowGrowth(), 2.);
        EXPECT_EQ(eager->getWindow(), even->getWindow());  // the rest is the prototype's
    }
    ASSERT_TRUE(orparc.params().setParam("diversify", "0"));
    EXPECT_EQ(orparc.createInstance(1, 9)->getSampleCap(), 5000u);

    const auto cage = scenarios::createPandaCage(4);
    ORPARC arms(cage.getSpaceInformation());
    arms.setProblemDefinition(cage.createProblemDefinition());
    for (const unsigned int k : {0u, 1u})
    {
        EXPECT_EQ(arms.createInstance(k, 9)->getSampleCap(), 12500u) << k;
        EXPECT_DOUBLE_EQ(arms.createInstance(k, 9)->getMinWindowGrowth(), 2.5) << k;
    }
    // The eager schedule's limits: no cap stays none, the growth stops at the parameter's top.
    ArcSettings settings;
    settings.sampleCap = 0;
    settings.minWindowGrowth = 2.;
    EXPECT_EQ(settings.eager().sampleCap, 0u);
    EXPECT_DOUBLE_EQ(settings.eager().minWindowGrowth, 4.);
    settings.sampleCap = 2000;
    EXPECT_EQ(settings.eager().sampleCap, 1000u);
}

TEST(OrParc, InconsistentWorkerBudgetsAreClearErrorsAndTimeoutIsPrompt)
{
    const auto problem = scenarios::createMobileCircle(12);
    ORPARC orparc(problem.getSpaceInformation());
    EXPECT_THROW(orparc.setInstances(0), ompl::Exception);
    orparc.setInstances(3);
    EXPECT_THROW(orparc.setTotalWorkers(4), ompl::Exception);
    orparc.setTotalWorkers(6);
    EXPECT_EQ(orparc.getWorkers(), 2u);
    orparc.setProblemDefinition(problem.createProblemDefinition());
    const auto start = ompl::time::now();
    EXPECT_EQ(orparc.solve(ob::timedPlannerTerminationCondition(0.03)), ob::PlannerStatus::TIMEOUT);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.03 + test::promptReturn());
}

TEST(Parc, SixteenWorkersOnPandaCage16StopPromptly)
{
    // Issue 15: every worker, solver call and motion check notices the stop, also when 16 workers share a small
    // machine's cores (the benchmark ompl_parc_bench_stop measures the lateness; this bound is generous).
    const auto problem = scenarios::createPandaCage(16, 3);
    for (double limit : {0.3, 1.0})
    {
        PARC parc(problem.getSpaceInformation());
        ASSERT_TRUE(parc.params().setParam("profile", "panda"));
        parc.setWorkers(16);
        parc.setSeed(1);
        parc.setProblemDefinition(problem.createProblemDefinition());
        const auto start = ompl::time::now();
        const auto status = parc.solve(ob::timedPlannerTerminationCondition(limit));
        EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), limit + test::promptReturn());
        if (status == ob::PlannerStatus::EXACT_SOLUTION)
            EXPECT_TRUE(SolutionValidator(problem).validate(parc.getPlan()).valid);
        else
            EXPECT_EQ(status, ob::PlannerStatus::TIMEOUT);
    }
}

TEST(Parc, StopsPromptlyAtTheFinestResolution)
{
    // At 3e6 timesteps per unit (near the finest a team of these bounds accepts, MultiRobotPlan::MAX_TIMESTEP to
    // cross them) one motion check spans tens of millions of states: motion checks poll the stop too. The two
    // discs can never pass each other (no solution exists), so every run ends by the stop: initial paths, detection
    // and repairs of ever larger windows, each with motion checks over up to 3e7 states, until the limit.
    const auto swap = test::corridorSwap(3e6);
    for (unsigned int workers : {1u, 2u})
    {
        PARC parc(swap.getSpaceInformation());
        parc.setWorkers(workers);
        parc.setSeed(1);
        parc.setProblemDefinition(swap.createProblemDefinition());
        const auto start = ompl::time::now();
        EXPECT_EQ(parc.solve(ob::timedPlannerTerminationCondition(0.3)), ob::PlannerStatus::TIMEOUT);
        EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.3 + test::promptReturn());
    }
}
