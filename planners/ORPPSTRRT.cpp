#include "ompl_parc/planners/ORPPSTRRT.h"

#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/tools/multiplan/ParallelPlan.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>

#include <limits>
#include <map>

namespace ob = ompl::base;

ompl_parc::ORPPSTRRT::ORPPSTRRT(const ob::SpaceInformationPtr &si) : PrioritizedSTRRT(si)
{
    setName("ORPPSTRRT");
    specs_.multithreaded = true;
    setPriorityOrder("shuffled");
    declareParam<unsigned int>("instances", this, &ORPPSTRRT::setInstances, &ORPPSTRRT::getInstances, "1:1:64");
}

void ompl_parc::ORPPSTRRT::setInstances(unsigned int instances)
{
    if (instances == 0)
        throw ompl::Exception(getName(), "instances must be at least 1");
    instances_ = instances;
}

ob::PlannerStatus ompl_parc::ORPPSTRRT::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    winner_.clear();
    std::map<std::string, std::string> values;
    params().getParams(values);
    values.erase("instances");
    values["priority_order"] = "shuffled";
    const std::uint_fast32_t seed =
        getSeed() != 0 ? getSeed() : ompl::RNG().uniformInt(1, std::numeric_limits<int>::max());
    std::vector<std::shared_ptr<PrioritizedSTRRT>> racers;
    ompl::tools::ParallelPlan race(pdef_);
    for (unsigned int k = 0; k < instances_; ++k)
    {
        auto racer = std::make_shared<PrioritizedSTRRT>(si_);
        racer->setName(getName() + "#" + std::to_string(k));
        racer->params().setParams(values, true);
        racer->setSeed(mixSeed(seed, k));
        racer->setProblemDefinition(pdef_);
        racers.push_back(racer);
        race.addPlanner(racer);
    }
    // ParallelPlan terminates the condition it is given once a racer wins: give it its own.
    const ob::PlannerTerminationCondition raceStop([&ptc] { return ptc(); });
    race.solve(raceStop, 1, racers.size(), false);
    for (const auto &solution : pdef_->getSolutions())
        for (const auto &racer : racers)
            if (!solution.approximate_ && solution.plannerName_ == racer->getName())
            {
                winner_ = racer->getName();
                plan_ = racer->getPlan();
                return ob::PlannerStatus::EXACT_SOLUTION;
            }
    return ob::PlannerStatus::TIMEOUT;
}

void ompl_parc::ORPPSTRRT::getPlannerData(ob::PlannerData &data) const
{
    PrioritizedSTRRT::getPlannerData(data);
    data.properties["instances INTEGER"] = std::to_string(instances_);
    data.properties["winner STRING"] = winner_;
}
