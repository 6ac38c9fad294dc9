#ifndef OMPL_PARC_URDF_MESH_OPTIONS_
#define OMPL_PARC_URDF_MESH_OPTIONS_

#include "ompl_parc/meshes/MeshLocator.h"

namespace ompl_parc
{
    /** \brief Where the meshes of a URDF (UrdfArm) are found, and how they are fitted. */
    struct UrdfMeshOptions
    {
        /** \brief Resolves `package://` URIs and relative paths (from the URDF's folder). */
        MeshLocator locator;
        /** \brief At most this many capsules per mesh (CapsuleFit): more fit tighter and cost more checks. */
        unsigned int maxCapsules{4};
        /** \brief Whether fits made now are stored beside their meshes for the next load (CapsuleFitCache). */
        bool writeCache{true};
    };
}  // namespace ompl_parc

#endif
