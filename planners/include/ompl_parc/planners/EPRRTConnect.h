#ifndef OMPL_PARC_PLANNERS_EP_RRT_CONNECT_
#define OMPL_PARC_PLANNERS_EP_RRT_CONNECT_

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/base/Planner.h>
#include <ompl/datastructures/NearestNeighbors.h>

#include <atomic>
#include <memory>
#include <mutex>

namespace ompl_parc
{
    /** \brief EP-RRT-C, the paper's coupled baseline with internal parallelism: W worker threads grow ONE pair
        of RRT-Connect trees over the composite space.

        OMPL's only shared-tree parallel planner (pRRT) is a single-tree RRT, so this is our own RRT-Connect.
        Design: each tree is a nearest-neighbour structure behind its own mutex, held only for the nearest
        query and for inserting a motion; sampling, interpolation and the motion check (the N-robot validity
        test, nearly all of the time) run unlocked, so workers overlap on what is expensive. Motions never
        change once inserted (parent pointers are immutable), so building the path needs no lock. Every
        worker alternates the tree it extends like RRT-Connect, with even workers starting from the start
        tree and odd ones from the goal tree; the first worker to connect the trees publishes the path and
        stops the others, all joined before solve() returns.

        Worker w samples from its own stream seeded with a mix of \e seed and w, so with one worker a seed
        fixes the result; with more the interleaving of the workers still varies between runs. Needs a
        MultiRobotSpaceInformation and a goal that can be sampled (the composite GoalState of a problem). */
    class EPRRTConnect : public ompl::base::Planner
    {
      public:
        explicit EPRRTConnect(const ompl::base::SpaceInformationPtr &si);
        ~EPRRTConnect() override;

        using ompl::base::Planner::solve;  // keep solve(seconds) visible next to the override
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void setup() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief Number of threads growing the trees; throws ompl::Exception for 0. */
        void setWorkers(unsigned int workers);
        unsigned int getWorkers() const { return workers_; }
        /** \brief Longest motion added to a tree (0: OMPL's default, 20% of the space's extent). */
        void setRange(double range);
        double getRange() const { return range_; }
        /** \brief 0: draw a seed from OMPL's global random sequence at each solve(). */
        void setSeed(unsigned int seed) { seed_ = seed; }
        unsigned int getSeed() const { return seed_; }

      private:
        struct Motion;
        struct Tree;
        enum class Growth
        {
            TRAPPED,
            ADVANCED,
            REACHED
        };

        /** \brief One RRT-Connect extension of \e tree toward \e target; \e added is the new motion. */
        Growth grow(Tree &tree, const ompl::base::State *target, ompl::base::State *scratch, Motion *&added);
        /** \brief The loop of one worker until \e ptc fires or some worker connects the trees. */
        void work(unsigned int worker, std::uint_fast32_t seed, const ompl::base::PlannerTerminationCondition &ptc);
        /** \brief Record the first connection between a start-tree and a goal-tree motion. */
        void connect(Motion *startSide, Motion *goalSide);
        void freeTree(Tree &tree);

        MultiRobotSpaceInformationPtr mrsi_;
        unsigned int workers_{1};
        double range_{0.};
        unsigned int seed_{0};
        std::unique_ptr<Tree> startTree_, goalTree_;
        std::mutex connectionMutex_;
        /** \brief Set once the trees are connected or a worker failed: every worker then stops. */
        std::atomic<bool> stop_{false};
        Motion *connection_[2]{nullptr, nullptr};
    };
}  // namespace ompl_parc

#endif
