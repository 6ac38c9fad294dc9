#include "ompl_parc/planners/subproblem/LatticeMapfSolver.h"

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/mapf/LatticeGraph.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/robots/RakeMotionValidator.h"
#include "ompl_parc/spacetime/LatticeSearch.h"
#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/PathGeometric.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <unordered_set>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    using ompl_parc::LatticeGraph;
    using ompl_parc::Robot;
    using Vertex = LatticeGraph::Vertex;
    using Point = std::vector<double>;

    /** The largest team x lattice size whose hop tables (4 bytes an entry) the solver builds. */
    constexpr std::size_t MAX_HOP_ENTRIES = std::size_t(1) << 26;
    /** Lattice origins a solve tries before it gives up on stepping every robot onto one. */
    constexpr unsigned int LATTICE_TRIES = 16;

    /** The radius around a translating robot's configuration point that holds its body. */
    double reach(const Robot &robot, const double *q)
    {
        ompl_parc::CollisionBody body;
        robot.computeBody(q, body);
        const double centre[3] = {body.centerX_, body.centerY_, body.centerZ_};
        double squared = 0.;
        for (unsigned int d = 0; d < 3; ++d)
        {
            const double diff = centre[d] - (d < robot.getDimension() ? q[d] : 0.);
            squared += diff * diff;
        }
        return std::sqrt(squared) + body.boundRadius_;
    }

    /** Whether \e robot may move straight from \e a to \e b among the static obstacles: its own motion check
        (swept where the kind can, else sampled at its checking resolution), through the validator's entry that leaves
        OMPL's non-atomic motion counters alone, as P-ARC's workers may check one robot's moves at once. */
    bool moveValid(const Robot &robot, const double *a, const double *b)
    {
        const auto *validator = dynamic_cast<const ompl_parc::RakeMotionValidator *>(
            robot.getSpaceInformation()->getMotionValidator().get());
        if (validator == nullptr || !robot.isValid(a) || !robot.isValid(b))
            return false;
        const double segments = std::ceil(robot.distance(a, b) / robot.getStateSpace()->getLongestValidSegmentLength());
        const unsigned int dim = robot.getDimension();
        return validator
            ->checkStraight(Point(a, a + dim), Point(b, b + dim),
                            static_cast<unsigned int>(std::clamp(segments, 1., 1e9)))
            .value_or(false);
    }

    /** The smallest distance between two points moving straight from a0 to a1 and from b0 to b1 in the same time. */
    double closestApproach(const double *a0, const double *a1, const double *b0, const double *b1, unsigned int dim)
    {
        double dd = 0., dv = 0., vv = 0.;
        for (unsigned int d = 0; d < dim; ++d)
        {
            const double p = a0[d] - b0[d], v = (a1[d] - a0[d]) - (b1[d] - b0[d]);
            dd += p * p;
            dv += p * v;
            vv += v * v;
        }
        const double t = vv > 0. ? std::clamp(-dv / vv, 0., 1.) : 0.;
        return std::sqrt(std::max(0., dd + 2. * t * dv + t * t * vv));
    }

    /** Each robot's step between its own point (start or goal) and a lattice vertex of its own, and the waves the
        steps are made in: a wave's steps are clear of each other and of every robot not in it, standing on its
        point or its vertex. */
    struct Attachment
    {
        std::vector<Vertex> vertices;
        std::vector<std::vector<std::size_t>> waves;
    };

    std::optional<Attachment> attach(const LatticeGraph &graph, const std::vector<const Robot *> &robots,
                                     const std::vector<Point> &points, const std::vector<double> &reaches)
    {
        const std::size_t n = robots.size();
        const unsigned int dim = graph.getDimension();
        const auto apart =
            [&](std::size_t i, const double *a0, const double *a1, std::size_t j, const double *b0, const double *b1)
        { return closestApproach(a0, a1, b0, b1, dim) >= reaches[i] + reaches[j]; };
        // Each robot's candidates: the vertices within two steps it can step to, first those clear of every other
        // robot's point (the order of the waves does not matter for them), nearest first.
        struct Candidate
        {
            bool blocked;
            double distance;
            Vertex vertex;
            bool operator<(const Candidate &o) const
            {
                return std::tie(blocked, distance, vertex) < std::tie(o.blocked, o.distance, o.vertex);
            }
        };
        std::vector<std::vector<Candidate>> candidates(n);
        std::vector<std::tuple<bool, double, std::size_t, std::size_t>>
            ranked;  // over all robots: (candidate, robot, index)
        for (std::size_t i = 0; i < n; ++i)
        {
            const double *p = points[i].data();
            for (const Vertex v : graph.near(p, 2. * graph.getStep()))
                if (moveValid(*robots[i], p, graph.getPoint(v)))
                {
                    bool blocked = false;
                    for (std::size_t j = 0; j < n && !blocked; ++j)
                        blocked = j != i && !apart(i, graph.getPoint(v), graph.getPoint(v), j, points[j].data(),
                                                   points[j].data());
                    candidates[i].push_back(
                        {blocked, closestApproach(p, p, graph.getPoint(v), graph.getPoint(v), dim), v});
                }
            std::sort(candidates[i].begin(), candidates[i].end());
            for (std::size_t k = 0; k < candidates[i].size(); ++k)
                ranked.emplace_back(candidates[i][k].blocked, candidates[i][k].distance, i, k);
        }
        std::sort(ranked.begin(), ranked.end());
        Attachment attachment;
        attachment.vertices.assign(n, LatticeGraph::NONE);
        std::unordered_set<Vertex> taken;
        for (const auto &[blocked, distance, i, k] : ranked)
            if (attachment.vertices[i] == LatticeGraph::NONE && taken.insert(candidates[i][k].vertex).second)
                attachment.vertices[i] = candidates[i][k].vertex;
        if (std::count(attachment.vertices.begin(), attachment.vertices.end(), LatticeGraph::NONE) != 0)
            return std::nullopt;
        // Waves: every robot whose step is clear joins, against the robots standing (on their points or vertices)
        // and the wave's other robots stepping at the same time; a robot whose step is not takes another free
        // candidate whose step is.
        std::vector<const double *> at(n);
        std::vector<std::size_t> pending;
        for (std::size_t i = 0; i < n; ++i)
        {
            at[i] = points[i].data();
            if (!std::equal(points[i].begin(), points[i].end(), graph.getPoint(attachment.vertices[i])))
                pending.push_back(i);
        }
        while (!pending.empty())
        {
            std::vector<std::size_t> wave, rest;
            std::vector<char> moving(n, 0);
            const auto clear = [&](std::size_t i, Vertex v)
            {
                for (std::size_t j = 0; j < n; ++j)
                    if (j != i && !apart(i, at[i], graph.getPoint(v), j, at[j],
                                         moving[j] ? graph.getPoint(attachment.vertices[j]) : at[j]))
                        return false;
                return true;
            };
            for (const std::size_t i : pending)
            {
                Vertex &v = attachment.vertices[i];
                if (!clear(i, v))
                    for (const auto &c : candidates[i])
                        if (taken.count(c.vertex) == 0 && clear(i, c.vertex))
                        {
                            taken.erase(v);
                            taken.insert(c.vertex);
                            v = c.vertex;
                            break;
                        }
                if (clear(i, v))
                {
                    wave.push_back(i);
                    moving[i] = 1;
                }
                else
                    rest.push_back(i);
            }
            if (wave.empty())
                return std::nullopt;
            for (const std::size_t i : wave)
                at[i] = graph.getPoint(attachment.vertices[i]);
            attachment.waves.push_back(std::move(wave));
            pending = std::move(rest);
        }
        return attachment;
    }

    /** The robots whose checks are the same (discs of one radius, environment and bounds) share them. */
    std::vector<const Robot *> distinctRobots(const std::vector<const Robot *> &robots,
                                              const std::vector<double> &reaches)
    {
        std::vector<const Robot *> distinct;
        std::vector<double> distinctReaches;
        for (std::size_t i = 0; i < robots.size(); ++i)
        {
            const Robot &r = *robots[i];
            bool same = false;
            for (std::size_t k = 0; k < distinct.size() && !same; ++k)
            {
                const Robot &o = *distinct[k];
                same = r.getKind() == "disc" && o.getKind() == "disc" && r.getEnvironment() == o.getEnvironment() &&
                       r.getBounds().low == o.getBounds().low && r.getBounds().high == o.getBounds().high &&
                       reaches[i] == distinctReaches[k];
            }
            if (!same)
            {
                distinct.push_back(&r);
                distinctReaches.push_back(reaches[i]);
            }
        }
        return distinct;
    }

    /** A lattice every robot of a team can step onto from its start and off to its goal, reaching one from the
        other. */
    struct Lattice
    {
        std::unique_ptr<LatticeGraph> graph;
        Attachment entry, exit;
    };

    /** A lattice of \e step over [\e low, \e high] at origins drawn from \e rng until one serves every robot
        (robots packed closer than the lattice allows only some; one that misses a narrow passage leaves a goal out
        of reach); none after LATTICE_TRIES origins, for a lattice too large, or once \e ptc fires. */
    std::optional<Lattice> buildLattice(const std::vector<double> &low, const std::vector<double> &high, double step,
                                        const LatticeGraph::PointCheck &free, const LatticeGraph::MoveCheck &move,
                                        const std::vector<const Robot *> &robots,
                                        const ompl_parc::Subproblem &subproblem, const std::vector<double> &reaches,
                                        std::size_t maxPoints, boost::random::mt19937 &rng,
                                        const ob::PlannerTerminationCondition &ptc)
    {
        const std::size_t n = robots.size();
        std::vector<double> origin(low.size());
        for (unsigned int attempt = 0; attempt < LATTICE_TRIES && !ptc; ++attempt)
        {
            for (std::size_t d = 0; d < low.size(); ++d)
                origin[d] = low[d] + step * boost::random::uniform_real_distribution<double>(0., 1.)(rng);
            const std::size_t points = LatticeGraph::countPoints(low, high, origin, step);
            if (points > maxPoints || points > MAX_HOP_ENTRIES / n)
                return std::nullopt;
            Lattice lattice;
            lattice.graph = std::make_unique<LatticeGraph>(low, high, origin, step, free, move, maxPoints);
            if (ptc)
                return std::nullopt;
            auto entry = attach(*lattice.graph, robots, subproblem.starts, reaches);
            auto exit = entry ? attach(*lattice.graph, robots, subproblem.goals, reaches) : std::nullopt;
            if (!entry || !exit)
                continue;
            const auto component = lattice.graph->components();
            bool connected = true;
            for (std::size_t k = 0; k < n && connected; ++k)
                connected = component[entry->vertices[k]] == component[exit->vertices[k]];
            if (!connected)
                continue;
            lattice.entry = std::move(*entry);
            lattice.exit = std::move(*exit);
            return lattice;
        }
        return std::nullopt;
    }

    /** The team path of \e steps on \e lattice: onto the lattice in the entry's waves, each step as one motion (or,
        with \e subSteps, in its sub-steps: ConfigurationSearch::followLevels), off in the exit's waves backwards.
        False if a step breaks the search's rules. */
    bool layOut(const ompl_parc::MultiRobotSpaceInformation &team, const LatticeGraph &graph, const Lattice &lattice,
                const std::vector<ompl_parc::ConfigurationSearch::Configuration> &steps,
                const ompl_parc::Subproblem &subproblem, bool subSteps, og::PathGeometric &path)
    {
        const std::size_t n = subproblem.robots.size();
        const unsigned int dim = graph.getDimension();
        std::vector<Point> at = subproblem.starts;
        ob::ScopedState<> state(team.getStateSpace());
        const auto append = [&]
        {
            for (std::size_t k = 0; k < n; ++k)
                std::copy(at[k].begin(), at[k].end(), team.getRobotValues(state.get(), k));
            path.append(state.get());
        };
        const auto place = [&](std::size_t k, const double *q) { std::copy(q, q + dim, at[k].begin()); };
        append();
        for (const auto &wave : lattice.entry.waves)
        {
            for (std::size_t k : wave)
                place(k, graph.getPoint(lattice.entry.vertices[k]));
            append();
        }
        std::vector<unsigned int> levels;
        for (std::size_t s = 1; s < steps.size(); ++s)
        {
            if (!ompl_parc::ConfigurationSearch::followLevels(graph, steps[s - 1], steps[s], levels))
                return false;
            if (!subSteps)
                std::fill(levels.begin(), levels.end(), 0);
            const unsigned int deepest = *std::max_element(levels.begin(), levels.end());
            for (unsigned int level = 0; level <= deepest; ++level)
            {
                bool moved = false;
                for (std::size_t k = 0; k < n; ++k)
                    if (levels[k] == level && steps[s][k] != steps[s - 1][k])
                    {
                        place(k, graph.getPoint(steps[s][k]));
                        moved = true;
                    }
                if (moved)
                    append();
            }
        }
        for (auto wave = lattice.exit.waves.rbegin(); wave != lattice.exit.waves.rend(); ++wave)
        {
            for (std::size_t k : *wave)
                place(k, subproblem.goals[k].data());
            append();
        }
        return true;
    }
}  // namespace

