#ifndef OMPL_PARC_PLANNERS_STRRT_STAR_
#define OMPL_PARC_PLANNERS_STRRT_STAR_

#include "ompl_parc/spacetime/SpaceTimeInUse.h"

#include <ompl/base/Planner.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/RandomNumbers.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Space-Time RRT* (Grothe, Hoffmann, Arras, ICRA 2022): a bidirectional RRT* in a robot's space x
        time, for planning among moving obstacles without knowing the arrival time in advance.

        The start tree grows forward in time from the start; the goal tree grows backward in time from goal
        states whose times are sampled inside the current time bound. When time is unbounded the bound grows
        in batches: the first batch samples goal times in [T, f0 T] (T the least arrival time at vMax, f0 the
        initial time-bound factor), and each full batch multiplies the factor by the increase factor. Samples
        are conditional: a space sample gets a time at which it is reachable from the start and can still
        reach a goal. Rewiring (off, radius or k-nearest) picks the parent among a neighbourhood and re-parents
        goal-tree neighbours whose goal is reached earlier through a new vertex.

        OMPL 1.5 lacks this planner (OMPL >= 1.6 has ompl::geometric::STRRTstar; see planners/SpaceTime.h);
        this is our implementation with the same parameters, plus two extensions for prioritised planning: a
        minimum goal time (a goal counts only from then on, so a robot can hold its goal safely) and stopping
        at the first solution. After a solution it keeps searching, until the termination condition, only
        for earlier arrivals (no tree pruning), and reports each solution to the problem definition's
        intermediate solution callback. Needs the space-time state space in use
        (spacetime::SpaceTimeStateSpace, OMPL's from OMPL 1.6 on; throws ompl::Exception otherwise) and a goal
        that can be sampled; goal samples get their time from the planner. */
    class STRRTstar : public ompl::base::Planner
    {
      public:
        explicit STRRTstar(const ompl::base::SpaceInformationPtr &si);
        ~STRRTstar() override;

        void setup() override;
        void clear() override;
        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief Longest motion added to a tree, in the space-time distance; 0: a fifth of the space
            component's extent. */
        void setRange(double distance) { maxDistance_ = distance; }
        double getRange() const { return maxDistance_; }

        void setRewiringToOff() { rewireState_ = RewireState::OFF; }
        void setRewiringToRadius() { rewireState_ = RewireState::RADIUS; }
        void setRewiringToKNearest() { rewireState_ = RewireState::KNEAREST; }
        /** \brief "off", "radius" or "knearest" (also accepted by setRewiringState()). */
        std::string getRewiringState() const;
        void setRewiringState(const std::string &state);

        /** \brief The factor s > 1 by which the neighbourhood exceeds the RRT* bound (radius or k). */
        void setRewireFactor(double factor) { rewireFactor_ = factor; }
        double getRewireFactor() const { return rewireFactor_; }

        /** \brief Samples of the first batch, before the time bound is first increased. */
        void setBatchSize(unsigned int size);
        unsigned int getBatchSize() const { return initialBatchSize_; }

        /** \brief The first batch samples goal times up to this factor times the least arrival time. */
        void setInitialTimeBoundFactor(double factor);
        double getInitialTimeBoundFactor() const { return initialTimeBoundFactor_; }

        /** \brief Each full batch multiplies the time bound factor by this (> 1). */
        void setTimeBoundFactorIncrease(double factor);
        double getTimeBoundFactorIncrease() const { return timeBoundFactorIncrease_; }

        /** \brief With unbounded time, sample the grown region uniformly (true) or favour early times. */
        void setSampleUniformForUnboundedTime(bool uniform) { sampleUniformForUnboundedTime_ = uniform; }
        bool getSampleUniformForUnboundedTime() const { return sampleUniformForUnboundedTime_; }

        /** \brief Goal states are only accepted at times >= \e time (e.g. when the goal is safe to hold). */
        void setMinimumGoalTime(double time) { minimumGoalTime_ = time; }
        double getMinimumGoalTime() const { return minimumGoalTime_; }

        /** \brief Return as soon as one solution is found instead of improving it until the termination
            condition holds. */
        void setStopAtFirstSolution(bool stop) { stopAtFirstSolution_ = stop; }
        bool getStopAtFirstSolution() const { return stopAtFirstSolution_; }

        /** \brief Seed the planner's own random numbers (goal times, batch choice), for reproducible runs;
            the state sampler is the space component's. */
        void setLocalSeed(std::uint_fast32_t seed) { rng_.setLocalSeed(seed); }

      protected:
        enum class RewireState
        {
            OFF,
            RADIUS,
            KNEAREST
        };

        /** \brief A tree vertex; goal-tree vertices lead forward in time to their root (a goal). */
        struct Motion
        {
            ompl::base::State *state{nullptr};
            Motion *parent{nullptr};
            const Motion *root{nullptr};
            std::vector<Motion *> children;
        };
        using Tree = std::shared_ptr<ompl::NearestNeighbors<Motion *>>;

        /** \brief Time of a vertex's state. */
        static double timeOf(const Motion *motion)
        {
            return spacetime::SpaceTimeStateSpace::getStateTime(motion->state);
        }

        /** \brief A new vertex with a copy of \e state, owned by the planner. */
        Motion *newMotion(const ompl::base::State *state, Motion *parent);

        /** \brief The valid motion rule: strictly forward in time and valid for the motion validator. */
        bool motionValid(const ompl::base::State *from, const ompl::base::State *to) const;

        /** \brief One step from \e near towards \e target (at most the range); the new vertex or nullptr. */
        Motion *growSingle(Tree &tree, bool startTree, Motion *near, const ompl::base::State *target, bool &reached);

        /** \brief Extend \e tree by one step towards \e target from the best vertex of its neighbourhood. */
        Motion *extend(Tree &tree, bool startTree, const ompl::base::State *target);

        /** \brief Extend \e tree repeatedly towards \e target; the vertex at \e target if reached, else nullptr. */
        Motion *connect(Tree &tree, bool startTree, const ompl::base::State *target,
                        const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief The rewiring neighbourhood of \e state in \e tree (empty when rewiring is off). */
        void getNeighbors(const Tree &tree, const ompl::base::State *state, std::vector<Motion *> &nbh) const;

        /** \brief Re-parent goal-tree neighbours of \e added that reach an earlier goal through it. */
        void rewireGoalTree(Motion *added);

        /** \brief Sample a state reachable from the start that can still reach one of the goals in the batch. */
        bool sampleConditional(ompl::base::State *state, bool oldBatch);

        /** \brief Up to \e tries goal samples with times in the batch's region; the first valid one or nullptr. */
        Motion *sampleGoal(unsigned int tries, bool oldBatch, const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief Grow the time bound factor; \e skipEmpty skips a region in which no goal could be sampled. */
        void increaseTimeBound(bool skipEmpty);

        /** \brief Store the path start root ... startSide, goalSide ... goal root if it arrives earlier, and
            report it to the intermediate solution callback. */
        bool recordSolution(const Motion *startSide, const Motion *goalSide);

        void freeMemory();

        /** \brief The space-time space (not const: OMPL's has no const accessors to its components). */
        spacetime::SpaceTimeStateSpace *space_{nullptr};
        ompl::base::StateSamplerPtr spaceSampler_;
        Tree tStart_, tGoal_;
        std::vector<std::unique_ptr<Motion>> motions_;
        Motion *startMotion_{nullptr};
        std::vector<Motion *> goalMotions_, newBatchGoalMotions_;
        ompl::base::State *scratch_{nullptr};
        /** \brief A vertex-shaped wrapper for nearest-neighbour queries of a free state. */
        mutable Motion query_;
        const ompl::base::GoalSampleableRegion *goal_{nullptr};
        ompl::RNG rng_;

        double maxDistance_{0.};
        RewireState rewireState_{RewireState::KNEAREST};
        double rewireFactor_{1.1};
        unsigned int initialBatchSize_{512};
        double initialTimeBoundFactor_{2.};
        double timeBoundFactorIncrease_{2.};
        bool sampleUniformForUnboundedTime_{true};
        double minimumGoalTime_{0.};
        bool stopAtFirstSolution_{false};

        /** \brief Least duration of a goal's arrival (at vMax, not before the minimum goal time), the
            duration the time bound factors multiply. */
        double referenceDuration(const ompl::base::State *goal) const;
        /** \brief Space-time volume searched so far, for the RRT* radius. */
        double currentHorizon() const;

        /** \brief Per-solve state of the batch schedule. */
        double startTime_{0.}, minimumDuration_{0.}, durationFloor_{0.};
        unsigned int batchSize_{0}, batchSamples_{0};
        bool nextFromStart_{true};
        double oldBatchFactor_{0.}, newBatchFactor_{0.};
        bool timeBounded_{false};
        double upperTimeBound_{0.};
        unsigned int iterations_{0}, solutions_{0};
        double bestTime_{0.};
        std::vector<const ompl::base::State *> bestPath_;
    };
}  // namespace ompl_parc

#endif
