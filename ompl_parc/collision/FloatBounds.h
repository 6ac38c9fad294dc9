#ifndef OMPL_PARC_FLOAT_BOUNDS_
#define OMPL_PARC_FLOAT_BOUNDS_

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_parc
{
    /** \brief A bound \e x rounded to single precision downwards, past the conversion's error and the error of the
        double-precision arithmetic that produced it: the result is never above \e x, so boxes built from such bounds
        always contain the double-precision shapes.

        \e scale is the magnitude of the numbers \e x was computed from (for a capsule's low bound min(a, b) - r:
        max(|a|, |b|) + r): a bound near zero computed from large numbers carries their rounding, not its own. The
        widening by 2^-20 of the larger of |x| and \e scale (plus a normal float's worth, for values near zero)
        covers the conversion (2^-24 of |x|), that arithmetic and the rounding of the widening itself, with room to
        spare for the exact tests' own rounding (about 2^-50 of the coordinates). Values are clamped to the float
        range first; at its ends the widening overflows to the infinity on the safe side. Branch-free, so that
        loops over capsules vectorise. */
    inline float roundedDown(double x, double scale)
    {
        constexpr double largest = std::numeric_limits<float>::max();
        const float f = static_cast<float>(std::min(std::max(x, -largest), largest));
        const float s = static_cast<float>(std::min(std::fabs(scale), largest));
        return f - (std::max(std::fabs(f), s) * 0x1p-20f + 1e-30f);
    }

    /** \brief A bound \e x rounded to single precision upwards, never below \e x (see roundedDown()). */
    inline float roundedUp(double x, double scale)
    {
        constexpr double largest = std::numeric_limits<float>::max();
        const float f = static_cast<float>(std::min(std::max(x, -largest), largest));
        const float s = static_cast<float>(std::min(std::fabs(scale), largest));
        return f + (std::max(std::fabs(f), s) * 0x1p-20f + 1e-30f);
    }
}  // namespace ompl_parc

#endif