ompl_parc::LatticeMapfSolver::LatticeMapfSolver(std::size_t maxPoints, double wideSeconds)
  : maxPoints_(maxPoints), wideSeconds_(wideSeconds)
{
}

ompl_parc::SubproblemSolverPtr ompl_parc::LatticeMapfSolver::makeTeamSolver()
{
    return std::make_shared<LatticeMapfSolver>(std::size_t(1) << 18, 0.1);
}

bool ompl_parc::LatticeMapfSolver::appliesTo(const MultiRobotSpaceInformation &si,
                                             const std::vector<std::size_t> &robots) const
{
    for (std::size_t r : robots)
        if (!LatticeSearch::applies(*si.getRobot(r)) ||
            si.getRobot(r)->getDimension() != si.getRobot(robots.front())->getDimension())
            return false;
    return !robots.empty();
}

bool ompl_parc::LatticeMapfSolver::solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                         const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                         Patch &patch) const
{
    if (!subproblem.check(si).empty() || !appliesTo(si, subproblem.robots))
        return false;
    const std::size_t n = subproblem.robots.size();
    const unsigned int dim = si.getRobot(subproblem.robots.front())->getDimension();
    std::vector<const Robot *> robots;
    std::vector<double> reaches;
    double largest = 0.;
    for (std::size_t k = 0; k < n; ++k)
    {
        robots.push_back(si.getRobot(subproblem.robots[k]).get());
        reaches.push_back(reach(*robots.back(), subproblem.starts[k].data()));
        largest = std::max(largest, reaches.back());
    }
    // The lattice covers the local boxes (the robots' whole spaces without them).
    std::vector<double> low(dim, std::numeric_limits<double>::infinity()),
        high(dim, -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < n; ++k)
    {
        const auto &b = subproblem.bounds.empty() ? robots[k]->getBounds() : subproblem.bounds[k];
        for (unsigned int d = 0; d < dim; ++d)
        {
            low[d] = std::min(low[d], b.low[d]);
            high[d] = std::max(high[d], b.high[d]);
        }
    }
    const auto distinct = distinctRobots(robots, reaches);
    // The checks of a large lattice poll the stop every 1024 points or moves (a lattice built after it is dropped).
    std::size_t checks = 0;
    bool halted = false;
    const auto stopped = [&]
    {
        if (!halted && (++checks & 1023) == 0)
            halted = ptc;
        return halted;
    };
    const auto free = [&](const double *q) {
        return !stopped() &&
               std::all_of(distinct.begin(), distinct.end(), [q](const Robot *r) { return r->isValid(q); });
    };
    const auto move = [&](const double *a, const double *b)
    {
        return !stopped() &&
               std::all_of(distinct.begin(), distinct.end(), [a, b](const Robot *r) { return moveValid(*r, a, b); });
    };
    std::shared_ptr<MultiRobotSpaceInformation> team;  // the team's space without local bounds, once needed
    boost::random::mt19937 rng(static_cast<std::uint32_t>(seed));
    // Two lattices: a wide one first, whose step (over 2 sqrt 2 bounding radii) lets a robot turn into the point
    // another leaves at right angles at the same time, so that every step is one motion; then a tight one (over 2
    // radii: more points in narrow places), where such turns wait for the robot ahead (sub-steps, several times
    // the motion in a dense team: crossing 48, instances 0-4, paths of 197-332 units against 74-89 on the wide one).
    for (const bool wide : {true, false})
    {
        const double step = (largest > 0. ? 2.02 * largest : 0.1) * (wide ? std::sqrt(2.) : 1.);
        const auto lattice =
            buildLattice(low, high, step, free, move, robots, subproblem, reaches, maxPoints_, rng, ptc);
        const auto searchStop = wide && std::isfinite(wideSeconds_)
                                    ? ob::plannerOrTerminationCondition(
                                          ptc, ob::timedPlannerTerminationCondition(wideSeconds_))
                                    : ptc;
        if (!lattice)
            continue;
        const LatticeGraph &graph = *lattice->graph;
        ConfigurationSearch search(graph);
        const auto steps = search.solve(lattice->entry.vertices, lattice->exit.vertices, searchStop, seed);
        if (steps.empty())
            continue;
        if (!team)
        {
            Subproblem whole = subproblem;
            whole.bounds.clear();
            team = whole.createSpaceInformation(si, seed);
        }
        og::PathGeometric path(team);
        if (!layOut(*team, graph, *lattice, steps, subproblem, !wide, path))
            continue;
        bool valid = true;
        for (std::size_t s = 1; s < path.getStateCount() && valid; ++s)
            valid = !ptc && team->checkMotion(path.getState(s - 1), path.getState(s));
        if (!valid)
            continue;
        // Shortened as composite RRT-Connect's patches can be (one pass of vertex reduction, shortcuts bounded like
        // the initial paths'), every change checked on the team's space: joint straight motions across the waves and
        // the lattice's corners where they are clear (field and rooms of 48 robots, instances 0-4: ARC's makespans
        // summed 156 000 and 268 000 timesteps against 281 000 and 373 000 without).
        // OMPL's simplifier takes no stop: under the scope every motion check it makes fails once ptc fires.
        const StopSignal::Scope scope(ptc);
        SeededPathSimplifier simplifier(team, mixSeed(seed, 0x5eed));
        simplifier.reduceVertices(path);
        compat::shortcutPath(simplifier, path, 128, 32);
        if (ptc)
            return false;
        patch.paths = MultiRobotPlan::layTeamPath(*team, path);
        return true;
    }
    return false;
}
