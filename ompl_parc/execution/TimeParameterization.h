#ifndef OMPL_PARC_TIME_PARAMETERIZATION_
#define OMPL_PARC_TIME_PARAMETERIZATION_

#include "ompl_parc/execution/ExecutionCheck.h"
#include "ompl_parc/execution/TeamTrajectory.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/robots/MotionLimits.h"

#include <map>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Turns a team plan (timesteps) into a TeamTrajectory (seconds) within every robot's velocity and
        acceleration limits (Robot::getMotionLimits()), still conflict-free.

        One clock for the team keeps the plan's order: the team moves through plan time at one rate, so whatever the
        rate, the robots are where the plan has them at the same plan time. A robot's corner (where its velocity in
        plan time jumps: it starts, stops or turns) cannot be passed at a positive rate within an acceleration limit,
        so each corner is rounded over a window of plan time (as wide as needed to pass it at the team's top rate,
        at most half-way to the robot's neighbouring corners and no wider than keeps the corner cut within the
        largest deviation). Half of each acceleration limit goes to the rounding,
        half to the team's changes of pace. The rate is then the largest profile under the caps (the velocity
        limits of the robots moving, the roundings' caps; zero at sharp corners, the start and the end) with its
        changes bounded: the forward-backward pass of time-optimal path parameterization, per timestep.

        Rounding moves robots off the plan near corners. computeConflictFree() first narrows the windows where a
        rounded robot would touch another (nearContacts()), down to sharp corners: there the team slows to rest and
        passes exactly through the plan. Then the independent validator (ExecutionCheck) checks the result, and any
       corner whose window holds a violation it still finds is sharpened too. With every corner sharp the trajectory is
       the plan's motion itself. */
    class TimeParameterization
    {
      public:
        /** \brief What computeConflictFree() returns. */
        struct Result
        {
            TeamTrajectory trajectory;
            /** \brief True once the trajectory passed ExecutionCheck; false only if the plan itself does not. */
            bool valid{false};
            /** \brief The last check's violation, if any. */
            std::string message;
            /** \brief Corners made sharp, and how many checks it took. */
            std::size_t sharpened{0};
            unsigned int checks{0};
        };

        /** \brief The largest deviation from the plan's path a rounded corner may take a robot, in its configuration
            space's distance (radians for an arm, as MoveIt's time-optimal trajectory generation's default path
            tolerance of 0.1; 0: every corner sharp). Throws std::invalid_argument if negative or not finite. */
        static constexpr double DEFAULT_MAX_DEVIATION = 0.1;

        explicit TimeParameterization(const MultiRobotProblem &problem, double maxDeviation = DEFAULT_MAX_DEVIATION);

        /** \brief Per robot, the largest window (half-width, timesteps; 0: sharp) of its corner at a plan timestep. */
        using WindowCaps = std::vector<std::map<std::size_t, double>>;

        /** \brief The trajectory with every corner rounded, its windows no wider than \e caps (empty, or one map per
            robot). Throws std::invalid_argument if \e plan is not one for the problem's team. */
        TeamTrajectory compute(const MultiRobotPlan &plan, const WindowCaps &caps = {}) const;

        /** \brief compute(), then the windows of nearContacts() narrowed (to a quarter, a few times, then sharp)
            until there are none; then checked by ExecutionCheck: each violation sharpens the corners whose windows
            hold it (each robot's corners on both sides of it if none does) and the check runs again. After
            \e maxChecks failed checks every corner becomes sharp. */
        Result computeConflictFree(const MultiRobotPlan &plan, unsigned int maxChecks = 16) const;

        /** \brief ExecutionCheck of \e trajectory over its whole span. */
        ValidationReport check(const TeamTrajectory &trajectory) const;

        const std::vector<MotionLimits> &getLimits() const { return limits_; }
        /** \brief The largest speed of any robot (ExecutionCheck::maxSpeed()). */
        double getMaxSpeed() const { return maxSpeed_; }

        /** \brief Per robot, the indices of its rounded corners in \e trajectory during whose windows it would touch
            another robot: both at their rounded configurations, twice per plan timestep, capsules grown by how far
            they move to the nearest sample and shrunk by half the validator's tolerance. A quick filter before the
            validator, which decides. */
        std::vector<std::vector<std::size_t>> nearContacts(const TeamTrajectory &trajectory) const;

      private:
        MultiRobotProblem problem_;
        std::vector<MotionLimits> limits_;
        double maxDeviation_;
        double maxSpeed_{0.};
        ExecutionCheck check_;
    };
}  // namespace ompl_parc

#endif
