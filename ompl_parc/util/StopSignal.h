#ifndef OMPL_PARC_UTIL_STOP_SIGNAL_
#define OMPL_PARC_UTIL_STOP_SIGNAL_

#include <ompl/base/PlannerTerminationCondition.h>

namespace ompl_parc
{
    /** \brief The termination condition of the planning the current thread does, for checks that OMPL calls
        without one: a motion check (StateSpace::validSegmentCount() steps, a billion at resolution 1e8) polls
        it every POLL_INTERVAL states and gives up (reports the motion invalid) once it fires, so solve()
        returns promptly whatever the resolution. A planner opens a Scope around its work in every thread it
        plans in; scopes nest (a capped subproblem call inside a solve), the innermost one is polled. Without
        a scope nothing is polled. */
    class StopSignal
    {
      public:
        /** \brief States checked between two polls. */
        static constexpr unsigned int POLL_INTERVAL = 4096;

        /** \brief Makes \e ptc this thread's condition until destroyed (then the previous one again). */
        class Scope
        {
          public:
            explicit Scope(const ompl::base::PlannerTerminationCondition &ptc);
            ~Scope();
            Scope(const Scope &) = delete;
            Scope &operator=(const Scope &) = delete;

          private:
            const ompl::base::PlannerTerminationCondition *previous_;
        };

        /** \brief True if this thread's current condition (if any) has fired. */
        static bool raised();
    };
}  // namespace ompl_parc

#endif
