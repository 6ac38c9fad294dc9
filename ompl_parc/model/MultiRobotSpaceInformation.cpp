#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollidingPairSweep.h"
#include "ompl_parc/model/MultiRobotValidityChecker.h"
#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/robots/RakeMotionValidator.h"
#include "ompl_parc/statespaces/SpaceRegistryLock.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>

namespace ob = ompl::base;

namespace
{
    void checkTeam(const std::vector<ompl_parc::RobotPtr> &robots)
    {
        if (robots.empty())
            throw ompl::Exception("MultiRobotSpaceInformation", "a team needs at least one robot");
        ompl_parc::checkTeamSize(robots.size(), "MultiRobotSpaceInformation");
        std::set<std::string> names;
        for (const auto &robot : robots)
        {
            if (!robot)
                throw ompl::Exception("MultiRobotSpaceInformation", "null robot in the team");
            if (robot->getEnvironment() != robots.front()->getEnvironment())
                throw ompl::Exception("MultiRobotSpaceInformation",
                                      "robot '" + robot->getName() + "' lives in another Environment than the team");
            if (!names.insert(robot->getName()).second)
                throw ompl::Exception("MultiRobotSpaceInformation", "duplicate robot name '" + robot->getName() + "'");
        }
    }

    /** Fresh robot spaces: the given (or the robots' own) bounds, one motion check per timestep, and
        samplers seeded from \e seed when it is non-zero. */
    std::vector<ob::StateSpacePtr> robotSpaces(const std::vector<ompl_parc::RobotPtr> &robots, double resolution,
                                               const std::vector<ob::RealVectorBounds> &bounds, std::uint_fast32_t seed)
    {
        checkTeam(robots);
        if (!bounds.empty() && bounds.size() != robots.size())
            throw ompl::Exception("MultiRobotSpaceInformation", "need one bounds entry per robot");
        std::vector<ob::StateSpacePtr> spaces;
        for (std::size_t i = 0; i < robots.size(); ++i)
        {
            const auto &robot = *robots[i];
            const ob::RealVectorBounds &b = bounds.empty() ? robot.getBounds() : bounds[i];
            if (b.low.size() != robot.getDimension() || b.high.size() != robot.getDimension())
                throw ompl::Exception("MultiRobotSpaceInformation",
                                      "bounds of robot '" + robot.getName() + "' have the wrong dimension");
            for (unsigned int d = 0; d < robot.getDimension(); ++d)
                if (!(b.low[d] < b.high[d]))
                    throw ompl::Exception(
                        "MultiRobotSpaceInformation",
                        "bounds of robot '" + robot.getName() + "' are empty in dimension " + std::to_string(d));
            ompl_parc::Robot::checkTimesteps(robot.getName(), b, resolution);
            auto space = ompl_parc::makeStateSpace<ob::RealVectorStateSpace>(robot.getDimension());
            space->setBounds(b);
            space->setName(robot.getName());
            space->setLongestValidSegmentFraction(std::min(0.5, 1. / (resolution * space->getMaximumExtent())));
            if (seed != 0)
                space->setStateSamplerAllocator(
                    ompl_parc::SeededRealVectorSampler::allocator(ompl_parc::mixSeed(seed, i)));
            spaces.push_back(space);
        }
        return spaces;
    }
}  // namespace

ompl_parc::MultiRobotSpaceInformation::MultiRobotSpaceInformation(std::vector<RobotPtr> robots, double resolution,
                                                                  const std::vector<ob::RealVectorBounds> &bounds,
                                                                  std::uint_fast32_t seed)
    : ob::SpaceInformation(makeStateSpace<CompositeStateSpace>(robotSpaces(robots, resolution, bounds, seed))),
      robots_(std::move(robots)),
      composite_(std::static_pointer_cast<CompositeStateSpace>(getStateSpace())),
      resolution_(resolution)
{
    auto checker = std::make_shared<MultiRobotValidityChecker>(this, robots_);
    setStateValidityChecker(checker);
    setMotionValidator(std::make_shared<RakeMotionValidator>(
        this, [checker](const double *configs, std::size_t count) { return checker->allValid(configs, count); },
        checker.get(), [checker](const double *from, const double *to) { return checker->sweepValid(from, to); }));
    setup();
}

