#include "ompl_parc/scenarios/ProblemFamilies.h"

#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <ompl/util/Exception.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/seed_seq.hpp>
#include <boost/random/uniform_int_distribution.hpp>
#include <boost/random/uniform_real_distribution.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <map>

namespace ompl_parc::scenarios
{
    namespace
    {
        using Rng = boost::random::mt19937;
        using Point = std::vector<double>;

        constexpr double RADIUS = 0.5;
        /** Draws of a family's random layout before it gives up on an instance. */
        constexpr unsigned int LAYOUT_DRAWS = 200;

        double uniform(Rng &rng, double low, double high)
        {
            return boost::random::uniform_real_distribution<double>(low, high)(rng);
        }

        std::size_t uniformIndex(Rng &rng, std::size_t size)
        {
            return boost::random::uniform_int_distribution<std::size_t>(0, size - 1)(rng);
        }

        /** Fisher-Yates with Boost's distribution: std::shuffle's output differs between standard libraries. */
        template <typename T>
        void shuffle(std::vector<T> &values, Rng &rng)
        {
            for (std::size_t i = values.size(); i > 1; --i)
                std::swap(values[i - 1], values[uniformIndex(rng, i)]);
        }

        /** A disc world: the obstacles and the square or rectangle the discs' centres stay in. */
        struct DiscWorld
        {
            EnvironmentPtr environment{std::make_shared<Environment>()};
            ompl::base::RealVectorBounds bounds{2};

            DiscWorld(double lowX, double lowY, double highX, double highY)
            {
                bounds.setLow(0, lowX);
                bounds.setLow(1, lowY);
                bounds.setHigh(0, highX);
                bounds.setHigh(1, highY);
            }

            DiscRobot probe() const { return DiscRobot("probe", environment, RADIUS, bounds); }

            /** The points of \e candidates a disc may stand on. */
            std::vector<Point> freePoints(const std::vector<Point> &candidates) const
            {
                const DiscRobot disc = probe();
                std::vector<Point> free;
                for (const auto &p : candidates)
                    if (disc.isValid(p.data()))
                        free.push_back(p);
                return free;
            }

            /** The points of \e points in the largest free region, found by a flood fill of disc centres on a
                grid of step 0.25 (neighbours joined when the midpoint is free too); a point joins the region
                of a free grid node within 0.25 of it. */
            std::vector<Point> connectedPoints(const std::vector<Point> &points) const
            {
                const DiscRobot disc = probe();
                constexpr double STEP = 0.25;
                const double x0 = bounds.low[0], y0 = bounds.low[1];
                const auto nx = static_cast<std::size_t>((bounds.high[0] - x0) / STEP) + 1,
                           ny = static_cast<std::size_t>((bounds.high[1] - y0) / STEP) + 1;
                const auto node = [&](std::size_t i, std::size_t j) -> Point {
                    return {x0 + STEP * static_cast<double>(i), y0 + STEP * static_cast<double>(j)};
                };
                std::vector<char> free(nx * ny);
                for (std::size_t i = 0; i < nx; ++i)
                    for (std::size_t j = 0; j < ny; ++j)
                        free[i * ny + j] = disc.isValid(node(i, j).data()) ? 1 : 0;
                // Label the regions; the largest one wins.
                std::vector<std::size_t> label(nx * ny, 0);
                std::vector<std::size_t> sizes(1, 0);
                for (std::size_t seed = 0; seed < free.size(); ++seed)
                {
                    if (!free[seed] || label[seed] != 0)
                        continue;
                    sizes.push_back(0);
                    std::deque<std::size_t> queue{seed};
                    label[seed] = sizes.size() - 1;
                    while (!queue.empty())
                    {
                        const std::size_t c = queue.front(), i = c / ny, j = c % ny;
                        queue.pop_front();
                        ++sizes.back();
                        const std::pair<long, long> moves[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                        for (const auto &[di, dj] : moves)
                        {
                            const long a = static_cast<long>(i) + di, b = static_cast<long>(j) + dj;
                            if (a < 0 || b < 0 || a >= static_cast<long>(nx) || b >= static_cast<long>(ny))
                                continue;
                            const std::size_t n = static_cast<std::size_t>(a) * ny + static_cast<std::size_t>(b);
                            const Point mid = {x0 + STEP * (static_cast<double>(i) + 0.5 * di),
                                               y0 + STEP * (static_cast<double>(j) + 0.5 * dj)};
                            if (free[n] && label[n] == 0 && disc.isValid(mid.data()))
                            {
                                label[n] = label[seed];
                                queue.push_back(n);
                            }
                        }
                    }
                }
                const std::size_t largest =
                    static_cast<std::size_t>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
                std::vector<Point> connected;
                for (const auto &p : points)
                {
                    const auto i = static_cast<std::size_t>(std::lround((p[0] - x0) / STEP)),
                               j = static_cast<std::size_t>(std::lround((p[1] - y0) / STEP));
                    if (largest != 0 && i < nx && j < ny && label[i * ny + j] == largest)
                        connected.push_back(p);
                }
                return connected;
            }

            MultiRobotProblem problem(const std::string &name, std::vector<Point> starts, std::vector<Point> goals,
                                      double resolution) const
            {
                std::vector<RobotPtr> team;
                for (std::size_t i = 0; i < starts.size(); ++i)
                    team.push_back(std::make_shared<DiscRobot>("r" + std::to_string(i), environment, RADIUS, bounds));
                return MultiRobotProblem(std::make_shared<MultiRobotSpaceInformation>(team, resolution),
                                         std::move(starts), std::move(goals), name);
            }
        };

