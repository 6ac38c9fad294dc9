#ifndef OMPL_PARC_PICTURE_FILE_
#define OMPL_PARC_PICTURE_FILE_

#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <string>

namespace ompl_parc
{
    /** \brief A picture of a problem and its plan, of the kind its file name asks for: the one place where the tools,
        MultiRobotSetup and Python choose between the 3D page and the SVG. */
    class PictureFile
    {
      public:
        /** \brief Draw \e problem and \e plan (null: the problem only) to \e path: an interactive 3D page (HtmlWriter)
            for a name HtmlWriter::isPagePath() accepts, else an SVG (SvgWriter, with \e options). Throws
            ompl::Exception if it cannot be written or the plan is of another team. */
        static void write(const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan,
                          const SvgOptions &options = {});
    };
}  // namespace ompl_parc

#endif
