#ifndef OMPL_PARC_PLANNERS_OR_RRT_CONNECT_
#define OMPL_PARC_PLANNERS_OR_RRT_CONNECT_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/parallel/OrRace.h"

#include <ompl/base/Planner.h>

namespace ompl_parc
{
    /** \brief OR-EP-RRT-C K x W_k, the paper's coupled OR-parallel baselines: K independent RRT-Connect
        instances over the composite space raced with OrRace (fresh instances at every solve()); the first
        solution wins and stops the others, all joined before solve() returns. The PlannerData holds the
        winner and every instance's status and properties.

        With W_k = 1 (\e workers) the instances are OMPL's own RRTConnect (OR-RRT-C); with W_k > 1 they are
        EPRRTConnect with W_k workers each (OR-EP-RRT-C). \e total_workers (W) sets W_k = W / K and must be a
        multiple of \e instances. Instance k samples from its own stream seeded with a mix of \e seed and k: an
        OMPL RRTConnect samples from a copy of the team's spaces seeded that way (OMPL planners draw their
        samplers from the SpaceInformation), an EPRRTConnect gets the seed itself. Needs a MultiRobotSpaceInformation.
     */
    class ORRRTConnect : public ompl::base::Planner
    {
      public:
        explicit ORRRTConnect(const ompl::base::SpaceInformationPtr &si);

        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief K; throws ompl::Exception for 0. */
        void setInstances(unsigned int instances) { race_.setInstances(instances); }
        unsigned int getInstances() const { return race_.getInstances(); }
        /** \brief W_k; throws ompl::Exception for 0. */
        void setWorkers(unsigned int workers);
        unsigned int getWorkers() const { return workers_; }
        /** \brief Sets W_k = total / K; throws ompl::Exception unless total is a positive multiple of K. */
        void setTotalWorkers(unsigned int total);
        unsigned int getTotalWorkers() const { return getInstances() * workers_; }
        /** \brief Every instance's range (0: OMPL's default, 20% of the space's extent). */
        void setRange(double range);
        double getRange() const { return range_; }
        /** \brief 0: draw a seed from OMPL's global random sequence at each solve(). */
        void setSeed(unsigned int seed) { seed_ = seed; }
        unsigned int getSeed() const { return seed_; }

      private:
        MultiRobotSpaceInformationPtr mrsi_;
        OrRace race_;
        unsigned int workers_{1};
        double range_{0.};
        unsigned int seed_{0};
    };
}  // namespace ompl_parc

#endif
