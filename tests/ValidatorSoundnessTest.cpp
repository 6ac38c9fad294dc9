/* The fast SolutionValidator against a dense reference: it must never accept a plan that dense sampling rejects,
   and its displacement bounds must hold. */
#include "TestProblems.h"

#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/DisplacementBound.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <gtest/gtest.h>

#include <random>

using namespace ompl_parc;

namespace
{
    /** One capsule of a body as an FCL shape with its pose, radius shrunk by \e shrink (at least 1e-9). */
    std::pair<std::shared_ptr<fcl::CollisionGeometryd>, fcl::Transform3d> fclCapsule(const CollisionBody &body,
                                                                                     std::size_t c, double shrink)
    {
        const Eigen::Vector3d a(body.ax_[c], body.ay_[c], body.az_[c]), b(body.bx_[c], body.by_[c], body.bz_[c]);
        const double radius = std::max(body.radius_[c] - shrink, 1e-9);
        fcl::Transform3d pose = fcl::Transform3d::Identity();
        pose.translation() = 0.5 * (a + b);
        if ((b - a).norm() == 0.)
            return {std::make_shared<fcl::Sphered>(radius), pose};
        pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), b - a).toRotationMatrix();
        return {std::make_shared<fcl::Capsuled>(radius, (b - a).norm()), pose};
    }

    bool touch(const std::pair<std::shared_ptr<fcl::CollisionGeometryd>, fcl::Transform3d> &x,
               const std::shared_ptr<fcl::CollisionGeometryd> &g, const fcl::Transform3d &pose)
    {
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        return fcl::collide(x.first.get(), x.second, g.get(), pose, request, result) > 0;
    }

    /** The reference: the previous validator's semantics by brute force. Every timestep with radii shrunk by the
        contact tolerance and \e samples evenly spaced instants per interval with radii shrunk by the slack (half a
        timestep), every configuration against bounds, obstacles, its self pairs and every other robot, FCL on
        every capsule pair. The plan is assumed to respect its endpoints and the motion bound. */
    bool denseValid(const MultiRobotProblem &problem, const MultiRobotPlan &plan, unsigned int samples)
    {
        const auto &si = *problem.getSpaceInformation();
        const double slack = 0.5 / si.getResolution();
        const auto &obstacles = si.getEnvironment()->getObstacles();
        std::vector<std::shared_ptr<fcl::CollisionGeometryd>> walls;
        for (const auto &o : obstacles)
            walls.push_back(Environment::createGeometry(o));
        std::vector<CollisionBody> bodies(si.getRobotCount());
        for (std::size_t t = 0; t <= plan.getMakespan(); ++t)
            for (unsigned int sub = 0; sub < (t < plan.getMakespan() ? samples : 1u); ++sub)
            {
                const double s = static_cast<double>(sub) / samples, shrink = sub == 0 ? 1e-6 : slack;
                for (std::size_t i = 0; i < si.getRobotCount(); ++i)
                {
                    std::vector<double> a(plan.getDimension(i)), b(a.size()), q(a.size());
                    plan.getConfig(i, t, a.data());
                    plan.getConfig(i, t + 1, b.data());
                    for (std::size_t d = 0; d < q.size(); ++d)
                    {
                        q[d] = a[d] + s * (b[d] - a[d]);
                        if (q[d] < si.getRobot(i)->getBounds().low[d] || q[d] > si.getRobot(i)->getBounds().high[d])
                            return false;
                    }
                    si.getRobot(i)->computeBody(q.data(), bodies[i]);
                }
                for (std::size_t i = 0; i < si.getRobotCount(); ++i)
                {
                    for (std::size_t c = 0; c < bodies[i].size(); ++c)
                    {
                        const auto capsule = fclCapsule(bodies[i], c, shrink);
                        for (std::size_t k = 0; k < walls.size(); ++k)
                            if (touch(capsule, walls[k], obstacles[k].pose))
                                return false;
                        for (std::size_t j = i + 1; j < si.getRobotCount(); ++j)
                            for (std::size_t e = 0; e < bodies[j].size(); ++e)
                            {
                                const auto other = fclCapsule(bodies[j], e, shrink);
                                if (touch(capsule, other.first, other.second))
                                    return false;
                            }
                    }
                    for (const auto &pair : si.getRobot(i)->getSelfCollisionPairs())
                    {
                        const auto other = fclCapsule(bodies[i], pair.second, shrink);
                        if (touch(fclCapsule(bodies[i], pair.first, shrink), other.first, other.second))
                            return false;
                    }
                }
            }
        return true;
    }

    /** A path through \e waypoints laid on the timestep grid, waiting a random number of timesteps at each. */
    std::vector<double> randomPath(const std::vector<std::vector<double>> &waypoints, double resolution,
                                   std::mt19937 &rng)
    {
        std::uniform_int_distribution<int> wait(0, 3);
        std::vector<double> path = waypoints[0];
        for (std::size_t w = 1; w < waypoints.size(); ++w)
        {
            const auto segment = test::straightLine(waypoints[w - 1], waypoints[w], resolution);
            path.insert(path.end(), segment.begin() + static_cast<std::ptrdiff_t>(waypoints[w].size()), segment.end());
            for (int k = wait(rng); k > 0; --k)
                path.insert(path.end(), waypoints[w].begin(), waypoints[w].end());
        }
        return path;
    }

    std::size_t templateSize(const Robot &robot)
    {
        CollisionBody body;
        robot.computeBody(std::vector<double>(robot.getDimension(), 0.).data(), body);
        return body.size();
    }

    struct Tally
    {
        std::size_t denseRejected{0}, denseAccepted{0}, onlyFastRejected{0};
    };

    /** Both kinds of plan occurred (the comparison tested something); records how many only the fast validator
        rejected. */
    void expectBothOutcomes(const Tally &tally, std::size_t atLeastRejected)
    {
        EXPECT_GE(tally.denseRejected, atLeastRejected);
        EXPECT_GE(tally.denseAccepted, 10u);
        ::testing::Test::RecordProperty("rejected_only_by_the_fast_validator",
                                        static_cast<int>(tally.onlyFastRejected));
    }

    void compare(const MultiRobotSpaceInformationPtr &si, const MultiRobotPlan &plan, Tally &tally);

    /** \e plans plans of \e base's arms, each arm through \e waypoints configurations drawn within \e spread of its
        start (in its bounds), checked both ways. */
    Tally compareJitteredArms(const MultiRobotProblem &base, unsigned int seed, double spread, int waypoints, int plans)
    {
        const auto &si = base.getSpaceInformation();
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> perturb(-spread, spread);
        Tally tally;
        for (int k = 0; k < plans; ++k)
        {
            MultiRobotPlan plan(*si);
            for (std::size_t i = 0; i < si->getRobotCount(); ++i)
            {
                const auto &limits = si->getRobot(i)->getBounds();
                std::vector<std::vector<double>> path = {base.getStart(i)};
                for (int w = 0; w < waypoints; ++w)
                {
                    std::vector<double> q = base.getStart(i);
                    for (std::size_t d = 0; d < q.size(); ++d)
                        q[d] = std::clamp(q[d] + perturb(rng), limits.low[d], limits.high[d]);
                    path.push_back(q);
                }
                plan.setRobotPath(i, randomPath(path, si->getResolution(), rng));
            }
            compare(si, plan, tally);
        }
        return tally;
    }

    /** Checks one plan both ways: whatever dense sampling rejects, the fast validator rejects, with every value
        of the substeps option (it sets the fewest samples, never whether instants between timesteps are checked). */
    void compare(const MultiRobotSpaceInformationPtr &si, const MultiRobotPlan &plan, Tally &tally)
    {
        const MultiRobotProblem problem = test::problemOfPlan(si, plan);
        const bool dense = denseValid(problem, plan, 32);
        const auto fast = SolutionValidator(problem).validate(plan);
        if (!dense)
        {
            ++tally.denseRejected;
            EXPECT_FALSE(fast.valid) << "accepted a plan dense sampling rejects";
            for (unsigned int substeps : {0u, 1u, 2u})
            {
                ValidationOptions options;
                options.substeps = substeps;
                EXPECT_FALSE(SolutionValidator(problem, options).validate(plan).valid)
                    << "accepted with substeps " << substeps << " a plan dense sampling rejects";
            }
        }
        else
        {
            ++tally.denseAccepted;
            tally.onlyFastRejected += fast.valid ? 0 : 1;
        }
    }
}  // namespace

