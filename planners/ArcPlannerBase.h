#ifndef OMPL_PARC_PLANNERS_ARC_PLANNER_BASE_
#define OMPL_PARC_PLANNERS_ARC_PLANNER_BASE_

#include "ompl_parc/arc/ArcSettings.h"
#include "ompl_parc/arc/ConflictDetector.h"
#include "ompl_parc/arc/ConflictResolver.h"
#include "ompl_parc/arc/RepairCache.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <ompl/base/Planner.h>

#include <map>
#include <memory>
#include <string>

namespace ompl_parc
{
    /** \brief Counters and per-stage times of an ARC-family solve (wall and summed CPU seconds). */
    struct ArcStatistics
    {
        double initialWall{0.}, initialCpu{0.}, detectionWall{0.}, detectionCpu{0.}, resolutionWall{0.},
            resolutionCpu{0.};
        unsigned int conflicts{0}, repairs{0}, solverCalls{0}, expansions{0}, teamGrowths{0}, globalRepairs{0};
        std::map<std::string, unsigned int> solverWins;
    };

    /** \brief What ARC and P-ARC share: the OMPL planner shell over a MultiRobotSpaceInformation, the
        declared ArcSettings parameters, the plan being repaired, conflict frontiers and the repair cache.

        solve() follows OMPL's conventions: it checks the start and goal (INVALID_START / INVALID_GOAL, the
        reason naming the robot in getStatusMessage() and the log; CRASH with the reason if a stage throws),
        runs the initial stage
        (computeInitialPlans()) and conflict resolution (resolveConflicts()) until the plan is conflict-free
        (EXACT_SOLUTION, added to the ProblemDefinition as a composite path with one state per timestep) or
        the termination condition fires (TIMEOUT). A later solve() continues where the last one stopped;
        clear() starts over. The same seed gives the same plan. */
    class ArcPlannerBase : public ompl::base::Planner
    {
      public:
        ArcPlannerBase(const ompl::base::SpaceInformationPtr &si, const std::string &name);
        ~ArcPlannerBase() override;

        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief The current plan (the solution after a successful solve()). */
        const MultiRobotPlan &getPlan() const { return plan_; }
        const ArcStatistics &getStatistics() const { return statistics_; }
        /** \brief Why the last solve() did not succeed (empty after success). */
        const std::string &getStatusMessage() const { return statusMessage_; }
        const ArcSettings &getSettings() const { return settings_; }

        /** \name Declared parameters
            @{ */
        void setProfile(const std::string &profile);
        std::string getProfile() const { return profile_; }
        void setWindow(unsigned int window);
        unsigned int getWindow() const { return settings_.window; }
        void setGrowth(const std::string &growth);
        std::string getGrowth() const { return ArcSettings::toString(settings_.growth); }
        void setGrowthStep(double step);
        double getGrowthStep() const { return settings_.growthStep; }
        void setEndpointStep(unsigned int step);
        unsigned int getEndpointStep() const { return settings_.endpointStep; }
        void setBoundMargin(double margin);
        double getBoundMargin() const { return settings_.boundMargin; }
        void setMinBoundRange(double range);
        double getMinBoundRange() const { return settings_.minBoundRange; }
        void setSampleCap(unsigned int cap);
        unsigned int getSampleCap() const { return settings_.sampleCap; }
        void setSolvers(const std::string &solvers);
        std::string getSolvers() const { return ArcSettings::toString(settings_.solvers); }
        void setSimplifyInitial(bool simplify);
        bool getSimplifyInitial() const { return settings_.simplifyInitial; }
        /** \brief 0: draw a seed from OMPL's global random sequence at the first solve(). */
        void setSeed(unsigned int seed);
        unsigned int getSeed() const { return seed_; }
        /** @} */

      protected:
        /** \brief Fill plan_ with one single-robot path per robot; false if \e ptc fired first. */
        virtual bool computeInitialPlans(const ompl::base::PlannerTerminationCondition &ptc) = 0;

        /** \brief Detect and repair conflicts until none is left (true) or \e ptc fires (false). */
        virtual bool resolveConflicts(const ompl::base::PlannerTerminationCondition &ptc) = 0;

        /** \brief The solution path handed to the ProblemDefinition (one composite state per timestep). */
        virtual ompl::geometric::PathGeometricPtr buildSolutionPath() const;

        /** \brief Splice \e repair into plan_, pull back the frontiers of its robots, cache its interval. */
        void applyRepair(const Repair &repair);

        /** \brief The solvers of settings_.solvers, in the order they are tried. */
        std::vector<SubproblemSolverPtr> makeHierarchy() const;

        MultiRobotSpaceInformationPtr mrsi_;
        ArcSettings settings_;
        std::string profile_{"mobile"};
        unsigned int seed_{0};
        /** \brief The seed in use (seed_, or the one drawn for seed_ == 0). */
        std::uint_fast32_t effectiveSeed_{0};

        std::unique_ptr<MultiRobotProblem> problem_;
        MultiRobotPlan plan_;
        std::vector<char> planned_;
        bool initialised_{false};
        std::unique_ptr<ConflictDetector> detector_;
        std::unique_ptr<ConflictResolver> resolver_;
        RepairCache cache_;
        ArcStatistics statistics_;
        std::string statusMessage_;

        /** \brief Build problem_ from the ProblemDefinition; returns the status to report if it is bad. */
        std::optional<ompl::base::PlannerStatus> readProblem();

      private:
        ompl::base::PlannerStatus solveStages(const ompl::base::PlannerTerminationCondition &ptc);
        void invalidateState();
    };
}  // namespace ompl_parc

#endif
