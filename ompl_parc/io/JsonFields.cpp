#include "ompl_parc/io/JsonFields.h"

#include <ompl/util/Exception.h>

void ompl_parc::allowOnlyFields(const nlohmann::json &object, const std::set<std::string> &allowed,
                                const std::string &where, const char *context)
{
    for (const auto &entry : object.items())
        if (allowed.count(entry.key()) == 0)
            throw ompl::Exception(context, where + ": unknown field '" + entry.key() + "'");
}
