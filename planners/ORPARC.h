#ifndef OMPL_PARC_PLANNERS_ORPARC_
#define OMPL_PARC_PLANNERS_ORPARC_

#include "ompl_parc/planners/PARC.h"

#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief OR-P-ARC K x W_k: K independent P-ARC instances with W_k workers each (K x W_k = W workers in
        all), raced with OMPL's ParallelPlan; the first solution wins and stops the others, all joined before
        solve() returns. OR-ARC is ORPARC with W_k = 1.

        Parameters are P-ARC's (applied to every instance; \e workers is W_k) plus \e instances (K) and
        \e total_workers (W, which must be a multiple of K and sets W_k = W / K). Instance k runs with the
        seed mixed from the planner seed and k. After a solve, getPlan() and the statistics are the winner's. */
    class ORPARC : public PARC
    {
      public:
        explicit ORPARC(const ompl::base::SpaceInformationPtr &si);
        ~ORPARC() override;

        using PARC::solve;
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief The winner's plan after a successful solve(). */
        const MultiRobotPlan &getPlan() const;

        void setInstances(unsigned int instances);
        unsigned int getInstances() const { return instances_; }
        /** \brief Sets W_k = total / K; throws ompl::Exception unless total is a positive multiple of K. */
        void setTotalWorkers(unsigned int total);
        unsigned int getTotalWorkers() const { return instances_ * getWorkers(); }

      private:
        unsigned int instances_{2};
        std::vector<std::shared_ptr<PARC>> racers_;
        std::shared_ptr<PARC> winner_;
    };
}  // namespace ompl_parc

#endif
