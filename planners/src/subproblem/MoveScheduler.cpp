#include "ompl_parc/planners/subproblem/MoveScheduler.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/TimedPath.h"

#include <ompl/base/ScopedState.h>

#include <algorithm>
#include <limits>

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct ompl_parc::MoveScheduler::Timeline
{
    std::size_t robot{0};
    /** \brief The move at full speed from local timestep 0 (its start) to its arrival (its goal). */
    TimedPath path;
    /** \brief The robot's body at each local timestep of the move. */
    std::vector<CollisionBody> bodies;
    /** \brief Local timesteps at which a straight piece of the move ends. */
    std::vector<std::size_t> turns;
    /** \brief The team timestep at which the move starts. */
    std::size_t begin{0};

    std::size_t duration() const { return bodies.size() - 1; }

    /** \brief The local timestep of team timestep \e t: the start before the move, the goal after it. */
    std::size_t local(std::size_t t) const { return t < begin ? 0 : std::min(t - begin, duration()); }
};

ompl_parc::MoveScheduler::MoveScheduler(std::shared_ptr<MultiRobotSpaceInformation> team) : team_(std::move(team)) {}

bool ompl_parc::MoveScheduler::apart(const Timeline &a, const Timeline &b)
{
    // Before the first move both stand at their starts, after the last at their goals: the first and the last
    // timestep of the span stand for those.
    const std::size_t from = std::min(a.begin, b.begin);
    const std::size_t to = std::max(a.begin + a.duration(), b.begin + b.duration());
    std::size_t lastA = std::numeric_limits<std::size_t>::max(), lastB = lastA;
    for (std::size_t t = from; t <= to; ++t)
    {
        const std::size_t ia = a.local(t), ib = b.local(t);
        if (ia == lastA && ib == lastB)
            continue;  // both holding: the same pair of bodies as the timestep before
        lastA = ia;
        lastB = ib;
        if (bodiesCollide(a.bodies[ia], b.bodies[ib]))
            return false;
    }
    return true;
}

bool ompl_parc::MoveScheduler::schedule(const std::vector<Move> &moves, const ob::State *start, og::PathGeometric &path,
                                        const ob::PlannerTerminationCondition &ptc)
{
    const double resolution = team_->getResolution();
    std::vector<Timeline> lines(moves.size());
    std::size_t sequential = 0;
    for (std::size_t k = 0; k < moves.size(); ++k)
    {
        Timeline &line = lines[k];
        line.robot = moves[k].first;
        const Robot &robot = *team_->getRobot(line.robot);
        const auto &states = *moves[k].second;
        line.path = TimedPath(robot.getDimension(), states.front().data());
        for (std::size_t s = 1; s < states.size(); ++s)
        {
            line.path.appendMotion(
                states[s - 1].data(), states[s].data(),
                MultiRobotPlan::stepsFor(robot.distance(states[s - 1].data(), states[s].data()), resolution));
            line.turns.push_back(line.path.getArrival());
        }
        sequential += line.path.getArrival();
    }
    duration_ = sequential;
    if (sequential + moves.size() > MAX_BODIES)
        return false;  // the bodies of every timestep would not be worth their memory
    for (Timeline &line : lines)
    {
        if (ptc)
            return false;
        const Robot &robot = *team_->getRobot(line.robot);
        line.bodies.resize(line.path.getArrival() + 1);
        std::vector<double> q(robot.getDimension());
        for (std::size_t t = 0; t < line.bodies.size(); ++t)
        {
            line.path.getConfig(t, q.data());
            robot.computeBody(q.data(), line.bodies[t]);
        }
    }

    std::size_t end = 0;  // the last end of the moves placed
    for (std::size_t k = 0; k < lines.size(); ++k)
    {
        if (ptc)
            return false;
        std::vector<std::size_t> candidates{0, end};
        const std::size_t step = std::max<std::size_t>(1, end / 16);
        for (std::size_t c = step; c < end; c += step)
            candidates.push_back(c);
        for (std::size_t j = 0; j < k; ++j)
        {
            candidates.push_back(lines[j].begin);
            candidates.push_back(lines[j].begin + lines[j].duration());
        }
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        const auto placed = std::find_if(candidates.begin(), candidates.end(),
                                         [&](std::size_t c)
                                         {
                                             lines[k].begin = c;
                                             for (std::size_t j = 0; j < k; ++j)
                                                 if (!apart(lines[k], lines[j]))
                                                     return false;
                                             return true;
                                         });
        if (placed == candidates.end())
            return false;  // the bodies' test and the moves' checks disagree: keep the moves one after another
        lines[k].begin = *placed;
        end = std::max(end, lines[k].begin + lines[k].duration());
    }
    if (end >= sequential)
        return false;

    // A team state wherever a move starts or turns: between two of them every robot moves on a straight line.
    std::vector<std::size_t> times{0, end};
    for (const Timeline &line : lines)
    {
        times.push_back(line.begin);
        for (std::size_t turn : line.turns)
            times.push_back(line.begin + turn);
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    og::PathGeometric overlapped(team_);
    ob::ScopedState<> at(team_);
    team_->copyState(at.get(), start);
    for (std::size_t t : times)
    {
        for (const Timeline &line : lines)
            line.path.getConfig(line.local(t), team_->getRobotValues(at.get(), line.robot));
        overlapped.append(at.get());
    }
    for (std::size_t s = 1; s < overlapped.getStateCount(); ++s)
        if (ptc || !team_->checkMotion(overlapped.getState(s - 1), overlapped.getState(s)))
            return false;
    path = overlapped;
    duration_ = end;
    return true;
}
