#ifndef OMPL_PARC_PLANNERS_OR_PP_ST_RRT_
#define OMPL_PARC_PLANNERS_OR_PP_ST_RRT_

#include "ompl_parc/parallel/OrRace.h"
#include "ompl_parc/planners/PrioritizedSTRRT.h"

namespace ompl_parc
{
    /** \brief OR-PP-ST-RRT, the paper's decoupled OR-parallel baseline: K PrioritizedSTRRT instances, each with
        its own shuffled priority order and seed (a mix of \e seed and k), raced with OMPL's ParallelPlan. The
        first solution wins and stops the others, all joined before solve() returns. Sampling different
        priority orders is what makes OR-parallel prioritised planning effective: one order may be infeasible
        where another is easy.

        Parameters are PrioritizedSTRRT's (applied to every instance; \e priority_order is always "shuffled")
        plus \e instances (K). Every solve() races fresh instances (OrRace). After a solve, getPlan() is the
        winner's plan; the PlannerData holds the winner and every instance's status and properties. */
    class ORPPSTRRT : public PrioritizedSTRRT
    {
      public:
        explicit ORPPSTRRT(const ompl::base::SpaceInformationPtr &si);

        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief K; throws ompl::Exception for 0. */
        void setInstances(unsigned int instances) { race_.setInstances(instances); }
        unsigned int getInstances() const { return race_.getInstances(); }

      private:
        OrRace race_;
    };
}  // namespace ompl_parc

#endif
