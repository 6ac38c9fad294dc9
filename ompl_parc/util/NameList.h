#ifndef OMPL_PARC_UTIL_NAME_LIST_
#define OMPL_PARC_UTIL_NAME_LIST_

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief "a, b, c": the valid choices an error message lists ("unknown planner 'x' (valid: a, b, c)"). */
    std::string listNames(const std::vector<std::string> &names);
}  // namespace ompl_parc

#endif
