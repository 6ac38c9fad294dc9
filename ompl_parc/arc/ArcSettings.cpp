#include "ompl_parc/arc/ArcSettings.h"

#include "ompl_parc/model/MultiRobotSpaceInformation.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

ompl_parc::ArcSettings ompl_parc::ArcSettings::profile(const std::string &name)
{
    ArcSettings s;
    if (name == "mobile")
        return s;
    if (name == "planar" || name == "panda")
    {
        s.window = name == "planar" ? 100 : 20;
        s.growth = Growth::EXPONENTIAL;
        s.growthStep = 1.05;
        s.endpointStep = 10;
        s.boundMargin = 1.;
        s.minBoundRange = 0.5;
        s.sampleCap = 50000;
        if (name == "panda")
        {
            s.minWindowGrowth = 1.25;
            s.solvers = Solvers::COMPOSITE;
            s.sequential = true;
            s.shortenPatches = true;
        }
        return s;
    }
    throw ompl::Exception("ArcSettings", "unknown profile '" + name + "' (valid: mobile, planar, panda)");
}

void ompl_parc::ArcSettings::applyProfile(const std::string &name)
{
    const ArcSettings p = profile(name);
    const auto take = [this](Field field, auto &mine, const auto &theirs)
    {
        if ((explicitFields & field) == 0)
            mine = theirs;
    };
    take(WINDOW, window, p.window);
    take(GROWTH, growth, p.growth);
    take(GROWTH_STEP, growthStep, p.growthStep);
    take(MIN_WINDOW_GROWTH, minWindowGrowth, p.minWindowGrowth);
    take(ENDPOINT_STEP, endpointStep, p.endpointStep);
    take(BOUND_MARGIN, boundMargin, p.boundMargin);
    take(MIN_BOUND_RANGE, minBoundRange, p.minBoundRange);
    take(SAMPLE_CAP, sampleCap, p.sampleCap);
    take(SOLVERS, solvers, p.solvers);
    take(SIMPLIFY_INITIAL, simplifyInitial, p.simplifyInitial);
    take(SHORTEN_PATCHES, shortenPatches, p.shortenPatches);
    take(STRAIGHT_INITIAL, straightInitial, p.straightInitial);
    take(LATTICE_MAPF, latticeMapf, p.latticeMapf);
    take(SEQUENTIAL, sequential, p.sequential);
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
