#ifndef OMPL_PARC_PLANNERS_ORPARC_
#define OMPL_PARC_PLANNERS_ORPARC_

#include "ompl_parc/parallel/OrRace.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/quality/SmoothingStep.h"

#include <memory>
#include <optional>
#include <string>

namespace ompl_parc
{
    /** \brief OR-P-ARC K x W_k: K independent P-ARC instances with W_k workers each (K x W_k = W workers in
        all), raced with OrRace; the first solution wins and stops the others, all joined before solve()
        returns. OR-ARC is ORPARC with W_k = 1.

        ORPARC wraps P-ARC instances rather than being one. Its parameters are those of a prototype P-ARC
        (shared, so every P-ARC parameter can be set by name; \e workers is W_k) plus \e instances (K) and
        \e total_workers (W, a multiple of K, sets W_k = W / K). The racers are created at setup() or the
        first solve() with the prototype's values (its \e profile first, then the others, so explicit
        values win) and the seeds mixSeed(seed, k), the odd ones with an eager repair schedule when \e diversify is on
        (the default; setDiversify()); a later solve() continues them, clear() discards them
        so that the next solve() uses changed parameters.

        After a solve the reported instance is the winner or, if nobody won, the instance that went furthest
        (most conflicts resolved, then most solver calls; the lowest index on a tie): getStatistics(),
        getParallelStatistics(), getStatusMessage() and the top-level PlannerData properties are its own
        (P-ARC's complete set, \e reported_instance says which). getPlan() is the winner's plan. The
        PlannerData also holds \e instances, \e winner and every instance's status and properties
        (instancek_status, instancek_conflicts, ...), so a timeout shows what each instance did.

        With \e objective "makespan" or "sum_of_costs" (default "first": the paper's OR) it is an anytime planner:
        it races again with fresh seeds (round r: mixSeed(seed, r)) until the termination condition (or a plan that
        meets its lower bound, PlanQuality), smooths each round's winner (\e smooth), keeps the plan with the lowest
        objective and reports each improvement through the ProblemDefinition's intermediate-solution callback (cost =
        the objective in timesteps; \e first_solution_time says when the first came). The statistics are then the last
       race's (which the termination condition may have cut short); \e anytime_rounds counts the races started, \e
       improvements the better plans. A first race that ends otherwise than with a solution or a timeout (an invalid
       start, a crash) ends the solve. */
    class ORPARC : public ompl::base::Planner
    {
      public:
        explicit ORPARC(const ompl::base::SpaceInformationPtr &si);
        ~ORPARC() override;

        using ompl::base::Planner::solve;
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void setup() override;
        void clear() override;
        void setProblemDefinition(const ompl::base::ProblemDefinitionPtr &pdef) override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief The winner's plan after a successful solve(), smoothed if \e smooth (the prototype's) is set (the
            best one with an objective); empty otherwise. The instances never smooth: the winner's plan is smoothed
            once, after its race. */
        const MultiRobotPlan &getPlan() const;
        /** \brief Where the race is, safe to read from another thread while solve() runs (also this planner's
            OMPL progress properties): the furthest stage of any instance, the sums of their counters. */
        const ArcProgress &getProgress() const { return progress_; }
        /** \brief The reported instance's statistics (all zero before a solve). */
        const ArcStatistics &getStatistics() const;
        const ParcStatistics &getParallelStatistics() const;
        /** \brief Why the last solve() did not succeed, in the reported instance's words (empty after success). */
        const std::string &getStatusMessage() const;

        /** \brief The P-ARC whose parameters every instance gets (never solved itself). */
        PARC &getPrototype() { return *prototype_; }
        const PARC &getPrototype() const { return *prototype_; }
        /** \brief The instances (empty before setup() or solve() and after clear()). */
        std::size_t getRacerCount() const { return race_.getRacers().size(); }
        const PARC &getRacer(std::size_t k) const;
        /** \brief How instance \e k's last solve() ended. */
        ompl::base::PlannerStatus getRacerStatus(std::size_t k) const { return race_.getStatus(k); }
        /** \brief The index of the reported instance, -1 before a solve and after clear(). */
        int getReportedInstance() const;

