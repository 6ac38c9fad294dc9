#include "ompl_parc/spacetime/DynamicObstacles.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"
#include "ompl_parc/spacetime/SpaceTimeValidityChecker.h"
#include "ompl_parc/spacetime/SpaceTimeInUse.h"
#include "ompl_parc/statespaces/SpaceRegistryLock.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <cmath>

ompl_parc::DynamicObstacles::DynamicObstacles(RobotPtr robot, double resolution)
    : robot_(std::move(robot)), resolution_(resolution)
{
    if (!robot_)
        throw ompl::Exception("DynamicObstacles", "null robot");
    if (!(resolution > 0.))
        throw ompl::Exception("DynamicObstacles", "resolution must be positive");
}

std::shared_ptr<const ompl_parc::BodyTrack> ompl_parc::DynamicObstacles::computeTrack(const Robot &other,
                                                                                      const TimedPath &path)
{
    if (!fits(path))
        throw ompl::Exception("DynamicObstacles", "a path of " + std::to_string(path.getArrival()) +
                                                      " timesteps is too long to keep its bodies");
    if (path.empty() || path.getDimension() != other.getDimension())
        throw ompl::Exception("DynamicObstacles",
                              "path of robot '" + other.getName() + "' is empty or not of its dimension");
    auto track = std::make_shared<BodyTrack>();
    CollisionBody body;
    std::vector<double> q(path.getDimension());
    TimedPath::Cursor cursor(path);
    for (std::size_t t = 0; t <= path.getArrival(); ++t)
    {
        cursor.get(t, q.data());
        other.computeBody(q.data(), body);
        if (t == 0)
            track->reserve(path.getArrival() + 1, body.size());
        track->append(body);
    }
    return track;
}

void ompl_parc::DynamicObstacles::addPath(const Robot &other, const TimedPath &path)
{
    addTrack(computeTrack(other, path));
}

void ompl_parc::DynamicObstacles::addTrack(std::shared_ptr<const BodyTrack> track)
{
    if (!track || track->size() == 0)
        throw ompl::Exception("DynamicObstacles", "an obstacle needs a track of at least one body");
    lastMove_ = std::max(lastMove_, track->size() - 1);
    tracks_.push_back(std::move(track));
}

bool ompl_parc::DynamicObstacles::isClear(const double *q, std::size_t timestep) const
{
    if (!robot_->isValid(q))
        return false;
    thread_local CollisionBody body, other;
    robot_->computeBody(q, body);
    return std::none_of(tracks_.begin(), tracks_.end(),
                        [&](const auto &track)
                        { return track->collides(std::min(timestep, track->size() - 1), body, other); });
}

bool ompl_parc::DynamicObstacles::isMotionClear(const double *from, const double *to, std::size_t first,
                                                std::size_t steps) const
{
    const unsigned int d = robot_->getDimension();
    thread_local std::vector<double> q, lo, hi;
    q.resize(d);
    if (steps == 0)
        return true;
    std::array<double, 3> boxLo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, boxHi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    lo.assign(from, from + d);
    hi.assign(from, from + d);
    for (unsigned int i = 0; i < d; ++i)
    {
        lo[i] = std::min(lo[i], to[i]);
        hi[i] = std::max(hi[i], to[i]);
    }
    if (!isStaticMotionValid(from, to, steps))
        return false;
    if (!robot_->expandBoxOver(lo.data(), hi.data(), boxLo, boxHi))
    {
        for (std::size_t s = 1; s <= steps; ++s)
        {
            TimedPath::interpolate(from, to, s, steps, d, q.data());
            if (!isClear(q.data(), first + s))
                return false;
        }
        return true;
    }
    // Bodies along the motion, computed when an obstacle's block first needs them (most motions need none).
    thread_local std::vector<CollisionBody> bodies;
    thread_local std::vector<unsigned char> computed;
    thread_local CollisionBody scratch;
    if (bodies.size() < steps + 1)
        bodies.resize(steps + 1);
    computed.assign(steps + 1, 0);
    const auto bodyAt = [&](std::size_t s) -> const CollisionBody &
    {
        if (computed[s] == 0)
        {
            TimedPath::interpolate(from, to, s, steps, d, q.data());
            robot_->computeBody(q.data(), bodies[s]);
            computed[s] = 1;
        }
        return bodies[s];
    };
    for (const auto &track : tracks_)
    {
        const std::size_t end = track->size() - 1;
        // Timesteps first+1 .. first+steps; past the obstacle's end it holds its last body (in the last block).
        for (std::size_t s = 1; s <= steps;)
        {
            const std::size_t t = std::min(first + s, end), block = t / BodyTrack::BLOCK;
            // The local steps that fall in this block (all the remaining ones once past the end).
            const std::size_t blockEnd =
                (t == end) ? steps : std::min(steps, (block + 1) * BodyTrack::BLOCK - first - 1);
            if (track->blockMayTouch(block, boxLo, boxHi))
                for (std::size_t k = s; k <= blockEnd; ++k)
                    if (track->collides(std::min(first + k, end), bodyAt(k), scratch))
                        return false;
            s = blockEnd + 1;
        }
    }
    return true;
}

bool ompl_parc::DynamicObstacles::isStaticMotionValid(const double *from, const double *to, std::size_t steps) const
{
    if (const auto swept = robot_->sweepValid(from, to))
        return *swept;
    const unsigned int d = robot_->getDimension();
    thread_local std::vector<double> q;
    q.resize(d);
    for (std::size_t s = 1; s <= steps; ++s)
    {
        TimedPath::interpolate(from, to, s, steps, d, q.data());
        if (!robot_->isValid(q.data()))
            return false;
    }
    return true;
}

std::optional<std::size_t> ompl_parc::DynamicObstacles::earliestHold(const double *q) const
{
    if (!robot_->isValid(q))
        return std::nullopt;
    CollisionBody body, other;
    robot_->computeBody(q, body);
    std::size_t hold = 0;
    for (const auto &track : tracks_)
    {
        if (track->collides(track->size() - 1, body, other))
            return std::nullopt;  // it arrives there (or stays) and never leaves
        for (std::size_t t = track->size() - 1; t-- > hold;)
            if (track->collides(t, body, other))
            {
                hold = t + 1;
                break;
            }
    }
    return hold;
}

ompl::base::SpaceInformationPtr ompl_parc::createSpaceTimeSpaceInformation(const ompl::base::StateSpacePtr &space,
                                                                           const DynamicObstaclesPtr &obstacles)
{
    auto si = std::make_shared<ompl::base::SpaceInformation>(makeStateSpace<spacetime::SpaceTimeStateSpace>(space, 1.));
    si->setStateValidityChecker(std::make_shared<SpaceTimeValidityChecker>(si.get(), obstacles));
    si->setMotionValidator(std::make_shared<SpaceTimeMotionValidator>(si.get(), obstacles));
    si->setup();
    return si;
}
