#include "ompl_parc/scenarios/PandaCage.h"

#include "ompl_parc/CapsuleCollision.h"
#include "ompl_parc/UrdfArm.h"

#include <ompl/util/Exception.h>

#include <cmath>
#include <random>

namespace ompl_parc::scenarios
{
    namespace
    {
        // Layout: a cage of 4 vertical bars (radius 1 cm) at the corners of a square around the z axis
        // (0.5 m wide for up to 4 robots, wider for more hands), from the floor to the ceiling 1.6 m up. Half the
        // Pandas stand on the floor, half hang from the ceiling, evenly spaced on circles around the cage (ceiling ones
        // offset by half a step), all facing its axis. End effectors go to points inside the cage: floor arms' in its
        // lower half, ceiling arms' in its upper half. There is no floor or ceiling slab: the bases rest on them.
        constexpr double BAR_RADIUS = 0.01, CEILING = 1.6;
        constexpr unsigned int ATTEMPTS_PER_ROBOT = 20;

        /** Half the cage's width; targets keep 0.1 from its bars, bases stand 0.3 outside them. */
        double cageHalf(std::size_t robots)
        {
            return robots <= 4 ? 0.25 : robots == 8 ? 0.35 : 0.45;
        }

        /** Robot \e robot's configuration for a random target inside the cage reached by position IK,
            valid alone and against the configurations in \e placed; empty if none was found. */
        std::vector<double> placeEndEffector(const std::vector<std::shared_ptr<UrdfArm>> &team, std::size_t robot,
                                             const std::vector<std::vector<double>> &placed, std::mt19937 &rng)
        {
            const UrdfArm &arm = *team[robot];
            const bool floor = robot % 2 == 0;
            const double half = cageHalf(team.size()) - 0.1;
            std::uniform_real_distribution<double> xy(-half, half);
            std::uniform_real_distribution<double> z(floor ? 0.35 : 0.9, floor ? 0.7 : 1.25);
            CollisionBody body, other;
            std::vector<double> q;
            for (unsigned int attempt = 0; attempt < ATTEMPTS_PER_ROBOT; ++attempt)
            {
                if (!arm.solvePositionIk(Eigen::Vector3d(xy(rng), xy(rng), z(rng)), rng, q, 10))
                    continue;
                arm.computeBody(q.data(), body);
                bool free = true;
                for (std::size_t j = 0; j < placed.size() && free; ++j)
                {
                    team[j]->computeBody(placed[j].data(), other);
                    free = !bodiesCollide(body, other);
                }
                if (free)
                    return q;
            }
            return {};
        }

        /** Valid, mutually collision-free configurations of the whole team (a start or a goal set); placed
            greedily robot by robot, starting over when a robot finds no room. */
        std::vector<std::vector<double>> placeTeam(const std::vector<std::shared_ptr<UrdfArm>> &team, std::mt19937 &rng)
        {
            constexpr int TEAM_ATTEMPTS = 50;
            for (int attempt = 0; attempt < TEAM_ATTEMPTS; ++attempt)
            {
                std::vector<std::vector<double>> placed;
                while (placed.size() < team.size())
                {
                    auto q = placeEndEffector(team, placed.size(), placed, rng);
                    if (q.empty())
                        break;
                    placed.push_back(std::move(q));
                }
                if (placed.size() == team.size())
                    return placed;
            }
            throw ompl::Exception(
                "PandaCage", "could not place all " + std::to_string(team.size()) + " end effectors inside the cage");
        }
    }  // namespace

    MultiRobotProblem createPandaCage(std::size_t robots, std::size_t task, double resolution)
    {
        if (robots != 2 && robots != 4 && robots != 8)  // 16 do not fit with this task generator yet
            throw ompl::Exception("PandaCage", "needs 2, 4 or 8 robots, got " + std::to_string(robots));
        if (task >= PANDA_CAGE_TASKS)
            throw ompl::Exception("PandaCage", "task must be below " + std::to_string(PANDA_CAGE_TASKS) + ", got " +
                                                   std::to_string(task));
        auto environment = std::make_shared<Environment>();
        for (int k = 0; k < 4; ++k)
        {
            Obstacle bar;
            bar.name = "bar" + std::to_string(k);
            bar.shape = Obstacle::Shape::CYLINDER;
            bar.size = Eigen::Vector3d(BAR_RADIUS, 0., CEILING);
            const double c = cageHalf(robots);
            bar.pose.translation() = Eigen::Vector3d(k % 2 == 0 ? -c : c, k / 2 == 0 ? -c : c, 0.5 * CEILING);
            environment->addObstacle(bar);
        }

        // Robots alternate floor (even index) and ceiling (odd), so every team has both.
        const std::size_t perLevel = robots / 2;
        std::vector<std::shared_ptr<UrdfArm>> team;
        for (std::size_t i = 0; i < robots; ++i)
        {
            const bool floor = i % 2 == 0;
            const double angle =
                2. * M_PI * (static_cast<double>(i / 2) + (floor ? 0. : 0.5)) / static_cast<double>(perLevel);
            const double r = cageHalf(robots) + 0.3, x = r * std::cos(angle), y = r * std::sin(angle);
            // Facing the axis (the arm reaches along its base x axis); ceiling arms upside down (roll pi).
            const auto base = floor ? UrdfArm::pose(x, y, 0., 0., 0., angle + M_PI)
                                    : UrdfArm::pose(x, y, CEILING, M_PI, 0., angle + M_PI);
            team.push_back(std::make_shared<UrdfArm>("panda" + std::to_string(i), environment, pandaUrdf(),
                                                     "panda_link0", "panda_link8", base));
        }

        std::mt19937 rng(static_cast<unsigned int>(1000 * robots + task));
        const auto starts = placeTeam(team, rng);
        const auto goals = placeTeam(team, rng);
        return MultiRobotProblem(
            std::make_shared<MultiRobotSpaceInformation>(std::vector<RobotPtr>(team.begin(), team.end()), resolution),
            starts, goals, "panda_cage");
    }
}  // namespace ompl_parc::scenarios
