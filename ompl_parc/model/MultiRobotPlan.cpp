#include "ompl_parc/model/MultiRobotPlan.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** Number of timesteps a motion of length \e d takes at \e resolution (0 for no motion). */
    std::size_t stepsFor(double d, double resolution)
    {
        return static_cast<std::size_t>(std::ceil(d * resolution - 1e-9));
    }

    /** Append to \e out the grid states of \e path over \e space, excluding the first state. */
    template <typename Append>
    void layOnGrid(const ob::StateSpacePtr &space, const og::PathGeometric &path, double resolution, Append append)
    {
        ob::State *tmp = space->allocState();
        for (std::size_t k = 1; k < path.getStateCount(); ++k)
        {
            const ob::State *from = path.getState(k - 1), *to = path.getState(k);
            const std::size_t steps = stepsFor(space->distance(from, to), resolution);
            for (std::size_t s = 1; s <= steps; ++s)
            {
                if (s == steps)  // the waypoint itself, not a rounded interpolation of it
                    space->copyState(tmp, to);
                else
                    space->interpolate(from, to, static_cast<double>(s) / static_cast<double>(steps), tmp);
                append(tmp);
            }
        }
        space->freeState(tmp);
    }
}  // namespace

ompl_parc::MultiRobotPlan::MultiRobotPlan(std::vector<unsigned int> dimensions, double resolution)
    : dimensions_(std::move(dimensions)), paths_(dimensions_.size()), resolution_(resolution)
{
    if (!(resolution > 0.))
        throw ompl::Exception("MultiRobotPlan", "resolution must be positive");
}

ompl_parc::MultiRobotPlan::MultiRobotPlan(const MultiRobotSpaceInformation &si) : resolution_(si.getResolution())
{
    for (const auto &robot : si.getRobots())
        dimensions_.push_back(robot->getDimension());
    paths_.resize(dimensions_.size());
}

std::size_t ompl_parc::MultiRobotPlan::getArrival(std::size_t robot) const
{
    const std::size_t n = getStateCount(robot);
    if (n == 0)
        throw ompl::Exception("MultiRobotPlan", "robot " + std::to_string(robot) + " has no states");
    return n - 1;
}

const double *ompl_parc::MultiRobotPlan::getConfig(std::size_t robot, std::size_t t) const
{
    return paths_[robot].data() + std::min(t, getArrival(robot)) * dimensions_[robot];
}

void ompl_parc::MultiRobotPlan::setRobotPath(std::size_t robot, std::vector<double> flat)
{
    if (flat.size() % dimensions_.at(robot) != 0)
        throw ompl::Exception("MultiRobotPlan", "path size is not a multiple of the robot's dimension");
    paths_[robot] = std::move(flat);
}

void ompl_parc::MultiRobotPlan::appendConfig(std::size_t robot, const double *q)
{
    paths_.at(robot).insert(paths_[robot].end(), q, q + dimensions_[robot]);
}

void ompl_parc::MultiRobotPlan::splice(std::size_t robot, std::size_t from, std::size_t to,
                                       const std::vector<double> &segment)
{
    const unsigned int d = dimensions_.at(robot);
    auto &path = paths_[robot];
    const std::size_t arrival = getArrival(robot);
    if (from > to || segment.empty() || segment.size() % d != 0)
        throw ompl::Exception("MultiRobotPlan", "invalid splice");
    // States before the window; a robot that arrived earlier holds its goal until the window starts.
    std::vector<double> spliced(path.begin(), path.begin() + std::min(from, arrival) * d);
    for (std::size_t t = arrival; t < from; ++t)
        spliced.insert(spliced.end(), path.end() - d, path.end());
    spliced.insert(spliced.end(), segment.begin(), segment.end());
    if (to < arrival)
        spliced.insert(spliced.end(), path.begin() + (to + 1) * d, path.end());
    path = std::move(spliced);
    trimArrival(robot);
}

