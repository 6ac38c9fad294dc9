#ifndef OMPL_PARC_DISC_ROBOT_
#define OMPL_PARC_DISC_ROBOT_

#include "ompl_parc/robots/Robot.h"

namespace ompl_parc
{
    /** \brief A holonomic disc in the plane; configuration (x, y) of its centre. */
    class DiscRobot : public Robot
    {
      public:
        /** \brief \e bounds limit the centre; throws ompl::Exception for a non-positive radius. */
        DiscRobot(std::string name, EnvironmentPtr environment, double radius,
                  const ompl::base::RealVectorBounds &bounds);

        std::string getKind() const override { return "disc"; }
        void computeCapsules(const double *q, CollisionBody &body) const override;

        /** \brief Exact for a translation: the disc sweeps the capsule from \e from to \e to with its radius (tested
            against the obstacles like any capsule), and the bounds box is convex, so \e to in bounds keeps the
            whole motion in. One test per motion instead of one per timestep. */
        std::optional<bool> sweepValid(const double *from, const double *to) const override;

        /** \brief The configuration box grown by the radius (z: the disc's own extent): exactly the union of the
            bodies' boxes. */
        bool expandBoxOver(const double *lo, const double *hi, std::array<double, 3> &boxLo,
                           std::array<double, 3> &boxHi) const override;

        double getRadius() const { return radius_; }

        /** \brief "x", "y". */
        std::vector<std::string> getCoordinateNames() const override { return {"x", "y"}; }

      protected:
        /** \brief A speed of 1 unit/s and an acceleration of 2 units/s^2 in any direction (one group). */
        MotionLimits defaultMotionLimits() const override { return MotionLimits{{{0u, 2u, 1., 2.}}}; }

      private:
        double radius_;
    };
}  // namespace ompl_parc

#endif
