#include "ompl_parc/robots/RakeMotionValidator.h"

bool ompl_parc::RakeMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const
{
    // s1 is assumed valid, as in OMPL
    if (!si_->isValid(s2))
    {
        invalid_++;
        return false;
    }
    ompl::base::StateSpace &space = *si_->getStateSpace();  // DiscreteMotionValidator keeps its own private
    const unsigned int n = space.validSegmentCount(s1, s2);
    bool valid = true;
    if (n >= 2)
    {
        unsigned int stride = 1;
        while (2 * stride < n)
            stride *= 2;
        ompl::base::State *test = si_->allocState();
        for (; stride >= 1 && valid; stride /= 2)
            for (unsigned int j = stride; j < n && valid; j += 2 * stride)
            {
                space.interpolate(s1, s2, static_cast<double>(j) / static_cast<double>(n), test);
                valid = si_->isValid(test);
            }
        si_->freeState(test);
    }
    if (valid)
        valid_++;
    else
        invalid_++;
    return valid;
}
