#include "ompl_parc/model/TeamLimit.h"

#include <stdexcept>

void ompl_parc::checkTeamSize(std::size_t robots, const std::string &what)
{
    if (robots > MAX_ROBOTS)
        throw std::invalid_argument(what + ": a team of " + std::to_string(robots) + " robots is over the limit of " +
                                    std::to_string(MAX_ROBOTS));
}
