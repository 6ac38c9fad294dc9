#include "ompl_parc/planners/setup/PlannerRegistry.h"

#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/EPRRTConnect.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/ORPPSTRRT.h"
#include "ompl_parc/planners/ORRRTConnect.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/util/NameList.h"
#include "ompl_parc/util/ParseNumber.h"

#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>

namespace ob = ompl::base;

namespace
{
    /** The bounds of a declared numeric parameter range "lo:step:hi" (or "lo:hi"), if \e range is one. */
    std::optional<std::pair<double, double>> numericRange(const std::string &range)
    {
        const auto first = range.find(':'), last = range.rfind(':');
        if (first == std::string::npos)
            return std::nullopt;
        char *end = nullptr;
        const double lo = std::strtod(range.c_str(), &end);
        if (end != range.c_str() + first)
            return std::nullopt;
        const double hi = std::strtod(range.c_str() + last + 1, &end);
        if (end == range.c_str() + last + 1 || *end != '\0')
            return std::nullopt;
        return std::make_pair(lo, hi);
    }

    template <typename P>
    ob::PlannerAllocator allocator()
    {
        return [](const ob::SpaceInformationPtr &si) { return std::make_shared<P>(si); };
    }

    const std::map<std::string, ob::PlannerAllocator> &planners()
    {
        static const std::map<std::string, ob::PlannerAllocator> table = {
            {"arc", allocator<ompl_parc::ARC>()},
            {"parc", allocator<ompl_parc::PARC>()},
            {"orparc", allocator<ompl_parc::ORPARC>()},
            {"pp-st-rrt", allocator<ompl_parc::PrioritizedSTRRT>()},
            {"rrtconnect", allocator<ompl::geometric::RRTConnect>()},
            {"or-rrt-c", allocator<ompl_parc::ORRRTConnect>()},
            {"ep-rrt-c", allocator<ompl_parc::EPRRTConnect>()},
            // OR-EP-RRT-C is ORRRTConnect with EP-RRT-C instances: two workers each unless configured.
            {"or-ep-rrt-c",
             [](const ob::SpaceInformationPtr &si)
             {
                 auto planner = std::make_shared<ompl_parc::ORRRTConnect>(si);
                 planner->setName("OREPRRTConnect");
                 planner->setWorkers(2);
                 return planner;
             }},
            {"or-pp-st-rrt", allocator<ompl_parc::ORPPSTRRT>()},
        };
        return table;
    }

    /** \e name in lower case without '-' and '_': the form names are compared in. */
    std::string folded(const std::string &name)
    {
        std::string out;
        for (char c : name)
            if (c != '-' && c != '_')
                out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return out;
    }

}  // namespace

std::vector<std::string> ompl_parc::PlannerRegistry::names()
{
    std::vector<std::string> names;
    for (const auto &entry : planners())
        names.push_back(entry.first);
    return names;
}

std::string ompl_parc::PlannerRegistry::canonicalName(const std::string &name)
{
    for (const auto &entry : planners())
        if (folded(entry.first) == folded(name))
            return entry.first;
    throw std::invalid_argument("unknown planner '" + name + "' (valid: " + listNames(names()) + ")");
}

ob::PlannerPtr ompl_parc::PlannerRegistry::create(const std::string &name, const ob::SpaceInformationPtr &si,
                                                  const std::vector<std::string> &params)
{
    auto planner = planners().at(canonicalName(name))(si);
    // A named profile first, so that the parameters given with it override its values whatever their order.
    std::vector<std::string> ordered(params);
    std::stable_partition(ordered.begin(), ordered.end(),
                          [](const std::string &assignment) { return assignment.rfind("profile=", 0) == 0; });
    for (const auto &assignment : ordered)
    {
        const auto eq = assignment.find('=');
        if (eq == std::string::npos)
            throw std::invalid_argument("a planner parameter needs key=value, got '" + assignment + "'");
        setParameter(*planner, assignment.substr(0, eq), assignment.substr(eq + 1));
    }
    return planner;
}

void ompl_parc::PlannerRegistry::setParameter(ob::Planner &planner, const std::string &key, const std::string &value)
{
    if (!planner.params().hasParam(key))
    {
        std::vector<std::string> valid;
        planner.params().getParamNames(valid);
        throw std::invalid_argument("planner '" + planner.getName() + "' has no parameter '" + key +
                                    "' (valid: " + listNames(valid) + ")");
    }
    if (const auto range = numericRange(planner.params().getParams().at(key)->getRangeSuggestion()))
        parseReal(value, "parameter '" + key + "'", range->first, range->second);
    bool set = false;
    try
    {
        set = planner.params().setParam(key, value);
    }
    catch (const std::exception &e)  // a setter's own check (ompl::Exception)
    {
        throw std::invalid_argument("bad value '" + value + "' for parameter '" + key + "': " + e.what());
    }
    if (!set)
        throw std::invalid_argument("bad value '" + value + "' for parameter '" + key + "'");
}

const ompl_parc::ArcProgress *ompl_parc::PlannerRegistry::progressOf(const ob::Planner &planner)
{
    if (const auto *arc = dynamic_cast<const ArcPlannerBase *>(&planner))
        return &arc->getProgress();
    if (const auto *orparc = dynamic_cast<const ORPARC *>(&planner))
        return &orparc->getProgress();
    return nullptr;
}

ompl_parc::MultiRobotPlan ompl_parc::PlannerRegistry::planOf(const ob::Planner &planner,
                                                             const MultiRobotSpaceInformationPtr &si, bool simplify)
{
    if (const auto *arc = dynamic_cast<const ArcPlannerBase *>(&planner))
        return arc->getPlan();
    if (const auto *orparc = dynamic_cast<const ORPARC *>(&planner))
        return orparc->getPlan();
    if (const auto *prioritized = dynamic_cast<const PrioritizedSTRRT *>(&planner))
        return prioritized->getPlan();
    auto &path = *planner.getProblemDefinition()->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    if (simplify)
        ompl::geometric::PathSimplifier(si).simplify(path, 1.0);
    return MultiRobotPlan::fromPathGeometric(*si, path);
}
