#include "TestProblems.h"
#include "ToolSupport.h"

#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>
#include <ompl/base/PlannerData.h>
#include <ompl/util/Time.h>

#include <algorithm>

using namespace ompl_parc;
namespace ob = ompl::base;

/* The tool path (--param, benchmark configs): a profile and explicit parameters, in either order, give every
   racer the explicit values, the profile's values for the rest, W_k workers and seed mixSeed(seed, k). */
TEST(OrParcRace, ProfileAndExplicitParametersReachEveryRacerInAnyOrder)
{
    const auto problem = scenarios::createMobileCross(4);
    const std::vector<std::string> explicitFirst = {"window=33", "bound_margin=0.25", "instances=3", "total_workers=6",
                                                    "seed=5",    "profile=panda"};
    std::vector<std::string> profileFirst(explicitFirst.rbegin(), explicitFirst.rend());
    std::swap(profileFirst[2], profileFirst[3]);  // instances before total_workers
    for (const auto &params : {explicitFirst, profileFirst})
    {
        auto planner = PlannerRegistry::create("orparc", problem.getSpaceInformation(), params);
        planner->setProblemDefinition(problem.createProblemDefinition());
        planner->setup();
        const auto &orparc = static_cast<const ORPARC &>(*planner);
        ASSERT_EQ(orparc.getRacerCount(), 3u);
        for (std::size_t k = 0; k < orparc.getRacerCount(); ++k)
        {
            const PARC &racer = orparc.getRacer(k);
            EXPECT_EQ(racer.getProfile(), "panda");
            EXPECT_EQ(racer.getWindow(), 33u) << "racer " << k;
            EXPECT_DOUBLE_EQ(racer.getBoundMargin(), 0.25) << "racer " << k;
            EXPECT_DOUBLE_EQ(racer.getMinBoundRange(), 0.5) << "racer " << k;  // the panda profile's
            EXPECT_EQ(racer.getGrowth(), "exponential") << "racer " << k;
            EXPECT_EQ(racer.getWorkers(), 2u) << "racer " << k;
            EXPECT_EQ(racer.getSeed(), mixSeed(5, k)) << "racer " << k;
        }
    }
}

/* OR-P-ARC reports the winner's complete P-ARC statistics, and every instance's outcome. */
TEST(OrParcRace, TheWinnersCompleteStatisticsOnMobileCross8)
{
    const auto problem = scenarios::createMobileCross(8);
    ORPARC orparc(problem.getSpaceInformation());
    orparc.setInstances(2);
    orparc.setWorkers(2);
    orparc.setSeed(3);
    ASSERT_EQ(test::solveWith(orparc, problem), ob::PlannerStatus::EXACT_SOLUTION) << orparc.getStatusMessage();
    const auto report = SolutionValidator(problem).validate(orparc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;

    const int winner = orparc.getReportedInstance();
    ASSERT_GE(winner, 0);
    const PARC &won = orparc.getRacer(winner);
    EXPECT_EQ(orparc.getRacerStatus(winner), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(&orparc.getPlan(), &won.getPlan());
    ob::PlannerData data(problem.getSpaceInformation());
    orparc.getPlannerData(data);
    auto &p = data.properties;
    EXPECT_EQ(p["winner STRING"], won.getName());
    EXPECT_EQ(p["instances INTEGER"], "2");
    EXPECT_GT(won.getParallelStatistics().batches, 0u);
    EXPECT_GT(won.getParallelStatistics().repairAttempts, 0u);
    EXPECT_EQ(p["batches INTEGER"], std::to_string(won.getParallelStatistics().batches));
    EXPECT_EQ(p["repair_attempts INTEGER"], std::to_string(won.getParallelStatistics().repairAttempts));
    EXPECT_EQ(p["conflicts INTEGER"], std::to_string(won.getStatistics().conflicts));
    EXPECT_EQ(p["makespan INTEGER"], std::to_string(won.getPlan().getMakespan()));
    EXPECT_EQ(p.count("projected_total_time REAL"), 1u);
    EXPECT_EQ(orparc.getParallelStatistics().batches, won.getParallelStatistics().batches);
    for (unsigned int k = 0; k < 2; ++k)
    {
        const std::string prefix = "instance" + std::to_string(k) + "_";
        EXPECT_EQ(p[prefix + "status STRING"], orparc.getRacerStatus(k).asString());
        EXPECT_EQ(p[prefix + "batches INTEGER"], std::to_string(orparc.getRacer(k).getParallelStatistics().batches));
    }
    for (const auto &[name, value] : p)
        EXPECT_EQ(name.find_first_of("-#"), std::string::npos) << name << " is no SQL column name";
}

/* Nobody wins in 30 ms: solve() returns promptly with every instance joined, and the PlannerData says what each
   instance did, the top level being the instance that went furthest. */
TEST(OrParcRace, ATimeoutReportsWhatTheInstancesDid)
{
    const auto problem = scenarios::createMobileCircle(16);
    ORPARC orparc(problem.getSpaceInformation());
    orparc.setInstances(3);
    orparc.setSeed(2);
    orparc.setProblemDefinition(problem.createProblemDefinition());
    const auto start = ompl::time::now();
    ASSERT_EQ(orparc.solve(ob::timedPlannerTerminationCondition(0.03)), ob::PlannerStatus::TIMEOUT);
    EXPECT_LT(ompl::time::seconds(ompl::time::now() - start), 0.03 + test::promptReturn());

    ob::PlannerData data(problem.getSpaceInformation());
    orparc.getPlannerData(data);
    auto &p = data.properties;
    EXPECT_EQ(p["winner STRING"], "");
    const int furthest = orparc.getReportedInstance();
    ASSERT_GE(furthest, 0);
    EXPECT_EQ(p["reported_instance INTEGER"], std::to_string(furthest));
    unsigned int mostConflicts = 0;
    for (std::size_t k = 0; k < orparc.getRacerCount(); ++k)
    {
        const std::string prefix = "instance" + std::to_string(k) + "_";
        EXPECT_EQ(p[prefix + "status STRING"], ob::PlannerStatus(ob::PlannerStatus::TIMEOUT).asString());
        EXPECT_EQ(p[prefix + "conflicts INTEGER"], std::to_string(orparc.getRacer(k).getStatistics().conflicts));
        mostConflicts = std::max(mostConflicts, orparc.getRacer(k).getStatistics().conflicts);
    }
    EXPECT_EQ(p["conflicts INTEGER"], std::to_string(mostConflicts));
    EXPECT_EQ(p["initial_wall_time REAL"], p["instance" + std::to_string(furthest) + "_initial_wall_time REAL"]);
    EXPECT_FALSE(orparc.getStatusMessage().empty());
    EXPECT_EQ(orparc.getPlan().getRobotCount(), 0u);  // no winner, no plan
}
