#include "ompl_parc/execution/TemporalPlanGraph.h"

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/collision/PrimitiveDistance.h"
#include "ompl_parc/validation/BoxOverlaps.h"
#include "ompl_parc/validation/DisplacementBound.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <numeric>
#include <tuple>
#include <stdexcept>

namespace
{
    /** The sweeps of all nodes, flat: capsule end points and radii, each node's capsules a range. */
    struct Sweeps
    {
        std::vector<double> ax, ay, az, bx, by, bz, radius;
        /** Per capsule, a sphere around it (the quick test before the exact one). */
        std::vector<double> cx, cy, cz, cr;
        std::vector<std::size_t> begin{0};

        /** Append robot \e robot's body at every instant of the straight motion from \e from to \e to (and
            more): a disc's exact swept capsule, else each capsule at \e from grown by how far it moves. */
        void add(const ompl_parc::Robot &robot, const ompl_parc::DisplacementBound &bound, const double *from,
                 const double *to, ompl_parc::CollisionBody &body, ompl_parc::AxisBox &box)
        {
            robot.computeCapsules(from, body);
            std::vector<double> dq(robot.getDimension());
            for (std::size_t d = 0; d < dq.size(); ++d)
                dq[d] = to[d] - from[d];
            const bool disc = bound.isTranslation() && body.size() == 1;
            box = {{{INFINITY, INFINITY, INFINITY}}, {{-INFINITY, -INFINITY, -INFINITY}}};
            for (std::size_t c = 0; c < body.size(); ++c)
            {
                const double r = body.radius_[c] + (disc ? 0. : bound.capsuleBound(c, dq.data()));
                const double ex = body.bx_[c] + (disc ? dq[0] : 0.), ey = body.by_[c] + (disc ? dq[1] : 0.);
                ax.push_back(body.ax_[c]), ay.push_back(body.ay_[c]), az.push_back(body.az_[c]);
                bx.push_back(ex), by.push_back(ey), bz.push_back(body.bz_[c]);
                radius.push_back(r);
                cx.push_back((body.ax_[c] + ex) / 2.), cy.push_back((body.ay_[c] + ey) / 2.);
                cz.push_back((body.az_[c] + body.bz_[c]) / 2.);
                cr.push_back(std::hypot(ex - body.ax_[c], ey - body.ay_[c], body.bz_[c] - body.az_[c]) / 2. + r);
                const double lo[3] = {std::min(body.ax_[c], ex), std::min(body.ay_[c], ey),
                                      std::min(body.az_[c], body.bz_[c])};
                const double hi[3] = {std::max(body.ax_[c], ex), std::max(body.ay_[c], ey),
                                      std::max(body.az_[c], body.bz_[c])};
                for (int d = 0; d < 3; ++d)
                {
                    box.lo[d] = std::min(box.lo[d], lo[d] - r);
                    box.hi[d] = std::max(box.hi[d], hi[d] + r);
                }
            }
            begin.push_back(radius.size());
        }

        /** True if a capsule of node \e a touches one of node \e b. */
        bool meet(std::size_t a, std::size_t b) const
        {
            for (std::size_t i = begin[a]; i < begin[a + 1]; ++i)
                for (std::size_t j = begin[b]; j < begin[b + 1]; ++j)
                {
                    const double dx = cx[i] - cx[j], dy = cy[i] - cy[j], dz = cz[i] - cz[j], bound = cr[i] + cr[j];
                    if (dx * dx + dy * dy + dz * dz > bound * bound)
                        continue;
                    const double reach = radius[i] + radius[j];
                    if (ompl_parc::segmentSegmentDistanceSquared(ax[i], ay[i], az[i], bx[i], by[i], bz[i], ax[j], ay[j],
                                                                 az[j], bx[j], by[j], bz[j]) <= reach * reach)
                        return true;
                }
            return false;
        }
    };

    std::uint32_t findRoot(std::vector<std::uint32_t> &parent, std::uint32_t x)
    {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    }
}  // namespace