        /** Draws one cell for each robot from its group's cells (no cell twice): \e groupOf[r] is robot r's group
            and \e cells[g] the cells of group g. Throws if a group has too few cells. */
        std::vector<Point> drawCells(const std::vector<std::size_t> &groupOf, std::vector<std::vector<Point>> cells,
                                     Rng &rng)
        {
            for (auto &group : cells)
                shuffle(group, rng);
            std::vector<Point> drawn;
            for (std::size_t g : groupOf)
            {
                if (cells[g].empty())
                    throw ompl::Exception("ProblemFamilies", "a region of the layout has too few free cells");
                drawn.push_back(cells[g].back());
                cells[g].pop_back();
            }
            return drawn;
        }

        /** Each robot's group (balanced, in random order) and a different group for its goal, drawn among the
            groups with room left (each of \e groups has \e capacity cells). */
        std::pair<std::vector<std::size_t>, std::vector<std::size_t>> crossGroups(std::size_t robots,
                                                                                  std::size_t groups,
                                                                                  std::size_t capacity, Rng &rng)
        {
            std::vector<std::size_t> from(robots), to;
            for (std::size_t r = 0; r < robots; ++r)
                from[r] = r % groups;
            shuffle(from, rng);
            std::vector<std::size_t> load(groups, 0);
            for (std::size_t g : from)
            {
                std::vector<std::size_t> choices;
                for (std::size_t h = 0; h < groups; ++h)
                    if (h != g && load[h] < capacity)
                        choices.push_back(h);
                if (choices.empty())
                    throw ompl::Exception("ProblemFamilies", "no room left for a goal");
                to.push_back(choices[uniformIndex(rng, choices.size())]);
                ++load[to.back()];
            }
            return {from, to};
        }

        std::string instanceName(const std::string &family, std::size_t robots, std::uint32_t instance)
        {
            return family + "_" + std::to_string(robots) + "_" + std::to_string(instance);
        }

        MultiRobotProblem rooms(std::size_t robots, std::uint32_t instance, double resolution, Rng &rng)
        {
            const std::size_t count = 2 + uniformIndex(rng, 2);
            const std::size_t perRoom = (robots + count - 1) / count;
            // Cells 2 apart, at least twice as many as robots in a room (starts and goals are drawn apart).
            const auto side = std::max<std::size_t>(
                3, static_cast<std::size_t>(std::ceil(std::sqrt(2. * static_cast<double>(perRoom)))));
            const double size = 2. * static_cast<double>(side), wall = 1.;
            const double length = static_cast<double>(count) * (size + wall) - wall;
            DiscWorld world(RADIUS, RADIUS, length - RADIUS, size - RADIUS);
            for (std::size_t k = 0; k + 1 < count; ++k)
            {
                const double x = static_cast<double>(k + 1) * (size + wall) - 0.5 * wall;
                const double door = uniform(rng, 1.5, 2.5);
                const double centre = uniform(rng, 0.5 * door + 1., size - 0.5 * door - 1.);
                const double low = centre - 0.5 * door, high = centre + 0.5 * door;
                world.environment->addBox2D("wall" + std::to_string(k) + "_low", x, 0.5 * low, wall, low);
                world.environment->addBox2D("wall" + std::to_string(k) + "_high", x, 0.5 * (high + size), wall,
                                            size - high);
            }
            std::vector<std::vector<Point>> cells(count);
            for (std::size_t k = 0; k < count; ++k)
                for (std::size_t i = 0; i < side; ++i)
                    for (std::size_t j = 0; j < side; ++j)
                        cells[k].push_back({static_cast<double>(k) * (size + wall) + 1. + 2. * static_cast<double>(i),
                                            1. + 2. * static_cast<double>(j)});
            const auto [from, to] = crossGroups(robots, count, side * side, rng);
            auto starts = drawCells(from, cells, rng);
            auto goals = drawCells(to, cells, rng);
            return world.problem(instanceName("rooms", robots, instance), starts, goals, resolution);
        }

