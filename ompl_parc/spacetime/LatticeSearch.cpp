#include "ompl_parc/spacetime/LatticeSearch.h"

#include "ompl_parc/collision/CollisionBody.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_set>

namespace
{
    using Coords = std::array<std::int32_t, ompl_parc::LatticeSearch::MAX_DIMENSION>;

    /** A search state: a lattice point at a timestep, and the state it was reached from. */
    struct LatticeState
    {
        Coords coords;
        std::size_t timestep;
        std::size_t parent;
    };

    /** A lattice point at a timestep (clamped where time no longer matters), as a set key. */
    struct StateKey
    {
        Coords coords;
        std::size_t timestep;
        bool operator==(const StateKey &other) const { return coords == other.coords && timestep == other.timestep; }
    };

    struct StateKeyHash
    {
        std::size_t operator()(const StateKey &key) const
        {
            std::size_t h = key.timestep * 0x9e3779b97f4a7c15ULL;
            for (std::int32_t c : key.coords)
                h = (h ^ static_cast<std::uint32_t>(c)) * 0x100000001b3ULL;
            return h;
        }
    };

    /** An open entry: estimated arrival, then later timesteps first (deeper states), then the state. */
    struct OpenEntry
    {
        std::size_t estimate, timestep, state;
        bool operator>(const OpenEntry &other) const
        {
            if (estimate != other.estimate)
                return estimate > other.estimate;
            return timestep < other.timestep;
        }
    };
    constexpr std::size_t UNREACHABLE = std::numeric_limits<std::size_t>::max();

    /** Timesteps from each lattice point to the goal with the moving obstacles left out (Dijkstra from the goal
        over the lattice's static motions): the search's heuristic, exact where no robot is in the way, and a
        point without one cannot reach the goal at all. Beyond MAX_POINTS lattice points in the bounds (a wide
        open field), the lattice distance instead, as if there were no static obstacles. */
    class StaticDistances
    {
      public:
        StaticDistances(const ompl_parc::DynamicObstacles &obstacles, const std::vector<double> &low,
                        const std::vector<double> &high, double step, const std::vector<double> &start,
                        const std::vector<double> &goal, std::size_t move, double finishRadius, double resolution,
                        const ompl::base::PlannerTerminationCondition &ptc)
            : dimension_(obstacles.getRobot()->getDimension()), move_(move)
        {
            const ompl_parc::Robot &robot = *obstacles.getRobot();
            std::size_t points = 1;
            for (unsigned int i = 0; i < dimension_; ++i)
            {
                const auto at = [&](long c) { return start[i] + step * static_cast<double>(c); };
                long lo = static_cast<long>(std::ceil((low[i] - start[i]) / step)),
                     hi = static_cast<long>(std::floor((high[i] - start[i]) / step));
                // Rounding moves the first and last lattice points inside the bounds by a step at most.
                for (int k = 0; k < 2 && at(lo) < low[i]; ++k)
                    ++lo;
                for (int k = 0; k < 2 && at(lo - 1) >= low[i]; ++k)
                    --lo;
                for (int k = 0; k < 2 && at(hi) > high[i]; ++k)
                    --hi;
                for (int k = 0; k < 2 && at(hi + 1) <= high[i]; ++k)
                    ++hi;
                min_[i] = lo;
                count_[i] = hi >= lo ? static_cast<std::size_t>(hi - lo + 1) : 0;
                target_[i] = static_cast<std::int32_t>(std::lround((goal[i] - start[i]) / step));
                if (count_[i] == 0 || at(0) < low[i] || at(0) > high[i])
                    outside_ = true;  // the start is outside the bounds: no lattice point reaches the goal
                points = count_[i] == 0 || points > MAX_POINTS ? MAX_POINTS + 1 : points * count_[i];
            }
            if (points > MAX_POINTS || outside_)
                return;
            distances_.assign(points, UNREACHABLE);
            std::vector<double> q(dimension_), p(dimension_);
            const auto config = [&](std::size_t index, std::vector<double> &out)
            {
                for (unsigned int i = dimension_; i-- > 0;)
                {
                    out[i] = start[i] + step * static_cast<double>(min_[i] + static_cast<long>(index % count_[i]));
                    index /= count_[i];
                }
            };
            using Entry = std::pair<std::size_t, std::size_t>;
            std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
            for (std::size_t index = 0; index < points; ++index)  // the lattice points that can finish
            {
                config(index, q);
                const double remaining = robot.distance(q.data(), goal.data());
                if (remaining > finishRadius || !robot.isValid(q.data()))
                    continue;
                const auto steps = static_cast<std::size_t>(std::ceil(remaining * resolution));
                if (obstacles.isStaticMotionValid(q.data(), goal.data(), steps))
                    open.push({distances_[index] = steps, index});
            }
            for (std::size_t pops = 0; !open.empty(); ++pops)
            {
                if (pops % 256 == 0 && ptc)
                {
                    outside_ = true;  // stopped: no distances, no search
                    return;
                }
                const auto [distance, index] = open.top();
                open.pop();
                if (distance != distances_[index])
                    continue;
                config(index, q);
                std::size_t stride = 1;
                for (unsigned int i = dimension_; i-- > 0; stride *= count_[i])
                {
                    const std::size_t c = (index / stride) % count_[i];
                    for (int sign : {-1, 1})
                    {
                        if ((sign < 0 && c == 0) || (sign > 0 && c + 1 == count_[i]))
                            continue;
                        const std::size_t neighbour = sign < 0 ? index - stride : index + stride;
                        if (distances_[neighbour] <= distance + move_)
                            continue;
                        config(neighbour, p);
                        if (!robot.isValid(p.data()) || !obstacles.isStaticMotionValid(p.data(), q.data(), move_))
                            continue;
                        open.push({distances_[neighbour] = distance + move_, neighbour});
                    }
                }
            }
        }

