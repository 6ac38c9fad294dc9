#ifndef OMPL_PARC_SPACE_TIME_MOTION_VALIDATOR_
#define OMPL_PARC_SPACE_TIME_MOTION_VALIDATOR_

#include "ompl_parc/model/TimedPath.h"
#include "ompl_parc/spacetime/DynamicObstacles.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/geometric/PathGeometric.h>

#include <functional>
#include <vector>

namespace ompl_parc
{
    /** \brief Motions of a robot in space-time among DynamicObstacles, checked where plans live: at integer
        timesteps.

        A motion from (q1, t1) to (q2, t2) is valid iff t2 > t1, its speed is at most vMax (1 unit of distance
        per unit of time, one unit of time being resolution timesteps), its end state is valid, and the
        linearly interpolated configuration at every integer timestep k in [t1 x res, t2 x res] is clear.
        The configurations at the first and last such k are interpolated in time; those between them are laid
        between these two as TimedPath lays a piece, so that layOnGrid() emits exactly the checked
        configurations as one piece per motion, and a path of valid motions becomes a valid timed path. */
    class SpaceTimeMotionValidator : public ompl::base::MotionValidator
    {
      public:
        SpaceTimeMotionValidator(ompl::base::SpaceInformation *si, DynamicObstaclesPtr obstacles);

        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        /** \brief As above; on failure \e lastValid is the first state (no partial motions are reported). */
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

        /** \brief Call \e visit(k, q) for each integer timestep k in [t1 x res, t2 x res] with the robot's
            interpolated configuration q; stops early (returning false) when \e visit returns false. */
        bool forEachTimestep(const ompl::base::State *s1, const ompl::base::State *s2,
                             const std::function<bool(std::size_t, const double *)> &visit) const;

        /** \brief The robot's configurations at timesteps 0 .. ceil(t_end x res) along a space-time path
            starting at time 0: the checked interpolations, and the path's last configuration at the last
            (rounded up) timestep. */
        TimedPath layOnGrid(const ompl::geometric::PathGeometric &path) const;

      private:
        /** \brief The integer timesteps [first, last] of the motion s1 -> s2 and the configurations \e a, \e b
            interpolated at them; false if the motion covers no integer timestep. */
        bool gridAnchors(const ompl::base::State *s1, const ompl::base::State *s2, std::size_t &first,
                         std::size_t &last, double *a, double *b) const;

        DynamicObstaclesPtr obstacles_;
    };
}  // namespace ompl_parc

#endif
