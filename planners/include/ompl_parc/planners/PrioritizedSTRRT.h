#ifndef OMPL_PARC_PLANNERS_PRIORITIZED_STRRT_
#define OMPL_PARC_PLANNERS_PRIORITIZED_STRRT_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/quality/SmoothingStep.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <string>

namespace ompl_parc
{
    /** \brief Prioritised planning with ST-RRT (PP-ST-RRT) as an OMPL planner for a whole multi-robot problem:
        the decoupled baseline of the P-ARC paper, and the same PrioritizedSTRRTSolver that ARC uses on its
        subproblems, applied to all robots, their global starts and goals and their whole spaces.

        Needs a MultiRobotSpaceInformation (throws ompl::Exception otherwise) and a GoalState. The solution
        is a composite PathGeometric with one state per timestep (MultiRobotPlan::toPathGeometric). */
    class PrioritizedSTRRT : public ompl::base::Planner
    {
      public:
        explicit PrioritizedSTRRT(const ompl::base::SpaceInformationPtr &si);

        /** \brief INVALID_START / INVALID_GOAL (logging which robot is invalid), EXACT_SOLUTION, or TIMEOUT.
            Plans in rounds until the termination condition: round r caps each robot's ST-RRT at sample_cap x 2^r
            iterations and draws fresh samples (after the first, with the lattice, a shuffled base order: the lattice
           plans an order the same way every time), and within a round a robot that fails is promoted to the front
            (promote). With sample_cap 0 there is one uncapped round, which may fail before the condition. */
        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief The plan on the timestep grid after a successful solve(): the solution path has one state
            per timestep, waits included, which re-timing it (MultiRobotPlan::fromPathGeometric) would drop. */
        const MultiRobotPlan &getPlan() const { return plan_; }

        void setRange(double range) { settings_.range = range; }
        double getRange() const { return settings_.range; }
        /** \brief "given" (the team's order) or "shuffled" (from the seed). */
        void setPriorityOrder(const std::string &order);
        std::string getPriorityOrder() const { return settings_.shuffle ? "shuffled" : "given"; }
        /** \brief Seed of the priority shuffle and of all sampling; 0: drawn from OMPL's seed sequence. */
        void setSeed(unsigned int seed) { seed_ = seed; }
        unsigned int getSeed() const { return seed_; }
        /** \brief Promote a robot that cannot be planned to the front of the order and plan again (default on). */
        void setPromote(bool promote) { settings_.promote = promote; }
        bool getPromote() const { return settings_.promote; }
        /** \brief Order the robots so that they get out of each other's way, from their paths planned alone
            (BlockingOrder; default on); the given or shuffled order breaks ties. */
        void setUnblock(bool unblock) { settings_.unblock = unblock; }
        bool getUnblock() const { return settings_.unblock; }
        /** \brief Plan each translating robot on a space-time lattice first (LatticeSearch; default on), ST-RRT
            only where the lattice has no path. */
        void setLattice(bool lattice) { settings_.lattice = lattice; }
        bool getLattice() const { return settings_.lattice; }
        /** \brief The lattice's step; 0 (default): the robot's bounding radius. Throws for a negative or
            non-finite step. */
        void setLatticeStep(double step);
        double getLatticeStep() const { return settings_.latticeStep; }
        /** \brief ST-RRT iterations per robot in the first round (doubling each round); 0: no cap, one round. */
        void setSampleCap(unsigned int cap) { sampleCap_ = cap; }
        unsigned int getSampleCap() const { return sampleCap_; }
        /** \brief ST-RRT rewiring: "off" (default, as in the paper), "radius" or "knearest". */
        void setRewiring(const std::string &rewiring);
        std::string getRewiring() const { return settings_.rewiring; }
        void setBatchSize(unsigned int size);
        unsigned int getBatchSize() const { return settings_.batchSize; }
        void setInitialTimeBoundFactor(double factor);
        double getInitialTimeBoundFactor() const { return settings_.initialTimeBoundFactor; }
        void setTimeBoundFactorIncrease(double factor);
        double getTimeBoundFactorIncrease() const { return settings_.timeBoundFactorIncrease; }
        /** \brief Seconds of time-aware shortcutting (PlanSmoother) after a solution; 0 (the default): none. */
        void setSmoothing(double seconds) { smoothing_.setBudget(seconds); }
        double getSmoothing() const { return smoothing_.getBudget(); }

      protected:
        /** \brief Add plan_ to the ProblemDefinition; with a \e smooth budget, smoothed first (drawing from \e seed)
            and as the only solution. Without one nothing is cleared: OR racers share the ProblemDefinition. */
        void publishPlan(const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed);

        MultiRobotPlan plan_;
        SmoothingStep smoothing_;
        /** \brief Whether the last solve() found a plan (the PlannerData's \e solved, which OMPL's benchmark takes
            over its own). */
        bool solved_{false};

      private:
        /** \brief Apply \e settings if PrioritizedSTRRTSolver accepts them (it throws otherwise). */
        void updateSettings(const PrioritizedSTRRTSettings &settings);

        MultiRobotSpaceInformationPtr mrsi_;
        PrioritizedSTRRTSettings settings_;
        unsigned int seed_{0};
        unsigned int lastSeed_{0};
        unsigned int sampleCap_{DEFAULT_SAMPLE_CAP};
        /** \brief Rounds the last solve() ran. */
        unsigned int rounds_{0};

        static constexpr unsigned int DEFAULT_SAMPLE_CAP = 50000;
    };
}  // namespace ompl_parc

#endif
