#ifndef OMPL_PARC_PLAN_IMPROVER_
#define OMPL_PARC_PLAN_IMPROVER_

#include "ompl_parc/arc/SubproblemSolver.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/parallel/WorkerPool.h"
#include "ompl_parc/quality/PlanObjective.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <cstddef>
#include <cstdint>
#include <functional>

namespace ompl_parc
{
    /** \brief What one PlanImprover::improve() did. */
    struct ImprovementReport
    {
        /** \brief Rounds started, and better plans found (each reported to the callback). */
        std::size_t rounds{0}, improvements{0};
        double seconds{0.};
    };

    /** \brief The anytime phase of ARC and P-ARC: after the first solution, keep making the plan better by an
        objective until the termination condition fires or the plan meets its lower bound (PlanQuality).

        It works in rounds. In each round every worker of the pool smooths its own copy of the best plan so far with
        a PlanSmoother of its own seed: first it solves the whole team with the team solver (setTeamSolver()), then it
        goes on with its replan of the whole team (prioritised planning,
        worker 0 first in the team's order, then each worker in shuffled orders), kept if better, then shortcuts
        and one-robot replans. The best of the workers' plans replaces the best so far if the objective is lower,
        and is reported to the callback. A round lasts ROUND_SECONDS x 2^round (at most MAX_ROUND_DOUBLINGS
        doublings), half of it for the team replan, which a worker's later rounds continue where the last stopped
        (PlanSmoother::setTeamReplanMemory()): a prioritised plan that needs seconds (dense crossings, rooms of
        48 robots) is found after a few rounds, while the first short rounds bring the easy gains early. Every
        plan it keeps is conflict-free, as the PlanSmoother keeps only conflict-free changes. */
    class PlanImprover
    {
      public:
        using Callback = std::function<void(const MultiRobotPlan &)>;

        /** \brief An improver for plans of the team of \e si, whose replans use solvers made by \e replanner (its
            argument: whether the priority order is shuffled with each solve's seed). */
        PlanImprover(MultiRobotSpaceInformationPtr si, PlanObjective objective,
                     std::function<SubproblemSolverPtr(bool shuffle)> replanner);

        /** \brief Give every worker's smoother in every round a team solver made by \e factory
            (PlanSmoother::setTeamSolver()): each round's seeds give it other lattices, so other whole-team plans. */
        void setTeamSolver(std::function<SubproblemSolverPtr()> factory) { teamSolver_ = std::move(factory); }

        /** \brief Improve \e plan (conflict-free) in place with the workers of \e pool until \e ptc fires or it
            meets its bound, drawing every seed from \e seed; \e callback (if set) receives each better plan as it
            is found, on the calling thread. */
        ImprovementReport improve(MultiRobotPlan &plan, WorkerPool &pool,
                                  const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                  const Callback &callback) const;

        /** \brief The first round's length, in seconds. */
        static constexpr double ROUND_SECONDS = 0.5;
        /** \brief Rounds stop doubling after this many (ROUND_SECONDS x 64 = 32 s). */
        static constexpr unsigned int MAX_ROUND_DOUBLINGS = 6;

      private:
        /** \brief \e plan's obstacle-aware lower bound for the objective (PlanQuality): a plan that meets it has
            nothing left to gain. */
        std::size_t boundOf(const MultiRobotPlan &plan) const;

        MultiRobotSpaceInformationPtr si_;
        PlanObjective objective_;
        std::function<SubproblemSolverPtr(bool shuffle)> replanner_;
        std::function<SubproblemSolverPtr()> teamSolver_;
    };
}  // namespace ompl_parc

#endif
