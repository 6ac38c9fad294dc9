#ifndef OMPL_PARC_ROBOTS_BUILTIN_MODELS_
#define OMPL_PARC_ROBOTS_BUILTIN_MODELS_

#include <map>
#include <string>

namespace ompl_parc
{
    /** \brief The robot models compiled into the library, so that scenario files can name them
        ("builtin_urdf": "panda") and built-in scenarios need no resource files at run time. */
    namespace models
    {
        /** \brief The Franka Panda of ompl_parc/robots/models/panda.urdf (Franka's published kinematics and joint
            limits, primitive collision shapes). */
        const std::string &pandaUrdf();

        /** \brief Every built-in URDF by the name scenario files use for it. */
        const std::map<std::string, const std::string &(*)()> &builtinUrdfs();
    }  // namespace models
}  // namespace ompl_parc

#endif
