#ifndef OMPL_PARC_SOLUTION_VALIDATOR_
#define OMPL_PARC_SOLUTION_VALIDATOR_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    /** \brief Tolerances of the SolutionValidator. */
    struct ValidationOptions
    {
        /** \brief Largest per-coordinate difference accepted between a path end and its start/goal. */
        double endpointTolerance{1e-6};
        /** \brief Samples per timestep interval; 1 checks the timesteps only. */
        unsigned int substeps{4};
        /** \brief Radius reduction at sub-step samples; negative means half a timestep (0.5/resolution).
            The plan's guarantee is collision-freedom at timesteps; between them grazing overlaps far
            below a timestep are expected, tunnelling through a robot or obstacle is not. */
        double substepSlack{-1.};
        /** \brief Radius reduction at timesteps: contacts shallower than this are below FCL's GJK
            tolerance and are not reported. */
        double contactTolerance{1e-6};
    };

    /** \brief Outcome of SolutionValidator::validate(). */
    struct ValidationReport
    {
        bool valid{false};
        /** \brief The first violation found, readable ("t=42: robots 'r0' and 'r1' collide"); empty if valid. */
        std::string message;
        /** \brief Number of (robot, sample) configurations checked. */
        std::size_t configurationsChecked{0};
    };

    /** \brief Re-checks a plan against its problem, independently of every planner.

        It shares the robot kinematics (computeBody) with the planners, nothing else: bounds and the
        motion bound are its own loops, and collisions (environment, self and every robot pair) are
        tested with FCL's dynamic AABB tree broad phase and FCL's narrow phase on its own FCL objects,
        not with the planners' capsule test or the robots' validity checkers. Checks, in order: team
        size and resolution; each robot starts at its start and ends at its goal; no timestep moves a
        robot more than 1/resolution; every timestep (robots holding their goals after arrival) and
        sub-step sample is in bounds and collision-free. */
    class SolutionValidator
    {
      public:
        explicit SolutionValidator(MultiRobotProblem problem, ValidationOptions options = ValidationOptions());

        ValidationReport validate(const MultiRobotPlan &plan) const;

      private:
        std::string checkStructure(const MultiRobotPlan &plan) const;
        std::string checkEndpoints(const MultiRobotPlan &plan) const;
        std::string checkMotionBound(const MultiRobotPlan &plan) const;
        std::string checkBounds(std::size_t robot, const double *q) const;

        MultiRobotProblem problem_;
        ValidationOptions options_;
    };
}  // namespace ompl_parc

#endif
