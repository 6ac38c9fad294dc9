#include "ompl_parc/planners/setup/MultiRobotSetup.h"

#include "ompl_parc/io/PictureFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/quality/SmoothingStep.h"
#include "ompl_parc/util/InnerPlannerLog.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/goals/GoalState.h>

#include <stdexcept>

namespace ob = ompl::base;

ompl_parc::MultiRobotSetup::MultiRobotSetup(std::vector<RobotPtr> robots, double resolution)
    : si_(std::make_shared<MultiRobotSpaceInformation>(std::move(robots), resolution)),
      setup_(si_),
      starts_(si_->getRobotCount()),
      goals_(si_->getRobotCount())
{
}

ompl_parc::MultiRobotSetup::MultiRobotSetup(const MultiRobotProblem &problem)
    : si_(problem.getSpaceInformation()),
      setup_(si_),
      name_(problem.getName()),
      starts_(si_->getRobotCount()),
      goals_(si_->getRobotCount())
{
    for (std::size_t i = 0; i < getRobotCount(); ++i)
    {
        starts_[i] = problem.getStart(i);
        goals_[i] = problem.getGoal(i);
    }
}

std::size_t ompl_parc::MultiRobotSetup::getRobotIndex(const std::string &name) const
{
    std::string names;
    for (std::size_t i = 0; i < getRobotCount(); ++i)
    {
        if (si_->getRobot(i)->getName() == name)
            return i;
        names += (i == 0 ? "" : ", ") + si_->getRobot(i)->getName();
    }
    throw std::invalid_argument("no robot named '" + name + "' (the team: " + names + ")");
}

void ompl_parc::MultiRobotSetup::checkConfiguration(std::size_t robot, const std::vector<double> &configuration) const
{
    if (robot >= getRobotCount())
        throw std::invalid_argument("no robot " + std::to_string(robot) + " (the team has " +
                                    std::to_string(getRobotCount()) + ")");
    const unsigned int d = si_->getRobot(robot)->getDimension();
    if (configuration.size() != d)
        throw std::invalid_argument("robot '" + si_->getRobot(robot)->getName() + "' has " + std::to_string(d) +
                                    " degrees of freedom, got " + std::to_string(configuration.size()) + " values");
}

void ompl_parc::MultiRobotSetup::setStart(std::size_t robot, const std::vector<double> &configuration)
{
    checkConfiguration(robot, configuration);
    starts_[robot] = configuration;
    changed_ = true;
}

void ompl_parc::MultiRobotSetup::setStart(const std::string &robot, const std::vector<double> &configuration)
{
    setStart(getRobotIndex(robot), configuration);
}

void ompl_parc::MultiRobotSetup::setGoal(std::size_t robot, const std::vector<double> &configuration)
{
    checkConfiguration(robot, configuration);
    goals_[robot] = configuration;
    changed_ = true;
}

void ompl_parc::MultiRobotSetup::setGoal(const std::string &robot, const std::vector<double> &configuration)
{
    setGoal(getRobotIndex(robot), configuration);
}

ompl_parc::MultiRobotProblem ompl_parc::MultiRobotSetup::getProblem() const
{
    std::vector<std::vector<double>> starts, goals;
    for (std::size_t i = 0; i < getRobotCount(); ++i)
    {
        if (!starts_[i] || !goals_[i])
            throw std::invalid_argument("robot '" + si_->getRobot(i)->getName() + "' has no " +
                                        (starts_[i] ? "goal" : "start") + " (setStart/setGoal)");
        starts.push_back(*starts_[i]);
        goals.push_back(*goals_[i]);
    }
    return MultiRobotProblem(si_, starts, goals, name_);
}

void ompl_parc::MultiRobotSetup::setPlanner(const std::string &name)
{
    setPlanner(PlannerRegistry::create(name, si_));
}

void ompl_parc::MultiRobotSetup::setPlanner(const ob::PlannerPtr &planner)
{
    setup_.setPlanner(planner);
    plan_.reset();
}

void ompl_parc::MultiRobotSetup::setPlannerParameterText(const std::string &key, const std::string &value)
{
    if (!getPlanner())
        throw std::invalid_argument("set a planner (setPlanner) before its parameter '" + key + "'");
    PlannerRegistry::setParameter(*getPlanner(), key, value);
}

ob::PlannerStatus ompl_parc::MultiRobotSetup::solve(double seconds)
{
    return solve(ob::timedPlannerTerminationCondition(seconds));
}

ob::PlannerStatus ompl_parc::MultiRobotSetup::solve(const ob::PlannerTerminationCondition &ptc)
{
    if (!getPlanner())
        throw std::invalid_argument("set a planner (setPlanner) before solve()");
    if (changed_)
    {
        const ob::ProblemDefinitionPtr pdef = getProblem().createProblemDefinition();
        setup_.setStartAndGoalStates(
            ob::ScopedState<>(si_->getStateSpace(), pdef->getStartState(0)),
            ob::ScopedState<>(si_->getStateSpace(), pdef->getGoal()->as<ob::GoalState>()->getState()), 1e-9);
        // A planner continues its last problem (OMPL's convention for a repeated solve()): start it over.
        getPlanner()->clear();
        setup_.getProblemDefinition()->clearSolutionPaths();
        changed_ = false;
    }
    plan_.reset();
    const ob::PlannerStatus status = setup_.solve(ptc);
    if (status == ob::PlannerStatus::EXACT_SOLUTION)
        plan_ = PlannerRegistry::planOf(*getPlanner(), si_, false);
    return status;
}

const ompl_parc::MultiRobotPlan &ompl_parc::MultiRobotSetup::getPlan() const
{
    if (!plan_)
        throw std::logic_error("no solution: the last solve() found no exact solution");
    return *plan_;
}

std::map<std::string, std::string> ompl_parc::MultiRobotSetup::getProgress() const
{
    std::map<std::string, std::string> values;
    if (getPlanner())
        for (const auto &[name, property] : getPlanner()->getPlannerProgressProperties())
            values[name] = property();
    return values;
}

ompl_parc::SmoothingReport ompl_parc::MultiRobotSetup::simplify(double seconds, unsigned int seed)
{
    if (!plan_)
        throw std::logic_error("no solution to simplify: the last solve() found no exact solution");
    const InnerPlannerLog::Session session;
    SmoothingStep step;
    step.setBudget(seconds);
    step.setReplanner([] { return PrioritizedSTRRTSolver::makeReplanner(); });
    step.apply(si_, *plan_, ob::plannerNonTerminatingCondition(), mixSeed(seed, 0x5300));
    return step.getReport().value_or(SmoothingReport{});
}

ompl_parc::ValidationReport ompl_parc::MultiRobotSetup::validate(const ValidationOptions &options) const
{
    return SolutionValidator(getProblem(), options).validate(getPlan());
}

void ompl_parc::MultiRobotSetup::writeSolution(const std::string &path) const
{
    SolutionFile::write(path, getPlan(), *si_);
}

void ompl_parc::MultiRobotSetup::writePicture(const std::string &path, const SvgOptions &options) const
{
    PictureFile::write(path, getProblem(), plan_ ? &*plan_ : nullptr, options);
}