ompl_parc::TemporalPlanGraph::TemporalPlanGraph(const MultiRobotProblem &problem, const MultiRobotPlan &plan,
                                                std::size_t maxPhaseSteps)
    : robots_(plan.getRobotCount())
{
    const auto &si = *problem.getSpaceInformation();
    if (const std::string mismatch = plan.checkTeam(si); !mismatch.empty())
        throw std::invalid_argument("TemporalPlanGraph: " + mismatch);
    if (maxPhaseSteps == 0)
        throw std::invalid_argument("TemporalPlanGraph: phases must be at least one timestep long");

    // Phases: the breakpoints, long intervals cut every maxPhaseSteps timesteps.
    const auto breakpoints = plan.getBreakpoints();
    boundaries_.push_back(breakpoints.front());
    for (std::size_t m = 1; m < breakpoints.size(); ++m)
    {
        for (std::size_t t = breakpoints[m - 1] + maxPhaseSteps; t < breakpoints[m]; t += maxPhaseSteps)
            boundaries_.push_back(t);
        boundaries_.push_back(breakpoints[m]);
    }
    if (boundaries_.size() == 1)
        boundaries_.push_back(boundaries_.front());
    const std::size_t phases = getPhaseCount();

    // Nodes and their sweeps.
    moving_.assign(phases * robots_, 0);
    Sweeps sweeps;
    std::vector<AxisBox> boxes;
    std::vector<Node> nodes;
    CollisionBody body;
    for (std::size_t i = 0; i < robots_; ++i)
    {
        const Robot &robot = *si.getRobot(i);
        const DisplacementBound bound(robot);
        TimedPath::Cursor cursor(plan.getPath(i));
        std::vector<double> from(robot.getDimension()), to(robot.getDimension());
        cursor.get(boundaries_[0], to.data());
        for (std::size_t p = 0; p < phases; ++p)
        {
            from = to;
            cursor.get(boundaries_[p + 1], to.data());
            if (from == to)
                continue;
            moving_[p * robots_ + i] = 1;
            nodes.push_back({i, p});
            boxes.emplace_back();
            sweeps.add(robot, bound, from.data(), to.data(), body, boxes.back());
        }
    }

    // Pairs of nodes whose sweeps meet: synchronisation within a phase, else an edge forward in time, of which
    // only the latest phase before each (robot pair, later phase) is kept as found.
    std::vector<std::uint32_t> parent(phases * robots_);
    std::iota(parent.begin(), parent.end(), 0u);
    std::unordered_map<std::uint64_t, std::size_t> latest;
    const std::vector<char> active(nodes.size(), 1);
    BoxOverlaps overlaps;
    overlaps.find(boxes.data(), active.data(), nodes.size(),
                  [&](std::size_t a, std::size_t b)
                  {
                      Node na = nodes[a], nb = nodes[b];
                      if (na.robot == nb.robot || !sweeps.meet(a, b))
                          return;
                      if (na.phase == nb.phase)
                      {
                          ++synchronisedPairs_;
                          const auto ra = findRoot(parent, static_cast<std::uint32_t>(na.phase * robots_ + na.robot));
                          const auto rb = findRoot(parent, static_cast<std::uint32_t>(nb.phase * robots_ + nb.robot));
                          parent[std::max(ra, rb)] = std::min(ra, rb);
                          return;
                      }
                      if (na.phase > nb.phase)
                          std::swap(na, nb);
                      ++unreducedEdges_;
                      const std::uint64_t key = (na.robot * robots_ + nb.robot) * phases + nb.phase;
                      auto [entry, inserted] = latest.emplace(key, na.phase);
                      if (!inserted)
                          entry->second = std::max(entry->second, na.phase);
                  });
    group_.resize(phases * robots_);
    for (std::size_t x = 0; x < group_.size(); ++x)
        group_[x] = findRoot(parent, static_cast<std::uint32_t>(x)) % robots_;

    // Per pair of robots, keep (p, q) unless another edge (p', q') has p' >= p and q' <= q.
    std::vector<Edge> found;
    found.reserve(latest.size());
    for (const auto &[key, from] : latest)
    {
        const std::size_t q = key % phases, pair = key / phases;
        found.push_back({{pair / robots_, from}, {pair % robots_, q}});
    }
    std::sort(found.begin(), found.end(),
              [](const Edge &a, const Edge &b)
              {
                  return std::make_tuple(a.from.robot, a.to.robot, a.to.phase) <
                         std::make_tuple(b.from.robot, b.to.robot, b.to.phase);
              });
    for (std::size_t e = 0; e < found.size(); ++e)
    {
        const bool newPair =
            e == 0 || found[e].from.robot != found[e - 1].from.robot || found[e].to.robot != found[e - 1].to.robot;
        // Kept edges of a pair have rising phases: the last kept one has the latest.
        if (newPair || found[e].from.phase > edges_.back().from.phase)
            edges_.push_back(found[e]);
    }
}

std::size_t ompl_parc::TemporalPlanGraph::getNodeCount() const
{
    return static_cast<std::size_t>(std::count(moving_.begin(), moving_.end(), 1));
}

nlohmann::ordered_json ompl_parc::TemporalPlanGraph::toJson() const
{
    nlohmann::ordered_json out;
    out["phases"] = boundaries_;
    out["robots"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < robots_; ++i)
    {
        auto nodes = nlohmann::ordered_json::array();
        for (std::size_t p = 0; p < getPhaseCount(); ++p)
            if (isMoving(i, p))
                nodes.push_back({{"phase", p},
                                 {"from_step", boundaries_[p]},
                                 {"to_step", boundaries_[p + 1]},
                                 {"synchronised_with", getGroup(i, p)}});
        out["robots"].push_back({{"nodes", nodes}});
    }
    out["edges"] = nlohmann::ordered_json::array();
    for (const Edge &e : edges_)
        out["edges"].push_back({{"from_robot", e.from.robot},
                                {"from_phase", e.from.phase},
                                {"to_robot", e.to.robot},
                                {"to_phase", e.to.phase}});
    return out;
}
