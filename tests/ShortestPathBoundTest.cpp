#include "TestProblems.h"

#include "ompl_parc/planners/PrioritizedSTRRT.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/quality/ShortestPathBound.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ompl_parc;

namespace
{
    double distance(const std::vector<double> &a, const std::vector<double> &b)
    {
        return std::hypot(b[0] - a[0], b[1] - a[1]);
    }

    /** The timestep path through \e waypoints, straight at full speed between them. */
    std::vector<double> polyline(const std::vector<std::vector<double>> &waypoints, double resolution)
    {
        std::vector<double> flat = waypoints.front();
        for (std::size_t k = 1; k < waypoints.size(); ++k)
        {
            const std::vector<double> leg = test::straightLine(waypoints[k - 1], waypoints[k], resolution);
            flat.insert(flat.end(), leg.begin() + 2, leg.end());
        }
        return flat;
    }
}  // namespace

TEST(ShortestPathBound, InAnEmptyWorldItIsTheStraightLine)
{
    const MultiRobotProblem problem = test::twoDiscs({-2, 0}, {2, 0}, {0, -1}, {0, 3});
    const ShortestPathBound bound(*problem.getSpaceInformation()->getEnvironment(), 0.5, 128.);
    EXPECT_EQ(bound.getPolygonCount(), 0u);
    const double start[2] = {-2., 1.}, goal[2] = {1., 5.};
    EXPECT_DOUBLE_EQ(bound.length(start, goal), 5.);
    const MultiRobotPlan plan = test::straightLinePlan(problem);
    const PlanQuality quality = PlanQuality::measure(*problem.getSpaceInformation(), plan);
    EXPECT_EQ(quality.makespanPathBound, quality.makespanBound);
    EXPECT_EQ(quality.sumOfCostsPathBound, quality.sumOfCostsBound);
    EXPECT_EQ(quality.makespanPathBound, 512u);  // 4 units at 128 timesteps per unit
    EXPECT_DOUBLE_EQ(quality.makespanPathRatio(), quality.makespanRatio());
}

TEST(ShortestPathBound, AroundAWallItIsTheInscribedPolygonsShortestPath)
{
    // Disc a (radius 0.5) crosses the wall 0.2 x 4 at the origin from (-3, 0) to (3, 0); b waits far away. The wall's
    // forbidden set is its rectangle grown by the clearance (0.5 less a few 1e-5), whose polygon has 4 vertices
    // on each rounded corner, at 0, 30, 60 and 90 degrees. The shortest way goes over the top: from the start
    // tangent to the vertex at 120 degrees of the corner (-0.1, 2), to the one at 90, across, and down likewise.
    const MultiRobotProblem problem = test::twoDiscs({-3, 0}, {3, 0}, {6, 6}, {6, 6}, true);
    const auto &si = *problem.getSpaceInformation();
    const ShortestPathBound bound(*si.getEnvironment(), 0.5, 128.);
    ASSERT_EQ(bound.getPolygonCount(), 1u);
    const double rho = bound.getClearance();
    EXPECT_NEAR(rho, 0.5, 1e-4);
    EXPECT_LT(rho, 0.5);
    const std::vector<double> start{-3., 0.}, goal{3., 0.}, tangent{-0.1 - 0.5 * rho, 2. + std::sqrt(0.75) * rho},
        top{-0.1, 2. + rho};
    const double hand = 2. * (distance(start, tangent) + distance(tangent, top)) + 0.2;
    const double length = bound.length(start.data(), goal.data());
    EXPECT_NEAR(length, hand, 1e-9);
    EXPECT_GT(length, 7.9);  // far above the straight line's 6

    // The same wall turned upside down (a flip about x) forbids the same positions.
    Environment flipped;
    Obstacle wall = si.getEnvironment()->getObstacles().front();
    wall.pose = wall.pose * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
    flipped.addObstacle(wall);
    EXPECT_NEAR(ShortestPathBound(flipped, 0.5, 128.).length(start.data(), goal.data()), length, 1e-9);

    // A feasible detour, 0.6 above the wall's corners, is no shorter.
    const std::vector<std::vector<double>> detour{start, {-0.7, 2.6}, {0.7, 2.6}, goal};
    double detourLength = 0.;
    for (std::size_t k = 1; k < detour.size(); ++k)
    {
        ASSERT_TRUE(*si.getRobot(0)->sweepValid(detour[k - 1].data(), detour[k].data()));
        detourLength += distance(detour[k - 1], detour[k]);
    }
    EXPECT_LT(length, detourLength);

    // Measured on the validated plan of the detour: the bound is the polygon path's timesteps, between the
    // straight line's and the detour's.
    MultiRobotPlan plan = test::straightLinePlan(problem);
    plan.setRobotPath(0, polyline(detour, si.getResolution()));
    const ValidationReport report = SolutionValidator(problem).validate(plan);
    ASSERT_TRUE(report.valid) << report.message;
    const PlanQuality quality = PlanQuality::measure(si, plan);
    EXPECT_EQ(quality.makespanBound, 768u);
    EXPECT_EQ(quality.makespanPathBound, static_cast<std::size_t>(std::ceil(hand * 128.)));
    EXPECT_EQ(quality.sumOfCostsPathBound, quality.makespanPathBound);  // b does not move
    EXPECT_LE(quality.makespanPathBound, plan.getMakespan());
    EXPECT_LT(quality.makespanPathRatio(), quality.makespanRatio());
}

