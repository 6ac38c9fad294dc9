#ifndef OMPL_PARC_DEMOS_PYTHON_INTERRUPT_SCOPE_
#define OMPL_PARC_DEMOS_PYTHON_INTERRUPT_SCOPE_

#include <csignal>

namespace ompl_parc::python
{
    /** \brief Ctrl-C during a solve from Python: while the GIL is released, Python's own SIGINT handler only sets a
        flag that nobody reads until the solve returns. For its lifetime this scope puts a handler of its own in
        place (restoring Python's at the end); the solve's termination condition polls fired(), so the planner
        stops promptly, joins its workers, and the caller raises KeyboardInterrupt. */
    class InterruptScope
    {
      public:
        InterruptScope();
        ~InterruptScope();
        InterruptScope(const InterruptScope &) = delete;
        InterruptScope &operator=(const InterruptScope &) = delete;

        /** \brief Whether SIGINT arrived since the scope began. */
        static bool fired();

      private:
        struct sigaction previous_;
    };
}  // namespace ompl_parc::python

#endif
