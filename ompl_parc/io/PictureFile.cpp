#include "ompl_parc/io/PictureFile.h"

#include "ompl_parc/io/HtmlWriter.h"

void ompl_parc::PictureFile::write(const std::string &path, const MultiRobotProblem &problem,
                                   const MultiRobotPlan *plan, const SvgOptions &options)
{
    if (HtmlWriter::isPagePath(path))
        HtmlWriter::write(path, problem, plan);
    else
        SvgWriter::write(path, problem, plan, options);
}
