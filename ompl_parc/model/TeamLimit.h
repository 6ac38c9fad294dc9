#ifndef OMPL_PARC_MODEL_TEAM_LIMIT_
#define OMPL_PARC_MODEL_TEAM_LIMIT_

#include <cstddef>
#include <string>

namespace ompl_parc
{
    /** \brief The largest team ompl_parc accepts, wherever a team comes from (a team, a built-in scenario, a scenario
        file, the tools, the Python module): the planners' bookkeeping grows with the team and the pairs that meet,
        about 10 KB per robot of a well-separated team, so that the largest team loads and plans in about 1 GB. */
    constexpr std::size_t MAX_ROBOTS = 100000;

    /** \brief Throws std::invalid_argument "WHAT: a team of N robots is over the limit of MAX_ROBOTS" if \e robots
        is over MAX_ROBOTS; called before anything is built for the team. */
    void checkTeamSize(std::size_t robots, const std::string &what);
}  // namespace ompl_parc

#endif
