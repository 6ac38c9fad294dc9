#ifndef OMPL_PARC_SVG_WRITER_
#define OMPL_PARC_SVG_WRITER_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    /** \brief How SvgWriter draws a problem and its plan. */
    struct SvgOptions
    {
        /** \brief Animate the robots along the plan (SMIL); false draws a static snapshot. */
        bool animate{true};
        /** \brief At most this many sampled timesteps per robot (long plans are subsampled evenly), which
            bounds the file size of both the animation and the traced paths. */
        unsigned int maxKeyframes{200};
        /** \brief Length of one animation loop in seconds, whatever the makespan. */
        double duration{10.};
        /** \brief Pixel size of the picture's longer side. */
        double size{800.};
    };

    /** \brief Pictures of 2D multi-robot problems and plans as SVG, seen from above (z is dropped).

        Robots are drawn from their collision bodies, so every robot kind is covered: a single sphere
        (a disc) becomes a circle, chained capsules (a planar arm's links) a polyline of the capsules'
        width. Each robot is one `<g class="robot">` holding its start (faded), goal (thin dashed outline), the
        traced path of its last capsule's tip and, when animating, its moving body (`<animate>` of the
        circle's centre or the polyline's points). Obstacles are drawn as the convex hull of their
        footprint in `<g class="obstacles">`. Without a plan only starts and goals are drawn. Viewable in
        any browser; static renderers show the robots at their starts. A problem that is not planar (isPlanar())
        is still drawn from above, under a note saying so and pointing to the 3D drawing (GeometryFile and
        scripts/draw_panda_cage.py), so that nobody mistakes the top view for the whole picture. */
    class SvgWriter
    {
      public:
        /** \brief The SVG document for \e problem and (if not null) \e plan, a plan of its team. */
        static std::string toSvg(const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                                 const SvgOptions &options = {});

        /** \brief True if every robot's body at its start and goal lies in the plane z = 0 (2D robots; the obstacles of
           2D problems may have a height, which a top view drops harmlessly). */
        static bool isPlanar(const MultiRobotProblem &problem);

        /** \brief The note a picture of a problem that is not planar carries. */
        static const char *const TOP_VIEW_NOTE;

        /** \brief Write toSvg() to \e path; throws ompl::Exception if unwritable. */
        static void write(const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                          const SvgOptions &options = {});
    };
}  // namespace ompl_parc

#endif
