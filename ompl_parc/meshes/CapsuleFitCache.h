#ifndef OMPL_PARC_CAPSULE_FIT_CACHE_
#define OMPL_PARC_CAPSULE_FIT_CACHE_

#include "ompl_parc/meshes/CapsuleFit.h"

#include <optional>
#include <string>

namespace ompl_parc
{
    /** \brief Capsule fits kept beside the meshes they fit (\e mesh.ompl_parc_fit.json), so that loading a
        meshed robot again reads neither the mesh nor fits it.

        An entry holds the fit, its volumes, and what it was made from: the mesh file's size and a hash of its
        bytes, the scale and the number of capsules allowed. A mesh that changed, another scale or another
        number misses; so does an unreadable or malformed entry (it is rewritten). Writing is best effort (a
        read-only folder just keeps nothing) and atomic (a temporary file renamed), so robots loading at once
        in several processes never read half an entry. */
    class CapsuleFitCache
    {
      public:
        /** \brief The fit of \e meshFile at \e scale with up to \e maxCapsules capsules: the cached one if it is
            still good, else one made now from the mesh (TriangleMesh::read, which throws for bad meshes) and, if
            \e write, stored. */
        static CapsuleFit fit(const std::string &meshFile, const Eigen::Vector3d &scale, unsigned int maxCapsules,
                              bool write = true);

        /** \brief Where the fit of \e meshFile is kept. */
        static std::string entryPath(const std::string &meshFile);

      private:
        static std::optional<CapsuleFit> load(const std::string &meshFile, const std::string &key);
        static void store(const std::string &meshFile, const std::string &key, const CapsuleFit &fit);
    };
}  // namespace ompl_parc

#endif
