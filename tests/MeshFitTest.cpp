/* Meshes: reading STL, OBJ and COLLADA, finding them, fitting capsules (links) and boxes (obstacles) that contain
   them, caching fits, and one clear line for each kind of bad mesh. */
#include "TestProblems.h"
#include "ompl_parc/collision/Environment.h"
#include "ompl_parc/meshes/BoxFit.h"
#include "ompl_parc/meshes/CapsuleFit.h"
#include "ompl_parc/meshes/CapsuleFitCache.h"
#include "ompl_parc/meshes/MeshLocator.h"
#include "ompl_parc/meshes/TriangleMesh.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

using namespace ompl_parc;

namespace
{
    const std::string MESHES = std::string(OMPL_PARC_ASSET_DIR) + "/meshed_arm/meshes/";

    /** Points on the surface: every vertex, and \e perTriangle random points of each triangle (fixed seed). */
    std::vector<Eigen::Vector3d> surfacePoints(const TriangleMesh &mesh, int perTriangle)
    {
        std::vector<Eigen::Vector3d> points = mesh.getVertices();
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> unit(0., 1.);
        for (const auto &t : mesh.getTriangles())
            for (int k = 0; k < perTriangle; ++k)
            {
                double u = unit(rng), v = unit(rng);
                if (u + v > 1.)
                {
                    u = 1. - u;
                    v = 1. - v;
                }
                const auto &p = mesh.getVertices();
                points.push_back(p[t[0]] + u * (p[t[1]] - p[t[0]]) + v * (p[t[2]] - p[t[0]]));
            }
        return points;
    }

    std::filesystem::path scratchFolder(const std::string &name)
    {
        const auto folder = std::filesystem::temp_directory_path() / ("ompl_parc_mesh_test_" + name);
        std::filesystem::remove_all(folder);
        std::filesystem::create_directories(folder);
        return folder;
    }
}  // namespace

TEST(TriangleMesh, ReadsStlObjAndColladaAlike)
{
    for (const auto &[a, b] :
         {std::pair<std::string, std::string>{"link5.stl", "link5.obj"}, {"link6.stl", "link6.dae"}})
    {
        const auto stl = TriangleMesh::read(MESHES + a), other = TriangleMesh::read(MESHES + b);
        EXPECT_TRUE(stl->isClosed()) << a;
        EXPECT_TRUE(other->isClosed()) << b;
        EXPECT_EQ(stl->getTriangles().size(), other->getTriangles().size()) << b;
        EXPECT_NEAR(stl->getVolume(), other->getVolume(), 1e-6 * stl->getVolume()) << b;
        EXPECT_TRUE(stl->getBounds().min().isApprox(other->getBounds().min(), 1e-6)) << b;
        EXPECT_TRUE(stl->getBounds().max().isApprox(other->getBounds().max(), 1e-6)) << b;
    }
    const auto scaled = TriangleMesh::read(MESHES + "hand.stl", Eigen::Vector3d(2., 1., 1.));
    const auto plain = TriangleMesh::read(MESHES + "hand.stl");
    EXPECT_NEAR(scaled->getVolume(), 2. * plain->getVolume(), 1e-9);
}

