#ifndef OMPL_PARC_FLOAT_BOUNDS_
#define OMPL_PARC_FLOAT_BOUNDS_

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_parc
{
    /** \brief A double rounded to single precision downwards, past the conversion's error: the result is never above
        \e x, so boxes built from such bounds always contain the double-precision shapes.

        The conversion moves a value by at most 2^-24 of it; the widening by 2^-20 of it (plus a normal float's
        worth, for values near zero) covers that and the rounding of the widening itself, with room to spare for
        the exact tests' own rounding. Values are clamped to the float range first; at its ends the widening
        overflows to the infinity on the safe side. Branch-free, so that loops over capsules vectorise. */
    inline float roundedDown(double x)
    {
        constexpr double largest = std::numeric_limits<float>::max();
        const float f = static_cast<float>(std::min(std::max(x, -largest), largest));
        return f - (std::fabs(f) * 0x1p-20f + 1e-30f);
    }

    /** \brief A double rounded to single precision upwards, never below \e x (see roundedDown()). */
    inline float roundedUp(double x)
    {
        constexpr double largest = std::numeric_limits<float>::max();
        const float f = static_cast<float>(std::min(std::max(x, -largest), largest));
        return f + (std::fabs(f) * 0x1p-20f + 1e-30f);
    }
}  // namespace ompl_parc

#endif
