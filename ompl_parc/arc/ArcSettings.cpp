#include "ompl_parc/arc/ArcSettings.h"

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

ompl_parc::ArcSettings ompl_parc::ArcSettings::profile(const std::string &name)
{
    const std::vector<std::string> names = profileNames();
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end())
        throw ompl::Exception("ArcSettings", "unknown profile '" + name + "' (valid: mobile, planar, panda)");
    const auto which = static_cast<std::size_t>(found - names.begin());  // ArcKnobs.def's column of the profile
    ArcSettings s;
#define OMPL_PARC_ARC_KNOB(Name, member, parameter, Type, Parameter, range, valid, otherwise, mobile, planar, panda) \
    {                                                                                                                  \
        const Type values[] = {mobile, planar, panda};                                                                 \
        s.member = values[which];                                                                                      \
    }
#include "ompl_parc/arc/ArcKnobs.def"
    return s;
}

void ompl_parc::ArcSettings::applyProfile(const std::string &name)
{
    const ArcSettings p = profile(name);
#define OMPL_PARC_ARC_KNOB(Name, member, ...)                                                                          \
    if (!isExplicit(Knob::member))                                                                                     \
        member = p.member;
#include "ompl_parc/arc/ArcKnobs.def"
}

std::string ompl_parc::ArcSettings::profileFor(const MultiRobotSpaceInformation &si)
{
    const auto any = [&si](const char *kind)
    {
        for (std::size_t i = 0; i < si.getRobotCount(); ++i)
            if (si.getRobot(i)->getKind() == kind)
                return true;
        return false;
    };
    if (any("urdf_arm"))
        return "panda";
    if (any("planar_arm"))
        return "planar";
    return "mobile";
}

ompl_parc::ArcSettings ompl_parc::ArcSettings::eager() const
{
    ArcSettings s = *this;
    if (s.minWindowGrowth >= EAGER_GROWTH)
        return s;
    if (s.sampleCap != 0)
        s.sampleCap = std::max(1000u, s.sampleCap / 4);
    s.minWindowGrowth = std::min(4., 2. * std::max(1., s.minWindowGrowth));
    return s;
}

std::vector<std::string> ompl_parc::ArcSettings::profileNames()
{
    return {"mobile", "planar", "panda"};
}

std::size_t ompl_parc::ArcSettings::halfWidth(unsigned int k) const
{
    if (k == 0)
        return window;
    const double extra = growth == Growth::LINEAR ? growthStep * k : growthStep * std::pow(2., k - 1.);
    return window + static_cast<std::size_t>(std::ceil(std::min(extra, 1e15)));
}

ompl_parc::ArcSettings::Growth ompl_parc::ArcSettings::growthFromString(const std::string &name)
{
    if (name == "linear")
        return Growth::LINEAR;
    if (name == "exponential")
        return Growth::EXPONENTIAL;
    throw ompl::Exception("ArcSettings", "unknown growth '" + name + "' (valid: linear, exponential)");
}

std::string ompl_parc::ArcSettings::toString(Growth growth)
{
    return growth == Growth::LINEAR ? "linear" : "exponential";
}

ompl_parc::ArcSettings::Solvers ompl_parc::ArcSettings::solversFromString(const std::string &name)
{
    if (name == "hierarchy")
        return Solvers::HIERARCHY;
    if (name == "composite")
        return Solvers::COMPOSITE;
    if (name == "prioritized")
        return Solvers::PRIORITIZED;
    if (name == "composite-first")
        return Solvers::COMPOSITE_FIRST;
    throw ompl::Exception("ArcSettings",
                          "unknown solvers '" + name + "' (valid: hierarchy, composite, prioritized, composite-first)");
}

std::string ompl_parc::ArcSettings::toString(Solvers solvers)
{
    switch (solvers)
    {
        case Solvers::HIERARCHY:
            return "hierarchy";
        case Solvers::COMPOSITE:
            return "composite";
        case Solvers::PRIORITIZED:
            return "prioritized";
        case Solvers::COMPOSITE_FIRST:
            return "composite-first";
    }
    return "";
}
