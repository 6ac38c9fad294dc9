#include "ompl_parc/util/NameList.h"

std::string ompl_parc::listNames(const std::vector<std::string> &names)
{
    std::string out;
    for (const auto &name : names)
        out += (out.empty() ? "" : ", ") + name;
    return out;
}
