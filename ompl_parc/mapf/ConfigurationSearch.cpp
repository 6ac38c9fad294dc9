#include "ompl_parc/mapf/ConfigurationSearch.h"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_int_distribution.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <numeric>
#include <unordered_map>

namespace
{
    using Vertex = ompl_parc::LatticeGraph::Vertex;
    using Configuration = ompl_parc::ConfigurationSearch::Configuration;
    constexpr Vertex NONE = ompl_parc::LatticeGraph::NONE;
    constexpr std::uint32_t NOBODY = std::numeric_limits<std::uint32_t>::max();

    struct ConfigurationHash
    {
        std::size_t operator()(const Configuration &q) const
        {
            std::size_t h = q.size();
            for (Vertex v : q)
                h = (h ^ v) * 0x100000001b3ULL;
            return h;
        }
    };

    /** LaCAM's constraint: robots who[k] must go to where[k] in the next step. */
    struct Constraint
    {
        std::vector<std::uint32_t> who;
        std::vector<Vertex> where;
    };

    /** A configuration reached, its robots' priorities and order, and the constraints still to try from it. */
    struct Node
    {
        Configuration q;
        std::size_t parent;
        std::vector<double> priorities;
        std::vector<std::uint32_t> order;
        std::deque<Constraint> tree;
    };

    /** One search: the graph, the goals' hop tables, and PIBT's scratch (who is on or goes to each vertex). */
    class Search
    {
      public:
        /** The hop tables (one breadth-first search per robot) until \e ptc fires: complete() says if they are. */
        Search(const ompl_parc::LatticeGraph &graph, const Configuration &goals, std::uint_fast32_t seed,
               const ompl::base::PlannerTerminationCondition &ptc)
            : graph_(graph), goals_(goals), rng_(seed), now_(graph.size(), NOBODY), next_(graph.size(), NOBODY)
        {
            hops_.resize(goals.size());
            for (std::size_t i = 0; i < goals.size() && !ptc; ++i)
                graph.hopsTo(goals[i], hops_[i]);
        }

        bool complete() const { return hops_.empty() || !hops_.back().empty(); }

        /** The search's random sequence (ties, and the order of the constraints tried). */
        boost::random::mt19937 &rng() { return rng_; }

        bool reachable(const Configuration &starts) const
        {
            for (std::size_t i = 0; i < starts.size(); ++i)
                if (hops_[i][starts[i]] == ompl_parc::LatticeGraph::UNREACHABLE)
                    return false;
            return true;
        }

        std::unique_ptr<Node> makeNode(Configuration q, std::size_t parent, const Node *from)
        {
            auto node = std::make_unique<Node>();
            const std::size_t n = q.size();
            node->priorities.resize(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                if (from == nullptr)  // first: the farthest robots first, a fraction below one step
                    node->priorities[i] = static_cast<double>(hops_[i][q[i]]) / static_cast<double>(graph_.size() + 1);
                else if (q[i] != goals_[i])  // waiting for its goal: more urgent each step
                    node->priorities[i] = from->priorities[i] + 1.;
                else
                    node->priorities[i] = from->priorities[i] - std::floor(from->priorities[i]);
            }
            node->order.resize(n);
            std::iota(node->order.begin(), node->order.end(), 0);
            std::stable_sort(node->order.begin(), node->order.end(),
                             [&](std::uint32_t a, std::uint32_t b)
                             { return node->priorities[a] > node->priorities[b]; });
            node->q = std::move(q);
            node->parent = parent;
            node->tree.emplace_back();
            return node;
        }

