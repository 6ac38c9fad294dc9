#ifndef OMPL_PARC_VIEWER_ASSETS_
#define OMPL_PARC_VIEWER_ASSETS_

#include <string>

namespace ompl_parc::viewer
{
    /** \brief The viewer page (ompl_parc/io/viewer.html) with its placeholders for the scripts and the scene. */
    const std::string &pageTemplate();
    /** \brief three.js and its OrbitControls, from Debian's libjs-three at build time: compiled in, so that the
        pages HtmlWriter writes need neither the network nor the package when they are viewed. */
    const std::string &threeJs();
    const std::string &orbitControlsJs();
}  // namespace ompl_parc::viewer

#endif
