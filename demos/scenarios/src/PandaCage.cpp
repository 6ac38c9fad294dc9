#include "ompl_parc/scenarios/PandaCage.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/scenarios/ConflictingPairs.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace ompl_parc::scenarios
{
    namespace
    {
        // The authors' layout (parasollab/comotion: apps/panda_cage.cpp and the task file it compiles in,
        // apps/panda_cage_builtin_tasks.hpp, as in the fork aezkcl/comotion): the cage is the frame of
        // a box 1 m (x) by 2 m (y) by 1 m (z) centred at the origin, 12 bars of radius 5 cm on its edges, open
        // faces. Pandas stand 0.25 m outside its x faces (x = -0.75, and x = +0.75 for 16 robots) facing it,
        // on the floor 0.5 m below it (z = -1) or upside down from the ceiling 0.5 m above it (z = +1), in rows
        // along y. An end effector target is drawn uniformly from the part of the cage within 0.855 m of its
        // base (the Panda's reach); each target gets 20 IK restarts.
        constexpr double CAGE_HALF_X = 0.5, CAGE_HALF_Y = 1.0, CAGE_HALF_Z = 0.5, BAR_RADIUS = 0.05;
        constexpr double BASE_X = 0.75, BASE_Z = 1.0, REACH = 0.855;
        constexpr unsigned int IK_RESTARTS = 20;

        void checkTask(std::size_t robots, std::size_t task)
        {
            const auto &sizes = pandaCageTeamSizes();
            if (std::find(sizes.begin(), sizes.end(), robots) == sizes.end())
                throw ompl::Exception("PandaCage", "needs 2, 4, 8 or 16 robots, got " + std::to_string(robots));
            if (task >= PANDA_CAGE_TASKS)
                throw ompl::Exception("PandaCage", "task must be below " + std::to_string(PANDA_CAGE_TASKS) + ", got " +
                                                       std::to_string(task));
        }

        /** The 12 bars on the edges of the cage box, in the authors' order: 4 posts along z, 4 bars along x,
            4 along y. */
        EnvironmentPtr createCage()
        {
            const Eigen::Vector3d half = pandaCageInterior().max();
            auto environment = std::make_shared<Environment>();
            for (int axis : {2, 0, 1})
                for (int corner = 0; corner < 4; ++corner)
                {
                    // The bar along `axis` through corner (+-, +-) of the other two axes u and v.
                    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
                    Eigen::Vector3d center = Eigen::Vector3d::Zero();
                    center[u] = corner % 2 == 0 ? -half[u] : half[u];
                    center[v] = corner / 2 == 0 ? -half[v] : half[v];
                    Obstacle bar;
                    bar.name = "bar" + std::to_string(environment->getObstacles().size());
                    bar.shape = Obstacle::Shape::CYLINDER;
                    bar.size = Eigen::Vector3d(BAR_RADIUS, 0., 2. * half[axis]);
                    bar.pose =
                        Eigen::Translation3d(center) *
                        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Unit(axis));
                    environment->addObstacle(bar);
                }
            return environment;
        }

        /** The base poses of a team of \e robots: rows along y on the -x side (and the +x side for 16), the
            floor level first, then the ceiling (none for 2 robots). The Panda reaches along its base's x axis,
            so +x side arms are turned by pi about z; ceiling arms hang upside down (turned by pi about x).
            Ours, not the authors': 2 robots stand at y = +-0.25 (the floor row of 4), not +-0.5, where their
            reachable parts of the cage share a strip only 0.3 m wide and hardly a task needs coordination. */
        std::vector<Eigen::Isometry3d> basePoses(std::size_t robots)
        {
            const std::vector<double> rows =
                robots <= 4 ? std::vector<double>{-0.25, 0.25} : std::vector<double>{-0.75, -0.25, 0.25, 0.75};
            std::vector<Eigen::Isometry3d> poses;
            for (double side : robots == 16 ? std::vector<double>{-1., 1.} : std::vector<double>{-1.})
                for (double level : robots == 2 ? std::vector<double>{-1.} : std::vector<double>{-1., 1.})
                    for (double y : rows)
                        poses.push_back(UrdfArm::pose(side * BASE_X, y, level * BASE_Z, level > 0. ? M_PI : 0., 0.,
                                                      side > 0. ? M_PI : 0.));
            return poses;
        }

        /** A point drawn uniformly from the part of the cage within REACH of \e base (rejection sampling in
            the box around that part). */
        Eigen::Vector3d drawTarget(const Eigen::Vector3d &base, std::mt19937 &rng)
        {
            const Eigen::AlignedBox3d reach(base - Eigen::Vector3d::Constant(REACH),
                                            base + Eigen::Vector3d::Constant(REACH));
            const Eigen::AlignedBox3d box = pandaCageInterior().intersection(reach);
            if (box.isEmpty())
                throw ompl::Exception("PandaCage", "a base is out of reach of the cage");
            std::uniform_real_distribution<double> x(box.min().x(), box.max().x()), y(box.min().y(), box.max().y()),
                z(box.min().z(), box.max().z());
            for (;;)
            {
                const Eigen::Vector3d p(x(rng), y(rng), z(rng));
                if ((p - base).norm() <= REACH)
                    return p;
            }
        }

        /** Valid, mutually collision-free configurations of the whole team with every end effector in the
            cage (a start or a goal set): robots placed in order, each trying up to \e attempts targets; the
            team starts over (up to \e attempts times) when one finds no room. */
        std::vector<std::vector<double>> placeTeam(const std::vector<std::shared_ptr<UrdfArm>> &team,
                                                   unsigned int attempts, std::mt19937 &rng)
        {
            CollisionBody body, other;
            for (unsigned int restart = 0; restart < attempts; ++restart)
            {
                std::vector<std::vector<double>> placed;
                for (std::size_t r = 0; r < team.size() && placed.size() == r; ++r)
                {
                    std::vector<double> q;
                    for (unsigned int attempt = 0; attempt < attempts; ++attempt)
                    {
                        const Eigen::Vector3d target = drawTarget(team[r]->getBasePose().translation(), rng);
                        if (!team[r]->solvePositionIk(target, rng, q, IK_RESTARTS))
                            continue;
                        team[r]->computeBody(q.data(), body);
                        bool free = true;
                        for (std::size_t j = 0; j < placed.size() && free; ++j)
                        {
                            team[j]->computeBody(placed[j].data(), other);
                            free = !bodiesCollide(body, other);
                        }
                        if (free)
                        {
                            placed.push_back(q);
                            break;
                        }
                    }
                }
                if (placed.size() == team.size())
                    return placed;
            }
            throw ompl::Exception("PandaCage",
                                  "could not place all " + std::to_string(team.size()) + " end effectors in the cage");
        }
    }  // namespace

    const std::vector<std::size_t> &pandaCageTeamSizes()
    {
        static const std::vector<std::size_t> sizes = {2, 4, 8, 16};
        return sizes;
    }

    Eigen::AlignedBox3d pandaCageInterior()
    {
        const Eigen::Vector3d half(CAGE_HALF_X, CAGE_HALF_Y, CAGE_HALF_Z);
        return {-half, half};
    }

    MultiRobotProblem createPandaCage(std::size_t robots, std::size_t task, double resolution)
    {
        checkTask(robots, task);
        const MultiRobotProblem stored = ScenarioFile::fromJson(pandaCageTaskJson(robots, task));
        return stored.getSpaceInformation()->getResolution() == resolution ? stored : stored.withResolution(resolution);
    }

    MultiRobotProblem generatePandaCageTask(std::size_t robots, std::size_t task)
    {
        checkTask(robots, task);
        return generatePandaCageProblem(robots, static_cast<std::uint32_t>(1000 * robots + task),
                                        "panda_cage_" + std::to_string(robots) + "_" + std::to_string(task));
    }

    MultiRobotProblem generatePandaCageProblem(std::size_t robots, std::uint32_t seed, const std::string &name)
    {
        checkTask(robots, 0);
        const auto environment = createCage();
        std::vector<std::shared_ptr<UrdfArm>> team;
        for (const auto &base : basePoses(robots))
            team.push_back(std::make_shared<UrdfArm>("panda" + std::to_string(team.size()), environment, models::pandaUrdf(),
                                                     "panda_link0", "panda_link8", base));
        // The authors' effort: 100 targets per robot and 100 team restarts for 2 robots, 200 for 4, ... 400 for 16.
        const auto attempts = static_cast<unsigned int>(100 * std::log2(static_cast<double>(robots)));
        std::mt19937 rng(seed);
        // A task the robots might solve without coordinating is drawn again: with each of ARC seeds 1, 2 and 3,
        // some pair's individual paths must collide (one seed alone lets lucky paths through).
        constexpr unsigned int CANDIDATES = 200;
        const auto needsCoordination = [](const MultiRobotProblem &problem)
        {
            for (unsigned int seed = 1; seed <= 3; ++seed)
                if (countConflictingPairs(problem, seed) == 0)
                    return false;
            return true;
        };
        const auto si = std::make_shared<MultiRobotSpaceInformation>(std::vector<RobotPtr>(team.begin(), team.end()));
        for (unsigned int candidate = 0; candidate < CANDIDATES; ++candidate)
        {
            auto starts = placeTeam(team, attempts, rng);
            auto goals = placeTeam(team, attempts, rng);
            MultiRobotProblem problem(si, std::move(starts), std::move(goals), name);
            if (needsCoordination(problem))
                return problem;
        }
        throw ompl::Exception(
            "PandaCage", "no task among " + std::to_string(CANDIDATES) + " candidates needs the robots to coordinate");
    }
}  // namespace ompl_parc::scenarios
