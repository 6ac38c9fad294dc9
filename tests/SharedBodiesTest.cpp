#include "TestProblems.h"

#include "ompl_parc/SharedBodies.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <gtest/gtest.h>

#include <thread>

using namespace ompl_parc;

namespace
{
    bool sameBody(const CollisionBody &a, const CollisionBody &b)
    {
        return a.ax_ == b.ax_ && a.ay_ == b.ay_ && a.az_ == b.az_ && a.bx_ == b.bx_ && a.by_ == b.by_ &&
               a.bz_ == b.bz_ && a.radius_ == b.radius_ && a.boundRadius_ == b.boundRadius_;
    }
}  // namespace

/* Four threads ask for every body of two rounds of a Panda Cage 4 plan (straight joint-space lines), each in
   its own order, so that slots are claimed, found being computed and found ready: every body a thread gets is
   the one computeBody gives. The ThreadSanitizer pass runs this too. */
TEST(SharedBodies, EveryThreadGetsTheRobotsBodiesWhoeverComputedThem)
{
    const auto problem = scenarios::createPandaCage(4, 0);
    const auto &si = *problem.getSpaceInformation();
    MultiRobotPlan plan(si);
    for (std::size_t r = 0; r < si.getRobotCount(); ++r)
        plan.setRobotPath(r, test::straightLine(problem.getStart(r), problem.getGoal(r), si.getResolution()));
    SharedBodies shared(si);
    constexpr unsigned int THREADS = 4;
    for (const auto &[from, to] : {std::pair<std::size_t, std::size_t>{0, 40}, {25, 90}})
    {
        shared.reset(plan, from, to);
        EXPECT_TRUE(shared.covers(from));
        EXPECT_FALSE(shared.covers(to));
        std::vector<int> mismatches(THREADS, 0);
        std::vector<std::thread> threads;
        for (unsigned int k = 0; k < THREADS; ++k)
            threads.emplace_back(
                [&, k]
                {
                    CollisionBody scratch, expected;
                    for (std::size_t n = 0; n < si.getRobotCount() * (to - from); ++n)
                    {
                        // Thread k walks the slots forwards (even k) or backwards, from its own offset.
                        const std::size_t m = (k % 2 == 0 ? n : si.getRobotCount() * (to - from) - 1 - n);
                        const std::size_t robot = (m + k) % si.getRobotCount(), t = from + m / si.getRobotCount();
                        si.getRobot(robot)->computeBody(plan.getConfig(robot, t), expected);
                        mismatches[k] += sameBody(shared.get(robot, t, scratch), expected) ? 0 : 1;
                    }
                });
        for (auto &thread : threads)
            thread.join();
        for (unsigned int k = 0; k < THREADS; ++k)
            EXPECT_EQ(mismatches[k], 0) << "thread " << k << ", round [" << from << ", " << to << ")";
    }
}
