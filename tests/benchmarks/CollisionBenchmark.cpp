/* Robot-robot pair checks per second: discs (Mobile Cross) and 3-link planar arms (Planar Cross).
   "Bodies" benchmarks test precomputed bodies (the conflict scan's inner loop); "Configs" ones include
   forward kinematics of both robots, as MultiRobotSpaceInformation::robotsCollide() does. The FCL
   variant runs FCL's narrow phase on the same capsule pairs, for comparison.

   Robot-environment checks, side by side on the same 10 000 random configurations: a Panda of Panda Cage 8
   against the cage's 12 bars and a disc of Warehouse Aisle against its shelves and pillar, the analytic test
   (Environment::collides) against FCL (Environment::collidesFcl). "Env" variants check precomputed bodies;
   "Validity" ones the whole state check: Robot::isValid against the same steps with FCL (body,
   self-collision, environment; the bounds test, which only isValid does, is a few comparisons). "teamPairs": a whole
   team's robot pairs at one state, every pair against the sweep (below). allocs_per_check counts heap allocations
   inside the timed loop (this file replaces the global operator new to count them). */
#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/collision/CollidingPairSweep.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/scenarios/PandaCage.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/narrowphase/collision.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

namespace
{
    std::atomic<std::size_t> allocations{0};
}  // namespace

void *operator new(std::size_t size)
{
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(size == 0 ? 1 : size))
        return p;
    throw std::bad_alloc();
}

void operator delete(void *p) noexcept
{
    std::free(p);
}

void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}

using namespace ompl_parc;

namespace
{
    constexpr std::size_t SAMPLES = 4096;

    /** Random configurations of robots 0 and 1 of a scenario, all with overlapping bounding spheres, so
        that the narrow phase runs on every pair (far-apart pairs would only measure the early-out). */
    struct PairSet
    {
        MultiRobotProblem problem;
        std::vector<std::vector<double>> qa, qb;
        std::vector<CollisionBody> a, b;

        explicit PairSet(const std::string &scenario) : problem(scenarios::createScenario(scenario, 2))
        {
            std::mt19937 rng(1);
            const auto &si = *problem.getSpaceInformation();
            CollisionBody ba, bb;
            while (qa.size() < SAMPLES)
            {
                auto q0 = sample(*si.getRobot(0), rng), q1 = sample(*si.getRobot(1), rng);
                if (scenario == "mobile_cross")  // bring discs within a few radii of each other
                    for (int d = 0; d < 2; ++d)
                        q1[d] = q0[d] + std::uniform_real_distribution<double>(-1.5, 1.5)(rng);
                si.getRobot(0)->computeBody(q0.data(), ba);
                si.getRobot(1)->computeBody(q1.data(), bb);
                const double dx = ba.centerX_ - bb.centerX_, dy = ba.centerY_ - bb.centerY_;
                if (std::hypot(dx, dy) >= ba.boundRadius_ + bb.boundRadius_)
                    continue;
                qa.push_back(q0);
                qb.push_back(q1);
                a.push_back(ba);
                b.push_back(bb);
            }
        }

        static std::vector<double> sample(const Robot &robot, std::mt19937 &rng)
        {
            std::vector<double> q(robot.getDimension());
            for (unsigned int d = 0; d < q.size(); ++d)
                q[d] = std::uniform_real_distribution<double>(robot.getBounds().low[d], robot.getBounds().high[d])(rng);
            return q;
        }
    };

    const PairSet &pairs(const std::string &scenario)
    {
        static const PairSet discs("mobile_cross"), arms("planar_cross");
        return scenario == "mobile_cross" ? discs : arms;
    }

    void bodies(benchmark::State &state, const std::string &scenario)
    {
        const PairSet &set = pairs(scenario);
        std::size_t k = 0, hits = 0;
        for (auto _ : state)
        {
            hits += bodiesCollide(set.a[k], set.b[k]);
            k = (k + 1) % SAMPLES;
        }
        state.SetItemsProcessed(state.iterations());
        state.counters["collision_fraction"] = double(hits) / double(state.iterations());
    }

    void configs(benchmark::State &state, const std::string &scenario)
    {
        const PairSet &set = pairs(scenario);
        const auto &si = *set.problem.getSpaceInformation();
        std::size_t k = 0;
        for (auto _ : state)
        {
            benchmark::DoNotOptimize(si.robotsCollide(0, set.qa[k].data(), 1, set.qb[k].data()));
            k = (k + 1) % SAMPLES;
        }
        state.SetItemsProcessed(state.iterations());
    }

