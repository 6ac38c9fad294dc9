#ifndef OMPL_PARC_HTML_WRITER_
#define OMPL_PARC_HTML_WRITER_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    /** \brief What HtmlWriter puts in a page. */
    struct HtmlOptions
    {
        /** \brief Per robot, the most keyframes added between its path's breakpoints where interpolating its capsules
            linearly would stray more than KEYFRAME_TOLERANCE x its thinnest capsule's radius (the breakpoints are
            kept whatever their number). */
        unsigned int maxKeyframes{400};
        static constexpr double KEYFRAME_TOLERANCE = 0.1;
        /** \brief Samples of each robot's tip trace (GeometryFile). */
        unsigned int traceSamples{200};
        /** \brief The closest robot-robot approaches listed and marked (ClosestApproaches), and the timesteps they
            are looked for at. */
        unsigned int closest{5};
        unsigned int approachSamples{1000};
    };

    /** \brief A plan as one self-contained, interactive 3D page: open it offline, mail it.

        The page (ompl_parc/io/viewer.html) draws the scene with three.js, which is inlined (Debian's libjs-three,
        compiled into the library): the obstacles; every robot's collision capsules (the shapes the checks use,
        Robot::computeBody, so every robot kind is drawn, and a URDF arm as its collision model), moving along the
        plan, in per-robot colours; start and goal ghosts; the tips' traces. Play, pause, speed, a time slider,
        orbit and zoom, and a list to show or hide robots. 2D problems (SvgWriter::isPlanar()) are drawn in the same
        viewer, discs as short cylinders and planar links as flat bars. The closest robot-robot approaches of the
        plan (ClosestApproaches) are marked by red segments and listed; a click jumps to that time. The address
        suffix "#t=SECONDS" opens the page paused at that time.

        Each robot's bodies are stored at its own timed keyframes (float32, base64) and interpolated in the page, as
        the solution file stores timed waypoints: its path's breakpoints, and between them as many more as keep the
        interpolated capsules within a tenth of their radius of the true ones (HtmlOptions), so a still robot costs
        two keyframes and an arm's curved sweep gets what it needs. Without a plan, the page shows the problem: starts
       and goals. */
    class HtmlWriter
    {
      public:
        /** \brief The page for \e problem and, if not null, \e plan (a plan of its team; throws ompl::Exception
            otherwise). */
        static std::string toHtml(const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                  const HtmlOptions &options = {});

        /** \brief Write toHtml() to \e path; throws ompl::Exception if it cannot be written. */
        static void write(const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                          const HtmlOptions &options = {});

        /** \brief Whether \e path names a page (ends in ".html" or ".htm", any case): the tools' --picture writes one
            for such a name and an SVG otherwise. */
        static bool isPagePath(const std::string &path);
    };
}  // namespace ompl_parc

#endif
