/* The waypoint plan against a tiny dense reference: the per-timestep grid as MultiRobotPlan stored it before
   it became timed waypoints (flat states per robot, laid with OMPL's own interpolate, spliced and trimmed state
   by state). Every comparison is bit for bit (memcmp), at every timestep and past the arrival. */
#include "TestProblems.h"

#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace ompl_parc;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** The dense reference: one robot's states at timesteps 0..arrival, flat. */
    using Dense = std::vector<double>;

    std::size_t stepsFor(double d, double resolution)
    {
        return static_cast<std::size_t>(std::ceil(d * resolution - 1e-9));
    }

    /** The former grid laying: every grid state through the space's own interpolate, the waypoint copied. */
    template <typename Append>
    void denseLay(const ob::StateSpacePtr &space, const og::PathGeometric &path, double resolution, Append append)
    {
        ob::State *tmp = space->allocState();
        append(path.getState(0));
        for (std::size_t k = 1; k < path.getStateCount(); ++k)
        {
            const ob::State *from = path.getState(k - 1), *to = path.getState(k);
            const std::size_t steps = stepsFor(space->distance(from, to), resolution);
            for (std::size_t s = 1; s <= steps; ++s)
            {
                if (s == steps)
                    space->copyState(tmp, to);
                else
                    space->interpolate(from, to, static_cast<double>(s) / static_cast<double>(steps), tmp);
                append(tmp);
            }
        }
        space->freeState(tmp);
    }

    std::vector<Dense> denseTeam(const MultiRobotSpaceInformation &si, const og::PathGeometric &path)
    {
        std::vector<Dense> paths(si.getRobotCount());
        denseLay(si.getStateSpace(), path, si.getResolution(),
                 [&](const ob::State *state)
                 {
                     for (std::size_t i = 0; i < paths.size(); ++i)
                     {
                         const double *q = si.getRobotValues(state, i);
                         paths[i].insert(paths[i].end(), q, q + si.getRobot(i)->getDimension());
                     }
                 });
        return paths;
    }

    void denseTrim(Dense &p, unsigned int d)
    {
        while (p.size() > d && std::equal(p.end() - 2 * d, p.end() - d, p.end() - d))
            p.resize(p.size() - d);
    }

    void denseSplice(Dense &path, unsigned int d, std::size_t from, std::size_t to, const Dense &segment)
    {
        const std::size_t arrival = path.size() / d - 1;
        Dense spliced(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(std::min(from, arrival) * d));
        for (std::size_t t = arrival; t < from; ++t)
            spliced.insert(spliced.end(), path.end() - d, path.end());
        spliced.insert(spliced.end(), segment.begin(), segment.end());
        if (to < arrival)
            spliced.insert(spliced.end(), path.begin() + static_cast<std::ptrdiff_t>((to + 1) * d), path.end());
        path = std::move(spliced);
        denseTrim(path, d);
    }

    /** \e timed equals \e dense bit for bit at every timestep (and holds past the arrival), through getConfig(),
        a forward Cursor and bounds() of a few windows. */
    void expectSame(const TimedPath &timed, const Dense &dense, const std::string &what)
    {
        const unsigned int d = timed.getDimension();
        const std::size_t arrival = dense.size() / d - 1;
        ASSERT_EQ(timed.getArrival(), arrival) << what;
        std::vector<double> q(d), c(d);
        TimedPath::Cursor cursor(timed);
        for (std::size_t t = 0; t <= arrival + 3; ++t)
        {
            const double *expected = dense.data() + std::min(t, arrival) * d;
            timed.getConfig(t, q.data());
            cursor.get(t, c.data());
            ASSERT_EQ(std::memcmp(q.data(), expected, d * sizeof(double)), 0) << what << ", timestep " << t;
            ASSERT_EQ(std::memcmp(c.data(), expected, d * sizeof(double)), 0) << what << ", cursor, timestep " << t;
        }
        std::vector<double> lo(d), hi(d);
        for (const auto &[a, b] : {std::pair<std::size_t, std::size_t>{0, arrival}, {arrival / 3, arrival / 2 + 1},
                                   {arrival / 2, arrival + 5}})
        {
            timed.bounds(a, b, lo.data(), hi.data());
            for (unsigned int i = 0; i < d; ++i)
            {
                double l = dense[std::min(a, arrival) * d + i], h = l;
                for (std::size_t t = a; t <= std::min(b, arrival); ++t)
                {
                    l = std::min(l, dense[t * d + i]);
                    h = std::max(h, dense[t * d + i]);
                }
                ASSERT_EQ(lo[i], l) << what << ", bounds [" << a << ", " << b << "]";
                ASSERT_EQ(hi[i], h) << what << ", bounds [" << a << ", " << b << "]";
            }
        }
    }

    /** A random composite path of the team: big and small moves, robots that stay (the others move), whole
        states repeated (segments of 0 steps), moves too small for a step, and signed zeros. */
    og::PathGeometric randomPath(const MultiRobotSpaceInformationPtr &si, std::mt19937 &rng)
    {
        std::uniform_real_distribution<double> where(-4., 4.), unit(0., 1.);
        og::PathGeometric path(si);
        ob::ScopedState<> state(si);
        const int count = std::uniform_int_distribution<int>(1, 7)(rng);
        for (int k = 0; k < count; ++k)
        {
            if (k == 0 || unit(rng) > 0.1)  // else: the same state again
                for (std::size_t i = 0; i < si->getRobotCount(); ++i)
                {
                    double *q = si->getRobotValues(state.get(), i);
                    const double roll = unit(rng);
                    for (unsigned int d = 0; d < si->getRobot(i)->getDimension(); ++d)
                    {
                        if (k > 0 && roll < 0.3)
                            continue;  // this robot stays
                        if (k > 0 && roll < 0.4)
                            q[d] += 1e-13;  // a move of no timestep
                        else if (unit(rng) < 0.1)
                            q[d] = unit(rng) < 0.5 ? -0. : 0.;
                        else
                            q[d] = k > 0 && roll < 0.6 ? q[d] + 0.01 * where(rng) : where(rng);
                    }
                }
            path.append(state.get());
        }
        return path;
    }

    /** Random team problems: discs (2 values each) and planar arms (several joints). */
    std::vector<MultiRobotProblem> teams()
    {
        return {scenarios::createMobileCross(4, 16.), scenarios::createPlanarCross(2, 16.)};
    }
}  // namespace

