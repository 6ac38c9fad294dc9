#ifndef OMPL_PARC_PLANNERS_SETUP_PLANNER_REGISTRY_
#define OMPL_PARC_PLANNERS_SETUP_PLANNER_REGISTRY_

#include "ompl_parc/arc/ArcProgress.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/base/Planner.h>

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Every planner of ompl_parc (and the OMPL baseline) by name, so that user code, the tools, benchmark
        configurations and the Python-free scripts choose planners the same way.

        The names are "arc", "parc", "orparc", "pp-st-rrt", "or-pp-st-rrt", "rrtconnect", "ep-rrt-c", "or-rrt-c"
        and "or-ep-rrt-c". A name is matched ignoring case, '-' and '_', so the names of the paper and the tables
        ("ARC", "PARC", "P-ARC", "OR-P-ARC", "PP-ST-RRT", "RRTConnect") work too. Parameters are the planners'
        declared ones (ompl::base::ParamSet), checked against their declared ranges. */
    class PlannerRegistry
    {
      public:
        /** \brief The registry names, sorted. */
        static std::vector<std::string> names();

        /** \brief The registry name \e name stands for; throws std::invalid_argument listing the valid names. */
        static std::string canonicalName(const std::string &name);

        /** \brief Allocates planner \e name on \e si and applies \e params ("key=value", declared parameter names;
            a "profile" first, the others in the order given, so explicit values override the profile's); throws
            std::invalid_argument listing the valid names for an unknown planner or parameter. */
        static ompl::base::PlannerPtr create(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                             const std::vector<std::string> &params = {});

        /** \brief Sets declared parameter \e key of \e planner to \e value; throws std::invalid_argument listing the
            valid names for an unknown key, naming the declared range for a number outside it (OMPL itself neither
            checks ranges nor refuses "-1" for an unsigned parameter), or for a value the parameter does not take (with
            the setter's reason if it gave one). */
        static void setParameter(ompl::base::Planner &planner, const std::string &key, const std::string &value);

        /** \brief The solution of \e planner (after a solve with an exact solution) on the timestep grid, as the
            validator checks it: the ARC family's (OR-P-ARC included) and the prioritised planners' own plans; a
            composite path (OMPL's planners and the coupled baselines) laid on the grid with
            MultiRobotPlan::fromPathGeometric, after one second of OMPL's shortcutting if \e simplify (the path in
            the ProblemDefinition is simplified in place). */
        static MultiRobotPlan planOf(const ompl::base::Planner &planner, const MultiRobotSpaceInformationPtr &si,
                                     bool simplify);

        /** \brief The live progress of \e planner if it is of the ARC family (ARC, PARC, ORPARC), which may be read
            from another thread while it plans; null for other planners. */
        static const ArcProgress *progressOf(const ompl::base::Planner &planner);
    };
}  // namespace ompl_parc

#endif
