#ifndef OMPL_PARC_PLANNERS_ARC_PLANNER_BASE_
#define OMPL_PARC_PLANNERS_ARC_PLANNER_BASE_

#include "ompl_parc/arc/ArcProgress.h"
#include "ompl_parc/arc/RepairLoop.h"
#include "ompl_parc/arc/RepairWorkspace.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/quality/PlanImprover.h"
#include "ompl_parc/quality/PlanObjective.h"
#include "ompl_parc/quality/SmoothingStep.h"

#include <ompl/base/Planner.h>
#include <ompl/util/Time.h>

#include <memory>
#include <optional>
#include <string>
#include <type_traits>

namespace ompl_parc
{
    /** \brief The OMPL planner shell of the ARC family over a MultiRobotSpaceInformation: the declared ArcSettings
        parameters, the problem read from the ProblemDefinition and a RepairLoop that does the work. ARC is the
        shell with one worker; PARC declares the parallel parameters too.

        solve() follows OMPL's conventions: it checks the start and goal (INVALID_START / INVALID_GOAL, the
        reason naming the robot in getStatusMessage() and the log; CRASH with the reason if a stage throws),
        runs the initial stage and conflict resolution until the plan is conflict-free (EXACT_SOLUTION, added
        to the ProblemDefinition as a composite path with one state per timestep) or the termination condition
        fires (TIMEOUT). A later solve() continues where the last one stopped; clear() starts over. The same
        seed gives the same plan.

        With \e objective "makespan" or "sum_of_costs" (default "first": stop at the first solution, as the paper's
        planners do) it is an anytime planner: after the first solution (smoothed with \e smooth) it keeps improving
        the plan with a PlanImprover on its W workers (team replans in fresh priority orders, shortcuts, one-robot
        replans) until the termination condition fires or the plan meets its lower bound, and reports the first
        solution and each better one through the ProblemDefinition's intermediate-solution callback (cost = the
        objective in timesteps). The solve then ends with EXACT_SOLUTION and the best plan; the properties
        first_solution_time, anytime_rounds and improvements say what the anytime phase did. */
    class ArcPlannerBase : public ompl::base::Planner
    {
      public:
        ArcPlannerBase(const ompl::base::SpaceInformationPtr &si, const std::string &name);
        ~ArcPlannerBase() override;

        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        /** \brief Also makes the worker pool and the conflict detectors (RepairWorkspace), so that solve() does not
            spend its time on them; clear() keeps them for the next query. */
        void setup() override;
        void clear() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief The current plan (the solution after a successful solve(), smoothed if \e smooth is set); empty
            before the first solve(). */
        const MultiRobotPlan &getPlan() const;
        const ArcStatistics &getStatistics() const;
        /** \brief Where the solve is (stage, counters, makespan so far), safe to read from another thread while
            solve() runs; the same values are this planner's OMPL progress properties. */
        const ArcProgress &getProgress() const { return progress_; }
        /** \brief Report progress into \e shared instead of getProgress()'s (OR-P-ARC's instances into the race's);
            \e shared must outlive the solves. The stage then stops at "resolving": the owner says when it is done. */
        void reportProgressInto(ArcProgress &shared) { reportTo_ = &shared; }
        /** \brief Why the last solve() did not succeed (empty after success). */
        const std::string &getStatusMessage() const { return statusMessage_; }
        const ArcSettings &getSettings() const { return options_.settings; }

