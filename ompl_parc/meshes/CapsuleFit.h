#ifndef OMPL_PARC_CAPSULE_FIT_
#define OMPL_PARC_CAPSULE_FIT_

#include "ompl_parc/meshes/TriangleMesh.h"

#include <Eigen/Core>

#include <vector>

namespace ompl_parc
{
    /** \brief Capsules around a mesh, so that a meshed robot link is checked by the capsule tests of the planning
        hot path: the union of the capsules contains the mesh (its surface, and the solid it bounds if closed).

        The fit cuts the mesh into 1 .. maxCapsules slabs of equal width across one of its principal axes and
        puts one capsule along that axis around each slab's part of the surface (the triangles clipped to the
        slab: see TriangleMesh::clipToSlab). A capsule is convex and contains every clipped corner, so it
        contains the part; no tolerance is involved. Of the 3 x maxCapsules candidates it keeps the one of least
        volume, preferring fewer capsules unless more are 10% smaller. getVolumeRatio() tells how tight it is. */
    class CapsuleFit
    {
      public:
        /** \brief A capsule: the points within \e radius of the segment a-b (a sphere if a == b). */
        struct Capsule
        {
            Eigen::Vector3d a, b;
            double radius;
        };

        /** \brief No capsules (a fit to be assigned). */
        CapsuleFit() = default;

        /** \brief Fits \e mesh with at most \e maxCapsules capsules (at least 1). */
        CapsuleFit(const TriangleMesh &mesh, unsigned int maxCapsules);

        /** \brief A fit made before (CapsuleFitCache), with the volumes it was reported with. */
        CapsuleFit(std::vector<Capsule> capsules, double meshVolume, double fitVolume);

        const std::vector<Capsule> &getCapsules() const { return capsules_; }

        /** \brief The mesh's volume, 0 if it is not closed (then it bounds no volume to compare with). */
        double getMeshVolume() const { return meshVolume_; }

        /** \brief The volume of the capsules' union (Monte Carlo, fixed seed, within 1-2%). */
        double getFitVolume() const { return fitVolume_; }

        /** \brief getFitVolume() / getMeshVolume() (>= 1), or 0 for an open mesh. */
        double getVolumeRatio() const { return meshVolume_ > 0. ? fitVolume_ / meshVolume_ : 0.; }

        /** \brief Whether \e p lies in one of the capsules, or within \e tolerance of one. */
        bool contains(const Eigen::Vector3d &p, double tolerance = 0.) const;

        /** \brief The volume of the union of \e capsules, estimated from \e samples uniform points in their
            bounding box (fixed seed: the same capsules give the same figure). */
        static double estimateVolume(const std::vector<Capsule> &capsules, unsigned int samples);

      private:
        std::vector<Capsule> capsules_;
        double meshVolume_{0.};
        double fitVolume_{0.};
    };
}  // namespace ompl_parc

#endif