const double *ompl_parc::MultiRobotSpaceInformation::getRobotValues(const ob::State *state, std::size_t i) const
{
    return state->as<ob::CompoundState>()
        ->as<ob::RealVectorStateSpace::StateType>(static_cast<unsigned int>(i))
        ->values;
}

double *ompl_parc::MultiRobotSpaceInformation::getRobotValues(ob::State *state, std::size_t i) const
{
    return state->as<ob::CompoundState>()
        ->as<ob::RealVectorStateSpace::StateType>(static_cast<unsigned int>(i))
        ->values;
}

bool ompl_parc::MultiRobotSpaceInformation::robotsCollide(std::size_t i, const double *qi, std::size_t j,
                                                          const double *qj) const
{
    thread_local CollisionBody a, b;
    robots_[i]->computeBody(qi, a);
    robots_[j]->computeBody(qj, b);
    return bodiesCollide(a, b);
}

std::string ompl_parc::MultiRobotSpaceInformation::explainInvalid(const ob::State *state) const
{
    std::vector<const double *> configs(robots_.size());
    for (std::size_t i = 0; i < robots_.size(); ++i)
        configs[i] = getRobotValues(state, i);
    return explainInvalid(configs);
}

std::string ompl_parc::MultiRobotSpaceInformation::explainInvalid(const std::vector<const double *> &configs,
                                                                  const std::string &what) const
{
    if (configs.size() != robots_.size())
        throw ompl::Exception("MultiRobotSpaceInformation", std::to_string(configs.size()) + " configurations for " +
                                                                std::to_string(robots_.size()) + " robots");
    const std::string one = what.empty() ? "robot '" : what + " of robot '";
    const std::string two = what.empty() ? "robots '" : what + "s of robots '";
    for (std::size_t i = 0; i < robots_.size(); ++i)
    {
        const auto validity = robots_[i]->checkValidity(configs[i]);
        if (validity != Robot::Validity::VALID)
            return one + robots_[i]->getName() + "' is " + Robot::toString(validity);
    }
    std::vector<CollisionBody> bodies(robots_.size());
    for (std::size_t i = 0; i < robots_.size(); ++i)
        robots_[i]->computeBody(configs[i], bodies[i]);
    if (const auto pair = CollidingPairSweep().first(bodies))
        return two + robots_[pair->first]->getName() + "' and '" + robots_[pair->second]->getName() + "' collide";
    return "";
}

ompl_parc::MultiRobotSpaceInformationPtr ompl_parc::MultiRobotSpaceInformation::get(const ob::SpaceInformationPtr &si,
                                                                                    const std::string &who)
{
    auto mrsi = std::dynamic_pointer_cast<MultiRobotSpaceInformation>(si);
    if (!mrsi)
        throw ompl::Exception(who,
                              "needs an ompl_parc::MultiRobotSpaceInformation (a robot team over a "
                              "CompositeStateSpace), got a plain SpaceInformation");
    return mrsi;
}

std::string ompl_parc::MultiRobotSpaceInformation::checkPlanningResolution() const
{
    CollisionBody body;
    for (const auto &robot : robots_)
    {
        const auto &bounds = robot->getBounds();
        std::vector<double> centre(robot->getDimension());
        for (std::size_t d = 0; d < centre.size(); ++d)
            centre[d] = 0.5 * (bounds.low[d] + bounds.high[d]);
        robot->computeBody(centre.data(), body);
        if (body.size() == 0)
            continue;
        const double thinnest = *std::min_element(body.radius_.begin(), body.radius_.end());
        if (resolution_ * thinnest < 1.)
        {
            std::ostringstream out;
            out << "resolution " << resolution_ << " is too coarse to plan robot '" << robot->getName()
                << "': one timestep (1/resolution) must not exceed its thinnest part (radius " << thinnest
                << "), so the resolution must be at least " << 1. / thinnest;
            return out.str();
        }
    }
    return "";
}
