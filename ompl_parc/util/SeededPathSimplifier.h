#ifndef OMPL_PARC_SEEDED_PATH_SIMPLIFIER_
#define OMPL_PARC_SEEDED_PATH_SIMPLIFIER_

#include <ompl/geometric/PathSimplifier.h>

#include <cstdint>

namespace ompl_parc
{
    /** \brief OMPL's PathSimplifier with its random shortcuts drawn from a given seed, so that simplifying
        inside a planning task is as reproducible as the task itself (see SeededRealVectorSampler). */
    class SeededPathSimplifier : public ompl::geometric::PathSimplifier
    {
      public:
        SeededPathSimplifier(const ompl::base::SpaceInformationPtr &si, std::uint_fast32_t seed)
            : ompl::geometric::PathSimplifier(si)
        {
            rng_.setLocalSeed(seed);
        }
    };
}  // namespace ompl_parc

#endif
