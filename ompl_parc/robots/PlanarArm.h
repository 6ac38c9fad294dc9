#ifndef OMPL_PARC_PLANAR_ARM_
#define OMPL_PARC_PLANAR_ARM_

#include "ompl_parc/robots/Robot.h"

namespace ompl_parc
{
    /** \brief A serial arm of revolute joints in the plane, fixed at a base pose.

        Joint k rotates link k relative to link k-1; links are capsules (segment of the link's length,
        radius = half its width). Non-adjacent links must not touch (self-collision); adjacent ones
        share a joint and always do. */
    class PlanarArm : public Robot
    {
      public:
        /** \brief Base at (\e baseX, \e baseY) facing \e baseYaw; one joint limit pair per link.
            Throws ompl::Exception on mismatched sizes or non-positive lengths/widths. */
        PlanarArm(std::string name, EnvironmentPtr environment, double baseX, double baseY, double baseYaw,
                  std::vector<double> linkLengths, double linkWidth, const ompl::base::RealVectorBounds &jointLimits);

        std::string getKind() const override { return "planar_arm"; }
        void computeCapsules(const double *q, CollisionBody &body) const override;

        double getBaseX() const { return baseX_; }
        double getBaseY() const { return baseY_; }
        double getBaseYaw() const { return baseYaw_; }
        const std::vector<double> &getLinkLengths() const { return linkLengths_; }
        double getLinkWidth() const { return linkWidth_; }

      private:
        double baseX_, baseY_, baseYaw_;
        std::vector<double> linkLengths_;
        double linkWidth_;
    };
}  // namespace ompl_parc

#endif
