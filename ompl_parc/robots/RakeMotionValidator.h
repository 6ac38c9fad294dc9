#ifndef OMPL_PARC_RAKE_MOTION_VALIDATOR_
#define OMPL_PARC_RAKE_MOTION_VALIDATOR_

#include <ompl/base/DiscreteMotionValidator.h>

namespace ompl_parc
{
    /** \brief Checks a motion's samples far-apart first, without allocating per sample.

        The sample set is DiscreteMotionValidator's (the end state, then the fractions j / n for j = 1 .. n - 1,
        n = validSegmentCount(), one per timestep for our spaces), so plans stay valid at every timestep; only
        the order changes: the end state, then level by level of a bisection, stride = the largest power of two
        below n, then its halves, each level checking the odd multiples of its stride (like VAMP's rake, the first
        samples are spread over the whole motion, so a blocked motion is rejected after few checks). OMPL's
        validator visits the same bisection through a std::queue, allocating per motion; here the order is
        plain index arithmetic and the only allocation is one scratch state per motion.
        checkMotion(s1, s2, lastValid) must report the last valid state before the first invalid one, so it
        stays OMPL's sequential scan. */
    class RakeMotionValidator : public ompl::base::DiscreteMotionValidator
    {
      public:
        using ompl::base::DiscreteMotionValidator::checkMotion;
        using ompl::base::DiscreteMotionValidator::DiscreteMotionValidator;

        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    };
}  // namespace ompl_parc

#endif
