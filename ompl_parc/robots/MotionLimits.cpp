#include "ompl_parc/robots/MotionLimits.h"

#include <cmath>
#include <stdexcept>

namespace ompl_parc
{
    MotionLimits MotionLimits::perCoordinate(const std::vector<double> &velocity,
                                             const std::vector<double> &acceleration)
    {
        if (velocity.size() != acceleration.size())
            throw std::invalid_argument("MotionLimits: " + std::to_string(velocity.size()) + " velocity and " +
                                        std::to_string(acceleration.size()) + " acceleration limits");
        MotionLimits limits;
        for (std::size_t k = 0; k < velocity.size(); ++k)
            limits.groups.push_back({static_cast<unsigned int>(k), 1u, velocity[k], acceleration[k]});
        return limits;
    }

    std::string MotionLimits::check(unsigned int dimension) const
    {
        unsigned int next = 0;
        for (std::size_t g = 0; g < groups.size(); ++g)
        {
            const Group &group = groups[g];
            const std::string where = "group " + std::to_string(g) + ": ";
            if (group.first != next || group.count == 0)
                return where + "must start at coordinate " + std::to_string(next) + " and cover at least one";
            next += group.count;
            if (!std::isfinite(group.velocity) || !(group.velocity > 0.))
                return where + "velocity must be finite and > 0";
            if (!std::isfinite(group.acceleration) || !(group.acceleration > 0.))
                return where + "acceleration must be finite and > 0";
        }
        if (next != dimension)
            return "the groups cover " + std::to_string(next) + " coordinates, the robot has " +
                   std::to_string(dimension);
        return {};
    }
}  // namespace ompl_parc
