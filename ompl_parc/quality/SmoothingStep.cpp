#include "ompl_parc/quality/SmoothingStep.h"

#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/util/InnerPlannerLog.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <algorithm>
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

std::optional<ompl_parc::SmoothingReport> ompl_parc::SmoothingStep::reportOf(
    const std::map<std::string, std::string> &properties)
{
    const auto text = [&](const std::string &name)
    {
        const auto found = properties.find(name);
        return found == properties.end() ? std::string() : found->second;
    };
    if (text("smoothing_time REAL").empty())
        return std::nullopt;
    const auto count = [&](const std::string &name)
    { return static_cast<std::size_t>(std::stoull("0" + text(name))); };
    SmoothingReport report;
    report.seconds = std::stod(text("smoothing_time REAL"));
    report.makespanBefore = count("makespan_unsmoothed INTEGER");
    report.sumOfCostsBefore = count("sum_of_costs_unsmoothed INTEGER");
    report.attempts = count("smoothing_attempts INTEGER");
    const std::string team = text("smoothing_team_replan STRING"), solve = text("smoothing_team_solve STRING");
    report.teamReplanned = team == "kept" || team == "not kept";
    report.teamReplanKept = team == "kept";
    report.teamSolveTried = solve == "kept" || solve == "not kept" || solve == "not solved";
    report.teamSolved = solve == "kept" || solve == "not kept";
    report.teamSolveKept = solve == "kept";
    report.teamSolveSeconds = std::stod("0" + text("smoothing_team_solve_time REAL"));
    const std::size_t teamKept = (report.teamReplanKept ? 1 : 0) + (report.teamSolveKept ? 1 : 0),
                      kept = count("smoothing_shortcuts INTEGER");
    report.shortcuts = kept - std::min(teamKept, kept);
    return report;
}
