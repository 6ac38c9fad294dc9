#include "ompl_parc/meshes/TriangleMesh.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <ompl/util/Exception.h>

#include <filesystem>
#include <map>
#include <utility>

namespace
{
    const char *const MESH_CONTEXT = "TriangleMesh";

    /** The corners of convex polygon \e in on the side dot(axis, p) * sign >= bound * sign of a plane
        (Sutherland-Hodgman, one plane). */
    void clipPolygon(const std::vector<Eigen::Vector3d> &in, const Eigen::Vector3d &axis, double bound, double sign,
                     std::vector<Eigen::Vector3d> &out)
    {
        out.clear();
        for (std::size_t k = 0; k < in.size(); ++k)
        {
            const Eigen::Vector3d &p = in[k], &q = in[(k + 1) % in.size()];
            const double dp = sign * (axis.dot(p) - bound), dq = sign * (axis.dot(q) - bound);
            if (dp >= 0.)
                out.push_back(p);
            if ((dp >= 0.) != (dq >= 0.))
                out.push_back(p + (dp / (dp - dq)) * (q - p));
        }
    }
}  // namespace

ompl_parc::TriangleMesh::TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles,
                                      std::string file, const Eigen::Vector3d &scale)
    : vertices_(std::move(vertices)), file_(std::move(file)), scale_(scale)
{
    const std::string what = "mesh '" + file_ + "'";
    for (const Eigen::Vector3d &v : vertices_)
        if (!v.allFinite())
            throw ompl::Exception(MESH_CONTEXT, what + " has a non-finite vertex");
    for (const Triangle &t : triangles)
    {
        for (std::uint32_t index : t)
            if (index >= vertices_.size())
                throw ompl::Exception(MESH_CONTEXT, what + " has a triangle whose vertex index is out of range");
        const Eigen::Vector3d &a = vertices_[t[0]], &b = vertices_[t[1]], &c = vertices_[t[2]];
        if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0] && (b - a).cross(c - a).norm() > 0.)
            triangles_.push_back(t);
    }
    if (triangles_.empty())
        throw ompl::Exception(MESH_CONTEXT, what + " is degenerate: it has no triangle of positive area");
}

ompl_parc::TriangleMeshPtr ompl_parc::TriangleMesh::read(const std::string &file, const Eigen::Vector3d &scale)
{
    const std::string what = "mesh file '" + file + "'";
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
        throw ompl::Exception(MESH_CONTEXT, what + " does not exist or is not a file");
    if (!scale.allFinite() || !(scale.minCoeff() > 0.))
        throw ompl::Exception(MESH_CONTEXT, what + ": the scale must be positive and finite");
    Assimp::Importer importer;
    const aiScene *scene =
        importer.ReadFile(file, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (scene == nullptr || scene->mRootNode == nullptr)
        throw ompl::Exception(MESH_CONTEXT, what + " cannot be read: " + importer.GetErrorString());
    // Every node's meshes, through the node transforms from the root (COLLADA puts units and the up axis there).
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Triangle> triangles;
    std::vector<std::pair<const aiNode *, aiMatrix4x4>> pending = {
        {scene->mRootNode, scene->mRootNode->mTransformation}};
    while (!pending.empty())
    {
        const auto [node, transform] = pending.back();
        pending.pop_back();
        for (unsigned int m = 0; m < node->mNumMeshes; ++m)
        {
            if (node->mMeshes[m] >= scene->mNumMeshes)
                continue;
            const aiMesh &mesh = *scene->mMeshes[node->mMeshes[m]];
            const auto first = static_cast<std::uint32_t>(vertices.size());
            for (unsigned int v = 0; v < mesh.mNumVertices; ++v)
            {
                const aiVector3D p = transform * mesh.mVertices[v];
                vertices.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
            }
            for (unsigned int f = 0; f < mesh.mNumFaces; ++f)
            {
                const aiFace &face = mesh.mFaces[f];
                if (face.mNumIndices == 3)  // points and lines bound nothing
                    triangles.push_back({first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
            }
        }
        for (unsigned int c = 0; c < node->mNumChildren; ++c)
            pending.emplace_back(node->mChildren[c], transform * node->mChildren[c]->mTransformation);
    }
    // One vertex per position: formats such as STL repeat a corner for every triangle (and assimp keeps corners
    // apart whose normals differ), and a closed surface is only seen as closed when its triangles share corners.
    std::map<std::array<double, 3>, std::uint32_t> indexOf;
    std::vector<Eigen::Vector3d> welded;
    std::vector<std::uint32_t> renumbered(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v)
    {
        const auto [at, fresh] =
            indexOf.emplace(std::array<double, 3>{vertices[v].x(), vertices[v].y(), vertices[v].z()},
                            static_cast<std::uint32_t>(welded.size()));
        if (fresh)
            welded.push_back(vertices[v]);
        renumbered[v] = at->second;
    }
    for (Triangle &t : triangles)
        for (std::uint32_t &index : t)
            index = renumbered[index];
    return std::make_shared<const TriangleMesh>(std::move(welded), std::move(triangles), file, scale);
}

Eigen::AlignedBox3d ompl_parc::TriangleMesh::getBounds() const
{
    Eigen::AlignedBox3d box;
    for (const Triangle &t : triangles_)
        for (std::uint32_t index : t)
            box.extend(vertices_[index]);
    return box;
}

bool ompl_parc::TriangleMesh::isClosed() const
{
    // Each directed edge once, and its reverse once.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const Triangle &t : triangles_)
        for (int k = 0; k < 3; ++k)
            if (++edges[{t[k], t[(k + 1) % 3]}] > 1)
                return false;
    for (const auto &entry : edges)
        if (edges.count({entry.first.second, entry.first.first}) == 0)
            return false;
    return true;
}

double ompl_parc::TriangleMesh::getVolume() const
{
    double six = 0.;
    for (const Triangle &t : triangles_)
        six += vertices_[t[0]].dot(vertices_[t[1]].cross(vertices_[t[2]]));
    return std::abs(six) / 6.;
}

void ompl_parc::TriangleMesh::clipToSlab(const Eigen::Vector3d &axis, double lo, double hi,
                                         std::vector<Eigen::Vector3d> &out) const
{
    std::vector<Eigen::Vector3d> polygon, above;
    for (const Triangle &t : triangles_)
    {
        polygon = {vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]};
        clipPolygon(polygon, axis, lo, 1., above);
        clipPolygon(above, axis, hi, -1., polygon);
        out.insert(out.end(), polygon.begin(), polygon.end());
    }
}
