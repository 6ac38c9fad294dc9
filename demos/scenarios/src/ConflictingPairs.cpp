#include "ompl_parc/scenarios/ConflictingPairs.h"

#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/util/Exception.h>

#include <numeric>

std::size_t ompl_parc::scenarios::countConflictingPairs(const MultiRobotProblem &problem, unsigned int seed)
{
    const auto &si = *problem.getSpaceInformation();
    const InitialPlanner planner(problem);
    MultiRobotPlan plan(si);
    TimedPath path;
    for (std::size_t r = 0; r < si.getRobotCount(); ++r)
    {
        // The seed of robot r's path in ARC::computeInitialPlans().
        if (!planner.plan(r, ompl::base::timedPlannerTerminationCondition(60.), mixSeed(seed, r), path))
            throw ompl::Exception("countConflictingPairs",
                                  "no path for robot '" + si.getRobot(r)->getName() + "' within 60 s");
        plan.setPath(r, path);
    }
    ConflictDetector detector(si);
    detector.discoverPairs(plan);  // no planning to stop: complete
    std::vector<std::size_t> pairs(detector.getPairCount());
    std::iota(pairs.begin(), pairs.end(), 0);
    return detector.scan(plan, pairs, 0, plan.getMakespan() + 1, false).size();
}
