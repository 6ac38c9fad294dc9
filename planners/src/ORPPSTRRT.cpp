#include "ompl_parc/planners/ORPPSTRRT.h"

#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <map>

namespace ob = ompl::base;

ompl_parc::ORPPSTRRT::ORPPSTRRT(const ob::SpaceInformationPtr &si) : PrioritizedSTRRT(si), race_(*this)
{
    setName("ORPPSTRRT");
    specs_.multithreaded = true;
    setPriorityOrder("shuffled");
    race_.declareInstances(params());
}

ob::PlannerStatus ompl_parc::ORPPSTRRT::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    std::map<std::string, std::string> values;
    params().getParams(values);
    values.erase("instances");
    values["priority_order"] = "shuffled";
    values["smooth"] = "0";  // the winner's plan is smoothed once, below
    race_.createRacers(
        [&](unsigned int, std::uint_fast32_t seed)
        {
            auto racer = std::make_shared<PrioritizedSTRRT>(si_);
            racer->params().setParams(values, true);
            racer->setSeed(seed);
            return racer;
        },
        getSeed(), pdef_);
    const ob::PlannerStatus status = race_.run(ptc);
    solved_ = race_.getWinner() >= 0;
    if (solved_)
    {
        const auto &winner = static_cast<const PrioritizedSTRRT &>(*race_.getRacers()[race_.getWinner()]);
        plan_ = winner.getPlan();
        if (getSmoothing() > 0.)
            publishPlan(ptc, mixSeed(winner.getSeed(), 0x5300));
    }
    return status;
}

void ompl_parc::ORPPSTRRT::getPlannerData(ob::PlannerData &data) const
{
    PrioritizedSTRRT::getPlannerData(data);
    race_.addProperties(data);
}
