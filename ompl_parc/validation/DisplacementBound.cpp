#include "ompl_parc/validation/DisplacementBound.h"

#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/robots/UrdfArm.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace
{
    /** Per capsule (link j) and joint k: joint k turns link k and everything after it about the link's start; any
        point of link j >= k is within the link lengths k..j plus the half width of the joint. */
    std::vector<std::vector<double>> planarArmLevers(const ompl_parc::PlanarArm &arm)
    {
        const auto &lengths = arm.getLinkLengths();
        std::vector<std::vector<double>> levers(lengths.size(), std::vector<double>(lengths.size(), 0.));
        for (std::size_t j = 0; j < lengths.size(); ++j)
            for (std::size_t k = 0; k <= j; ++k)
                levers[j][k] = std::accumulate(lengths.begin() + static_cast<std::ptrdiff_t>(k),
                                               lengths.begin() + static_cast<std::ptrdiff_t>(j) + 1, 0.) +
                               0.5 * arm.getLinkWidth();
        return levers;
    }

    /** Joint k of the arm moves frame k + 1 and every frame below it, turning them about an axis through o_{k+1}
        (frame origins o) or sliding them along it. Per unit of joint k's value, a point p of a capsule on frame
        f below it moves by at most |p - o_{k+1}| if the joint turns and by exactly 1 if it slides. |p - o_{k+1}|
        is at most the capsule's farther end's distance from o_f plus its radius (rigid in frame f: measured at the
        zero configuration, the same everywhere) plus, for each frame j on the way from f up to k + 2,
        |o_j - o_{parent(j)}|: the joint's origin offset plus, for a prismatic joint, its largest travel within
        the bounds (the same at every configuration for a revolute joint). A coordinate changes a joint's value
        by |multiplier| times its own change (mimic joints), summed over the joints it drives. Per capsule and
        coordinate. */
    std::vector<std::vector<double>> urdfArmLevers(const ompl_parc::UrdfArm &arm)
    {
        const std::vector<double> zero(arm.getDimension(), 0.);
        std::vector<Eigen::Isometry3d> frames;
        arm.computeFrames(zero.data(), frames);
        ompl_parc::CollisionBody body;
        arm.computeBody(zero.data(), body);
        const auto &joints = arm.getJoints();
        std::vector<double> links;  // per joint k, the most |o_{k+1} - o_{parent}| can be
        for (const auto &joint : joints)
            links.push_back(joint.origin.translation().norm() +
                            (joint.prismatic ? arm.getLargestJointValue(joint) : 0.));
        std::vector<std::vector<double>> levers(body.size(), std::vector<double>(arm.getDimension(), 0.));
        for (std::size_t c = 0; c < body.size(); ++c)
        {
            const std::size_t f = arm.getPrimitives()[c].frame;
            const Eigen::Vector3d &o = frames[f].translation();
            // The most |p - o_frame| can be for the points p of the capsule, growing as the frames go up.
            double distance = std::max((Eigen::Vector3d(body.ax_[c], body.ay_[c], body.az_[c]) - o).norm(),
                                       (Eigen::Vector3d(body.bx_[c], body.by_[c], body.bz_[c]) - o).norm()) +
                              body.radius_[c];
            for (std::size_t frame = f; frame > 0; frame = joints[frame - 1].parent)
            {
                const auto &joint = joints[frame - 1];
                levers[c][joint.coordinate] += std::abs(joint.multiplier) * (joint.prismatic ? 1. : distance);
                distance += links[frame - 1];
            }
        }
        return levers;
    }
}  // namespace

ompl_parc::DisplacementBound::DisplacementBound(const Robot &robot)
{
    if (dynamic_cast<const DiscRobot *>(&robot) != nullptr)
        return;
    if (const auto *arm = dynamic_cast<const PlanarArm *>(&robot))
        capsuleLevers_ = planarArmLevers(*arm);
    else if (const auto *urdf = dynamic_cast<const UrdfArm *>(&robot))
        capsuleLevers_ = urdfArmLevers(*urdf);
    else
        throw std::invalid_argument("SolutionValidator: no displacement bound for robot '" + robot.getName() +
                                    "' of kind '" + robot.getKind() + "'");
    // The whole body's lever of a joint: the largest of its capsules'.
    levers_.assign(robot.getDimension(), 0.);
    for (const auto &capsule : capsuleLevers_)
        for (std::size_t k = 0; k < levers_.size(); ++k)
            levers_[k] = std::max(levers_[k], capsule[k]);
}

double ompl_parc::DisplacementBound::capsuleBound(std::size_t capsule, const double *dq) const
{
    if (capsuleLevers_.empty())
        return std::hypot(dq[0], dq[1]);
    double bound = 0.;
    for (std::size_t k = 0; k < levers_.size(); ++k)
        bound += std::abs(dq[k]) * capsuleLevers_[capsule][k];
    return bound;
}

double ompl_parc::DisplacementBound::operator()(const double *dq) const
{
    if (levers_.empty())
        return std::hypot(dq[0], dq[1]);
    double bound = 0.;
    for (std::size_t k = 0; k < levers_.size(); ++k)
        bound += std::abs(dq[k]) * levers_[k];
    return bound;
}
