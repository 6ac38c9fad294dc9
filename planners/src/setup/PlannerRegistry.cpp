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
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
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

    /** \e text in lower case. */
    std::string lowered(const std::string &text)
    {
        std::string out;
        for (char c : text)
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return out;
    }

    /** \e value checked against \e parameter's type and declared range, in the form OMPL's own parser reads
        unambiguously. OMPL's parser takes any text but "0", "false" and "" as true, wraps "-1" into 4294967295
        and truncates "2.5" to 2; here a truth value is one of 1/0, true/false, on/off, yes/no (any case), a whole
        number's text is digits only within its type and range, a real number's finite and within its range. */
    std::string checkedValue(const ob::GenericParam &parameter, const std::string &key, const std::string &value)
    {
        const std::string what = "parameter '" + key + "'";
        const auto range = numericRange(parameter.getRangeSuggestion());
        if (dynamic_cast<const ob::SpecificParam<bool> *>(&parameter) != nullptr)
        {
            const std::string v = lowered(value);
            if (v == "1" || v == "true" || v == "on" || v == "yes")
                return "1";
            if (v == "0" || v == "false" || v == "off" || v == "no")
                return "0";
            throw std::invalid_argument(what + " must be 1/0, true/false, on/off or yes/no (got '" + value + "')");
        }
        const auto whole = [&](std::uint64_t hi)
        {
            std::uint64_t lo = 0;
            if (range)
            {
                lo = static_cast<std::uint64_t>(std::max(0., std::ceil(range->first)));
                hi = std::min<std::uint64_t>(hi, static_cast<std::uint64_t>(std::max(0., std::floor(range->second))));
            }
            return std::to_string(ompl_parc::parseInteger(value, what, lo, hi));
        };
        if (dynamic_cast<const ob::SpecificParam<unsigned int> *>(&parameter) != nullptr)
            return whole(std::numeric_limits<unsigned int>::max());
        if (dynamic_cast<const ob::SpecificParam<unsigned long> *>(&parameter) != nullptr)
            return whole(std::numeric_limits<unsigned long>::max());
        if (dynamic_cast<const ob::SpecificParam<double> *>(&parameter) != nullptr ||
            dynamic_cast<const ob::SpecificParam<float> *>(&parameter) != nullptr)
        {
            const double lo = range ? range->first : -std::numeric_limits<double>::max();
            const double hi = range ? range->second : std::numeric_limits<double>::max();
            ompl_parc::parseReal(value, what, lo, hi);
            return value;
        }
        if (dynamic_cast<const ob::SpecificParam<int> *>(&parameter) != nullptr)
        {
            // A signed parameter: the sign apart, the same digits-only reading.
            const bool negative = !value.empty() && value[0] == '-';
            const std::string digits = negative ? value.substr(1) : value;
            const double lo = range ? range->first : std::numeric_limits<int>::min();
            const double hi = range ? range->second : std::numeric_limits<int>::max();
            const auto magnitude = ompl_parc::parseInteger(digits, what, 0, static_cast<std::uint64_t>(1) << 31);
            const double number = negative ? -static_cast<double>(magnitude) : static_cast<double>(magnitude);
            if (number < lo || number > hi)
                throw std::invalid_argument(what + " must be a whole number from " + std::to_string(lo) + " to " +
                                            std::to_string(hi) + " (got '" + value + "')");
            return value;
        }
        if (range)  // another type with a numeric range
            ompl_parc::parseReal(value, what, range->first, range->second);
        return value;
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
                out += c;
        return lowered(out);
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
    const std::string checked = checkedValue(*planner.params().getParams().at(key), key, value);
    bool set = false;
    try
    {
        set = planner.params().setParam(key, checked);
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