TEST(TimedPath, LaysCompositePathsExactlyAsTheDenseGrid)
{
    std::mt19937 rng(1);
    for (const auto &problem : teams())
    {
        const auto &si = problem.getSpaceInformation();
        for (int trial = 0; trial < 60; ++trial)
        {
            const auto path = randomPath(si, rng);
            auto dense = denseTeam(*si, path);
            const auto team = MultiRobotPlan::layTeamPath(*si, path);
            const auto plan = MultiRobotPlan::fromPathGeometric(*si, path);
            for (std::size_t i = 0; i < si->getRobotCount(); ++i)
            {
                const std::string what = problem.getName() + " trial " + std::to_string(trial) + " robot " +
                                         std::to_string(i);
                expectSame(team[i], dense[i], what + " (untrimmed)");
                denseTrim(dense[i], si->getRobot(i)->getDimension());
                expectSame(plan.getPath(i), dense[i], what);
                // A single robot's path over its own space lays the same way.
                og::PathGeometric own(si->getRobot(i)->getSpaceInformation());
                ob::ScopedState<> q(si->getRobot(i)->getSpaceInformation());
                for (std::size_t k = 0; k < path.getStateCount(); ++k)
                {
                    si->getRobot(i)->configToState(si->getRobotValues(path.getState(k), i), q.get());
                    own.append(q.get());
                }
                Dense alone;
                denseLay(own.getSpaceInformation()->getStateSpace(), own, si->getResolution(),
                         [&](const ob::State *s)
                         {
                             const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                             alone.insert(alone.end(), v, v + si->getRobot(i)->getDimension());
                         });
                expectSame(MultiRobotPlan::discretize(*si->getRobot(i), own, si->getResolution()), alone,
                           what + " (alone)");
            }
        }
    }
}

