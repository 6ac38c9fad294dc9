#ifndef OMPL_PARC_SMOOTHING_STEP_
#define OMPL_PARC_SMOOTHING_STEP_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/quality/PlanSmoother.h"

#include <ompl/base/Planner.h>
#include <ompl/base/PlannerData.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace ompl_parc
{
    /** \brief The post-processing step our planners share: the declared parameter \e smooth (seconds of PlanSmoother
        after a solution is found; 0, the default, leaves the plan and the planning time as they were) and the
        plan-quality properties every planner reports.

        Smoothing runs inside solve(), after the solution, until the budget is spent, no attempt gains any more, or
        the solve's own termination condition fires (a solve never outlasts its ptc for it). */
    class SmoothingStep
    {
      public:
        /** \brief Declare \e smooth on \e planner (its params()), backed by this step. */
        void declareParameter(ompl::base::Planner &planner);

        /** \brief Makes the smoother's replanner (PlanSmoother::setReplanner()) when a smoothing starts; planners give
            prioritised ST-RRT. (Made then, not before: an OMPL planner made draws from OMPL's seed sequence, which
            would change the planning of a solve that does not smooth.) */
        void setReplanner(std::function<SubproblemSolverPtr()> factory) { replanner_ = std::move(factory); }

        /** \brief Makes the smoother's team solver (PlanSmoother::setTeamSolver()) when a smoothing with a team replan
            share starts; the ARC family gives LatticeMapfSolver. */
        void setTeamSolver(std::function<SubproblemSolverPtr()> factory) { teamSolver_ = std::move(factory); }

        /** \brief The share of the budget the smoother may spend replanning the whole team first
            (PlanSmoother::setTeamReplanTime()); 0 (the default): none. A planner that plans prioritised itself
            has nothing to gain from it. */
        void setTeamReplanShare(double share) { teamReplanShare_ = share; }

        void setBudget(double seconds);
        double getBudget() const { return budget_; }

        /** \brief With a budget, smooth \e plan (conflict-free) in place, drawing from \e seed, under \e ptc and the
            budget; remembers the report. Without one, forgets the last report. A smoothing that fails (the plan
            has a conflict, memory runs out) leaves no report and a warning: the solution stands as it is. */
        void apply(const MultiRobotSpaceInformationPtr &si, MultiRobotPlan &plan,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed);

        /** \brief The last apply()'s report, if it smoothed. */
        const std::optional<SmoothingReport> &getReport() const { return report_; }
        void clear() { report_.reset(); }

        /** \brief Add \e plan's quality (makespan, sum_of_costs, their straight-line bounds and ratios, PlanQuality)
            and, with a \e smoothing report (the one that made \e plan), smoothing_time, smoothing_attempts,
            smoothing_shortcuts (every change kept), smoothing_team_replan (none, kept or not kept) and the unsmoothed
            makespan and sum of costs. Nothing for an empty plan. */
        static void addProperties(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                  const std::optional<SmoothingReport> &smoothing, ompl::base::PlannerData &data);

        /** \brief The smoothing report that addProperties() wrote into \e properties, as far as they tell it (every
            change kept counted as a shortcut, the team replan and solve apart); none if they hold no smoothing. What
            a tool that only has the planner's properties (ARC's, P-ARC's, OR-P-ARC's winner's) reports. */
        static std::optional<SmoothingReport> reportOf(const std::map<std::string, std::string> &properties);

      private:
        double budget_{0.}, teamReplanShare_{0.};
        std::function<SubproblemSolverPtr()> replanner_, teamSolver_;
        std::optional<SmoothingReport> report_;
    };
}  // namespace ompl_parc

#endif