        MultiRobotProblem crossing(std::size_t robots, std::uint32_t instance, double resolution, Rng &rng)
        {
            const double width = uniform(rng, 3., 4.5), half = 0.5 * width;
            constexpr double LANE = 1.25, ROW = 1.5;
            const auto lanes = static_cast<std::size_t>((width - 1.5) / LANE) + 1;
            const std::size_t perArm = 2 * ((robots + 3) / 4);
            const std::size_t rows = (perArm + lanes - 1) / lanes;
            const double reach = half + ROW + ROW * static_cast<double>(rows);
            DiscWorld world(-reach + RADIUS, -reach + RADIUS, reach - RADIUS, reach - RADIUS);
            const double block = reach - half, middle = 0.5 * (half + reach);
            for (int sx : {-1, 1})
                for (int sy : {-1, 1})
                    world.environment->addBox2D("block" + std::to_string(sx) + std::to_string(sy), sx * middle,
                                                sy * middle, block, block);
            // Arm a points along (cos, sin) of a * 90 degrees; its slots sit in rows across the corridor.
            std::vector<std::vector<Point>> cells(4);
            for (std::size_t a = 0; a < 4; ++a)
            {
                const double ux = std::round(std::cos(M_PI_2 * static_cast<double>(a))),
                             uy = std::round(std::sin(M_PI_2 * static_cast<double>(a)));
                for (std::size_t row = 0; row < rows; ++row)
                    for (std::size_t lane = 0; lane < lanes; ++lane)
                    {
                        const double along = half + ROW * (1. + static_cast<double>(row));
                        const double across = (static_cast<double>(lane) - 0.5 * static_cast<double>(lanes - 1)) * LANE;
                        cells[a].push_back({along * ux - across * uy, along * uy + across * ux});
                    }
            }
            const auto [from, to] = crossGroups(robots, 4, rows * lanes, rng);
            auto starts = drawCells(from, cells, rng);
            auto goals = drawCells(to, cells, rng);
            return world.problem(instanceName("crossing", robots, instance), starts, goals, resolution);
        }

        MultiRobotProblem ring(std::size_t robots, std::uint32_t instance, double resolution, Rng &rng)
        {
            const double n = static_cast<double>(robots);
            const double radius = std::max(1.5, uniform(rng, 1.3, 2.2) * n / (2. * M_PI));
            const double offset = uniform(rng, 0., 2. * M_PI), reach = radius + 2.5;
            DiscWorld world(-reach, -reach, reach, reach);
            if (instance % 2 == 1 && radius > 3.)
            {
                const double side = std::sqrt(2.) * (radius - 1.75);
                world.environment->addBox2D("block", 0., 0., side, side, uniform(rng, 0., M_PI_2));
            }
            std::vector<Point> starts, goals;
            for (std::size_t i = 0; i < robots; ++i)
            {
                const double angle = offset + 2. * M_PI * static_cast<double>(i) / n;
                starts.push_back({radius * std::cos(angle), radius * std::sin(angle)});
            }
            for (std::size_t i = 0; i < robots; ++i)
                goals.push_back(starts[(i + robots / 2) % robots]);
            return world.problem(instanceName("ring", robots, instance), starts, goals, resolution);
        }

        MultiRobotProblem field(std::size_t robots, std::uint32_t instance, double resolution, Rng &rng)
        {
            const double side = std::sqrt(static_cast<double>(robots) * uniform(rng, 10., 16.));
            constexpr double CELL = 1.6;
            std::vector<Point> grid;
            for (double x = 1.; x <= side - 1.; x += CELL)
                for (double y = 1.; y <= side - 1.; y += CELL)
                    grid.push_back({x, y});
            for (unsigned int draw = 0; draw < LAYOUT_DRAWS; ++draw)
            {
                DiscWorld world(RADIUS, RADIUS, side - RADIUS, side - RADIUS);
                for (std::size_t k = 0; k < (robots + 1) / 2; ++k)
                    world.environment->addBox2D("box" + std::to_string(k), uniform(rng, 0., side),
                                                uniform(rng, 0., side), uniform(rng, 0.8, 2.5), uniform(rng, 0.8, 2.5),
                                                uniform(rng, 0., M_PI));
                auto cells = world.connectedPoints(world.freePoints(grid));
                if (cells.size() < 2 * robots)
                    continue;
                shuffle(cells, rng);
                std::vector<Point> starts(cells.begin(), cells.begin() + static_cast<long>(robots)), goals = starts;
                shuffle(goals, rng);
                return world.problem(instanceName("field", robots, instance), starts, goals, resolution);
            }
            throw ompl::Exception("ProblemFamilies", "no field layout with room for the team");
        }

