#ifndef OMPL_PARC_DEMOS_INTERRUPTION_
#define OMPL_PARC_DEMOS_INTERRUPTION_

#include <ompl/base/PlannerTerminationCondition.h>

#include <string>

namespace ompl_parc::tools
{
    /** \brief Ctrl-C (SIGINT) for a command-line tool, so that an interrupted run still reports what it has. From
        construction to destruction a handler of ours is in place. With FirstSignal::STOP the first SIGINT only
        raises a flag (lock-free, async-signal-safe) and writes "TOOL: interrupted, stopping (...)" to stderr; the
        tool ORs condition() into its planners' termination conditions, so a solve returns promptly through its
        normal path, every worker joined, and the tool prints its summary and exits with EXIT_INTERRUPTED (130, as
        a shell reports a SIGINT). A second SIGINT ends the process at once (_exit(130), nothing flushed): the way
        out of a stop that takes too long. With FirstSignal::EXIT (a tool with nothing to report half-way) the
        first SIGINT already ends it, after the line "TOOL: interrupted".

        A SIGINT ignored when the tool starts (a background job of a non-interactive shell, nohup) stays ignored,
        as shells expect of their jobs: then nothing changes. SIGTERM keeps its default action: it is what
        process managers, `timeout` and mpirun send to end a process, and they expect it to end. One instance at a
        time per process. */
    class Interruption
    {
      public:
        /** \brief What the first SIGINT does. */
        enum class FirstSignal
        {
            STOP,  ///< raise the flag: the tool stops its work and reports
            EXIT   ///< end the process at once with one line
        };

        /** \brief Installs the handler (unless SIGINT is ignored) for \e tool, the name its lines start with;
            \e stopping says what the first SIGINT does (FirstSignal::STOP). */
        explicit Interruption(const std::string &tool, FirstSignal first = FirstSignal::STOP,
                              const std::string &stopping = "stopping");
        /** \brief Puts the previous action back. */
        ~Interruption();
        Interruption(const Interruption &) = delete;
        Interruption &operator=(const Interruption &) = delete;

        /** \brief Whether a SIGINT arrived since construction. */
        static bool raised();

        /** \brief A termination condition that fires once a SIGINT arrived, to OR into a planner's (it only reads an
            atomic flag: cheap to poll from any thread). */
        static ompl::base::PlannerTerminationCondition condition();

      private:
        /** \brief Whether the handler is ours to remove (not where SIGINT was ignored at construction). */
        bool listens_{false};
    };
}  // namespace ompl_parc::tools

#endif