TEST(TimedPath, SplicesExactlyAsTheDenseGrid)
{
    std::mt19937 rng(2);
    for (const auto &problem : teams())
    {
        const auto &si = problem.getSpaceInformation();
        auto plan = MultiRobotPlan::fromPathGeometric(*si, randomPath(si, rng));
        std::vector<Dense> dense;
        for (std::size_t i = 0; i < si->getRobotCount(); ++i)
            dense.push_back(plan.getRobotPath(i));
        for (int trial = 0; trial < 300; ++trial)
        {
            // A patch of a random sub-team laid from a random path (or a dense one, as from a version 1 file).
            const auto patchPath = randomPath(si, rng);
            const auto patch = MultiRobotPlan::layTeamPath(*si, patchPath);
            const std::size_t r = std::uniform_int_distribution<std::size_t>(0, si->getRobotCount() - 1)(rng);
            const std::size_t arrival = plan.getArrival(r);
            const std::size_t from = std::uniform_int_distribution<std::size_t>(0, arrival + 20)(rng);
            const std::size_t to = std::uniform_int_distribution<std::size_t>(from, arrival + 40)(rng);
            const unsigned int d = si->getRobot(r)->getDimension();
            const auto segment = trial % 5 == 0 ? TimedPath::fromDense(d, patch[r].toDense()) : patch[r];
            denseSplice(dense[r], d, from, to, patch[r].toDense());
            plan.splice(r, from, to, segment);
            expectSame(plan.getPath(r), dense[r],
                       problem.getName() + " splice " + std::to_string(trial) + " [" + std::to_string(from) + ", " +
                           std::to_string(to) + "] robot " + std::to_string(r));
            if (testing::Test::HasFatalFailure())
                return;
        }
        // The OMPL path (waypoints at the breakpoints) is the plan's motion: straight between them.
        const auto times = plan.getBreakpoints();
        const auto path = plan.toPathGeometric(si);
        EXPECT_TRUE(test::pathFollowsPlan(*si, *path, plan));
        for (std::size_t i = 0; i < si->getRobotCount(); ++i)
            for (std::size_t k = 1; k < times.size(); ++k)
                for (std::size_t t = times[k - 1]; t <= times[k]; ++t)
                {
                    const auto a = test::config(plan, i, times[k - 1]), b = test::config(plan, i, times[k]),
                               q = test::config(plan, i, t);
                    const double s =
                        static_cast<double>(t - times[k - 1]) / static_cast<double>(times[k] - times[k - 1]);
                    for (std::size_t c = 0; c < q.size(); ++c)
                        ASSERT_NEAR(q[c], a[c] + (b[c] - a[c]) * s, 1e-9) << "robot " << i << " timestep " << t;
                }
    }
}

TEST(TimedPath, DenseCompositePathsLayAsBefore)
{
    // A path of one state per timestep (as toPathGeometric wrote before) still gives the dense plan.
    std::mt19937 rng(3);
    const auto problem = scenarios::createMobileCross(4, 16.);
    const auto &si = problem.getSpaceInformation();
    const auto plan = MultiRobotPlan::fromPathGeometric(*si, randomPath(si, rng));
    og::PathGeometric dense(si);
    ob::ScopedState<> state(si);
    for (std::size_t t = 0; t <= plan.getMakespan(); ++t)
    {
        for (std::size_t i = 0; i < si->getRobotCount(); ++i)
            plan.getConfig(i, t, si->getRobotValues(state.get(), i));
        dense.append(state.get());
    }
    auto reference = denseTeam(*si, dense);
    const auto back = MultiRobotPlan::fromPathGeometric(*si, dense);
    for (std::size_t i = 0; i < si->getRobotCount(); ++i)
    {
        denseTrim(reference[i], 2);
        expectSame(back.getPath(i), reference[i], "robot " + std::to_string(i));
    }
}

TEST(TimedPath, ArcPlansOnTheBuiltInScenariosLayBothWaysAlike)
{
    for (const auto &[name, robots] : std::vector<std::pair<std::string, std::size_t>>{
             {"mobile_cross", 8}, {"mobile_circle", 8}, {"planar_cross", 4}})
    {
        const auto problem = scenarios::createScenario(name, robots);
        const auto &si = problem.getSpaceInformation();
        ARC arc(si);
        arc.setSeed(5);
        ASSERT_EQ(test::solveWith(arc, problem, 60.), ob::PlannerStatus::EXACT_SOLUTION) << name;
        const auto report = SolutionValidator(problem).validate(arc.getPlan());
        EXPECT_TRUE(report.valid) << name << ": " << report.message;
        const auto &path = *arc.getProblemDefinition()->getSolutionPath()->as<og::PathGeometric>();
        EXPECT_TRUE(test::pathFollowsPlan(*si, path, arc.getPlan())) << name;
        auto dense = denseTeam(*si, path);
        const auto laid = MultiRobotPlan::fromPathGeometric(*si, path);
        for (std::size_t i = 0; i < si->getRobotCount(); ++i)
        {
            denseTrim(dense[i], si->getRobot(i)->getDimension());
            expectSame(laid.getPath(i), dense[i], name + " robot " + std::to_string(i));
        }
    }
}

TEST(TimedPath, BadInputThrows)
{
    const std::vector<double> q = {1., 2.};
    TimedPath path(2, q.data());
    EXPECT_THROW(path.appendPiece({5, 0, 0}, q.data(), q.data(), 6), ompl::Exception);  // a gap
    EXPECT_THROW(path.splice(3, 2, path), ompl::Exception);
    EXPECT_THROW(path.splice(0, 1, TimedPath(2)), ompl::Exception);
    EXPECT_THROW(TimedPath(2).getArrival(), ompl::Exception);
    EXPECT_THROW(TimedPath::fromDense(2, {1., 2., 3.}), ompl::Exception);
}
