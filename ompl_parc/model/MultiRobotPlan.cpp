#include "ompl_parc/model/MultiRobotPlan.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** Call \e lay(from, to, steps) for each segment of \e path over \e space with the number of timesteps it
        takes on the grid (segments of 0 steps included: TimedPath::appendMotion skips them). */
    template <typename Lay>
    void layOnGrid(const ob::StateSpacePtr &space, const og::PathGeometric &path, double resolution, Lay lay)
    {
        if (path.getStateCount() == 0)
            throw ompl::Exception("MultiRobotPlan", "cannot lay an empty path on the timestep grid");
        for (std::size_t k = 1; k < path.getStateCount(); ++k)
        {
            const ob::State *from = path.getState(k - 1), *to = path.getState(k);
            lay(from, to, ompl_parc::MultiRobotPlan::stepsFor(space->distance(from, to), resolution));
        }
    }
}  // namespace

std::size_t ompl_parc::MultiRobotPlan::stepsFor(double distance, double resolution)
{
    return static_cast<std::size_t>(std::ceil(distance * resolution - 1e-9));
}

ompl_parc::MultiRobotPlan::MultiRobotPlan(std::vector<unsigned int> dimensions, double resolution)
    : resolution_(resolution)
{
    if (!(resolution > 0.))
        throw ompl::Exception("MultiRobotPlan", "resolution must be positive");
    for (unsigned int d : dimensions)
        paths_.emplace_back(d);
}

ompl_parc::MultiRobotPlan::MultiRobotPlan(const MultiRobotSpaceInformation &si) : resolution_(si.getResolution())
{
    for (const auto &robot : si.getRobots())
        paths_.emplace_back(robot->getDimension());
}

std::string ompl_parc::MultiRobotPlan::checkTeam(const MultiRobotSpaceInformation &si) const
{
    if (getRobotCount() != si.getRobotCount())
        return "plan has " + std::to_string(getRobotCount()) + " robots, problem has " +
               std::to_string(si.getRobotCount());
    if (std::abs(getResolution() - si.getResolution()) > 1e-9)
        return "plan resolution " + std::to_string(getResolution()) + " differs from the problem's " +
               std::to_string(si.getResolution());
    for (std::size_t i = 0; i < getRobotCount(); ++i)
    {
        if (getDimension(i) != si.getRobot(i)->getDimension())
            return "robot '" + si.getRobot(i)->getName() + "' has the wrong configuration size";
        if (getStateCount(i) == 0)
            return "robot '" + si.getRobot(i)->getName() + "' has no states";
    }
    return "";
}

void ompl_parc::MultiRobotPlan::setPath(std::size_t robot, TimedPath path)
{
    if (path.getDimension() != getDimension(robot))
        throw ompl::Exception("MultiRobotPlan", "path dimension differs from the robot's");
    paths_[robot] = std::move(path);
}

void ompl_parc::MultiRobotPlan::setRobotPath(std::size_t robot, const std::vector<double> &flat)
{
    setPath(robot, TimedPath::fromDense(getDimension(robot), flat));
}

void ompl_parc::MultiRobotPlan::splice(std::size_t robot, std::size_t from, std::size_t to, const TimedPath &segment)
{
    paths_.at(robot).splice(from, to, segment);
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

std::size_t ompl_parc::MultiRobotPlan::getPieceCount() const
{
    std::size_t n = 0;
    for (const auto &path : paths_)
        n += path.getPieceCount();
    return n;
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

std::vector<std::size_t> ompl_parc::MultiRobotPlan::getBreakpoints() const
{
    std::vector<std::size_t> times{0, getMakespan()};
    for (const auto &path : paths_)
        path.appendBreakpoints(times);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

og::PathGeometricPtr ompl_parc::MultiRobotPlan::toPathGeometric(const MultiRobotSpaceInformationPtr &si) const
{
    if (si->getRobotCount() != getRobotCount())
        throw ompl::Exception("MultiRobotPlan", "plan and space information have different team sizes");
    auto path = std::make_shared<og::PathGeometric>(si);
    const auto times = getBreakpoints();
    // The path owns the states we allocate straight into it (append() would clone each one once more).
    auto &states = path->getStates();
    states.resize(times.size());
    si->getCompositeSpace()->allocStates(states.size(), states.data());
    fillStates(*si, times, 0, times.size(), states.data());
    return path;
}

void ompl_parc::MultiRobotPlan::fillStates(const MultiRobotSpaceInformation &si, const std::vector<std::size_t> &times,
                                           std::size_t from, std::size_t to, ob::State *const *states) const
{
    std::vector<TimedPath::Cursor> cursors;
    for (const auto &path : paths_)
        cursors.emplace_back(path);
    for (std::size_t k = from; k < to; ++k)
        for (std::size_t i = 0; i < getRobotCount(); ++i)
            cursors[i].get(times[k], si.getRobotValues(states[k - from], i));
}

std::vector<ompl_parc::TimedPath> ompl_parc::MultiRobotPlan::layTeamPath(const MultiRobotSpaceInformation &si,
                                                                         const og::PathGeometric &path)
{
    if (path.getStateCount() == 0)
        throw ompl::Exception("MultiRobotPlan", "cannot lay an empty path on the timestep grid");
    std::vector<TimedPath> paths;
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        paths.emplace_back(si.getRobot(i)->getDimension(), si.getRobotValues(path.getState(0), i));
    layOnGrid(si.getStateSpace(), path, si.getResolution(),
              [&](const ob::State *from, const ob::State *to, std::size_t steps)
              {
                  for (std::size_t i = 0; i < paths.size(); ++i)
                      paths[i].appendMotion(si.getRobotValues(from, i), si.getRobotValues(to, i), steps);
              });
    return paths;
}

ompl_parc::MultiRobotPlan ompl_parc::MultiRobotPlan::fromPathGeometric(const MultiRobotSpaceInformation &si,
                                                                       const og::PathGeometric &path)
{
    MultiRobotPlan plan(si);
    plan.paths_ = layTeamPath(si, path);
    for (auto &p : plan.paths_)
        p.trimArrival();
    return plan;
}

ompl_parc::TimedPath ompl_parc::MultiRobotPlan::discretize(const Robot &robot, const og::PathGeometric &path,
                                                           double resolution)
{
    if (path.getStateCount() == 0)
        throw ompl::Exception("MultiRobotPlan", "cannot lay an empty path on the timestep grid");
    const unsigned int d = robot.getDimension();
    std::vector<double> from(d), to(d);
    robot.stateToConfig(path.getState(0), from.data());
    TimedPath timed(d, from.data());
    layOnGrid(robot.getStateSpace(), path, resolution,
              [&](const ob::State *a, const ob::State *b, std::size_t steps)
              {
                  robot.stateToConfig(a, from.data());
                  robot.stateToConfig(b, to.data());
                  timed.appendMotion(from.data(), to.data(), steps);
              });
    return timed;
}
