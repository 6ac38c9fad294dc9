#ifndef OMPL_PARC_DEMOS_PYTHON_INTERRUPT_SCOPE_
#define OMPL_PARC_DEMOS_PYTHON_INTERRUPT_SCOPE_

namespace ompl_parc::python
{
    /** \brief Ctrl-C during a solve from Python: while the GIL is released, Python's own SIGINT handler only sets a
        flag that nobody reads until the solve returns. From the first scope to the last (solves on several Python
        threads share it), a handler of ours is in place, and Python's is put back after the last; the solves'
        termination conditions poll fired(), so the planners stop promptly and join their workers, and the callers
        raise KeyboardInterrupt. Construct it with the GIL held: it raises a Ctrl-C that came just before (Python's
        pending signal) as KeyboardInterrupt (pybind11::error_already_set). Where SIGINT is ignored (SIG_IGN),
        or away from Python's main thread (where Python never handles signals), it changes nothing. */
    class InterruptScope
    {
      public:
        InterruptScope();
        ~InterruptScope();
        InterruptScope(const InterruptScope &) = delete;
        InterruptScope &operator=(const InterruptScope &) = delete;

        /** \brief Whether this scope listens for SIGINT (on Python's main thread, SIGINT not ignored). */
        bool listens() const { return counted_; }

        /** \brief Whether SIGINT arrived since the first of the current scopes began (stays set after the scopes
            end, until the next first scope); meaningful for a scope that listens(). */
        static bool fired();

      private:
        /** \brief Ends this scope's share: the last one puts Python's handler back. */
        void release();

        /** \brief Whether this scope counts among the current ones (not away from the main thread, not ignored). */
        bool counted_{false};
    };
}  // namespace ompl_parc::python

#endif