TEST(ValidatorSoundness, NeverAcceptsWhatDenseSamplingRejectsForDiscs)
{
    // Discs of radii 0.02 (smaller than the slack: points between timesteps), 0.05 and 0.2 at resolution 16 (a
    // timestep moves 1/16) around a wall 0.005 thick: crossings between timesteps, grazes, pair conflicts.
    auto env = std::make_shared<Environment>();
    env->addBox2D("wall", 0., 0., 0.005, 1.);
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(-1.);
    bounds.setHigh(1.);
    std::vector<RobotPtr> team;
    for (double radius : {0.02, 0.05, 0.2})
        team.push_back(std::make_shared<DiscRobot>("r" + std::to_string(team.size()), env, radius, bounds));
    const auto si = std::make_shared<MultiRobotSpaceInformation>(team, 16.);
    // Robot 0 left of the wall, robot 1 right of it, robot 2 sweeping left and right above it; waypoints jittered
    // so that some plans cross the wall, clip its end or bring two robots together.
    std::mt19937 rng(11);
    std::normal_distribution<double> jitter(0., 0.15);
    const std::vector<std::vector<double>> home = {{-0.3, 0.}, {0.3, 0.}, {0.6, 0.78}};
    Tally tally;
    for (int k = 0; k < 150; ++k)
    {
        MultiRobotPlan plan(*si);
        for (std::size_t i = 0; i < team.size(); ++i)
        {
            std::vector<std::vector<double>> waypoints;
            for (int w = 0; w < 4; ++w)
            {
                const double x = i == 2 && w % 2 == 1 ? -home[i][0] : home[i][0];
                waypoints.push_back({std::clamp(x + jitter(rng), -0.75, 0.75),
                                     std::clamp(home[i][1] + (i == 2 ? 0.3 : 2.) * jitter(rng), -0.75, 0.75)});
            }
            plan.setRobotPath(i, randomPath(waypoints, si->getResolution(), rng));
        }
        compare(si, plan, tally);
    }
    expectBothOutcomes(tally, 30u);
}

