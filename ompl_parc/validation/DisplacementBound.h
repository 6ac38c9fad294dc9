#ifndef OMPL_PARC_DISPLACEMENT_BOUND_
#define OMPL_PARC_DISPLACEMENT_BOUND_

#include "ompl_parc/robots/Robot.h"

#include <vector>

namespace ompl_parc
{
    /** \brief A sound bound on how far any point of a robot's body moves on a straight motion in configuration
        space: the validator's argument for what happens between the configurations it samples.

        On the straight motion q(s) = q + s dq, s in [0, 1], no body point moves more than bound(dq) (and no more
        than |s1 - s0| bound(dq) between s0 and s1: the bound is one on the speed). For a disc the body translates
        with its centre, bound = |dq|. For an arm of revolute joints, joint k turns every point beyond it about an
        axis through the joint, at speed |dq_k| times the point's distance from that axis; summed over joints,
        bound = sum_k |dq_k| lever_k, where lever_k bounds the distance from joint k to any body point it moves
        over all configurations: the chain of (rigid, configuration-independent) joint-to-joint distances out to
        the capsule's link plus the capsule's reach from its link frame (its end point distance plus radius). A
        prismatic joint moves every point beyond it at |dq_k| exactly (lever 1), and lengthens the joint-to-joint
        distances beyond it by at most its largest travel within the bounds; a mimic joint adds its |multiplier|
        times its own lever to the lever of the coordinate it follows. */
    class DisplacementBound
    {
      public:
        /** \brief Throws std::invalid_argument for a robot kind without a known bound (only discs, planar
            arms and URDF arms have one). */
        explicit DisplacementBound(const Robot &robot);

        /** \brief Largest distance any body point moves on the straight motion by \e dq. */
        double operator()(const double *dq) const;

        /** \brief True if the body translates rigidly with the first two coordinates (a disc). */
        bool isTranslation() const { return levers_.empty(); }

        /** \brief Per coordinate, the lever (empty for a translation). */
        const std::vector<double> &getLevers() const { return levers_; }

        /** \brief Largest distance any point of capsule \e capsule of the body (CollisionBody order) moves on the
            straight motion by \e dq: the same sum with only the joints that move that capsule, each with that
            capsule's lever. Never above operator(); 0 for a capsule no joint moves (an arm's base). */
        double capsuleBound(std::size_t capsule, const double *dq) const;

      private:
        std::vector<double> levers_;
        /** \brief Per capsule and coordinate, the capsule's lever (0: the joint does not move it); empty for a
            translation. */
        std::vector<std::vector<double>> capsuleLevers_;
    };
}  // namespace ompl_parc

#endif