        /** Timesteps from lattice point \e c to the goal, UNREACHABLE if none or outside the bounds. */
        std::size_t at(const Coords &c) const
        {
            if (outside_)
                return UNREACHABLE;
            if (distances_.empty())
            {
                std::size_t steps = 0;
                for (unsigned int i = 0; i < dimension_; ++i)
                    steps += static_cast<std::size_t>(std::abs(static_cast<long>(c[i]) - target_[i]));
                return steps * move_;
            }
            std::size_t index = 0;
            for (unsigned int i = 0; i < dimension_; ++i)
            {
                const long k = static_cast<long>(c[i]) - min_[i];
                if (k < 0 || static_cast<std::size_t>(k) >= count_[i])
                    return UNREACHABLE;
                index = index * count_[i] + static_cast<std::size_t>(k);
            }
            return distances_[index];
        }

        /** The most lattice points given a distance (2^15): the Dijkstra costs about as much per point as an
            expansion of the search, which in open space needs only a few per lattice step of the way. */
        static constexpr std::size_t MAX_POINTS = std::size_t{1} << 15;

      private:
        unsigned int dimension_;
        std::size_t move_;
        std::array<long, ompl_parc::LatticeSearch::MAX_DIMENSION> min_{};
        std::array<std::size_t, ompl_parc::LatticeSearch::MAX_DIMENSION> count_{};
        Coords target_{};
        std::vector<std::size_t> distances_;
        /** The start lies outside the bounds, or the stop came during the Dijkstra: nothing is reachable. */
        bool outside_{false};
    };
}  // namespace

ompl_parc::LatticeSearch::LatticeSearch(DynamicObstaclesPtr obstacles, std::vector<double> low,
                                        std::vector<double> high, double step)
    : obstacles_(std::move(obstacles)), low_(std::move(low)), high_(std::move(high)), step_(step)
{
    if (!obstacles_)
        throw ompl::Exception("LatticeSearch", "no obstacles given");
    const unsigned int d = obstacles_->getRobot()->getDimension();
    if (d == 0 || d > MAX_DIMENSION)
        throw ompl::Exception("LatticeSearch", "a lattice search needs 1 to " + std::to_string(MAX_DIMENSION) +
                                                   " degrees of freedom, robot '" + obstacles_->getRobot()->getName() +
                                                   "' has " + std::to_string(d));
    if (low_.size() != d || high_.size() != d)
        throw ompl::Exception("LatticeSearch", "the bounds must have one value per degree of freedom");
    if (!(step_ > 0.) || !std::isfinite(step_))
        throw ompl::Exception("LatticeSearch", "the lattice step must be positive and finite");
}

void ompl_parc::LatticeSearch::setHeuristicWeight(double weight)
{
    if (!(weight >= 1. && weight <= MAX_WEIGHT))
        throw ompl::Exception("LatticeSearch", "the heuristic weight must be in [1, 1000]");
    weight_ = weight;
}

bool ompl_parc::LatticeSearch::applies(const Robot &robot)
{
    std::array<double, 3> lo{}, hi{};
    const std::vector<double> q(robot.getDimension(), 0.);
    return robot.getDimension() >= 1 && robot.getDimension() <= MAX_DIMENSION &&
           robot.expandBoxOver(q.data(), q.data(), lo, hi);
}

double ompl_parc::LatticeSearch::defaultStep(const Robot &robot, const std::vector<double> &q)
{
    CollisionBody body;
    robot.computeBody(q.data(), body);
    return body.boundRadius_ > 0. ? body.boundRadius_ : 0.1;
}

