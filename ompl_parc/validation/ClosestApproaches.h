#ifndef OMPL_PARC_CLOSEST_APPROACHES_
#define OMPL_PARC_CLOSEST_APPROACHES_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <array>
#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief Where two robots come closest in a plan: at \e timestep their collision bodies are \e clearance apart
        (negative: overlapping by that much), between \e points (on robot \e first's body, on robot \e second's). */
    struct ClosestApproach
    {
        std::size_t first{0}, second{0}, timestep{0};
        double clearance{0.};
        std::array<std::array<double, 3>, 2> points{};
    };

    /** \brief The robot pairs of a plan that come closest to each other: what a user checks before running a plan
        (the validator says whether the plan is clear, these say by how much, and where).

        Each pair's clearance is its smallest exact capsule-capsule distance (less the radii) over the sampled
        timesteps; the \e count pairs with the smallest clearances are returned, smallest first. Pairs are skipped
        early by their bodies' bounding spheres against the count-th smallest clearance found so far (a sweep over
        x per timestep), so teams of thousands cost little more than their kinematics. */
    class ClosestApproaches
    {
      public:
        /** \brief The \e count closest pairs of \e plan (a plan of the team of \e si) over \e timesteps (each at most
            the makespan). */
        static std::vector<ClosestApproach> find(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan,
                                                 const std::vector<std::size_t> &timesteps, std::size_t count);

        /** \brief The closest points of the segments [\e p1, \e q1] and [\e p2, \e q2] (on the first, on the second).
         */
        static std::array<std::array<double, 3>, 2> closestPoints(const std::array<double, 3> &p1,
                                                                  const std::array<double, 3> &q1,
                                                                  const std::array<double, 3> &p2,
                                                                  const std::array<double, 3> &q2);
    };
}  // namespace ompl_parc

#endif