void ompl_parc::MultiRobotPlan::trimArrival(std::size_t robot)
{
    auto &p = paths_[robot];
    const unsigned int d = dimensions_[robot];
    while (p.size() > d && std::equal(p.end() - 2 * d, p.end() - d, p.end() - d))
        p.resize(p.size() - d);
}

std::size_t ompl_parc::MultiRobotPlan::getMakespan() const
{
    std::size_t m = 0;
    for (std::size_t i = 0; i < getRobotCount(); ++i)
        m = std::max(m, getArrival(i));
    return m;
}

std::size_t ompl_parc::MultiRobotPlan::getSumOfCosts() const
{
    std::size_t s = 0;
    for (std::size_t i = 0; i < getRobotCount(); ++i)
        s += getArrival(i);
    return s;
}

std::vector<std::size_t> ompl_parc::MultiRobotPlan::sampleTimesteps(std::size_t maxCount) const
{
    const std::size_t makespan = getMakespan();
    const std::size_t count = std::max<std::size_t>(2, std::min<std::size_t>(maxCount, makespan + 1));
    std::vector<std::size_t> times;
    for (std::size_t k = 0; k < count; ++k)
        times.push_back(
            static_cast<std::size_t>(std::llround(static_cast<double>(k * makespan) / static_cast<double>(count - 1))));
    return times;
}

og::PathGeometricPtr ompl_parc::MultiRobotPlan::toPathGeometric(const MultiRobotSpaceInformationPtr &si) const
{
    if (si->getRobotCount() != getRobotCount())
        throw ompl::Exception("MultiRobotPlan", "plan and space information have different team sizes");
    auto path = std::make_shared<og::PathGeometric>(si);
    // The path owns the states we allocate straight into it (append() would clone each one once more).
    auto &states = path->getStates();
    states.resize(getMakespan() + 1);
    allocateStates(*si, 0, states.size(), states.data());
    return path;
}

void ompl_parc::MultiRobotPlan::allocateStates(const MultiRobotSpaceInformation &si, std::size_t from, std::size_t to,
                                               ob::State **out) const
{
    for (std::size_t t = from; t < to; ++t)
    {
        ob::State *state = si.allocState();
        for (std::size_t i = 0; i < getRobotCount(); ++i)
            std::copy_n(getConfig(i, t), dimensions_[i], si.getRobotValues(state, i));
        out[t - from] = state;
    }
}

std::vector<std::vector<double>> ompl_parc::MultiRobotPlan::layTeamPath(const MultiRobotSpaceInformation &si,
                                                                        const og::PathGeometric &path)
{
    if (path.getStateCount() == 0)
        throw ompl::Exception("MultiRobotPlan", "cannot lay an empty path on the timestep grid");
    std::vector<std::vector<double>> paths(si.getRobotCount());
    const auto appendAll = [&](const ob::State *state)
    {
        for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        {
            const double *q = si.getRobotValues(state, i);
            paths[i].insert(paths[i].end(), q, q + si.getRobot(i)->getDimension());
        }
    };
    appendAll(path.getState(0));
    layOnGrid(si.getStateSpace(), path, si.getResolution(), appendAll);
    return paths;
}

ompl_parc::MultiRobotPlan ompl_parc::MultiRobotPlan::fromPathGeometric(const MultiRobotSpaceInformation &si,
                                                                       const og::PathGeometric &path)
{
    MultiRobotPlan plan(si);
    plan.paths_ = layTeamPath(si, path);
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        plan.trimArrival(i);
    return plan;
}

std::vector<double> ompl_parc::MultiRobotPlan::discretize(const Robot &robot, const og::PathGeometric &path,
                                                          double resolution)
{
    if (path.getStateCount() == 0)
        throw ompl::Exception("MultiRobotPlan", "cannot lay an empty path on the timestep grid");
    std::vector<double> flat(robot.getDimension());
    robot.stateToConfig(path.getState(0), flat.data());
    std::vector<double> q(robot.getDimension());
    layOnGrid(robot.getStateSpace(), path, resolution,
              [&](const ob::State *state)
              {
                  robot.stateToConfig(state, q.data());
                  flat.insert(flat.end(), q.begin(), q.end());
              });
    return flat;
}