        /** The next configuration from \e node under \e constraint (PIBT in the node's order); false if the
            constraint itself breaks the rules or PIBT cannot keep them. */
        bool generate(const Node &node, const Constraint &constraint, Configuration &out)
        {
            const Configuration &q = node.q;
            const std::size_t n = q.size();
            cur_ = &q;
            out.assign(n, NONE);
            out_ = &out;
            for (std::size_t i = 0; i < n; ++i)
                now_[q[i]] = static_cast<std::uint32_t>(i);
            bool ok = true;
            for (std::size_t k = 0; k < constraint.who.size() && ok; ++k)
            {
                const std::uint32_t i = constraint.who[k];
                const Vertex v = constraint.where[k];
                const std::uint32_t j = now_[v];
                if (next_[v] != NOBODY || (j != NOBODY && j != i && out[j] == q[i]))
                    ok = false;
                else
                {
                    out[i] = v;
                    next_[v] = i;
                }
            }
            for (std::size_t k = 0; k < n && ok; ++k)
                if (const std::uint32_t i = node.order[k]; out[i] == NONE)
                    pibt(i);
            for (std::size_t i = 0; i < n; ++i)
            {
                now_[q[i]] = NOBODY;
                if (out[i] != NONE)
                    next_[out[i]] = NOBODY;
            }
            return ok && ompl_parc::ConfigurationSearch::followLevels(graph_, q, out, levels_);
        }

      private:
        /** Whether robot \e asker entering the vertex of \e occupant (which already moves) closes a rotation. */
        bool closesCycle(std::uint32_t asker, std::uint32_t occupant) const
        {
            const Configuration &q = *cur_, &out = *out_;
            for (std::uint32_t a = occupant, steps = 0; steps <= q.size(); ++steps)
            {
                const Vertex w = out[a];
                if (w == q[asker])
                    return true;
                const std::uint32_t b = now_[w];
                if (w == q[a] || b == NOBODY || b == a || out[b] == NONE)
                    return false;
                a = b;
            }
            return true;
        }

        /** PIBT's step for robot \e i: the free neighbour (or its own vertex) nearest its goal, pushing the robot
            there out of the way first; false if it must stay. */
        bool pibt(std::uint32_t i)
        {
            const Configuration &q = *cur_;
            Configuration &out = *out_;
            const auto [first, last] = graph_.getNeighbours(q[i]);
            std::vector<Vertex> candidates(first, last);
            candidates.push_back(q[i]);
            for (std::size_t k = candidates.size(); k > 1; --k)
                std::swap(candidates[k - 1],
                          candidates[boost::random::uniform_int_distribution<std::size_t>(0, k - 1)(rng_)]);
            const auto &hops = hops_[i];
            std::stable_sort(candidates.begin(), candidates.end(),
                             [&](Vertex a, Vertex b) { return hops[a] < hops[b]; });
            for (const Vertex u : candidates)
            {
                if (next_[u] != NOBODY)
                    continue;
                const std::uint32_t j = now_[u];
                if (j != NOBODY && j != i && out[j] != NONE && (out[j] == q[i] || closesCycle(i, j)))
                    continue;
                out[i] = u;
                next_[u] = i;
                if (j == NOBODY || j == i)
                    return true;
                if (out[j] == NONE && !pibt(j))
                    continue;  // j stays on u (it took u back)
                return true;
            }
            out[i] = q[i];
            next_[q[i]] = i;
            return false;
        }

        const ompl_parc::LatticeGraph &graph_;
        const Configuration &goals_;
        std::vector<std::vector<std::uint32_t>> hops_;
        boost::random::mt19937 rng_;
        std::vector<std::uint32_t> now_, next_;
        std::vector<unsigned int> levels_;
        const Configuration *cur_{nullptr};
        Configuration *out_{nullptr};
    };
}  // namespace

