#ifndef OMPL_PARC_DEMOS_TOOL_SUPPORT_
#define OMPL_PARC_DEMOS_TOOL_SUPPORT_

#include "ompl_parc/model/MultiRobotProblem.h"

#include <boost/program_options.hpp>
#include <functional>
#include <string>
#include <utility>

namespace ompl_parc::tools
{
    /** \brief Exit codes shared by the command-line tools. */
    enum ExitCode
    {
        EXIT_SOLVED = 0,
        EXIT_FAILED = 1,
        EXIT_BAD_INPUT = 2,
        /** \brief Ended by Ctrl-C (SIGINT): 128 + 2, what a shell reports for a process a SIGINT ended. */
        EXIT_INTERRUPTED = 130
    };

    /** \brief Adds --scenario, --robots, --task and --scenario-file to \e options. */
    void addProblemOptions(boost::program_options::options_description &options);

    /** \brief Throws std::invalid_argument if both --scenario-file and one of --scenario/--robots/--task are given. */
    void checkProblemSource(const boost::program_options::variables_map &vm);

    /** \brief Builds the problem named by --scenario/--robots/--task, or read from --scenario-file, and checks
        its starts and goals; throws (std::invalid_argument, ompl::Exception) with a one-line reason on
        bad input. */
    MultiRobotProblem problemFromOptions(const boost::program_options::variables_map &vm);

    /** \brief An OMPL property key "name TYPE" ("conflicts INTEGER", as in PlannerData and Benchmark run properties)
        split into its name and its type ("" where the key has none). */
    std::pair<std::string, std::string> splitPropertyKey(const std::string &key);

    /** \brief "ompl_parc VERSION (OMPL VERSION)", what --version prints. */
    std::string versionLine();

    /** \brief Parses \e argc/\e argv into a variables map (throws on unknown or malformed options). Every tool
        gets --help (prints \e options) and --version here: either answers and ends the tool (inside runTool())
        with exit code 0. */
    boost::program_options::variables_map parse(
        int argc, char **argv, const boost::program_options::options_description &options,
        const boost::program_options::positional_options_description &positional = {});

    /** \brief Writes "tool: message" and a line break to stderr in one write, after flushing stdout: where both
        streams land in one file (a terminal, `2>&1`, mpirun forwarding each separately) the line never comes out
        split by, or into, the tool's other output. */
    void printError(const std::string &tool, const std::string &message);

    /** \brief Runs \e body, turning any exception into a one-line "tool: reason" on stderr and exit code 2
        (after --help or --version: exit code 0). */
    int runTool(const std::string &tool, const std::function<int()> &body);
}  // namespace ompl_parc::tools

#endif
