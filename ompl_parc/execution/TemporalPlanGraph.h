#ifndef OMPL_PARC_TEMPORAL_PLAN_GRAPH_
#define OMPL_PARC_TEMPORAL_PLAN_GRAPH_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ompl_parc
{
    /** \brief The order a conflict-free plan needs kept when robots run late: a temporal plan graph (the action
        dependency graph of Hönig et al., RA-L 2019, for continuous motion), so that robots coordinated by it never
        collide, whatever their delays and speeds.

        The plan's time is cut into phases at the plan's breakpoints (and every maxPhaseSteps timesteps): in a phase,
        every robot moves straight or rests. A node is a robot's motion in a phase; its sweep (the robot's capsules at
        the phase's start, each grown by how far any point of it moves in the phase, DisplacementBound; a disc's exact
        swept capsule) contains the robot at every instant of it. Two nodes of different robots whose sweeps meet:
        - in different phases p < q: an edge, the robot of q may start it only once the robot of p has finished p;
        - in the same phase: the two are synchronised, they start the phase together and move through it at the
          same fraction of it at every instant (so together they are at the plan's configurations, which are
          conflict-free).
        Resting needs no node: a robot resting where another one passes is held there by the edges of its own
        arriving and leaving motions, whose sweeps contain the resting place. Edges only go forward in plan time, so
        the graph has no cycle and execution never deadlocks. Edges implied by others (the same robots, an earlier
        phase before a later one) are removed. */
    class TemporalPlanGraph
    {
      public:
        /** \brief The robot of \e to may start its phase \e to.phase once the robot of \e from finished
            \e from.phase. */
        struct Node
        {
            std::size_t robot, phase;
        };
        struct Edge
        {
            Node from, to;
        };

        TemporalPlanGraph(const MultiRobotProblem &problem, const MultiRobotPlan &plan, std::size_t maxPhaseSteps = 4);

        /** \brief Phase boundaries (plan timesteps, ascending): phase p is [getBoundary(p), getBoundary(p + 1)]. */
        std::size_t getPhaseCount() const { return boundaries_.size() - 1; }
        std::size_t getBoundary(std::size_t p) const { return boundaries_[p]; }
        std::size_t getRobotCount() const { return robots_; }
        /** \brief True if robot \e i moves in phase \e p (it has a node there). */
        bool isMoving(std::size_t i, std::size_t p) const { return moving_[p * robots_ + i] != 0; }
        /** \brief The representative of the synchronised group of node (\e i, \e p) (a robot of that phase; \e i
            itself when it moves alone). */
        std::size_t getGroup(std::size_t i, std::size_t p) const { return group_[p * robots_ + i]; }
        /** \brief The edges, reduced. */
        const std::vector<Edge> &getEdges() const { return edges_; }
        std::size_t getNodeCount() const;
        /** \brief Edges found before the redundant ones were removed, and synchronised pairs of nodes. */
        std::size_t getUnreducedEdgeCount() const { return unreducedEdges_; }
        std::size_t getSynchronisedPairCount() const { return synchronisedPairs_; }

        /** \brief The graph as JSON: phases, per robot its nodes (phase, plan timesteps, group), the edges. */
        nlohmann::ordered_json toJson() const;

      private:
        std::size_t robots_;
        std::vector<std::size_t> boundaries_;
        std::vector<char> moving_;
        std::vector<std::uint32_t> group_;
        std::vector<Edge> edges_;
        std::size_t unreducedEdges_{0}, synchronisedPairs_{0};
    };
}  // namespace ompl_parc

#endif
