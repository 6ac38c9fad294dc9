#include "ompl_parc/validation/SolutionValidator.h"
#include "ompl_parc/planners/EPRRTConnect.h"
#include "ompl_parc/planners/ORPPSTRRT.h"
#include "ompl_parc/planners/ORRRTConnect.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <ompl/base/PlannerData.h>
#include <ompl/util/Exception.h>

#include <functional>

using namespace ompl_parc;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    struct Baseline
    {
        std::string label;
        std::function<ob::PlannerPtr(const ob::SpaceInformationPtr &)> make;
    };

    std::ostream &operator<<(std::ostream &out, const Baseline &b)
    {
        return out << b.label;
    }

    /** The paper's baselines at small sizes: OR-RRT-C-2, EP-RRT-C-2, OR-EP-RRT-C-2x2, OR-PP-ST-RRT-2. */
    std::vector<Baseline> baselines()
    {
        return {
            {"OrRrtC", [](const ob::SpaceInformationPtr &si) { return std::make_shared<ORRRTConnect>(si); }},
            {"EpRrtC",
             [](const ob::SpaceInformationPtr &si)
             {
                 auto p = std::make_shared<EPRRTConnect>(si);
                 p->setWorkers(2);
                 return p;
             }},
            {"OrEpRrtC",
             [](const ob::SpaceInformationPtr &si)
             {
                 auto p = std::make_shared<ORRRTConnect>(si);
                 p->setTotalWorkers(4);
                 return p;
             }},
            {"OrPpStRrt", [](const ob::SpaceInformationPtr &si) { return std::make_shared<ORPPSTRRT>(si); }},
        };
    }

    class BaselineSolves : public testing::TestWithParam<Baseline>
    {
    };
}  // namespace

TEST_P(BaselineSolves, MobileCross4AndTheIndependentValidatorAgrees)
{
    const MultiRobotProblem problem = scenarios::createMobileCross(4);
    const auto &si = problem.getSpaceInformation();
    const auto planner = GetParam().make(si);
    planner->params().setParam("seed", "7");
    const auto pdef = problem.createProblemDefinition();
    planner->setProblemDefinition(pdef);
    planner->setup();
    ASSERT_EQ(planner->solve(20.), ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_TRUE(pdef->hasExactSolution());
    // Prioritised planners lay their own plan on the grid; composite paths are re-timed onto it.
    const MultiRobotPlan plan =
        dynamic_cast<const PrioritizedSTRRT *>(planner.get()) != nullptr
            ? static_cast<const PrioritizedSTRRT &>(*planner).getPlan()
            : MultiRobotPlan::fromPathGeometric(*si, *pdef->getSolutionPath()->as<og::PathGeometric>());
    const ValidationReport report = SolutionValidator(problem).validate(plan);
    EXPECT_TRUE(report.valid) << report.message;
    // A planner that reports "solved" must say so: OMPL's benchmark stores the planner's value over its own.
    ob::PlannerData data(si);
    planner->getPlannerData(data);
    if (const auto solved = data.properties.find("solved BOOLEAN"); solved != data.properties.end())
        EXPECT_EQ(solved->second, "1");

    // The planner runs again after clear(), as the benchmark does between runs.
    planner->clear();
    pdef->clearSolutionPaths();
    EXPECT_EQ(planner->solve(20.), ob::PlannerStatus::EXACT_SOLUTION);
}

INSTANTIATE_TEST_SUITE_P(Paper, BaselineSolves, testing::ValuesIn(baselines()),
                         [](const testing::TestParamInfo<Baseline> &info) { return info.param.label; });

TEST(Baselines, BadParametersAreOmplExceptions)
{
    const MultiRobotProblem problem = scenarios::createMobileCross(4);
    const auto &si = problem.getSpaceInformation();
    EPRRTConnect ep(si);
    EXPECT_THROW(ep.setWorkers(0), ompl::Exception);
    EXPECT_THROW(ep.setRange(-1.), ompl::Exception);
    ORRRTConnect orc(si);
    EXPECT_THROW(orc.setInstances(0), ompl::Exception);
    EXPECT_THROW(orc.setWorkers(0), ompl::Exception);
    EXPECT_THROW(orc.setTotalWorkers(3), ompl::Exception);  // not a multiple of the 2 instances
    orc.setTotalWorkers(6);
    EXPECT_EQ(orc.getWorkers(), 3u);
    ORPPSTRRT orpp(si);
    EXPECT_THROW(orpp.setInstances(0), ompl::Exception);
    EXPECT_THROW(orpp.setRewiring("sideways"), ompl::Exception);
    // They all need a multi-robot SpaceInformation.
    const auto plain = std::make_shared<ob::SpaceInformation>(si->getStateSpace());
    EXPECT_THROW(EPRRTConnect{plain}, ompl::Exception);
    EXPECT_THROW(ORRRTConnect{plain}, ompl::Exception);
}
