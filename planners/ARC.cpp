#include "ompl_parc/planners/ARC.h"

#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/parallel/StageClock.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

ompl_parc::ARC::ARC(const ompl::base::SpaceInformationPtr &si) : ArcPlannerBase(si, "ARC") {}

bool ompl_parc::ARC::computeInitialPlans(const ompl::base::PlannerTerminationCondition &ptc)
{
    const InitialPlanner planner(*problem_, settings_.simplifyInitial);
    std::vector<double> path;
    for (std::size_t r = 0; r < mrsi_->getRobotCount(); ++r)
    {
        if (planned_[r])
            continue;
        if (!planner.plan(r, ptc, mixSeed(effectiveSeed_, r), path))
            return false;
        plan_.setRobotPath(r, path);
        planned_[r] = 1;
    }
    return true;
}

bool ompl_parc::ARC::resolveConflicts(const ompl::base::PlannerTerminationCondition &ptc)
{
    while (!ptc)
    {
        std::optional<Conflict> conflict;
        {
            StageClock clock(statistics_.detectionWall, statistics_.detectionCpu);
            conflict = detector_->findEarliest(plan_);
        }
        if (!conflict)
            return true;
        ++statistics_.conflicts;
        const auto team = cache_.expand(*conflict, settings_.window);
        statistics_.teamGrowths += team.size() > 2 ? 1 : 0;
        std::optional<Repair> repair;
        {
            StageClock clock(statistics_.resolutionWall, statistics_.resolutionCpu);
            repair = resolver_->resolve(plan_, team, conflict->timestep, ptc,
                                        mixSeed(effectiveSeed_, 0x10000 + statistics_.conflicts));
        }
        if (!repair)
            return false;
        applyRepair(*repair);
    }
    return false;
}