ompl_parc::TimedPath ompl_parc::LatticeSearch::plan(const std::vector<double> &start, const std::vector<double> &goal,
                                                    std::size_t hold,
                                                    const ompl::base::PlannerTerminationCondition &ptc) const
{
    expansions_ = 0;
    const Robot &robot = *obstacles_->getRobot();
    const unsigned int d = robot.getDimension();
    const double resolution = obstacles_->getResolution();
    if (start.size() != d || goal.size() != d)
        throw ompl::Exception("LatticeSearch", "start and goal must have one value per degree of freedom");

    std::vector<double> q(d), next(d);
    const auto configOf = [&](const Coords &c, std::vector<double> &out)
    {
        for (unsigned int i = 0; i < d; ++i)
            out[i] = start[i] + step_ * static_cast<double>(c[i]);
    };
    // One lattice move, or a wait, takes the timesteps of the longest axis step at unit speed.
    std::size_t move = 1;
    for (unsigned int i = 0; i < d; ++i)
    {
        next = start;
        next[i] += step_;
        move =
            std::max(move, static_cast<std::size_t>(std::ceil(robot.distance(start.data(), next.data()) * resolution)));
    }
    if (move > MAX_MOVE)
        return TimedPath();  // a resolution far above the usual: the motions would hold too many timesteps
    for (unsigned int i = 0; i < d; ++i)
        if (!((high_[i] - low_[i]) / step_ < MAX_STEPS) || !(std::abs(goal[i] - start[i]) / step_ < MAX_STEPS) ||
            !(step_ > 1e-9 * (1. + std::abs(start[i]))))
            return TimedPath();  // bounds or a way too long in lattice steps, or a step lost in the coordinates'
                                 // rounding
    const double finishRadius = step_ * std::sqrt(static_cast<double>(d)) * (1. + 1e-9);
    if (ptc)
        return TimedPath();
    const StaticDistances toGoal(*obstacles_, low_, high_, step_, start, goal, move, finishRadius, resolution, ptc);
    if (toGoal.at(Coords{}) == UNREACHABLE)
        return TimedPath();  // not even without the moving obstacles
    const auto estimate = [&](const Coords &c, std::size_t timestep)
    { return std::max(timestep + static_cast<std::size_t>(weight_ * static_cast<double>(toGoal.at(c))), hold); };
    // From this timestep on no obstacle moves and the goal can be held: a lattice point is one state after it.
    const std::size_t settled = (std::max(hold, obstacles_->getLastMove()) + move - 1) / move * move;

    std::vector<LatticeState> states{{Coords{}, 0, 0}};
    std::unordered_set<StateKey, StateKeyHash> seen{{Coords{}, 0}};
    std::priority_queue<OpenEntry, std::vector<OpenEntry>, std::greater<>> open;
    open.push({estimate(Coords{}, 0), 0, 0});
    const auto push = [&](const Coords &c, std::size_t timestep, std::size_t parent)
    {
        if (!seen.insert({c, std::min(timestep, settled)}).second)
            return;
        states.push_back({c, timestep, parent});
        open.push({estimate(c, timestep), timestep, states.size() - 1});
    };
    while (!open.empty())
    {
        if (expansions_ >= maxExpansions_ || (expansions_ % 8 == 0 && ptc))
            return TimedPath();
        ++expansions_;
        const std::size_t index = open.top().state;
        open.pop();
        const LatticeState current = states[index];
        configOf(current.coords, q);

        const double remaining = robot.distance(q.data(), goal.data());
        if (remaining <= finishRadius)
        {
            const auto steps = static_cast<std::size_t>(std::ceil(remaining * resolution));
            if (current.timestep + steps >= hold &&
                obstacles_->isMotionClear(q.data(), goal.data(), current.timestep, steps))
            {
                std::vector<std::size_t> chain;
                for (std::size_t s = index; s != 0; s = states[s].parent)
                    chain.push_back(s);
                TimedPath path(d, start.data());
                std::vector<double> from = start;
                for (auto it = chain.rbegin(); it != chain.rend(); ++it)
                {
                    configOf(states[*it].coords, next);
                    if (next == from)
                        path.appendHold(from.data(), states[*it].timestep);
                    else
                        path.appendMotion(from.data(), next.data(), move);
                    from = next;
                }
                path.appendMotion(from.data(), goal.data(), steps);
                return path;
            }
        }
        const std::size_t later = current.timestep + move;
        if (current.timestep < settled && seen.count({current.coords, std::min(later, settled)}) == 0 &&
            obstacles_->isMotionClear(q.data(), q.data(), current.timestep, move))
            push(current.coords, later, index);
        for (unsigned int i = 0; i < d; ++i)
            for (int sign : {-1, 1})
            {
                Coords c = current.coords;
                c[i] += sign;
                configOf(c, next);
                if (!(next[i] >= low_[i] && next[i] <= high_[i]) || toGoal.at(c) == UNREACHABLE ||
                    seen.count({c, std::min(later, settled)}) != 0 ||
                    !obstacles_->isMotionClear(q.data(), next.data(), current.timestep, move))
                    continue;
                push(c, later, index);
            }
    }
    return TimedPath();
}
