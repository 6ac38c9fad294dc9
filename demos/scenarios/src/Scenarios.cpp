#include "ompl_parc/scenarios/Scenarios.h"

#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/ProblemFamilies.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <functional>
#include <map>

namespace ompl_parc::scenarios
{
    namespace
    {
        void checkEvenTeam(const std::string &scenario, std::size_t robots)
        {
            if (robots < 2 || robots % 2 != 0)
                throw ompl::Exception(scenario, "needs an even number of robots >= 2, got " + std::to_string(robots));
        }

        /** Discs with the given starts and goals, inside the square centred on them with half-extent
            half their spread plus two radii. */
        MultiRobotProblem makeDiscTeam(const std::string &name, const std::vector<std::vector<double>> &starts,
                                       const std::vector<std::vector<double>> &goals, double resolution)
        {
            double lo[2] = {starts[0][0], starts[0][1]}, hi[2] = {lo[0], lo[1]};
            for (const auto *set : {&starts, &goals})
                for (const auto &p : *set)
                    for (int d = 0; d < 2; ++d)
                    {
                        lo[d] = std::min(lo[d], p[d]);
                        hi[d] = std::max(hi[d], p[d]);
                    }
            const double half = 0.5 * std::max(hi[0] - lo[0], hi[1] - lo[1]) + 2. * MOBILE_RADIUS;
            ompl::base::RealVectorBounds bounds(2);
            for (int d = 0; d < 2; ++d)
            {
                const double c = 0.5 * (lo[d] + hi[d]);
                bounds.setLow(d, c - half);
                bounds.setHigh(d, c + half);
            }
            auto environment = std::make_shared<Environment>();
            std::vector<RobotPtr> team;
            for (std::size_t i = 0; i < starts.size(); ++i)
                team.push_back(
                    std::make_shared<DiscRobot>("r" + std::to_string(i), environment, MOBILE_RADIUS, bounds));
            return MultiRobotProblem(std::make_shared<MultiRobotSpaceInformation>(team, resolution), starts, goals,
                                     name);
        }
    }  // namespace

    MultiRobotProblem createMobileCross(std::size_t robots, double resolution)
    {
        checkEvenTeam("MobileCross", robots);
        const std::size_t pairs = robots / 2;
        const double reach = MOBILE_SPACING * static_cast<double>(pairs);
        std::vector<std::vector<double>> starts, goals;
        for (std::size_t i = 0; i < pairs; ++i)
        {
            const double y = (static_cast<double>(i) - 0.5 * static_cast<double>(pairs - 1)) * MOBILE_SPACING;
            starts.push_back({reach, y});
            goals.push_back({-reach, y});
            starts.push_back({-reach, y});
            goals.push_back({reach, y});
        }
        return makeDiscTeam("mobile_cross", starts, goals, resolution);
    }

    MultiRobotProblem createMobileCircle(std::size_t robots, double resolution)
    {
        checkEvenTeam("MobileCircle", robots);
        const double n = static_cast<double>(robots);
        const double radius = std::max(MOBILE_SPACING, MOBILE_SPACING * n / (2. * M_PI));
        std::vector<std::vector<double>> starts;
        for (std::size_t i = 0; i < robots; ++i)
        {
            const double angle = 2. * M_PI * static_cast<double>(i) / n;
            starts.push_back({radius * std::cos(angle), radius * std::sin(angle)});
        }
        std::vector<std::vector<double>> goals;
        for (std::size_t i = 0; i < robots; ++i)
            goals.push_back(starts[(i + robots / 2) % robots]);
        return makeDiscTeam("mobile_circle", starts, goals, resolution);
    }

