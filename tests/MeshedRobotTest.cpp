/* The shipped meshed arm (demos/assets/meshed_arm): planned with its fitted capsules among the mesh table and
   validated, never more permissive than the exact meshes, and one clear line for bad meshes in scenario files. */
#include "TestProblems.h"
#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/robots/UrdfFclModel.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;

namespace
{
    const std::string MESHED_ARM_DIR = std::string(OMPL_PARC_ASSET_DIR) + "/meshed_arm/";

    std::string scenarioFailure(const std::string &json, const std::string &folder)
    {
        return test::messageOf([&] { ScenarioFile::fromJson(json, folder); });
    }
}  // namespace

TEST(MeshedRobot, TheMeshedCellIsPlannedByArcAndParcAndValidates)
{
    const MultiRobotProblem problem = ScenarioFile::read(MESHED_ARM_DIR + "meshed_cell.json");
    const auto arm = std::dynamic_pointer_cast<const UrdfArm>(problem.getSpaceInformation()->getRobot(0));
    ASSERT_NE(arm, nullptr);
    EXPECT_EQ(arm->getMeshes().size(), 10u);  // every link, both fingers
    EXPECT_EQ(arm->getCoordinateNames().back(), "finger_left_joint");
    ASSERT_FALSE(test::allConflicts(*problem.getSpaceInformation(), test::straightLinePlan(problem)).empty());
    ARC arc(problem.getSpaceInformation());
    arc.setSeed(1);
    ASSERT_EQ(test::solveWith(arc, problem, 60.), ob::PlannerStatus::EXACT_SOLUTION) << arc.getStatusMessage();
    EXPECT_TRUE(SolutionValidator(problem).validate(arc.getPlan()).valid);
    PARC parc(problem.getSpaceInformation());
    parc.setSeed(1);
    parc.setWorkers(2);
    ASSERT_EQ(test::solveWith(parc, problem, 60.), ob::PlannerStatus::EXACT_SOLUTION) << parc.getStatusMessage();
    const auto report = SolutionValidator(problem).validate(parc.getPlan());
    EXPECT_TRUE(report.valid) << report.message;
}

TEST(MeshedRobot, NoConfigurationTheExactMeshesFindInCollisionIsAcceptedByTheFit)
{
    // Two neighbouring arms of the cell and the table, at random configurations: wherever FCL finds the link meshes
    // touching the table's triangles or each other, the fitted capsules and the table's boxes must touch too.
    const MultiRobotProblem problem = ScenarioFile::read(MESHED_ARM_DIR + "meshed_cell.json");
    const auto &si = *problem.getSpaceInformation();
    const auto a = std::dynamic_pointer_cast<const UrdfArm>(si.getRobot(0));
    const auto b = std::dynamic_pointer_cast<const UrdfArm>(si.getRobot(1));
    UrdfFclModel exactA(a), exactB(b);
    const Environment &environment = *a->getEnvironment();
    std::mt19937 rng(11);
    std::vector<double> qa(a->getDimension()), qb(b->getDimension());
    CollisionBody bodyA, bodyB;
    int tableHits = 0, armHits = 0;
    for (int k = 0; k < 3000; ++k)
    {
        for (unsigned int j = 0; j < qa.size(); ++j)
        {
            qa[j] = std::uniform_real_distribution<double>(a->getBounds().low[j], a->getBounds().high[j])(rng);
            qb[j] = std::uniform_real_distribution<double>(b->getBounds().low[j], b->getBounds().high[j])(rng);
        }
        exactA.setConfig(qa.data());
        exactB.setConfig(qb.data());
        a->computeCapsules(qa.data(), bodyA);
        b->computeCapsules(qb.data(), bodyB);
        bodyA.updateBound();
        bodyB.updateBound();
        if (exactA.collides(environment))
        {
            ++tableHits;
            EXPECT_TRUE(environment.collides(bodyA)) << "configuration " << k << ": the meshes touch the table";
            EXPECT_FALSE(a->isValid(qa.data())) << k;
        }
        if (exactA.collides(exactB))
        {
            ++armHits;
            EXPECT_TRUE(bodiesCollide(bodyA, bodyB)) << "configuration " << k << ": the arms' meshes touch";
        }
    }
    // The property was put to the test: many configurations are in collision.
    EXPECT_GT(tableHits, 300);
    EXPECT_GT(armHits, 30);
}

