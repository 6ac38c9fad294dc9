#ifndef OMPL_PARC_SEEDED_REAL_VECTOR_SAMPLER_
#define OMPL_PARC_SEEDED_REAL_VECTOR_SAMPLER_

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <atomic>
#include <cstdint>
#include <memory>

namespace ompl_parc
{
    /** \brief OMPL's uniform real vector sampler with its own seed.

        OMPL seeds every sampler from one global sequence, so which seed a sampler gets depends on how many
        were created before it, in any thread. Our planners run many small planning tasks, possibly in
        parallel, and must give the same answer for the same seed: each task's spaces get an allocator
        (allocator()) that seeds its samplers from the task seed and a per-task counter. */
    class SeededRealVectorSampler : public ompl::base::RealVectorStateSampler
    {
      public:
        SeededRealVectorSampler(const ompl::base::StateSpace *space, std::uint_fast32_t seed);

        /** \brief A sampler allocator whose k-th sampler is seeded with a mix of \e seed and k. */
        static ompl::base::StateSamplerAllocator allocator(std::uint_fast32_t seed);
    };

    /** \brief Mixes two values into a well-spread 32-bit seed (SplitMix64 finaliser), so per-task and
        per-sampler seeds derived from one planner seed are unrelated streams. */
    std::uint_fast32_t mixSeed(std::uint64_t a, std::uint64_t b);
}  // namespace ompl_parc

#endif