        /** \name Declared parameters
            @{ */
        /** \brief ArcSettings::profile() \e profile's values for every setting not set on its own; "auto" (the
            default): the profile of the team's robots (ArcSettings::profileFor()). */
        void setProfile(const std::string &profile);
        std::string getProfile() const { return profile_; }
        /** \brief A setter's argument for a parameter of type \e T: a string by reference, a number by value. */
        template <typename T>
        using ParameterArgument = std::conditional_t<std::is_class_v<T>, const T &, T>;
        /* One setter and getter per ArcSettings knob (ompl_parc/arc/ArcKnobs.def, which says what each does):
           setWindow(unsigned int) and getWindow(), setGrowth(const std::string &) and getGrowth(), ... The setter
           throws ompl::Exception for a value out of the knob's range and marks the knob set, so that a profile set
           later keeps it (ArcSettings::explicitFields). */
#define OMPL_PARC_ARC_KNOB(Name, member, parameter, Type, Parameter, ...)                                              \
    void set##Name(ParameterArgument<Parameter> value);                                                                \
    Parameter get##Name() const;
#include "ompl_parc/arc/ArcKnobs.def"
        /** \brief Seconds of time-aware shortcutting (PlanSmoother) after a solution; 0 (the default): none. */
        void setSmoothing(double seconds) { smoothing_.setBudget(seconds); }
        double getSmoothing() const { return smoothing_.getBudget(); }
        /** \brief What the last solve()'s smoothing did, if it smoothed. */
        const std::optional<SmoothingReport> &getSmoothingReport() const { return smoothing_.getReport(); }
        /** \brief "first", "makespan" or "sum_of_costs" (see the class description); throws for anything else. */
        void setObjective(const std::string &objective) { objective_ = parsePlanObjective(objective); }
        std::string getObjective() const { return toString(objective_); }
        /** \brief What the last solve()'s anytime phase did, if it had one. */
        const std::optional<ImprovementReport> &getImprovementReport() const { return improvement_; }
        /** \brief 0: draw a seed from OMPL's global random sequence at the first solve(). */
        void setSeed(unsigned int seed);
        unsigned int getSeed() const { return seed_; }
        /** @} */

      protected:
        /** \name P-ARC's parallel parameters (ARC: one worker, the whole plan per detection round)
            @{ */
        /* One setter and getter per knob of ompl_parc/arc/ParcKnobs.def: setWorkers(unsigned int), getWorkers(),
           setBatchPerWorker(unsigned int), ... The setter throws ompl::Exception for a refused value. */
#define OMPL_PARC_PARALLEL_KNOB(Name, member, parameter, Parameter, ...)                                               \
    void set##Name(Parameter value);                                                                                   \
    Parameter get##Name() const;
#include "ompl_parc/arc/ParcKnobs.def"
        /** @} */

        /** \brief The engine of the current problem (null before the first solve() and after clear()). */
        const RepairLoop *getLoop() const { return loop_.get(); }

      private:
        /** \brief Build problem_ and loop_ from the ProblemDefinition; returns the status to report if it is bad. */
        std::optional<ompl::base::PlannerStatus> readProblem();
        ompl::base::PlannerStatus solveStages(const ompl::base::PlannerTerminationCondition &ptc);
        /** \brief The anytime phase after the first solution (objective_ set): improve smoothed_ until \e ptc. */
        void improve(const ompl::base::PlannerTerminationCondition &ptc);

        MultiRobotSpaceInformationPtr mrsi_;
        RepairLoopOptions options_;
        std::string profile_{"auto"};
        unsigned int seed_{0};
        std::unique_ptr<MultiRobotProblem> problem_;
        /** \brief Made by setup(), used by every loop_ (declared before it: it outlives the loop). */
        std::unique_ptr<RepairWorkspace> workspace_;
        std::unique_ptr<RepairLoop> loop_;
        SmoothingStep smoothing_;
        PlanObjective objective_{PlanObjective::FIRST};
        std::optional<ImprovementReport> improvement_;
        /** \brief Seconds from the start of the last solve() to its first solution (anytime solves). */
        double firstSolutionTime_{-1.};
        ompl::time::point solveStarted_;
        /** \brief The smoothed copy of the loop's plan after a smoothed solve (the loop keeps its own). */
        std::optional<MultiRobotPlan> smoothed_;
        std::string statusMessage_;
        ArcProgress progress_;
        /** \brief &progress_, or the progress of the planner this one is part of (reportProgressInto()). */
        ArcProgress *reportTo_{&progress_};
    };
}  // namespace ompl_parc

#endif
