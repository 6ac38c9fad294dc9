#ifndef OMPL_PARC_LATTICE_MAPF_SOLVER_
#define OMPL_PARC_LATTICE_MAPF_SOLVER_

#include "ompl_parc/arc/SubproblemSolver.h"
#include "ompl_parc/mapf/ConfigurationSearch.h"

#include <limits>
#include <vector>

namespace ompl_parc
{
    /** \brief Coupled subproblem solver for teams of translating robots (discs): the whole team on one lattice, by
        multi-agent path finding (ConfigurationSearch: LaCAM over PIBT).

        What the other solvers lack in dense places (a crossing whose arms are full both ways, robots that must step
        aside into free slots to let others pass): prioritised planning walls later robots in, composite RRT-Connect
        seldom samples the few joint motions that work. Here every robot moves each step and pushes the robots in its
        way aside, and the search over configurations is complete on its lattice. The lattice step is just over 2 sqrt 2
        times the team's largest bounding radius (robots on distinct points never touch, even when one turns into the
        point another leaves), then, if that lattice fails, just over twice it (more points in narrow places; such turns
        then wait a sub-step); its origin is drawn from the seed (so retries see other lattices). Each robot first
        steps from its start onto a lattice point of its own, in waves of robots whose steps are clear of each other
        and of the others, and leaves the lattice the same way for its goal. Every segment of the resulting team path
        is checked with the team's motion validator (robots and environment) before it is laid on the timestep grid, so
        a patch is as valid as a composite RRT-Connect one; it is then shortened with OMPL's simplifier (bounded).

        Declines (returns false at once) teams with a robot that does not translate (LatticeSearch::applies), of mixed
        dimensions, or whose local box holds more than maxPoints lattice points. Ignores the subproblem's context
        (robots outside the team), as composite RRT-Connect does; the sample cap does not apply (the search is bounded
        by its memory cap and the termination condition). */
    class LatticeMapfSolver : public SubproblemSolver
    {
      public:
        /** \brief \e maxPoints: the largest lattice (points in the local box, free or not) the solver builds.
            \e wideSeconds: the most time the search on the wide lattice may take before the tight one is tried (for
            a short budget: where LaCAM does not finish on the wide lattice in a dense field, it may on the tight
            one); infinite (the default): the wide search has the whole termination condition. */
        explicit LatticeMapfSolver(std::size_t maxPoints = 1u << 18,
                                   double wideSeconds = std::numeric_limits<double>::infinity());

        std::string getName() const override { return "lattice-mapf"; }

        bool solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                   const ompl::base::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                   Patch &patch) const override;

        /** \brief The smoother's and the anytime phase's whole-team solver (PlanSmoother::setTeamSolver()): the wide
            lattice's search gets 0.1 s, then the tight one the rest. Where the wide search succeeds on the generated
            families it takes under 0.08 s; where it does not finish (field 48, instance 3) the tight one may. */
        static SubproblemSolverPtr makeTeamSolver();

        /** \brief Whether the solver applies to the robots \e robots of \e si (see the class description). */
        bool appliesTo(const MultiRobotSpaceInformation &si, const std::vector<std::size_t> &robots) const override;

      private:
        std::size_t maxPoints_;
        double wideSeconds_;
    };
}  // namespace ompl_parc

#endif
