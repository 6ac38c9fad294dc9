#include "ompl_parc/arc/ConflictBatch.h"

#include <gtest/gtest.h>

using namespace ompl_parc;

namespace
{
    /** Offer conflicts {i, j, t} (robot set = the pair) in order; return which were accepted. */
    std::vector<bool> offerAll(ConflictBatch &batch, const std::vector<Conflict> &conflicts)
    {
        std::vector<bool> accepted;
        for (const auto &c : conflicts)
            accepted.push_back(batch.offer(c, {c.first, c.second}));
        return accepted;
    }
}  // namespace

/* The paper's Fig. 1: red {r2, r3} is independent; grey {r2, r4} and {r1, r3} come next; yellow {r1, r4} is
   optimistically independent (repairing red desynchronises r2 and r3, likely removing both grey ones), but
   not strictly independent. */
TEST(ConflictBatch, PaperFigureOneOptimisticAcceptsYellowStrictDoesNot)
{
    const std::vector<Conflict> all = {{2, 3, 10}, {2, 4, 20}, {1, 3, 30}, {1, 4, 40}};
    ConflictBatch optimistic(true, 4, 5);
    EXPECT_EQ(offerAll(optimistic, all), (std::vector<bool>{true, false, false, true}));
    ConflictBatch strict(false, 4, 5);
    EXPECT_EQ(offerAll(strict, all), (std::vector<bool>{true, false, false, false}));
}

TEST(ConflictBatch, OptimisticSkipsPairsOfBatchRobotsStrictOnlyFullyInvolvedPairs)
{
    ConflictBatch optimistic(true, 4, 5), strict(false, 4, 5);
    for (auto *b : {&optimistic, &strict})
        EXPECT_TRUE(b->offer({2, 3, 10}, {2, 3}));
    // Optimistic: once r2 is in the batch its pairs need no more checks (their conflicts could never block).
    EXPECT_TRUE(optimistic.skipPair(2, 4));
    EXPECT_FALSE(optimistic.skipPair(1, 4));
    // Strict: (r2, r4) must still be checked, it could make r4's later conflicts dependent.
    EXPECT_FALSE(strict.skipPair(2, 4));
    EXPECT_TRUE(strict.skipPair(2, 3));
}

TEST(ConflictBatch, AnUnexplainedDeferredConflictBlocksLaterOnesRecursively)
{
    ConflictBatch batch(true, 4, 10);
    EXPECT_TRUE(batch.offer({0, 1, 10}, {0, 1}));
    // {5, 6} at 20 grew (repair cache) to include robot 1, which is in the batch: deferred; 5 and 6 unexplained.
    EXPECT_FALSE(batch.offer({5, 6, 20}, {1, 5, 6}));
    // {5, 7} shares r5 with it, but r6 was never in the batch: not optimistically independent.
    EXPECT_FALSE(batch.offer({5, 7, 30}, {5, 7}));
    // ... and now r7 is unexplained too: {7, 8} is blocked in turn.
    EXPECT_FALSE(batch.offer({7, 8, 40}, {7, 8}));
    // An unrelated conflict is still independent.
    EXPECT_TRUE(batch.offer({2, 3, 50}, {2, 3}));
    EXPECT_EQ(batch.getEntries().size(), 2u);
    EXPECT_EQ(batch.getEntries()[1].conflict.timestep, 50u);
}

TEST(ConflictBatch, StopsAtCapacityAndIsRobotDisjoint)
{
    ConflictBatch batch(true, 2, 10);
    EXPECT_TRUE(batch.offer({0, 1, 1}, {0, 1}));
    EXPECT_FALSE(batch.offer({1, 2, 2}, {1, 2}));
    EXPECT_TRUE(batch.offer({3, 4, 3}, {3, 4, 5}));
    EXPECT_TRUE(batch.full());
    EXPECT_FALSE(batch.offer({6, 7, 4}, {6, 7}));
}