    void fclBodies(benchmark::State &state, const std::string &scenario)
    {
        const PairSet &set = pairs(scenario);
        auto transform = [](const CollisionBody &b, std::size_t i)
        {
            const Eigen::Vector3d p(b.ax_[i], b.ay_[i], b.az_[i]), q(b.bx_[i], b.by_[i], b.bz_[i]);
            fcl::Transform3d tf = fcl::Transform3d::Identity();
            tf.translation() = 0.5 * (p + q);
            if ((q - p).norm() > 0.)
                tf.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), q - p).toRotationMatrix();
            return std::make_pair(fcl::Capsuled(b.radius_[i], (q - p).norm()), tf);
        };
        std::size_t k = 0;
        fcl::CollisionRequestd request;
        for (auto _ : state)
        {
            bool hit = false;
            for (std::size_t i = 0; i < set.a[k].size() && !hit; ++i)
                for (std::size_t j = 0; j < set.b[k].size() && !hit; ++j)
                {
                    const auto [ca, ta] = transform(set.a[k], i);
                    const auto [cb, tb] = transform(set.b[k], j);
                    fcl::CollisionResultd result;
                    hit = fcl::collide(&ca, ta, &cb, tb, request, result) > 0;
                }
            benchmark::DoNotOptimize(hit);
            k = (k + 1) % SAMPLES;
        }
        state.SetItemsProcessed(state.iterations());
    }
}  // namespace

BENCHMARK_CAPTURE(bodies, Disc, std::string("mobile_cross"));
BENCHMARK_CAPTURE(bodies, PlanarArm3, std::string("planar_cross"));
BENCHMARK_CAPTURE(configs, Disc, std::string("mobile_cross"));
BENCHMARK_CAPTURE(configs, PlanarArm3, std::string("planar_cross"));
BENCHMARK_CAPTURE(fclBodies, Disc, std::string("mobile_cross"));
BENCHMARK_CAPTURE(fclBodies, PlanarArm3, std::string("planar_cross"));

namespace
{
    constexpr std::size_t CONFIGS = 10000;

    /** CONFIGS random configurations of one robot of a problem in its bounds, and their bodies. */
    struct ConfigSet
    {
        MultiRobotProblem problem;
        std::vector<std::vector<double>> q;
        std::vector<CollisionBody> bodies;

        explicit ConfigSet(MultiRobotProblem p) : problem(std::move(p))
        {
            const Robot &r = robot();
            std::mt19937 rng(1);
            for (std::size_t k = 0; k < CONFIGS; ++k)
            {
                q.push_back(PairSet::sample(r, rng));
                bodies.emplace_back();
                r.computeBody(q.back().data(), bodies.back());
            }
        }

        const Robot &robot() const { return *problem.getSpaceInformation()->getRobot(0); }
    };

    const ConfigSet &configSet(const std::string &kind)
    {
        static const ConfigSet panda(scenarios::createPandaCage(8, 0)),
            disc(ScenarioFile::read(std::string(OMPL_PARC_SCENARIO_DIR) + "/warehouse_aisle.json"));
        return kind == "panda" ? panda : disc;
    }

    /** The environment test alone, on precomputed bodies. */
    void env(benchmark::State &state, const std::string &kind, bool fcl)
    {
        const ConfigSet &set = configSet(kind);
        const Environment &environment = *set.robot().getEnvironment();
        std::size_t k = 0, hits = 0;
        const std::size_t before = allocations.load();
        for (auto _ : state)
        {
            hits += (fcl ? environment.collidesFcl(set.bodies[k]) : environment.collides(set.bodies[k])) ? 1 : 0;
            k = (k + 1) % CONFIGS;
        }
        state.SetItemsProcessed(state.iterations());
        state.counters["collision_fraction"] = double(hits) / double(state.iterations());
        state.counters["allocs_per_check"] = double(allocations.load() - before) / double(state.iterations());
    }