    MultiRobotProblem createPlanarCross(std::size_t robots, double resolution)
    {
        checkEvenTeam("PlanarCross", robots);
        // Layout of the authors' published setup: two facing columns of bases 1.35 apart, rows 1.2 apart;
        // 3 links of 0.3 with collision radius 0.05, so an arm reaches 0.9 * cos(30 deg) = 0.78 > 0.675 and
        // every facing pair must coordinate. Walls are their radius-0.05 cylinders seen from above: thin
        // boards 0.1 wide, backboards at x = +-0.785, side walls 1.2 beyond the outermost rows.
        const std::vector<double> links = {0.3, 0.3, 0.3};
        const double width = 0.1, baseX = 0.675, board = 0.785, rowSpacing = 1.2, wall = 0.1, margin = 1.2;
        const std::size_t perColumn = robots / 2;
        const double outerRow = 0.5 * static_cast<double>(perColumn - 1) * rowSpacing;
        auto environment = std::make_shared<Environment>();
        environment->addBox2D("backboard_left", -board, 0., wall, 2. * (outerRow + margin));
        environment->addBox2D("backboard_right", board, 0., wall, 2. * (outerRow + margin));
        environment->addBox2D("wall_top", 0., outerRow + margin, 2. * board, wall);
        environment->addBox2D("wall_bottom", 0., -outerRow - margin, 2. * board, wall);

        ompl::base::RealVectorBounds limits(3);
        limits.setLow(-M_PI);
        limits.setHigh(M_PI);
        std::vector<RobotPtr> team;
        std::vector<std::vector<double>> starts, goals;
        for (std::size_t i = 0; i < robots; ++i)
        {
            const bool left = i < perColumn;
            const std::size_t row = left ? i : i - perColumn;
            const double y = (static_cast<double>(row) - 0.5 * static_cast<double>(perColumn - 1)) * rowSpacing;
            team.push_back(std::make_shared<PlanarArm>("arm" + std::to_string(i), environment, left ? -baseX : baseX, y,
                                                       left ? 0. : M_PI, links, width, limits));
            starts.push_back({M_PI / 6., 0., 0.});
            goals.push_back({-M_PI / 6., 0., 0.});
        }
        return MultiRobotProblem(std::make_shared<MultiRobotSpaceInformation>(team, resolution), starts, goals,
                                 "planar_cross");
    }

    namespace
    {
        /** Builds a scenario from (robots, resolution, task). */
        using Builder = std::function<MultiRobotProblem(std::size_t, double, std::size_t)>;

        /** A scenario with one task: \e build, rejecting any other task. */
        Builder singleTask(const std::string &name, MultiRobotProblem (*build)(std::size_t, double))
        {
            return [name, build](std::size_t robots, double resolution, std::size_t task)
            {
                if (task != 0)
                    throw ompl::Exception("Scenarios",
                                          "scenario '" + name + "' has only task 0, got task " + std::to_string(task));
                return build(robots, resolution);
            };
        }

        const std::map<std::string, Builder> &builders()
        {
            static const std::map<std::string, Builder> table = []
            {
                std::map<std::string, Builder> builders = {
                    {"mobile_circle", singleTask("mobile_circle", createMobileCircle)},
                    {"mobile_cross", singleTask("mobile_cross", createMobileCross)},
                    {"planar_cross", singleTask("planar_cross", createPlanarCross)},
                    {"panda_cage", [](std::size_t robots, double resolution, std::size_t task)
                     { return createPandaCage(robots, task, resolution); }}};
                // A generated family's task is the instance.
                for (const auto &family : familyNames())
                    builders[family] = [family](std::size_t robots, double resolution, std::size_t task)
                    {
                        if (task > UINT32_MAX)
                            throw ompl::Exception("Scenarios", "an instance must be below 2^32");
                        return generateFamilyInstance(family, robots, static_cast<std::uint32_t>(task), resolution);
                    };
                return builders;
            }();
            return table;
        }
    }  // namespace

    MultiRobotProblem createScenario(const std::string &name, std::size_t robots, double resolution, std::size_t task)
    {
        const auto it = builders().find(name);
        if (it == builders().end())
        {
            std::string valid;
            for (const auto &n : scenarioNames())
                valid += (valid.empty() ? "" : ", ") + n;
            throw ompl::Exception("Scenarios", "unknown scenario '" + name + "' (valid: " + valid + ")");
        }
        checkTeamSize(robots, "scenario '" + name + "'");  // before the robots are built
        return it->second(robots, resolution, task);
    }

    std::vector<std::string> scenarioNames()
    {
        std::vector<std::string> names;
        for (const auto &entry : builders())
            names.push_back(entry.first);
        return names;
    }
}  // namespace ompl_parc::scenarios
