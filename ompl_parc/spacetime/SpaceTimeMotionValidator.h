#ifndef OMPL_PARC_SPACE_TIME_MOTION_VALIDATOR_
#define OMPL_PARC_SPACE_TIME_MOTION_VALIDATOR_

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
        layOnGrid() emits exactly these checked configurations, so a path of valid motions becomes a valid
        timestep path. */
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
            (rounded up) timestep. Flat, getDimension() values per timestep. */
        std::vector<double> layOnGrid(const ompl::geometric::PathGeometric &path) const;

      private:
        DynamicObstaclesPtr obstacles_;
    };
}  // namespace ompl_parc

#endif
