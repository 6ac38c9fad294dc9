#ifndef OMPL_PARC_BOX_FIT_
#define OMPL_PARC_BOX_FIT_

#include "ompl_parc/meshes/TriangleMesh.h"

#include <Eigen/Geometry>

#include <vector>

namespace ompl_parc
{
    /** \brief Boxes around a mesh, so that a mesh obstacle (a table, a shelf, a fixture) is checked by the box
        tests of the planning hot path: the union of the boxes contains the mesh's surface and, if it is closed,
        the solid it bounds.

        The mesh's bounding box is cut into cubic cells, \e resolution along its longest side. Every cell a
        triangle may touch is marked (the triangle is split until each piece's bounding box spans at most two
        cells, and the cells of those boxes are marked: a superset of the cells it meets). Cells reachable from
        outside without crossing a marked cell are outside; the rest (the surface and what it encloses) are merged
        greedily into boxes along x, then y, then z, each clipped to the mesh's bounding box (grown by a
        thousandth of a cell, so that a flat mesh gets boxes of positive thickness). A box is at most a
        cell larger than the mesh on each side: resolution trades tightness for boxes, and boxes cost every
        check. */
    class BoxFit
    {
      public:
        /** \brief Fits \e mesh with cells of 1/\e resolution of its longest side (1 .. 256). */
        BoxFit(const TriangleMesh &mesh, unsigned int resolution);

        /** \brief The boxes, axis-aligned in the mesh's frame. */
        const std::vector<Eigen::AlignedBox3d> &getBoxes() const { return boxes_; }

        /** \brief The mesh's volume, 0 if it is not closed. */
        double getMeshVolume() const { return meshVolume_; }

        /** \brief The boxes' volume (they do not overlap). */
        double getFitVolume() const { return fitVolume_; }

        /** \brief getFitVolume() / getMeshVolume() (>= 1), or 0 for an open mesh. */
        double getVolumeRatio() const { return meshVolume_ > 0. ? fitVolume_ / meshVolume_ : 0.; }

      private:
        std::vector<Eigen::AlignedBox3d> boxes_;
        double meshVolume_{0.};
        double fitVolume_{0.};
    };
}  // namespace ompl_parc

#endif
