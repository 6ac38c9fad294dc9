#ifndef OMPL_PARC_SUBPROBLEM_
#define OMPL_PARC_SUBPROBLEM_

#include "ompl_parc/model/TimedPath.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/spaces/RealVectorBounds.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ompl_parc
{
    class MultiRobotPlan;
    class MultiRobotSpaceInformation;

    /** \brief A locally coupled planning problem around a conflict: a team of robots, a window of the
        current plan, each robot's local start and goal (its states at the window's ends) and local
        sampling bounds. A SubproblemSolver answers it with a Patch. */
    struct Subproblem
    {
        /** \brief The team, as indices into the problem's robots (increasing). */
        std::vector<std::size_t> robots;
        /** \brief The window [windowStart, windowEnd] of timesteps of the current plan the patch replaces. */
        std::size_t windowStart{0}, windowEnd{0};
        /** \brief Local start and goal of each team robot (same order as \e robots). */
        std::vector<std::vector<double>> starts, goals;
        /** \brief Local sampling bounds of each team robot; empty: each robot's whole space. */
        std::vector<ompl::base::RealVectorBounds> bounds;
        /** \brief Largest number of planner iterations; 0: no cap. */
        unsigned int sampleCap{0};
        /** \brief The team's global problem (ConflictResolver): its whole plan, from the robots' own starts to their
            own goals, in their whole spaces; else a window, which starts and ends mid-motion. */
        bool global{false};

        /** \brief \e cap x 2^\e round, clamped to the largest sampleCap: the cap of a retry's round, so that rounds
            grow their effort geometrically. */
        static unsigned int doubledCap(unsigned int cap, unsigned int round);
        /** \brief Context: robots outside the team whose plans come near it during the window, and those plans
            over [windowStart, windowEnd] (timestep 0 = windowStart, held afterwards). A time-aware solver
            (SubproblemSolver::usesContext()) avoids them, so that a patch seldom makes new conflicts with the
            rest of the team: advisory only, the repaired plan is checked for conflicts as any other. */
        std::vector<std::size_t> others;
        std::vector<TimedPath> otherPaths;

        /** \brief Fill the context from \e plan (of the team of \e si): every robot outside the team whose bodies over
            the window (sampled every quarter unit of motion, boxes grown by half a unit) come near the team's, with
            its path over the window; left out are robots that touch a team robot's local start or goal at the
            window's ends (a conflict no patch of this team can avoid). */
        void fillContext(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan);

        /** \brief Empty if the subproblem is well formed for the team of \e si, else the reason. */
        std::string check(const MultiRobotSpaceInformation &si) const;

        /** \brief The subproblem's own team SpaceInformation: fresh robot spaces with the local bounds and
            samplers seeded from \e seed (what every SubproblemSolver plans in); null if check() fails. */
        std::shared_ptr<MultiRobotSpaceInformation> createSpaceInformation(const MultiRobotSpaceInformation &si,
                                                                           std::uint_fast32_t seed) const;

        /** \brief \e ptc, or the sample cap once it has been evaluated sampleCap times: OMPL's tree planners
            evaluate their condition once per iteration, so this caps their samples (no cap when 0). */
        ompl::base::PlannerTerminationCondition cappedTermination(
            const ompl::base::PlannerTerminationCondition &ptc) const;
    };
}  // namespace ompl_parc

#endif
