#include "ompl_parc/spacetime/DynamicObstacles.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/spacetime/SpaceTimeMotionValidator.h"
#include "ompl_parc/spacetime/SpaceTimeValidityChecker.h"
#include "ompl_parc/spacetime/SpaceTimeStateSpace.h"
#include "ompl_parc/statespaces/SpaceRegistryLock.h"

#include <ompl/util/Exception.h>

#include <algorithm>

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
