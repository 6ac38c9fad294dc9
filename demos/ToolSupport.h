#ifndef OMPL_PARC_DEMOS_TOOL_SUPPORT_
#define OMPL_PARC_DEMOS_TOOL_SUPPORT_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <boost/program_options.hpp>
#include <ompl/base/Planner.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ompl_parc::tools
{
    /** \brief Exit codes shared by the command-line tools. */
    enum ExitCode
    {
        EXIT_SOLVED = 0,
        EXIT_FAILED = 1,
        EXIT_BAD_INPUT = 2
    };

    /** \brief The largest team a tool or benchmark config accepts: far above every built-in scenario's sizes
        (Planar Cross goes to 256, Mobile Cross runs at 1024), below what the pair bookkeeping of a team could
        not hold (about 24 bytes per robot pair). */
    constexpr std::uint64_t MAX_ROBOTS = 10000;
    /** \brief The largest task (instance) number a tool or benchmark config accepts. */
    constexpr std::uint64_t MAX_TASK = 1000000;

    /** \brief Adds --scenario, --robots, --task and --scenario-file to \e options. */
    void addProblemOptions(boost::program_options::options_description &options);

    /** \brief Builds the problem named by --scenario/--robots/--task, or read from --scenario-file, and checks
        its starts and goals; throws (std::invalid_argument, ompl::Exception) with a one-line reason on
        bad input. */
    MultiRobotProblem problemFromOptions(const boost::program_options::variables_map &vm);

    /** \brief The planners the tools can run, by name ("arc", "rrtconnect"). */
    std::vector<std::string> plannerNames();

    /** \brief Allocates planner \e name on \e si and applies \e params ("key=value", declared parameter
        names; a "profile" first, the others in the order given, so explicit values override the profile's);
        throws std::invalid_argument listing the valid names for an unknown planner or parameter. */
    ompl::base::PlannerPtr createPlanner(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                         const std::vector<std::string> &params);

    /** \brief Sets declared parameter \e key of \e planner to \e value; throws std::invalid_argument listing the
        valid names for an unknown key, naming the declared range for a number outside it (OMPL itself neither
        checks ranges nor refuses "-1" for an unsigned parameter), or for a value the parameter does not take. */
    void setPlannerParameter(ompl::base::Planner &planner, const std::string &key, const std::string &value);

    /** \brief The solution of \e planner (after a solve with an exact solution) on the timestep grid, as the
        validator checks it: ARC-family (OR-P-ARC included) and prioritised planners' own plans; a composite path
       (OMPL's planners and the coupled baselines) laid on the grid with MultiRobotPlan::fromPathGeometric, after one
       second of OMPL's shortcutting if \e simplify (the path in the ProblemDefinition is simplified in place). */
    MultiRobotPlan planOf(const ompl::base::Planner &planner, const MultiRobotSpaceInformationPtr &si, bool simplify);

    /** \brief \e text as a whole number in [\e lo, \e hi], digits only: no sign, no fraction, no wrapping of
        negative numbers into huge ones. Throws std::invalid_argument "WHAT must be a whole number from LO to HI
        (got 'TEXT')" otherwise. Numeric command-line options are declared as text and read through it. */
    std::uint64_t parseInteger(const std::string &text, const std::string &what, std::uint64_t lo, std::uint64_t hi);

    /** \brief \e text as a finite number in [\e lo, \e hi] (the whole text); throws std::invalid_argument
        "WHAT must be a number from LO to HI (got 'TEXT')" otherwise. */
    double parseReal(const std::string &text, const std::string &what, double lo, double hi);

    /** \brief Parses \e argc/\e argv into a variables map (throws on unknown or malformed options). */
    boost::program_options::variables_map parse(
        int argc, char **argv, const boost::program_options::options_description &options,
        const boost::program_options::positional_options_description &positional = {});

    /** \brief Runs \e body, turning any exception into a one-line "tool: reason" on stderr and exit code 2. */
    int runTool(const std::string &tool, const std::function<int()> &body);
}  // namespace ompl_parc::tools

#endif
