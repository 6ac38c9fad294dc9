#ifndef OMPL_PARC_MOTION_LIMITS_
#define OMPL_PARC_MOTION_LIMITS_

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief How fast a robot may move: a plan is geometry on a timestep grid, and turning it into a trajectory
        (TimeParameterization) needs each coordinate's velocity and acceleration limit in the robot's units per
        second (rad/s for joints, metres/s for a mobile robot's position).

        Limits come in groups of consecutive coordinates bounded together by the Euclidean norm: an arm's joint is a
        group of one (a box limit per joint, as a URDF's `<limit velocity=...>` says), a disc's (x, y) one group of
        two (a speed, whatever the heading). */
    struct MotionLimits
    {
        /** \brief Coordinates [first, first + count) whose velocity (and acceleration) vector has a Euclidean norm
            of at most \e velocity (\e acceleration). */
        struct Group
        {
            unsigned int first, count;
            double velocity, acceleration;
        };
        std::vector<Group> groups;

        /** \brief One group per coordinate. */
        static MotionLimits perCoordinate(const std::vector<double> &velocity, const std::vector<double> &acceleration);

        /** \brief Empty if the groups cover coordinates 0 .. dimension - 1 once each, in order, with finite
            positive limits; else what is wrong ("group 2: acceleration must be finite and > 0"). */
        std::string check(unsigned int dimension) const;
    };
}  // namespace ompl_parc

#endif
