#include "ompl_parc/planners/ORPARC.h"

#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/tools/multiplan/ParallelPlan.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>

#include <limits>
#include <map>

namespace ob = ompl::base;

ompl_parc::ORPARC::ORPARC(const ob::SpaceInformationPtr &si) : PARC(si)
{
    setName("ORPARC");
    declareParam<unsigned int>("instances", this, &ORPARC::setInstances, &ORPARC::getInstances, "1:1:64");
    declareParam<unsigned int>("total_workers", this, &ORPARC::setTotalWorkers, &ORPARC::getTotalWorkers, "1:1:64");
}

ompl_parc::ORPARC::~ORPARC() = default;

void ompl_parc::ORPARC::setInstances(unsigned int instances)
{
    if (instances == 0)
        throw ompl::Exception(getName(), "instances must be at least 1");
    instances_ = instances;
    racers_.clear();
}

void ompl_parc::ORPARC::setTotalWorkers(unsigned int total)
{
    if (total == 0 || total % instances_ != 0)
        throw ompl::Exception(getName(), "total_workers (" + std::to_string(total) +
                                             ") must be a positive multiple of "
                                             "instances (" +
                                             std::to_string(instances_) + ")");
    setWorkers(total / instances_);
    racers_.clear();
}

void ompl_parc::ORPARC::clear()
{
    PARC::clear();
    racers_.clear();
    winner_.reset();
}

const ompl_parc::MultiRobotPlan &ompl_parc::ORPARC::getPlan() const
{
    return winner_ ? winner_->getPlan() : PARC::getPlan();
}

ob::PlannerStatus ompl_parc::ORPARC::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    winner_.reset();
    if (racers_.empty())
    {
        // Every instance gets this planner's parameters, its share of the workers and its own seed.
        std::map<std::string, std::string> values;
        params().getParams(values);
        values.erase("instances");
        values.erase("total_workers");
        const std::uint_fast32_t seed =
            getSeed() != 0 ? getSeed() : ompl::RNG().uniformInt(1, std::numeric_limits<int>::max());
        for (unsigned int k = 0; k < instances_; ++k)
        {
            auto racer = std::make_shared<PARC>(si_);
            racer->setName(getName() + "#" + std::to_string(k));
            racer->params().setParams(values, true);
            racer->setSeed(mixSeed(seed, k));
            racer->setProblemDefinition(pdef_);
            racers_.push_back(racer);
        }
    }
    ompl::tools::ParallelPlan race(pdef_);
    for (const auto &racer : racers_)
        race.addPlanner(racer);
    // ParallelPlan terminates the condition it is given once a racer wins: give it its own.
    const ob::PlannerTerminationCondition raceStop([&ptc] { return ptc(); });
    race.solve(raceStop, 1, racers_.size(), false);

    // The winner is the racer that added the first exact solution.
    for (const auto &solution : pdef_->getSolutions())
        for (const auto &racer : racers_)
            if (!solution.approximate_ && solution.plannerName_ == racer->getName())
            {
                winner_ = racer;
                return ob::PlannerStatus(ob::PlannerStatus::EXACT_SOLUTION);
            }
    return ob::PlannerStatus(ob::PlannerStatus::TIMEOUT);
}

void ompl_parc::ORPARC::getPlannerData(ob::PlannerData &data) const
{
    PARC::getPlannerData(data);
    data.properties["instances INTEGER"] = std::to_string(instances_);
    data.properties["winner STRING"] = winner_ ? winner_->getName() : "";
}
