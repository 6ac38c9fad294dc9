#ifndef OMPL_PARC_UTIL_INNER_PLANNER_LOG_
#define OMPL_PARC_UTIL_INNER_PLANNER_LOG_

namespace ompl_parc
{
    /** \brief Keeps the inner planners' chatter out of the log: every RRT-Connect of the initial stage and of the
        repairs, every ST-RRT* of a prioritised repair logs "Created N states" at INFO, hundreds of lines per solve
        that hide the planner's own stage lines.

        A Session (held by each solve of the ARC family and PP-ST-RRT, and MultiRobotSetup::simplify) puts a filter
        in front of OMPL's output handler; when the last Session ends, the handler and OMPL's "previous handler"
        (restorePreviousOutputHandler()) are as before the first began, unless someone installed a handler of
        their own meanwhile, which stays. The filter drops messages below warnings logged on a thread inside a Scope
        (held around each inner planner call), unless setShown(true) asked for them; everything else passes
        unchanged, warnings and errors always. */
    class InnerPlannerLog
    {
      public:
        /** \brief Shows the inner planners' INFO and DEBUG messages too (off by default; process-wide). */
        static void setShown(bool shown);
        static bool isShown();

        /** \brief Installs the filter for the duration of a solve (nested and concurrent Sessions share it). */
        class Session
        {
          public:
            Session();
            ~Session();
            Session(const Session &) = delete;
            Session &operator=(const Session &) = delete;
        };

        /** \brief Marks the calling thread as inside an inner planner call. */
        class Scope
        {
          public:
            Scope();
            ~Scope();
            Scope(const Scope &) = delete;
            Scope &operator=(const Scope &) = delete;
        };
    };
}  // namespace ompl_parc

#endif