TEST(ShortestPathBound, UprightCylindersAndSpheresNearThePlaneCountTiltedBoxesDoNot)
{
    // A cylinder of radius 1 standing at (0, 0) blocks the way from (-3, 0) to (3, 0); a sphere of radius 1 at
    // height 1.2 leaves a forbidden disc of radius sqrt(1.5^2 - 1.2^2) = 0.9; a box tilted about x is left out.
    Environment world;
    Obstacle cylinder;
    cylinder.shape = Obstacle::Shape::CYLINDER;
    cylinder.size = Eigen::Vector3d(1., 0., 2.);
    world.addObstacle(cylinder);
    Obstacle sphere;
    sphere.shape = Obstacle::Shape::SPHERE;
    sphere.size = Eigen::Vector3d(1., 0., 0.);
    sphere.pose = Eigen::Translation3d(0., 6., 1.2) * Eigen::Isometry3d::Identity();
    world.addObstacle(sphere);
    Obstacle tilted;
    tilted.size = Eigen::Vector3d(1., 1., 1.);
    tilted.pose = Eigen::Translation3d(0., -6., 0.) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX());
    world.addObstacle(tilted);
    const ShortestPathBound bound(world, 0.5, 128.);
    EXPECT_EQ(bound.getPolygonCount(), 2u);
    const double start[2] = {-3., 0.}, goal[2] = {3., 0.};
    // Around the 16-gon inscribed in the circle of radius about 1.5: no longer than around the circle (tangents
    // and arc: 6.767), no shorter than around the 16-gon's incircle (6.737).
    const double reach = 1. + bound.getClearance();
    const double leg = std::sqrt(9. - reach * reach), arc = M_PI - 2. * std::acos(reach / 3.);
    EXPECT_GT(bound.length(start, goal), 6.73);
    EXPECT_LE(bound.length(start, goal), 2. * leg + reach * arc);
    const double aboveSphere[2][2] = {{-3., 6.}, {3., 6.}}, besideBox[2][2] = {{-3., -6.}, {3., -6.}};
    const double sphereLength = bound.length(aboveSphere[0], aboveSphere[1]);
    EXPECT_GT(sphereLength, 6.26);  // around the circle of radius 0.9: 6.272
    EXPECT_LT(sphereLength, 6.273);
    EXPECT_DOUBLE_EQ(bound.length(besideBox[0], besideBox[1]), 6.);
}

TEST(ShortestPathBound, NoValidatedPlanOfAFamilyInstanceBeatsIt)
{
    // Soundness on the generated disc families: every robot of a validated PP-ST-RRT plan (smoothed, so near its
    // shortest way) arrives no earlier than its path bound, which is never below its straight-line bound.
    for (const std::string family : {"rooms", "crossing", "field"})
    {
        SCOPED_TRACE(family);
        const MultiRobotProblem problem = scenarios::generateFamilyInstance(family, 8, 0);
        const auto &si = *problem.getSpaceInformation();
        PrioritizedSTRRT planner(problem.getSpaceInformation());
        planner.params().setParam("seed", "5");
        planner.params().setParam("smooth", "0.2");
        ASSERT_EQ(test::solveWith(planner, problem, 30.), ompl::base::PlannerStatus::EXACT_SOLUTION);
        const MultiRobotPlan &plan = planner.getPlan();
        const ValidationReport report = SolutionValidator(problem).validate(plan);
        ASSERT_TRUE(report.valid) << report.message;
        const std::vector<std::size_t> path = PlanQuality::pathSteps(si, plan);
        ASSERT_EQ(path.size(), si.getRobotCount());
        std::size_t above = 0;
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            const std::size_t straight = PlanQuality::straightLineSteps(si, plan, i);
            EXPECT_GE(plan.getArrival(i), path[i]) << "robot " << i;
            EXPECT_GE(path[i], straight) << "robot " << i;
            above += path[i] > straight ? 1 : 0;
        }
        if (family == "rooms")
            EXPECT_GT(above, 0u);  // every robot goes through a door
        const PlanQuality quality = PlanQuality::measure(si, plan);
        EXPECT_LE(quality.makespanPathRatio(), quality.makespanRatio());
        EXPECT_GE(quality.makespanPathRatio(), 1.);
        EXPECT_GE(quality.sumOfCostsPathRatio(), 1.);
    }
}

TEST(ShortestPathBound, ForArmsItIsTheStraightLineBound)
{
    const MultiRobotProblem problem = scenarios::generateFamilyInstance("planar_cell", 4, 0);
    const auto &si = *problem.getSpaceInformation();
    const MultiRobotPlan plan = test::straightLinePlan(problem);
    const PlanQuality quality = PlanQuality::measure(si, plan);
    EXPECT_GT(quality.makespanBound, 0u);
    EXPECT_EQ(quality.makespanPathBound, quality.makespanBound);
    EXPECT_EQ(quality.sumOfCostsPathBound, quality.sumOfCostsBound);
    const std::vector<std::size_t> path = PlanQuality::pathSteps(si, plan);
    for (std::size_t i = 0; i < path.size(); ++i)
        EXPECT_EQ(path[i], PlanQuality::straightLineSteps(si, plan, i));
    std::map<std::string, std::string> properties;
    quality.addProperties(properties);
    EXPECT_EQ(properties.at("makespan_path_bound INTEGER"), std::to_string(quality.makespanBound));
    EXPECT_EQ(properties.at("sum_of_costs_path_ratio REAL"), properties.at("sum_of_costs_ratio REAL"));
}
