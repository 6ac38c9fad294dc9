#include "ompl_parc/quality/SmoothingStep.h"

#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/util/InnerPlannerLog.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <string>

namespace ob = ompl::base;

void ompl_parc::SmoothingStep::declareParameter(ob::Planner &planner)
{
    planner.params().declareParam<double>(
        "smooth", [this](double seconds) { setBudget(seconds); }, [this] { return budget_; });
    planner.params()["smooth"].setRangeSuggestion("0.:0.1:3600.");
}

void ompl_parc::SmoothingStep::setBudget(double seconds)
{
    if (!(seconds >= 0.) || !std::isfinite(seconds))
        throw ompl::Exception("smooth", "the smoothing budget must be a finite number of seconds >= 0");
    budget_ = seconds;
}

void ompl_parc::SmoothingStep::apply(const MultiRobotSpaceInformationPtr &si, MultiRobotPlan &plan,
                                     const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed)
{
    report_.reset();
    if (budget_ <= 0.)
        return;
    const auto budget = ob::plannerOrTerminationCondition(ptc, ob::timedPlannerTerminationCondition(budget_));
    try
    {
        PlanSmoother smoother(si, seed);
        if (replanner_)
            smoother.setReplanner(replanner_());
        if (teamSolver_ && teamReplanShare_ > 0.)
            smoother.setTeamSolver(teamSolver_());
        smoother.setTeamReplanTime(teamReplanShare_ * budget_);
        {
            const InnerPlannerLog::Scope inner;  // the replans' planners
            report_ = smoother.smooth(plan, budget);
        }
        OMPL_INFORM("smoothing: makespan %zu -> %zu, sum of costs %zu -> %zu (%zu changes kept) in %.3f s",
                    report_->makespanBefore, report_->makespanAfter, report_->sumOfCostsBefore,
                    report_->sumOfCostsAfter, report_->kept(), report_->seconds);
    }
    catch (const std::exception &e)
    {
        // The solution stands: every change the smoother kept was checked, so the plan is as valid as before.
        OMPL_WARN("smoothing skipped: %s", e.what());
    }
}

void ompl_parc::SmoothingStep::addProperties(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                             const std::optional<SmoothingReport> &smoothing, ob::PlannerData &data)
{
    if (plan.getRobotCount() == 0 || plan.getPath(0).empty())
        return;
    auto &p = data.properties;
    PlanQuality::measure(si, plan).addProperties(p);
    if (smoothing)
    {
        p["smoothing_time REAL"] = std::to_string(smoothing->seconds);
        p["smoothing_attempts INTEGER"] = std::to_string(smoothing->attempts);
        p["smoothing_shortcuts INTEGER"] = std::to_string(smoothing->kept());
        p["smoothing_team_replan STRING"] =
            smoothing->teamReplanned ? (smoothing->teamReplanKept ? "kept" : "not kept") : "none";
        p["smoothing_team_solve STRING"] =
            !smoothing->teamSolveTried
                ? "none"
                : (smoothing->teamSolveKept ? "kept" : (smoothing->teamSolved ? "not kept" : "not solved"));
        p["smoothing_team_solve_time REAL"] = std::to_string(smoothing->teamSolveSeconds);
        p["makespan_unsmoothed INTEGER"] = std::to_string(smoothing->makespanBefore);
        p["sum_of_costs_unsmoothed INTEGER"] = std::to_string(smoothing->sumOfCostsBefore);
    }
}
