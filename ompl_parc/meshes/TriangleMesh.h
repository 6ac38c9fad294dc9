#ifndef OMPL_PARC_TRIANGLE_MESH_
#define OMPL_PARC_TRIANGLE_MESH_

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ompl_parc
{
    class TriangleMesh;
    using TriangleMeshPtr = std::shared_ptr<const TriangleMesh>;

    /** \brief A triangle mesh in its own frame, scaled: a robot link's or an obstacle's collision geometry as a
        URDF or a scenario file names it (STL, OBJ, COLLADA and whatever else assimp reads).

        Planning never checks it: the hot path checks primitives fitted around it (CapsuleFit for links,
        BoxFit for obstacles), and the exact checks (the validator, UrdfFclModel) check its triangles through
        FCL's bounding-volume hierarchy. */
    class TriangleMesh
    {
      public:
        using Triangle = std::array<std::uint32_t, 3>;

        /** \brief A mesh of \e vertices and \e triangles (indices into them) read from \e file at \e scale.
            Throws ompl::Exception if it has no triangle, a non-finite vertex, an index out of range, or no
            triangle of positive area (a degenerate mesh bounds no body); triangles of zero area are dropped. */
        TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles, std::string file,
                     const Eigen::Vector3d &scale);

        /** \brief Reads \e file with assimp (every node's mesh in the root's frame, so COLLADA units and up axes
            count) and scales it per axis. Throws ompl::Exception, one line naming the file, if it is missing,
            unreadable or degenerate. */
        static TriangleMeshPtr read(const std::string &file, const Eigen::Vector3d &scale = Eigen::Vector3d::Ones());

        const std::vector<Eigen::Vector3d> &getVertices() const { return vertices_; }
        const std::vector<Triangle> &getTriangles() const { return triangles_; }
        /** \brief The file it was read from and the scale it was read at (to write a scenario back). */
        const std::string &getFile() const { return file_; }
        const Eigen::Vector3d &getScale() const { return scale_; }

        Eigen::AlignedBox3d getBounds() const;

        /** \brief Whether every edge is shared by exactly two triangles that run it in opposite directions: the
            surface bounds a solid, and getVolume() is its volume. */
        bool isClosed() const;

        /** \brief The volume enclosed (divergence theorem; meaningful where isClosed()). */
        double getVolume() const;

        /** \brief Appends to \e out the corners of every triangle's part in the slab lo <= axis.p <= hi (each
            triangle clipped by the two planes): a convex set containing these points contains the surface in
            the slab and, for a closed mesh, the solid in it (any line in a slab plane through a point inside
            meets the surface on both sides, inside the slab). */
        void clipToSlab(const Eigen::Vector3d &axis, double lo, double hi, std::vector<Eigen::Vector3d> &out) const;

      private:
        std::vector<Eigen::Vector3d> vertices_;
        std::vector<Triangle> triangles_;
        std::string file_;
        Eigen::Vector3d scale_;
    };
}  // namespace ompl_parc

#endif