        /** \name Declared parameters (besides the prototype's)
            @{ */
        void setInstances(unsigned int instances) { race_.setInstances(instances); }
        unsigned int getInstances() const { return race_.getInstances(); }
        /** \brief "first", "makespan" or "sum_of_costs" (see the class description); throws ompl::Exception
            otherwise. */
        void setObjective(const std::string &objective);
        std::string getObjective() const { return objective_; }
        /** \brief Sets W_k = total / K; throws ompl::Exception unless total is a positive multiple of K. */
        void setTotalWorkers(unsigned int total);
        unsigned int getTotalWorkers() const { return getInstances() * getWorkers(); }
        /** \brief Whether the odd instances repair with ArcSettings::eager() (default on): identical instances differ
            only by their seeds, and where the time goes to one hard team of arms, seeds barely change it; two
            schedules do. Off: the paper's OR, every instance the prototype. */
        void setDiversify(bool diversify) { diversify_ = diversify; }
        bool getDiversify() const { return diversify_; }
        /** @} */
        /** \brief W_k, the prototype's \e workers. */
        void setWorkers(unsigned int workers) { prototype_->setWorkers(workers); }
        unsigned int getWorkers() const { return prototype_->getWorkers(); }
        /** \brief The prototype's \e seed; instance k runs with mixSeed(seed, k). */
        void setSeed(unsigned int seed) { prototype_->setSeed(seed); }
        unsigned int getSeed() const { return prototype_->getSeed(); }

        /** \brief Instance \e k of a race seeded with \e raceSeed (not 0: seedOrDraw() draws it), set up exactly as
            this planner's racer k (the prototype's values, seed mixSeed(raceSeed, k), no smoothing), on this planner's
            problem (set before): for racing the instances somewhere else, e.g. one per MPI rank (ompl_parc_mpi). */
        std::shared_ptr<PARC> createInstance(unsigned int k, std::uint_fast32_t raceSeed);
        /** \brief Smooths \e plan, the winning plan of the instance seeded \e instanceSeed, as this planner smooths its
            winner's (the prototype's \e smooth budget, a seed derived from the instance's), under \e ptc; returns the
            report (none without a budget). */
        std::optional<SmoothingReport> smoothWinner(MultiRobotPlan &plan, std::uint_fast32_t instanceSeed,
                                                    const ompl::base::PlannerTerminationCondition &ptc);

      private:
        /** \brief The K racers, seeded from \e seed (as OrRace::createRacers()). */
        void createRacers(unsigned int seed);
        /** \brief Racer \e k: like the prototype, with the instance seed \e seed, and the eager repair schedule for
            odd \e k when diversifying. */
        std::shared_ptr<PARC> makeRacer(unsigned int k, std::uint_fast32_t seed);
        /** \brief After a won race: smooth a copy of the winner's plan; keep it (and report it) if it is the first or
            better than the best so far by the objective. */
        void takeWinner(const ompl::base::PlannerTerminationCondition &ptc);
        /** \brief The end of a solve that returns \e status: the progress says "solved" (or the log why not). */
        ompl::base::PlannerStatus finish(ompl::base::PlannerStatus status);
        /** \brief The objective's value of \e plan (the makespan for "first"). */
        std::size_t objectiveOf(const MultiRobotPlan &plan) const;
        /** \brief The reported instance, or the prototype (all zero, empty plan) when there is none. */
        const PARC &reported() const;

        std::shared_ptr<PARC> prototype_;
        OrRace race_;
        SmoothingStep smoothing_;
        std::string objective_{"first"};
        bool diversify_{true};
        /** \brief The plan solve() returns when it is not the winner's own: smoothed, or the best of several rounds. */
        std::optional<MultiRobotPlan> result_;
        /** \brief The smoothing report of result_. */
        std::optional<SmoothingReport> resultSmoothing_;
        std::size_t rounds_{0}, improvements_{0};
        /** \brief Seconds from the start of the solve to the first race won (-1: none yet); with an objective, the
            PlannerData's first_solution_time. */
        double firstSolutionTime_{-1.};
        /** \brief Every instance reports into it (ArcPlannerBase::reportProgressInto()). */
        ArcProgress progress_;
    };
}  // namespace ompl_parc

#endif
