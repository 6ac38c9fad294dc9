#include "ompl_parc/planners/ARC.h"

ompl_parc::ARC::ARC(const ompl::base::SpaceInformationPtr &si) : ArcPlannerBase(si, "ARC") {}