        MultiRobotProblem planarCell(std::size_t robots, std::uint32_t instance, double resolution, Rng &rng)
        {
            const auto columns = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(robots))));
            const double dx = uniform(rng, 1.0, 1.4), dy = uniform(rng, 1.0, 1.4);
            ompl::base::RealVectorBounds limits(3);
            limits.setLow(-M_PI);
            limits.setHigh(M_PI);
            auto environment = std::make_shared<Environment>();
            std::vector<RobotPtr> team;
            for (std::size_t i = 0; i < robots; ++i)
                team.push_back(std::make_shared<PlanarArm>(
                    "arm" + std::to_string(i), environment,
                    dx * static_cast<double>(i % columns) + uniform(rng, -0.1, 0.1),
                    dy * static_cast<double>(i / columns) + uniform(rng, -0.1, 0.1), uniform(rng, -M_PI, M_PI),
                    std::vector<double>{0.3, 0.3, 0.3}, 0.1, limits));
            const auto si = std::make_shared<MultiRobotSpaceInformation>(team, resolution);
            // Each robot in turn draws configurations until one is valid and clear of those placed before it;
            // the team starts over when a robot finds none.
            const auto placeTeam = [&]
            {
                for (unsigned int restart = 0; restart < LAYOUT_DRAWS; ++restart)
                {
                    std::vector<Point> placed;
                    for (std::size_t r = 0; r < robots && placed.size() == r; ++r)
                        for (unsigned int draw = 0; draw < LAYOUT_DRAWS; ++draw)
                        {
                            Point q = {uniform(rng, -M_PI, M_PI), uniform(rng, -M_PI, M_PI), uniform(rng, -M_PI, M_PI)};
                            bool clear = team[r]->isValid(q.data());
                            for (std::size_t j = 0; j < placed.size() && clear; ++j)
                                clear = !si->robotsCollide(r, q.data(), j, placed[j].data());
                            if (clear)
                            {
                                placed.push_back(q);
                                break;
                            }
                        }
                    if (placed.size() == robots)
                        return placed;
                }
                throw ompl::Exception("ProblemFamilies", "could not place the planar arms");
            };
            auto starts = placeTeam();
            auto goals = placeTeam();
            return MultiRobotProblem(si, std::move(starts), std::move(goals),
                                     instanceName("planar_cell", robots, instance));
        }

        MultiRobotProblem pandaCell(std::size_t robots, std::uint32_t instance, double resolution, Rng &rng)
        {
            return generatePandaCageProblem(robots, static_cast<std::uint32_t>(rng()),
                                            instanceName("panda_cell", robots, instance))
                .withResolution(resolution);
        }

        using Generator = std::function<MultiRobotProblem(std::size_t, std::uint32_t, double, Rng &)>;

        const std::map<std::string, Generator> &generators()
        {
            static const std::map<std::string, Generator> table = {
                {"crossing", crossing},      {"field", field}, {"panda_cell", pandaCell},
                {"planar_cell", planarCell}, {"ring", ring},   {"rooms", rooms}};
            return table;
        }
    }  // namespace

    MultiRobotProblem generateFamilyInstance(const std::string &family, std::size_t robots, std::uint32_t instance,
                                             double resolution)
    {
        const auto it = generators().find(family);
        if (it == generators().end())
        {
            std::string valid;
            for (const auto &name : familyNames())
                valid += (valid.empty() ? "" : ", ") + name;
            throw ompl::Exception("ProblemFamilies", "unknown family '" + family + "' (valid: " + valid + ")");
        }
        if (robots < 2)
            throw ompl::Exception("ProblemFamilies", "a family instance needs at least 2 robots");
        // The family's name is part of the seed, so that families with equal counts draw differently.
        std::vector<std::uint32_t> seed(family.begin(), family.end());
        seed.push_back(static_cast<std::uint32_t>(robots));
        seed.push_back(instance);
        boost::random::seed_seq sequence(seed.begin(), seed.end());
        Rng rng(sequence);
        MultiRobotProblem problem = it->second(robots, instance, resolution, rng);
        if (const std::string reason = problem.checkEndpoints(); !reason.empty())
            throw ompl::Exception("ProblemFamilies", "instance " + problem.getName() + " is invalid: " + reason);
        return problem;
    }

    std::vector<std::string> familyNames()
    {
        std::vector<std::string> names;
        for (const auto &entry : generators())
            names.push_back(entry.first);
        return names;
    }
}  // namespace ompl_parc::scenarios