bool ompl_parc::ConfigurationSearch::followLevels(const LatticeGraph &graph, const Configuration &from,
                                                  const Configuration &to, std::vector<unsigned int> &levels)
{
    const std::size_t n = from.size();
    if (to.size() != n)
        return false;
    // Who stands on each vertex now, and who enters it: hashed, the graph may be far larger than the team.
    std::unordered_map<Vertex, std::uint32_t> standing, entering;
    for (std::size_t i = 0; i < n; ++i)
    {
        standing.emplace(from[i], static_cast<std::uint32_t>(i));
        if (!entering.emplace(to[i], static_cast<std::uint32_t>(i)).second)
            return false;  // two robots on one vertex
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (to[i] == from[i])
            continue;
        const auto [first, last] = graph.getNeighbours(from[i]);
        if (std::find(first, last, to[i]) == last)
            return false;  // not a move of the graph
        const auto j = standing.find(to[i]);
        if (j != standing.end() && to[j->second] == from[i])
            return false;  // a swap
    }
    constexpr unsigned int UNKNOWN = std::numeric_limits<unsigned int>::max();
    levels.assign(n, UNKNOWN);
    for (std::size_t start = 0; start < n; ++start)
    {
        // Walk the chain of robots each entering the next one's vertex, then set the levels back from its head.
        std::vector<std::uint32_t> chain;
        std::uint32_t a = static_cast<std::uint32_t>(start);
        while (levels[a] == UNKNOWN)
        {
            if (chain.size() > n)
                return false;  // a rotation
            chain.push_back(a);
            const auto j = standing.find(to[a]);
            if (to[a] == from[a] || j == standing.end() || to[j->second] == from[j->second])
                break;  // stays, or enters a vertex nobody leaves (one that stays there was ruled out above)
            a = j->second;
        }
        for (std::size_t k = chain.size(); k-- > 0;)
        {
            const std::uint32_t r = chain[k];
            const auto j = standing.find(to[r]);
            if (to[r] == from[r] || j == standing.end() || j->second == r)
                levels[r] = 0;
            else
            {
                const std::uint32_t ahead = j->second;
                if (levels[ahead] == UNKNOWN)
                    return false;  // a rotation: the chain came back to itself
                levels[r] = levels[ahead] + (graph.straight(from[r], to[r], to[ahead]) ? 0 : 1);
            }
        }
    }
    return true;
}

std::vector<ompl_parc::ConfigurationSearch::Configuration> ompl_parc::ConfigurationSearch::solve(
    const Configuration &starts, const Configuration &goals, const ompl::base::PlannerTerminationCondition &ptc,
    std::uint_fast32_t seed)
{
    nodeCount_ = 0;
    const std::size_t n = starts.size();
    if (goals.size() != n || n == 0)
        return {};
    Search search(graph_, goals, seed, ptc);
    if (!search.complete() || !search.reachable(starts))
        return {};
    std::vector<std::unique_ptr<Node>> nodes;
    std::unordered_map<Configuration, std::size_t, ConfigurationHash> explored;
    std::vector<std::size_t> open;
    nodes.push_back(search.makeNode(starts, NONE, nullptr));
    explored.emplace(starts, 0);
    open.push_back(0);
    std::size_t entries = n;  // robots' vertices held in configurations and constraints
    Configuration next;
    while (!open.empty() && !ptc)
    {
        Node &node = *nodes[open.back()];
        if (node.q == goals)
        {
            std::vector<Configuration> path;
            for (std::size_t k = open.back(); k != NONE; k = nodes[k]->parent)
                path.push_back(nodes[k]->q);
            std::reverse(path.begin(), path.end());
            nodeCount_ = nodes.size();
            return path;
        }
        if (node.tree.empty())
        {
            open.pop_back();
            continue;
        }
        Constraint constraint = std::move(node.tree.front());
        node.tree.pop_front();
        if (constraint.who.size() < n)
        {
            // The next robot in the order gets each of its moves (and staying) as a further constraint.
            const std::uint32_t i = node.order[constraint.who.size()];
            const auto [first, last] = graph_.getNeighbours(node.q[i]);
            std::vector<Vertex> moves(first, last);
            moves.push_back(node.q[i]);
            for (std::size_t k = moves.size(); k > 1; --k)
                std::swap(moves[k - 1],
                          moves[boost::random::uniform_int_distribution<std::size_t>(0, k - 1)(search.rng())]);
            for (const Vertex v : moves)
            {
                Constraint child = constraint;
                child.who.push_back(i);
                child.where.push_back(v);
                entries += child.who.size();
                node.tree.push_back(std::move(child));
            }
        }
        if (entries > maxEntries_)
            break;
        if (!search.generate(node, constraint, next))
            continue;
        if (explored.count(next) != 0)
            continue;
        entries += n;
        const std::size_t parent = open.back();
        nodes.push_back(search.makeNode(next, parent, &node));
        explored.emplace(next, nodes.size() - 1);
        open.push_back(nodes.size() - 1);
    }
    nodeCount_ = nodes.size();
    return {};
}
