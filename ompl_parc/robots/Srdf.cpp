#include "ompl_parc/robots/Srdf.h"

#include "ompl_parc/util/TextFile.h"

#include <ompl/util/Exception.h>

#include <tinyxml.h>

namespace
{
    const char *const SRDF_CONTEXT = "Srdf";

    std::string attribute(const TiXmlElement &element, const char *name, const std::string &where)
    {
        const char *value = element.Attribute(name);
        if (value == nullptr || *value == '\0')
            throw ompl::Exception(SRDF_CONTEXT, "malformed SRDF: " + where + " has no " + name);
        return value;
    }
}  // namespace

ompl_parc::Srdf ompl_parc::Srdf::parse(const std::string &xml)
{
    TiXmlDocument document;
    document.Parse(xml.c_str());
    if (document.Error())
        throw ompl::Exception(SRDF_CONTEXT, "malformed SRDF: " + std::string(document.ErrorDesc()) + " (line " +
                                                std::to_string(document.ErrorRow()) + ")");
    const TiXmlElement *robot = document.RootElement();
    if (robot == nullptr || robot->ValueStr() != "robot")
        throw ompl::Exception(SRDF_CONTEXT, "malformed SRDF: the root element is not <robot>");
    Srdf srdf;
    srdf.xml_ = xml;
    for (const TiXmlElement *e = robot->FirstChildElement("disable_collisions"); e != nullptr;
         e = e->NextSiblingElement("disable_collisions"))
    {
        const std::string a = attribute(*e, "link1", "a <disable_collisions>");
        const std::string b = attribute(*e, "link2", "a <disable_collisions>");
        srdf.disabled_.insert(a < b ? std::make_pair(a, b) : std::make_pair(b, a));
    }
    for (const TiXmlElement *g = robot->FirstChildElement("group"); g != nullptr; g = g->NextSiblingElement("group"))
    {
        const std::string name = attribute(*g, "name", "a <group>");
        const std::string where = "group '" + name + "'";
        const TiXmlElement *chain = g->FirstChildElement("chain");
        if (chain == nullptr)
        {
            if (srdf.groups_.count(name) != 0 || !srdf.otherGroups_.insert(name).second)
                throw ompl::Exception(SRDF_CONTEXT, "malformed SRDF: " + where + " is defined twice");
            continue;
        }
        if (chain->NextSiblingElement("chain") != nullptr)
            throw ompl::Exception(SRDF_CONTEXT, "malformed SRDF: " + where + " has more than one <chain>");
        const auto ends = std::make_pair(attribute(*chain, "base_link", where + "'s <chain>"),
                                         attribute(*chain, "tip_link", where + "'s <chain>"));
        if (srdf.otherGroups_.count(name) != 0 || !srdf.groups_.emplace(name, ends).second)
            throw ompl::Exception(SRDF_CONTEXT, "malformed SRDF: " + where + " is defined twice");
    }
    return srdf;
}

ompl_parc::Srdf ompl_parc::Srdf::read(const std::string &path)
{
    return parse(TextFile::read(path, SRDF_CONTEXT));
}

std::pair<std::string, std::string> ompl_parc::Srdf::getChain(const std::string &group) const
{
    const auto found = groups_.find(group);
    if (found != groups_.end())
        return found->second;
    std::string names;
    for (const auto &[name, ends] : groups_)
        names += (names.empty() ? "" : ", ") + name;
    const std::string chains = " (chain groups: " + (names.empty() ? std::string("none") : names) + ")";
    if (otherGroups_.count(group) != 0)
        throw ompl::Exception(SRDF_CONTEXT, "the SRDF's group '" + group + "' is not a <chain>: it cannot name an arm" +
                                                chains);
    throw ompl::Exception(SRDF_CONTEXT, "the SRDF has no group '" + group + "'" + chains);
}

std::set<std::string> ompl_parc::Srdf::getLinkNames() const
{
    std::set<std::string> links;
    for (const auto &[a, b] : disabled_)
        links.insert({a, b});
    for (const auto &[name, ends] : groups_)
        links.insert({ends.first, ends.second});
    return links;
}