TEST(TriangleMesh, RefusesBadMeshesWithOneLine)
{
    const auto folder = scratchFolder("bad");
    std::ofstream(folder / "garbage.stl") << "solid x\n this is not an STL file\n";
    std::ofstream(folder / "flat.stl") << "solid flat\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                          "vertex 2 0 0\nendloop\nendfacet\nendsolid flat\n";
    std::ofstream(folder / "table.xyz") << "1 2 3\n";
    for (const auto &[file, expected] :
         std::vector<std::pair<std::string, std::string>>{{(folder / "missing.stl").string(), "does not exist"},
                                                          {(folder / "garbage.stl").string(), "cannot be read"},
                                                          {(folder / "table.xyz").string(), "cannot be read"},
                                                          {(folder / "flat.stl").string(), "degenerate"}})
    {
        const std::string message = test::messageOf([&] { TriangleMesh::read(file); });
        EXPECT_NE(message.find(expected), std::string::npos) << file << ": " << message;
        EXPECT_NE(message.find(file), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_NE(
        test::messageOf([&] { TriangleMesh::read(MESHES + "hand.stl", Eigen::Vector3d(1., 0., 1.)); }).find("scale"),
        std::string::npos);
}

TEST(MeshLocator, FindsPackagesAndRelativePaths)
{
    const MeshLocator locator(std::string(OMPL_PARC_ASSET_DIR) + "/meshed_arm");
    // The URDF's folder is the package itself.
    EXPECT_TRUE(std::filesystem::exists(locator.resolve("package://meshed_arm/meshes/hand.stl")));
    EXPECT_TRUE(std::filesystem::exists(locator.resolve("meshes/hand.stl")));
    EXPECT_EQ(locator.resolve("file:///tmp/x.stl"), "/tmp/x.stl");
    // A package found through the search path, from anywhere.
    const MeshLocator elsewhere("/", {OMPL_PARC_ASSET_DIR});
    EXPECT_TRUE(std::filesystem::exists(elsewhere.resolve("package://meshed_arm/meshes/hand.stl")));
    const std::string missing = test::messageOf([&] { MeshLocator("/").resolve("package://no_such_package/a.stl"); });
    EXPECT_NE(missing.find("package 'no_such_package'"), std::string::npos) << missing;
    EXPECT_NE(missing.find("OMPL_PARC_PACKAGE_PATH"), std::string::npos) << missing;
    EXPECT_NE(test::messageOf([&] { locator.resolve("http://example.com/a.stl"); }).find("only package://"),
              std::string::npos);
}

TEST(CapsuleFit, ContainsEveryLinkMeshAndSaysHowTightly)
{
    for (const char *name : {"base_link.stl", "link1.stl", "link2.stl", "link3.stl", "link4.stl", "link5.obj",
                             "link6.dae", "hand.stl", "finger_left.stl"})
    {
        const auto mesh = TriangleMesh::read(MESHES + name);
        for (unsigned int capsules : {1u, 4u})
        {
            const CapsuleFit fit(*mesh, capsules);
            ASSERT_FALSE(fit.getCapsules().empty());
            EXPECT_LE(fit.getCapsules().size(), capsules);
            std::size_t outside = 0;
            for (const Eigen::Vector3d &p : surfacePoints(*mesh, 20))
                outside += !fit.contains(p);
            EXPECT_EQ(outside, 0u) << name << " with " << capsules;
            // A fit contains the mesh, so its volume is not below the mesh's (but for the estimate's noise).
            EXPECT_GT(fit.getVolumeRatio(), 0.97) << name;
            EXPECT_LT(fit.getVolumeRatio(), 6.) << name;
        }
    }
}

TEST(BoxFit, ContainsTheTableSurfaceAndSolid)
{
    const auto table = TriangleMesh::read(MESHES + "table.stl");
    ASSERT_TRUE(table->isClosed());
    const auto inBoxes = [](const BoxFit &fit, const Eigen::Vector3d &p)
    {
        for (const auto &box : fit.getBoxes())
            if (box.contains(p))
                return true;
        return false;
    };
    for (unsigned int resolution : {8u, 32u})
    {
        const BoxFit fit(*table, resolution);
        std::size_t outside = 0;
        for (const Eigen::Vector3d &p : surfacePoints(*table, 20))
            outside += !inBoxes(fit, p);
        EXPECT_EQ(outside, 0u) << resolution;
        // Inside the solid: the middle of the top and of a leg (the table: top 0.36 .. 0.40 m, legs below).
        const Eigen::AlignedBox3d bounds = table->getBounds();
        EXPECT_TRUE(inBoxes(fit, Eigen::Vector3d(0., 0., bounds.max().z() - 0.02)));
        EXPECT_GE(fit.getVolumeRatio(), 1.);
        // Under the top, between the legs, is free.
        EXPECT_FALSE(inBoxes(fit, Eigen::Vector3d(0., 0., 0.1))) << resolution;
    }
    EXPECT_LT(BoxFit(*table, 32).getVolumeRatio(), BoxFit(*table, 8).getVolumeRatio());
}

TEST(CapsuleFitCache, StoresBesideTheMeshAndMissesWhenItChanges)
{
    const auto folder = scratchFolder("cache");
    const auto mesh = folder / "link.stl";
    std::filesystem::copy_file(MESHES + "link3.stl", mesh);
    const CapsuleFit made = CapsuleFitCache::fit(mesh.string(), Eigen::Vector3d::Ones(), 3);
    ASSERT_TRUE(std::filesystem::exists(CapsuleFitCache::entryPath(mesh.string())));
    const CapsuleFit read = CapsuleFitCache::fit(mesh.string(), Eigen::Vector3d::Ones(), 3);
    ASSERT_EQ(read.getCapsules().size(), made.getCapsules().size());
    for (std::size_t k = 0; k < made.getCapsules().size(); ++k)
    {
        EXPECT_TRUE(read.getCapsules()[k].a.isApprox(made.getCapsules()[k].a, 1e-12));
        EXPECT_DOUBLE_EQ(read.getCapsules()[k].radius, made.getCapsules()[k].radius);
    }
    EXPECT_DOUBLE_EQ(read.getVolumeRatio(), made.getVolumeRatio());
    // An entry of another mesh (the file changed under it) is not used.
    std::filesystem::copy_file(MESHES + "hand.stl", mesh, std::filesystem::copy_options::overwrite_existing);
    const CapsuleFit other = CapsuleFitCache::fit(mesh.string(), Eigen::Vector3d::Ones(), 3);
    const auto hand = TriangleMesh::read(mesh.string());
    for (const Eigen::Vector3d &p : surfacePoints(*hand, 5))
        ASSERT_TRUE(other.contains(p));
    EXPECT_NE(other.getMeshVolume(), made.getMeshVolume());
    // A corrupt entry is a miss, not an error.
    std::ofstream(CapsuleFitCache::entryPath(mesh.string())) << "{\"key\": 3";
    EXPECT_EQ(CapsuleFitCache::fit(mesh.string(), Eigen::Vector3d::Ones(), 3).getCapsules().size(),
              other.getCapsules().size());
}

TEST(Environment, MeshObstacleIsExactForFclAndContainedForPlanning)
{
    auto environment = std::make_shared<Environment>();
    Obstacle table;
    table.name = "table";
    table.shape = Obstacle::Shape::MESH;
    table.mesh = TriangleMesh::read(MESHES + "table.stl");
    table.pose = Eigen::Translation3d(1., 0., 0.) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
    environment->addObstacle(table);
    ASSERT_NE(environment->getBoxFit(0), nullptr);
    // Random spheres (capsules of length 0): wherever FCL finds one touching the triangles, the boxes do too;
    // and the boxes are not everything (some spheres near the table are free).
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(0.2, 1.8), y(-0.8, 0.8), z(-0.05, 0.6), r(0.005, 0.05);
    int exact = 0, planning = 0;
    for (int k = 0; k < 4000; ++k)
    {
        CollisionBody body;
        body.resize(1, true);
        body.ax_[0] = body.bx_[0] = x(rng);
        body.ay_[0] = body.by_[0] = y(rng);
        body.az_[0] = body.bz_[0] = z(rng);
        body.radius_[0] = r(rng);
        const bool fcl = environment->collidesFcl(body), fitted = environment->collides(body);
        EXPECT_FALSE(fcl && !fitted) << "a sphere FCL finds on the table is free for planning";
        exact += fcl;
        planning += fitted;
    }
    EXPECT_GT(exact, 100);
    EXPECT_LT(planning, 4000);
}
