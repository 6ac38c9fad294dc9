#ifndef OMPL_PARC_UTIL_PARSE_NUMBER_
#define OMPL_PARC_UTIL_PARSE_NUMBER_

#include <cstdint>
#include <string>

namespace ompl_parc
{
    /** \brief The largest task (instance) number a tool or benchmark configuration accepts. */
    constexpr std::uint64_t MAX_TASK = 1000000;

    /** \brief \e text as a whole number in [\e lo, \e hi], digits only: no sign, no fraction, no wrapping of
        negative numbers into huge ones (which std::stoul and OMPL's parameter parsing do). Throws
        std::invalid_argument "WHAT must be a whole number from LO to HI (got 'TEXT')" otherwise. The tools read
        their numeric options through it, the benchmark configuration its numbers. */
    std::uint64_t parseInteger(const std::string &text, const std::string &what, std::uint64_t lo, std::uint64_t hi);

    /** \brief \e text as a finite number in [\e lo, \e hi] (the whole text); throws std::invalid_argument
        "WHAT must be a number from LO to HI (got 'TEXT')" otherwise. */
    double parseReal(const std::string &text, const std::string &what, double lo, double hi);
}  // namespace ompl_parc

#endif