    /** The whole state check: Robot::isValid, or its steps with FCL for the environment. */
    void validity(benchmark::State &state, const std::string &kind, bool fcl)
    {
        const ConfigSet &set = configSet(kind);
        const Robot &robot = set.robot();
        const Environment &environment = *robot.getEnvironment();
        CollisionBody body;
        const auto fclValid = [&](const double *q)  // the configurations are in bounds
        {
            robot.computeBody(q, body);
            return !robot.selfCollides(body) && !environment.collidesFcl(body);
        };
        std::size_t k = 0, valid = 0;
        const std::size_t before = allocations.load();
        for (auto _ : state)
        {
            valid += (fcl ? fclValid(set.q[k].data()) : robot.isValid(set.q[k].data())) ? 1 : 0;
            k = (k + 1) % CONFIGS;
        }
        state.SetItemsProcessed(state.iterations());
        state.counters["valid_fraction"] = double(valid) / double(state.iterations());
        state.counters["allocs_per_check"] = double(allocations.load() - before) / double(state.iterations());
    }
}  // namespace

BENCHMARK_CAPTURE(env, PandaCage_Analytic, std::string("panda"), false);
BENCHMARK_CAPTURE(env, PandaCage_FCL, std::string("panda"), true);
BENCHMARK_CAPTURE(validity, PandaCage_Analytic, std::string("panda"), false);
BENCHMARK_CAPTURE(validity, PandaCage_FCL, std::string("panda"), true);
BENCHMARK_CAPTURE(env, DiscWarehouse_Analytic, std::string("disc"), false);
BENCHMARK_CAPTURE(env, DiscWarehouse_FCL, std::string("disc"), true);
BENCHMARK_CAPTURE(validity, DiscWarehouse_Analytic, std::string("disc"), false);
BENCHMARK_CAPTURE(validity, DiscWarehouse_FCL, std::string("disc"), true);

/* A whole team's robot pairs at one state, as MultiRobotValidityChecker::isValid() tests them after each robot
   alone: every pair against CollidingPairSweep::any(), on the bodies of the team at its start configurations (no
   pair collides there: the common case of a valid path state, where no early exit helps). Mobile Cross stands in
   two crossing rows (the sweep's worst layout: one row overlaps along either axis), a field instance spreads the
   team over a square with obstacles. MultiRobotValidityChecker::SWEEP_FROM comes from these runs. */
namespace
{
    std::vector<CollisionBody> startBodies(const std::string &scenario, std::size_t robots)
    {
        const auto problem = scenarios::createScenario(scenario, robots);
        const auto &si = *problem.getSpaceInformation();
        std::vector<CollisionBody> bodies(robots);
        for (std::size_t i = 0; i < robots; ++i)
            si.getRobot(i)->computeBody(problem.getStart(i).data(), bodies[i]);
        return bodies;
    }

    void teamPairs(benchmark::State &state, const std::string &scenario, bool sweep)
    {
        const auto bodies = startBodies(scenario, static_cast<std::size_t>(state.range(0)));
        CollidingPairSweep sweeper;
        const std::size_t before = allocations.load();
        for (auto _ : state)
        {
            bool any = false;
            if (sweep)
                any = sweeper.any(bodies);
            else
                for (std::size_t i = 0; i < bodies.size() && !any; ++i)
                    for (std::size_t j = i + 1; j < bodies.size() && !any; ++j)
                        any = bodiesCollide(bodies[i], bodies[j]);
            benchmark::DoNotOptimize(any);
        }
        state.counters["allocs_per_check"] =
            static_cast<double>(allocations.load() - before) / static_cast<double>(state.iterations());
        state.SetItemsProcessed(state.iterations());
    }

    /** Team sizes around MultiRobotValidityChecker::SWEEP_FROM, and large ones. */
    void crossTeams(benchmark::internal::Benchmark *b)
    {
        for (int robots : {4, 8, 16, 24, 32, 64, 256})
            b->Arg(robots);
    }

    void fieldTeams(benchmark::internal::Benchmark *b)
    {
        for (int robots : {8, 16, 24, 32, 48})
            b->Arg(robots);
    }
}  // namespace

BENCHMARK_CAPTURE(teamPairs, EveryPairMobileCross, std::string("mobile_cross"), false)->Apply(crossTeams);
BENCHMARK_CAPTURE(teamPairs, SweepMobileCross, std::string("mobile_cross"), true)->Apply(crossTeams);
BENCHMARK_CAPTURE(teamPairs, EveryPairField, std::string("field"), false)->Apply(fieldTeams);
BENCHMARK_CAPTURE(teamPairs, SweepField, std::string("field"), true)->Apply(fieldTeams);
