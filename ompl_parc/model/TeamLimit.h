#ifndef OMPL_PARC_MODEL_TEAM_LIMIT_
#define OMPL_PARC_MODEL_TEAM_LIMIT_

#include <cstddef>
#include <string>

namespace ompl_parc
{
    /** \brief The largest team ompl_parc accepts, wherever a team comes from (a team, a built-in scenario, a scenario
        file, the tools, the Python module). Memory is not what bounds it (the planners' bookkeeping grows with the
        team and the pairs that meet: Mobile Cross 20 000 peaks at about 230 MB) but time outside the planning: OMPL
        keeps every state space in one list, which each space's destructor searches, so that dropping a team of n
        robots takes O(n^2) (6 s at 20 000 robots, minutes at 100 000). */
    constexpr std::size_t MAX_ROBOTS = 20000;

    /** \brief Throws std::invalid_argument "WHAT: a team of N robots is over the limit of MAX_ROBOTS" if \e robots
        is over MAX_ROBOTS; called before anything is built for the team. */
    void checkTeamSize(std::size_t robots, const std::string &what);
}  // namespace ompl_parc

#endif
