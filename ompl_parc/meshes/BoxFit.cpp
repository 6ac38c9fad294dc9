#include "ompl_parc/meshes/BoxFit.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
    /** A grid of cells with a border of one empty cell all round (the flood fill starts there). */
    class CellGrid
    {
      public:
        CellGrid(const Eigen::AlignedBox3d &bounds, unsigned int resolution)
            : origin_(bounds.min()), cell_(bounds.sizes().maxCoeff() / resolution)
        {
            for (int k = 0; k < 3; ++k)
                size_[k] = std::max(1, static_cast<int>(std::ceil(bounds.sizes()[k] / cell_ - 1e-9))) + 2;
            state_.assign(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2], EMPTY);
        }

        enum State : char
        {
            EMPTY,
            SURFACE,
            OUTSIDE
        };

        std::size_t index(int x, int y, int z) const
        {
            return (static_cast<std::size_t>(z) * size_[1] + y) * size_[0] + x;
        }

        /** The cell (with the border, so from 1) holding \e p, clamped into the mesh's cells. */
        Eigen::Array3i cellOf(const Eigen::Vector3d &p) const
        {
            Eigen::Array3i c;
            for (int k = 0; k < 3; ++k)
                c[k] = std::clamp(static_cast<int>(std::floor((p[k] - origin_[k]) / cell_)) + 1, 1, size_[k] - 2);
            return c;
        }

        /** Marks the cells a triangle may touch (see BoxFit). */
        void markTriangle(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c)
        {
            std::vector<std::array<Eigen::Vector3d, 3>> pending = {{a, b, c}};
            while (!pending.empty())
            {
                const auto t = pending.back();
                pending.pop_back();
                const Eigen::Array3i low = cellOf(t[0].cwiseMin(t[1]).cwiseMin(t[2]));
                const Eigen::Array3i high = cellOf(t[0].cwiseMax(t[1]).cwiseMax(t[2]));
                if ((high - low).maxCoeff() > 1 && (t[1] - t[0]).norm() + (t[2] - t[0]).norm() > 1e-6 * cell_)
                {
                    const Eigen::Vector3d ab = 0.5 * (t[0] + t[1]), bc = 0.5 * (t[1] + t[2]), ca = 0.5 * (t[2] + t[0]);
                    pending.push_back({t[0], ab, ca});
                    pending.push_back({ab, t[1], bc});
                    pending.push_back({ca, bc, t[2]});
                    pending.push_back({ab, bc, ca});
                    continue;
                }
                for (int z = low[2]; z <= high[2]; ++z)
                    for (int y = low[1]; y <= high[1]; ++y)
                        for (int x = low[0]; x <= high[0]; ++x)
                            state_[index(x, y, z)] = SURFACE;
            }
        }

        /** Marks OUTSIDE every empty cell reachable from the border through empty cells (6-neighbours). */
        void floodOutside()
        {
            std::vector<std::array<int, 3>> pending = {{0, 0, 0}};
            state_[0] = OUTSIDE;
            const int steps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            while (!pending.empty())
            {
                const auto c = pending.back();
                pending.pop_back();
                for (const auto &s : steps)
                {
                    const int x = c[0] + s[0], y = c[1] + s[1], z = c[2] + s[2];
                    if (x < 0 || y < 0 || z < 0 || x >= size_[0] || y >= size_[1] || z >= size_[2])
                        continue;
                    char &state = state_[index(x, y, z)];
                    if (state == EMPTY)
                    {
                        state = OUTSIDE;
                        pending.push_back({x, y, z});
                    }
                }
            }
        }

        /** The cells not OUTSIDE merged into boxes: runs along x, grown along y while the whole run is free,
            then along z while the whole rectangle is. */
        std::vector<Eigen::AlignedBox3d> mergeInside()
        {
            const auto inside = [&](int x, int y, int z) { return state_[index(x, y, z)] != OUTSIDE; };
            std::vector<char> taken(state_.size(), 0);
            const auto free = [&](int x, int y, int z) { return inside(x, y, z) && !taken[index(x, y, z)]; };
            std::vector<Eigen::AlignedBox3d> boxes;
            for (int z = 1; z < size_[2] - 1; ++z)
                for (int y = 1; y < size_[1] - 1; ++y)
                    for (int x = 1; x < size_[0] - 1; ++x)
                    {
                        if (!free(x, y, z))
                            continue;
                        int x1 = x, y1 = y, z1 = z;
                        while (x1 + 1 < size_[0] - 1 && free(x1 + 1, y, z))
                            ++x1;
                        const auto rowFree = [&](int yy, int zz)
                        {
                            for (int xx = x; xx <= x1; ++xx)
                                if (!free(xx, yy, zz))
                                    return false;
                            return true;
                        };
                        while (y1 + 1 < size_[1] - 1 && rowFree(y1 + 1, z))
                            ++y1;
                        const auto layerFree = [&](int zz)
                        {
                            for (int yy = y; yy <= y1; ++yy)
                                if (!rowFree(yy, zz))
                                    return false;
                            return true;
                        };
                        while (z1 + 1 < size_[2] - 1 && layerFree(z1 + 1))
                            ++z1;
                        for (int zz = z; zz <= z1; ++zz)
                            for (int yy = y; yy <= y1; ++yy)
                                for (int xx = x; xx <= x1; ++xx)
                                    taken[index(xx, yy, zz)] = 1;
                        boxes.emplace_back(corner(x, y, z), corner(x1 + 1, y1 + 1, z1 + 1));
                    }
            return boxes;
        }

      private:
        Eigen::Vector3d corner(int x, int y, int z) const
        {
            return origin_ + cell_ * Eigen::Vector3d(x - 1, y - 1, z - 1);
        }

        Eigen::Vector3d origin_;
        double cell_;
        std::array<int, 3> size_;
        std::vector<char> state_;
    };
}  // namespace

ompl_parc::BoxFit::BoxFit(const TriangleMesh &mesh, unsigned int resolution)
    : meshVolume_(mesh.isClosed() ? mesh.getVolume() : 0.)
{
    if (resolution == 0 || resolution > 256)
        throw ompl::Exception("BoxFit", "the resolution must be 1 .. 256 cells along the longest side");
    const Eigen::AlignedBox3d bounds = mesh.getBounds();
    if (!(bounds.sizes().maxCoeff() > 0.))
        throw ompl::Exception("BoxFit", "mesh '" + mesh.getFile() + "' is degenerate: it has no extent");
    CellGrid grid(bounds, resolution);
    const auto &v = mesh.getVertices();
    for (const auto &t : mesh.getTriangles())
        grid.markTriangle(v[t[0]], v[t[1]], v[t[2]]);
    grid.floodOutside();
    // Cells overhang the mesh's bounds on the high side, where nothing of the mesh is: boxes are clipped to the
    // bounds, grown by a hair so that a flat mesh (a sheet) still gets boxes of positive thickness.
    const Eigen::Vector3d hair = Eigen::Vector3d::Constant(1e-3 * bounds.sizes().maxCoeff() / resolution);
    const Eigen::AlignedBox3d clip(bounds.min() - hair, bounds.max() + hair);
    for (const Eigen::AlignedBox3d &box : grid.mergeInside())
    {
        const Eigen::AlignedBox3d clipped = box.intersection(clip);
        boxes_.push_back(clipped);
        fitVolume_ += clipped.volume();
    }
}
