#ifndef OMPL_PARC_COMPOSITE_RRT_CONNECT_SOLVER_
#define OMPL_PARC_COMPOSITE_RRT_CONNECT_SOLVER_

#include "ompl_parc/arc/SubproblemSolver.h"

namespace ompl_parc
{
    /** \brief Coupled subproblem solver: OMPL's RRTConnect over the sub-composite space of the team,
        sampling inside the local bounds, capped at the subproblem's sample cap. The composite path is laid
        on the timestep grid with every segment lasting as long as its largest robot motion, so the team
        stays synchronised and collision-free at every timestep. */
    class CompositeRRTConnectSolver : public SubproblemSolver
    {
      public:
        /** \brief \e range: RRTConnect's maximum motion (0: OMPL's default, 20% of the space extent);
            \e simplify: shorten the composite path with OMPL's simplifier, bounded (one pass of vertex reduction, 128
            shortcut steps), before laying it on the grid (ArcSettings::shortenPatches). */
        explicit CompositeRRTConnectSolver(double range = 0., bool simplify = false);

        std::string getName() const override { return "composite-rrtc"; }

        bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                   Patch &patch) const override;

      private:
        double range_;
        bool simplify_;
    };
}  // namespace ompl_parc

#endif
