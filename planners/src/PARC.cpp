#include "ompl_parc/planners/PARC.h"

namespace ob = ompl::base;

ompl_parc::PARC::PARC(const ob::SpaceInformationPtr &si) : ArcPlannerBase(si, "PARC")
{
    specs_.multithreaded = true;
    setHorizon(400);
#define OMPL_PARC_PARALLEL_KNOB(Name, member, parameter, Parameter, range, ...)                                      \
    declareParam<Parameter>(parameter, this, &PARC::set##Name, &PARC::get##Name, range);
#include "ompl_parc/arc/ParcKnobs.def"
}

const ompl_parc::ParcStatistics &ompl_parc::PARC::getParallelStatistics() const
{
    static const ParcStatistics none;
    return getLoop() != nullptr ? getLoop()->getParallelStatistics() : none;
}

void ompl_parc::PARC::getPlannerData(ob::PlannerData &data) const
{
    ArcPlannerBase::getPlannerData(data);
    auto &p = data.properties;
    const auto &s = getParallelStatistics();
    p["workers INTEGER"] = std::to_string(getWorkers());
    p["batches INTEGER"] = std::to_string(s.batches);
    p["first_batch_size INTEGER"] = std::to_string(s.firstBatchSize);
    p["largest_batch_size INTEGER"] = std::to_string(s.largestBatch);
    p["average_batch_size REAL"] = std::to_string(s.batches ? double(s.batchedConflicts) / s.batches : 0.);
    p["repair_attempts INTEGER"] = std::to_string(s.repairAttempts);
    p["cancelled_attempts INTEGER"] = std::to_string(s.cancelledAttempts + s.cancelledInitialAttempts);
    p["projected_initial_time REAL"] = std::to_string(s.projectedInitial);
    p["projected_detection_time REAL"] = std::to_string(s.projectedDetection);
    p["projected_resolution_time REAL"] = std::to_string(s.projectedResolution);
    p["projected_total_time REAL"] = std::to_string(s.projectedInitial + s.projectedDetection + s.projectedResolution);
}
