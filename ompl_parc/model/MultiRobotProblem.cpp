#include "ompl_parc/model/MultiRobotProblem.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

namespace
{
    void checkSizes(const ompl_parc::MultiRobotSpaceInformation &si, const std::vector<std::vector<double>> &configs,
                    const std::string &what)
    {
        if (configs.size() != si.getRobotCount())
            throw ompl::Exception("MultiRobotProblem", std::to_string(configs.size()) + " " + what + "s for " +
                                                           std::to_string(si.getRobotCount()) + " robots");
        for (std::size_t i = 0; i < configs.size(); ++i)
            if (configs[i].size() != si.getRobot(i)->getDimension())
                throw ompl::Exception("MultiRobotProblem", what + " of robot '" + si.getRobot(i)->getName() + "' has " +
                                                               std::to_string(configs[i].size()) +
                                                               " values, expected " +
                                                               std::to_string(si.getRobot(i)->getDimension()));
    }
}  // namespace

ompl_parc::MultiRobotProblem::MultiRobotProblem(MultiRobotSpaceInformationPtr si,
                                                std::vector<std::vector<double>> starts,
                                                std::vector<std::vector<double>> goals, std::string name)
    : si_(std::move(si)), starts_(std::move(starts)), goals_(std::move(goals)), name_(std::move(name))
{
    if (!si_)
        throw ompl::Exception("MultiRobotProblem", "null space information");
    checkSizes(*si_, starts_, "start");
    checkSizes(*si_, goals_, "goal");
}

std::string ompl_parc::MultiRobotProblem::checkConfigurations(const std::vector<std::vector<double>> &configs,
                                                              const std::string &what) const
{
    std::vector<const double *> values;
    for (const auto &config : configs)
        values.push_back(config.data());
    return si_->explainInvalid(values, what);
}

std::string ompl_parc::MultiRobotProblem::checkEndpoints() const
{
    std::string reason = checkConfigurations(starts_, "start");
    return reason.empty() ? checkConfigurations(goals_, "goal") : reason;
}

ompl::base::ProblemDefinitionPtr ompl_parc::MultiRobotProblem::createProblemDefinition() const
{
    ompl::base::ScopedState<> start(si_), goal(si_);
    for (std::size_t i = 0; i < getRobotCount(); ++i)
    {
        si_->getRobot(i)->configToState(starts_[i].data(), start->as<ompl::base::CompoundState>()->components[i]);
        si_->getRobot(i)->configToState(goals_[i].data(), goal->as<ompl::base::CompoundState>()->components[i]);
    }
    auto pdef = std::make_shared<ompl::base::ProblemDefinition>(si_);
    pdef->setStartAndGoalStates(start, goal, 1e-9);
    return pdef;
}

ompl_parc::MultiRobotProblem ompl_parc::MultiRobotProblem::withResolution(double resolution) const
{
    return MultiRobotProblem(std::make_shared<MultiRobotSpaceInformation>(si_->getRobots(), resolution), starts_,
                             goals_, name_);
}
