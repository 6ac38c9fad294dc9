#include "ompl_parc/util/SeededRealVectorSampler.h"

ompl_parc::SeededRealVectorSampler::SeededRealVectorSampler(const ompl::base::StateSpace *space,
                                                            std::uint_fast32_t seed)
    : ompl::base::RealVectorStateSampler(space)
{
    rng_.setLocalSeed(seed);
}

ompl::base::StateSamplerAllocator ompl_parc::SeededRealVectorSampler::allocator(std::uint_fast32_t seed)
{
    auto counter = std::make_shared<std::atomic<std::uint64_t>>(0);
    return [seed, counter](const ompl::base::StateSpace *space) -> ompl::base::StateSamplerPtr
    { return std::make_shared<SeededRealVectorSampler>(space, mixSeed(seed, (*counter)++)); };
}

std::uint_fast32_t ompl_parc::mixSeed(std::uint64_t a, std::uint64_t b)
{
    std::uint64_t z = a * 0x9E3779B97F4A7C15ULL + b + 0x632BE59BD9B4E019ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    const auto seed = static_cast<std::uint_fast32_t>(z & 0xFFFFFFFFULL);
    return seed == 0 ? 1 : seed;  // OMPL treats seed 0 as "unset"
}