TEST(MeshedRobot, ScenarioFilesKeepMeshesAndRefuseBadOnesInOneLine)
{
    const std::string cell = ScenarioFile::toJson(ScenarioFile::read(MESHED_ARM_DIR + "meshed_cell.json"));
    // Written back with absolute paths: read again from anywhere.
    const MultiRobotProblem again = ScenarioFile::fromJson(cell, "/");
    EXPECT_EQ(again.getSpaceInformation()->getRobot(0)->getEnvironment()->getObstacles()[0].shape,
              Obstacle::Shape::MESH);
    EXPECT_EQ(std::dynamic_pointer_cast<const UrdfArm>(again.getSpaceInformation()->getRobot(3))->getMeshes().size(),
              10u);

    const auto folder = std::filesystem::temp_directory_path() / "ompl_parc_meshed_robot_test";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "broken.stl") << "solid broken\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n";
    const std::string robot = R"({"name": "r", "kind": "disc", "radius": 0.1, "bounds": {"low": [0, 0],
        "high": [1, 1]}, "start": [0.2, 0.2], "goal": [0.8, 0.8]})";
    const auto withObstacle = [&](const std::string &obstacle)
    {
        return R"({"format": "ompl_parc.scenario", "version": 1, "name": "t", "obstacles": [)" + obstacle +
               R"(], "robots": [)" + robot + "]}";
    };
    for (const auto &[obstacle, expected] : std::vector<std::pair<std::string, std::string>>{
             {R"({"shape": "mesh", "file": "missing.stl"})", "missing.stl' does not exist"},
             {R"({"shape": "mesh", "file": "broken.stl"})", "broken.stl' cannot be read"},
             {R"({"shape": "mesh", "file": "broken.stl", "scale": -1})", "scale"},
             {R"({"shape": "mesh", "file": "broken.stl", "fit_resolution": 0.5})", "fit_resolution"},
             {R"({"shape": "mesh", "file": "broken.stl", "fit_resolution": 300})", "fit_resolution"},
             {R"({"shape": "mesh"})", "file"}})
    {
        const std::string message = scenarioFailure(withObstacle(obstacle), folder.string());
        EXPECT_NE(message.find(expected), std::string::npos) << obstacle << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    // A URDF whose mesh cannot be found names the link and the file, or the package and the folders searched.
    std::string urdf = UrdfArm::readFile(MESHED_ARM_DIR + "meshed_arm.urdf");
    const std::string package = "package://meshed_arm/";
    for (std::size_t at; (at = urdf.find(package)) != std::string::npos;)
        urdf.replace(at, package.size(), "package://no_such_arm/");
    const std::string message = test::messageOf(
        [&]
        {
            UrdfArm("arm", nullptr, urdf, "base_link", "hand", Eigen::Isometry3d::Identity(), nullptr,
                    UrdfMeshOptions{MeshLocator(MESHED_ARM_DIR)});
        });
    EXPECT_NE(message.find("link 'link1'"), std::string::npos) << message;
    EXPECT_NE(message.find("package 'no_such_arm'"), std::string::npos) << message;
    const std::string relative = test::messageOf(
        [&]
        {
            UrdfArm("arm", nullptr, UrdfArm::readFile(MESHED_ARM_DIR + "meshed_arm.urdf"), "base_link", "hand",
                    Eigen::Isometry3d::Identity(), nullptr, UrdfMeshOptions{MeshLocator(folder.string())});
        });
    EXPECT_NE(relative.find("link 'base_link'"), std::string::npos) << relative;
    EXPECT_NE(relative.find("meshes/base_link.stl' does not exist"), std::string::npos) << relative;
}