TEST(ValidatorSoundness, NeverAcceptsWhatDenseSamplingRejectsForArms)
{
    // Two facing planar arms of Planar Cross at resolution 8 (an eighth of a radian per timestep), each through three
    // waypoints jittered around its start: self-collisions, wall hits and arm-arm conflicts at and between
    // timesteps.
    expectBothOutcomes(compareJitteredArms(scenarios::createPlanarCross(2, 8.), 5, 0.7, 3, 60), 10u);
}

TEST(ValidatorSoundness, NeverAcceptsWhatDenseSamplingRejectsForPandas)
{
    // Two Pandas of Panda Cage at resolution 6 (a sixth of a radian per timestep: links sweep centimetres between
    // timesteps), each through two waypoints jittered around its start: hits of the cage and the table, self-collisions
    // and arm-arm contacts, at and between timesteps, where the fast validator skips intervals whose grown capsules
    // touch nothing.
    expectBothOutcomes(compareJitteredArms(scenarios::createPandaCage(2, 0, 6.), 11, 0.08, 2, 40), 5u);
}

TEST(ValidatorSoundness, DisplacementBoundsHoldForEveryRobotKind)
{
    // On straight motions, no capsule end point moves faster than the bound says (sampled finely).
    const auto disc = scenarios::createMobileCross(2);
    const auto arms = scenarios::createPlanarCross(2);
    const auto panda = scenarios::createPandaCage(4, 0);
    std::mt19937 rng(3);
    for (const auto *problem : {&disc, &arms, &panda})
    {
        const Robot &robot = *problem->getSpaceInformation()->getRobot(0);
        const DisplacementBound bound(robot);
        const auto &limits = robot.getBounds();
        for (int k = 0; k < 50; ++k)
        {
            std::vector<double> q(robot.getDimension()), dq(robot.getDimension()), x(robot.getDimension());
            for (std::size_t d = 0; d < q.size(); ++d)
            {
                q[d] = std::uniform_real_distribution<double>(limits.low[d], limits.high[d])(rng);
                dq[d] = std::uniform_real_distribution<double>(-0.5, 0.5)(rng);
            }
            const double speed = bound(dq.data());
            for (std::size_t c = 0; c < templateSize(robot); ++c)
                ASSERT_LE(bound.capsuleBound(c, dq.data()), speed * (1. + 1e-12))
                    << robot.getKind() << " capsule " << c;
            CollisionBody previous, body;
            robot.computeBody(q.data(), previous);
            constexpr int STEPS = 200;
            for (int s = 1; s <= STEPS; ++s)
            {
                for (std::size_t d = 0; d < q.size(); ++d)
                    x[d] = q[d] + dq[d] * s / STEPS;
                robot.computeBody(x.data(), body);
                for (std::size_t c = 0; c < body.size(); ++c)
                    for (const auto &[p, r] :
                         {std::pair{Eigen::Vector3d(previous.ax_[c], previous.ay_[c], previous.az_[c]),
                                    Eigen::Vector3d(body.ax_[c], body.ay_[c], body.az_[c])},
                          std::pair{Eigen::Vector3d(previous.bx_[c], previous.by_[c], previous.bz_[c]),
                                    Eigen::Vector3d(body.bx_[c], body.by_[c], body.bz_[c])}})
                    {
                        ASSERT_LE((r - p).norm(), speed / STEPS * (1. + 1e-9) + 1e-12)
                            << robot.getKind() << " capsule " << c;
                        ASSERT_LE((r - p).norm(), bound.capsuleBound(c, dq.data()) / STEPS * (1. + 1e-9) + 1e-12)
                            << robot.getKind() << " capsule " << c << " (its own bound)";
                    }
                previous = body;
            }
        }
    }
}
