#ifndef OMPL_PARC_TEAM_TRAJECTORY_
#define OMPL_PARC_TEAM_TRAJECTORY_

#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief A team plan in seconds, made by TimeParameterization: one clock for the whole team, and each robot's
        path with its corners rounded.

        Geometry and timing are separate. Geometry: robot i's plan path, a function of plan time (timesteps) that is
        straight between the robot's breakpoints, gets each corner (a change of its velocity in plan time) replaced
        by a parabola over a window of plan time centred on it, so its velocity changes continuously; a corner with a
        zero window stays sharp (the robot passes exactly through the plan there). Timing: one rate for the team,
        plan timesteps per second, a function of plan time with a constant acceleration within each timestep; it is
        zero at the start, at the end and at every sharp corner, where the team comes to rest. So the team is, at
        any instant, at the plan's configurations of one plan time, up to the rounding of corners (which cuts a
        corner by at most |dv| x window / 4 in the robot's coordinates).

        Positions, velocities and accelerations are exact (closed form), at any time; before getStartTime() robots
        hold their starts, after getEndTime() their goals. */
    class TeamTrajectory
    {
      public:
        /** \brief Robot \e i's position, velocity and acceleration at time \e t (seconds) into the arrays given
            (nullptr for those not wanted), getDimension(i) values each. */
        void evaluate(std::size_t i, double t, double *position, double *velocity, double *acceleration) const;

        std::size_t getRobotCount() const { return robots_.size(); }
        unsigned int getDimension(std::size_t i) const { return robots_[i].dimension; }

        double getStartTime() const { return 0.; }
        double getEndTime() const { return times_.back(); }
        double getDuration() const { return times_.back(); }
        /** \brief The time at which robot \e i comes to rest at its goal for good. */
        double getArrivalTime(std::size_t i) const;

        /** \brief How far robot \e i's trajectory leaves its plan path at most, in its configuration space's
            distance: the largest corner cut, |change of slope| x window / 4. */
        double getMaxDeviation(std::size_t i) const;

        /** \brief Robot \e i's corners (plan timesteps where its velocity in plan time changes), and how many of
            them are sharp (the team stops there). */
        std::size_t getCornerCount(std::size_t i) const { return robots_[i].corners.size(); }
        std::size_t getSharpCornerCount() const;
        /** \brief Robot \e i's corner \e c: its plan timestep and the half-width of its window (0: sharp). */
        std::size_t getCornerStep(std::size_t i, std::size_t c) const
        {
            return robots_[i].steps[robots_[i].corners[c]];
        }
        double getCornerWindow(std::size_t i, std::size_t c) const { return robots_[i].windows[robots_[i].corners[c]]; }

        /** \brief The times (ascending) at which robot \e i's acceleration may jump: the team's changes of pace and
            the ends of the robot's corner windows, from its first motion to its arrival. Between two of them its
            acceleration changes smoothly (it is constant wherever the team keeps its pace), so positions and
            velocities at these times, interpolated cubically as trajectory controllers do, follow it closely. */
        std::vector<double> getBreakTimes(std::size_t i) const;

        /** \brief The plan time (fractional timestep) the team is at, at time \e t; and its inverse. */
        double planTimeAt(double t) const;
        double timeAtPlanStep(double step) const;

      private:
        friend class TimeParameterization;

        /** \brief One robot's path in plan time: breakpoints (timesteps), the configuration at each and the slope
            (per timestep) of the straight part after each (zero after the last), the half-width of each
            breakpoint's window (0 unless it is a rounded corner), and which breakpoints are corners (the slope
            changes there). */
        struct RobotPath
        {
            unsigned int dimension{0};
            std::vector<std::size_t> steps;
            std::vector<double> configs, slopes, windows;
            std::vector<std::size_t> corners;
        };

        /** \brief Plan time, its rate and acceleration at time \e t. */
        void planMotionAt(double t, double &step, double &rate, double &acceleration) const;
        /** \brief Robot \e i's position and its first and second derivatives in plan time, at plan time \e s. */
        void pathAt(std::size_t i, double s, double *q, double *dq, double *ddq) const;

        std::vector<RobotPath> robots_;
        /** \brief Per integer timestep k, the time the team reaches it and its rate there (timesteps/s); a step
            from a rate of zero to zero is crossed accelerating, then braking, with bangBang_[k]. */
        std::vector<double> times_, rates_, bangBang_;
    };
}  // namespace ompl_parc

#endif
