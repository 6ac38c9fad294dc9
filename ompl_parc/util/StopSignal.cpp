#include "ompl_parc/util/StopSignal.h"

namespace
{
    thread_local const ompl::base::PlannerTerminationCondition *current = nullptr;
}  // namespace

ompl_parc::StopSignal::Scope::Scope(const ompl::base::PlannerTerminationCondition &ptc) : previous_(current)
{
    current = &ptc;
}

ompl_parc::StopSignal::Scope::~Scope()
{
    current = previous_;
}

bool ompl_parc::StopSignal::raised()
{
    return current != nullptr && (*current)();
}
