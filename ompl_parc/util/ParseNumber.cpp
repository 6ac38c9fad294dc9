#include "ompl_parc/util/ParseNumber.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

std::uint64_t ompl_parc::parseInteger(const std::string &text, const std::string &what, std::uint64_t lo,
                                      std::uint64_t hi)
{
    std::uint64_t value = 0;
    const char *end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || ptr != end || value < lo || value > hi)
        throw std::invalid_argument(what + " must be a whole number from " + std::to_string(lo) + " to " +
                                    std::to_string(hi) + " (got '" + text + "')");
    return value;
}

double ompl_parc::parseReal(const std::string &text, const std::string &what, double lo, double hi)
{
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < lo || value > hi)
    {
        std::ostringstream message;
        message << what << " must be a number from " << lo << " to " << hi << " (got '" << text << "')";
        throw std::invalid_argument(message.str());
    }
    return value;
}
