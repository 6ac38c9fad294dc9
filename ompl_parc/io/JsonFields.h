#ifndef OMPL_PARC_IO_JSON_FIELDS_
#define OMPL_PARC_IO_JSON_FIELDS_

#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace ompl_parc
{
    /** \brief Throws ompl::Exception(\e context, "WHERE: unknown field 'KEY'") for the first field of \e object
        outside \e allowed: the file readers (scenarios, solutions) are strict, so a misspelt optional field is
        reported instead of silently ignored. */
    void allowOnlyFields(const nlohmann::json &object, const std::set<std::string> &allowed, const std::string &where,
                         const char *context);
}  // namespace ompl_parc

#endif
