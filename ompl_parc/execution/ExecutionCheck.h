#ifndef OMPL_PARC_EXECUTION_CHECK_
#define OMPL_PARC_EXECUTION_CHECK_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <functional>

namespace ompl_parc
{
    /** \brief The independent validator applied to motion in seconds (a TeamTrajectory, an execution with delays):
        the motion is sampled often enough that no robot moves more than one timestep's distance (1/resolution)
        between two samples, and the samples, read as a plan, go through the SolutionValidator.

        Between samples the validator checks the straight motion from one sample to the next; the motion itself
        may bend there (a blend, a robot changing pieces), by at most acceleration x dt^2 / 8, far below the
        tolerance. Since any instant is now a sample, every sample is checked with the tolerance the validator
        grants a plan between its timesteps (half a timestep, the default substepSlack) rather than the one at
        timesteps: the motion being executed is the plan's own, so it is held to what the plan was held to. */
    class ExecutionCheck
    {
      public:
        /** \brief Robot \e i's configuration at time \e t (seconds) into \e out. */
        using Motion = std::function<void(std::size_t i, double t, double *out)>;

        explicit ExecutionCheck(const MultiRobotProblem &problem);

        /** \brief The motion over [\e start, \e end] as a plan: samples \e dt apart, \e dt such that a robot
            moving no faster than \e maxSpeed (in its configuration space's distance per second) moves at most
            1/resolution between two; a robot's samples along a straight, steady stretch (cruising, waiting) are
            one piece of the plan (within 2e-9 of a timestep), so its memory grows with the motion's bends, not with
            its duration. */
        MultiRobotPlan sample(double start, double end, double maxSpeed, const Motion &motion) const;

        /** \brief Validate sample(); a violation's time (ValidationReport::time) is in seconds. */
        ValidationReport check(double start, double end, double maxSpeed, const Motion &motion) const;

        /** \brief The largest speed, in configuration-space distance per second, that \e limits allow (the
            Euclidean norm of every group's velocity limit). */
        static double maxSpeed(const MotionLimits &limits);

      private:
        MultiRobotProblem problem_;
        SolutionValidator validator_;
    };
}  // namespace ompl_parc

#endif
