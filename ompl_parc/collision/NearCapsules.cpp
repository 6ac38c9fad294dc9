#include "ompl_parc/collision/NearCapsules.h"

#include <xsimd/xsimd.hpp>

#include <algorithm>

namespace
{
    using Lanes = xsimd::batch<float>;
    constexpr std::size_t LANES = Lanes::size;
    static_assert(ompl_parc::NearCapsules::CHUNK % LANES == 0, "a chunk must be whole SIMD vectors");
}  // namespace

ompl_parc::NearCapsules::NearCapsules(const CollisionBody &body, std::size_t base, const std::array<float, 3> &boxLo,
                                      const std::array<float, 3> &boxHi)
{
    if (body.isSingleSphere())  // it keeps no boxes: its own box is its only capsule's
    {
        std::array<float, 3> lo, hi;
        body.getBox(lo, hi);
        index_[0] = 0;
        bool overlap = true;
        for (std::size_t d = 0; d < 3; ++d)
        {
            lo_[d][0] = lo[d];
            hi_[d][0] = hi[d];
            overlap = overlap && lo[d] <= boxHi[d] && boxLo[d] <= hi[d];
        }
        count_ = overlap ? 1 : 0;
        return;
    }
    const std::size_t stride = body.boxStride_, end = std::min(stride, base + CHUNK);
    const float *boxes = body.boxes_.data();
    const Lanes l0(boxLo[0]), l1(boxLo[1]), l2(boxLo[2]), h0(boxHi[0]), h1(boxHi[1]), h2(boxHi[2]);
    alignas(64) float overlaps[LANES];
    for (std::size_t v = base; v < end; v += LANES)  // a vector of capsules per step; NaN padding never overlaps
    {
        const float *p = boxes + v;
        const auto overlap = (Lanes::load_unaligned(p) <= h0) & (Lanes::load_unaligned(p + 3 * stride) >= l0) &
                             (Lanes::load_unaligned(p + stride) <= h1) & (Lanes::load_unaligned(p + 4 * stride) >= l1) &
                             (Lanes::load_unaligned(p + 2 * stride) <= h2) &
                             (Lanes::load_unaligned(p + 5 * stride) >= l2);
        if (xsimd::none(overlap))  // the common case: far from the box
            continue;
        xsimd::select(overlap, Lanes(1.f), Lanes(0.f)).store_aligned(overlaps);
        // Branch-free compaction: each capsule is written to the next free slot, which only advances for an
        // overlapping one.
        for (std::size_t k = 0; k < LANES; ++k)
        {
            index_[count_] = v + k;
            for (std::size_t d = 0; d < 3; ++d)
            {
                lo_[d][count_] = p[d * stride + k];
                hi_[d][count_] = p[(3 + d) * stride + k];
            }
            count_ += overlaps[k] != 0.f ? 1 : 0;
        }
    }
}
