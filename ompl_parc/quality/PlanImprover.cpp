#include "ompl_parc/quality/PlanImprover.h"

#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/quality/PlanSmoother.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/util/Time.h>

#include <algorithm>
#include <optional>
#include <vector>

namespace ob = ompl::base;

ompl_parc::PlanImprover::PlanImprover(MultiRobotSpaceInformationPtr si, PlanObjective objective,
                                      std::function<SubproblemSolverPtr(bool shuffle)> replanner)
    : si_(std::move(si)), objective_(objective), replanner_(std::move(replanner))
{
}

std::size_t ompl_parc::PlanImprover::boundOf(const MultiRobotPlan &plan) const
{
    const PlanQuality quality = PlanQuality::measure(*si_, plan);
    // The obstacle-aware bounds are the tighter ones (never below the straight-line ones).
    return objective_ == PlanObjective::SUM_OF_COSTS ? quality.sumOfCostsPathBound : quality.makespanPathBound;
}

ompl_parc::ImprovementReport ompl_parc::PlanImprover::improve(MultiRobotPlan &plan, WorkerPool &pool,
                                                              const ob::PlannerTerminationCondition &ptc,
                                                              std::uint_fast32_t seed, const Callback &callback) const
{
    const auto started = ompl::time::now();
    ImprovementReport report;
    const unsigned int workers = pool.getWorkerCount();
    std::vector<std::optional<MultiRobotPlan>> candidates(workers);
    // Per worker, its replanner and the memory of its team replan (kept across rounds).
    std::vector<SubproblemSolverPtr> solvers(workers);
    std::vector<std::unique_ptr<SubproblemSolver::Memory>> memories(workers);
    std::vector<char> shuffled(workers);
    for (unsigned int w = 0; w < workers; ++w)
    {
        shuffled[w] = w > 0;
        solvers[w] = replanner_(shuffled[w] != 0);
        memories[w] = solvers[w]->makeMemory();
    }
    // Every plan has the same starts and goals, so the same bound: measured once.
    const std::size_t bound = boundOf(plan);
    for (unsigned int round = 0; !ptc() && objectiveKey(plan, objective_).first > bound; ++round)
    {
        ++report.rounds;
        const double seconds = ROUND_SECONDS * static_cast<double>(1u << std::min(round, MAX_ROUND_DOUBLINGS));
        const auto budget = ob::plannerOrTerminationCondition(ptc, ob::timedPlannerTerminationCondition(seconds));
        pool.run(
            [&](unsigned int worker)
            {
                candidates[worker] = plan;
                PlanSmoother smoother(si_, mixSeed(seed, round * workers + worker));
                smoother.setObjective(objective_);
                smoother.setReplanner(solvers[worker]);
                if (teamSolver_)
                    smoother.setTeamSolver(teamSolver_());
                smoother.setTeamReplanTime(0.5 * seconds);
                smoother.setTeamReplanMemory(memories[worker].get());
                // Once worker 0's team replan in the team's order has ended, it tries shuffled orders too: the
                // same order again would find the same plan.
                if (smoother.smooth(*candidates[worker], budget).teamReplanDone && !shuffled[worker])
                {
                    shuffled[worker] = true;
                    solvers[worker] = replanner_(true);
                    memories[worker] = solvers[worker]->makeMemory();
                }
            });
        // The best of the round (the lowest worker on a tie, so that a seeded run does not depend on timing more
        // than the budgets make it).
        std::optional<MultiRobotPlan> *best = nullptr;
        for (auto &candidate : candidates)
            if (candidate &&
                (best == nullptr || objectiveKey(*candidate, objective_) < objectiveKey(**best, objective_)))
                best = &candidate;
        if (best != nullptr && objectiveKey(**best, objective_) < objectiveKey(plan, objective_))
        {
            plan = std::move(**best);
            ++report.improvements;
            if (callback)
                callback(plan);
        }
        std::fill(candidates.begin(), candidates.end(), std::nullopt);
    }
    report.seconds = ompl::time::seconds(ompl::time::now() - started);
    return report;
}
