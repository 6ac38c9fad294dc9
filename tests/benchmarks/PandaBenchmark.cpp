/* Panda-Panda pair checks per second: our capsule model (bodiesCollide) against FCL on the URDF primitives
   (per primitive pair an AABB test, then FCL's narrow phase: UrdfFclModel), on the same random configuration
   pairs of two facing Pandas (the layout of tests/PandaCollisionTest.cpp). "Configs" variants include the
   forward kinematics of both arms; "Placed" ones check precomputed bodies / placed FCL objects, as the
   conflict scan does (it computes each robot's body once per timestep for all its pairs): "/4096" cycles through
   all 4096 pairs (the bodies do not fit this machine's caches), "/256" through the first 256 (they do, as the
   few bodies of one timestep of the scan do).

   PandaModel/<model>/Pair and /Alone: the cost per check of a Panda model as the planners use it, forward kinematics
   included: a pair of facing arms (bodiesCollide) and one arm's own validity (self-collision, a table:
   Robot::allValid over the 8 configurations of a motion's rake). <model> is Capsules, our built-in Panda, and, where
   the environment variable OMPL_PARC_SPHERE_PANDA names a Panda URDF of spheres (VAMP's
   resources/panda/panda_spherized.urdf: 59 spheres, the model VAMP and VAMP-MR plan with), Spheres, on the same
   configurations: what a user who brings such a model pays per check.

   PandaRRTConnect: one Panda alone in the cage, start and goal of Panda Cage 8 task 0, planned as ARC's first
   stage does (InitialPlanner: RRT-Connect, then optionally OMPL's simplifier with the authors' bounded effort);
   iteration i plans robot i mod 8 with seed i + 1; median_ms is the median over the iterations. */
#include "ompl_parc/arc/InitialPlanner.h"
#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/UrdfFclModel.h"
#include "ompl_parc/scenarios/PandaCage.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <random>

using namespace ompl_parc;

namespace
{
    constexpr std::size_t SAMPLES = 4096;

    struct PandaPairs
    {
        std::shared_ptr<UrdfArm> a, b;
        std::vector<std::vector<double>> qa, qb;

        PandaPairs()
        {
            const auto load = [](const Eigen::Isometry3d &base) {
                return std::make_shared<UrdfArm>("panda", nullptr, models::pandaUrdf(), "panda_link0", "panda_link8",
                                                 base);
            };
            a = load(Eigen::Isometry3d::Identity());
            b = load(UrdfArm::pose(0.6, 0., 1.2, M_PI, 0., M_PI));
            std::mt19937 rng(1);
            for (std::size_t k = 0; k < SAMPLES; ++k)
            {
                qa.push_back(sample(*a, rng));
                qb.push_back(sample(*b, rng));
            }
        }

        static std::vector<double> sample(const Robot &robot, std::mt19937 &rng)
        {
            std::vector<double> q(robot.getDimension());
            for (unsigned int k = 0; k < robot.getDimension(); ++k)
                q[k] = std::uniform_real_distribution<double>(robot.getBounds().low[k], robot.getBounds().high[k])(rng);
            return q;
        }
    };

    const PandaPairs &pairs()
    {
        static const PandaPairs set;
        return set;
    }

    /** Pair checks of arms \e a and \e b, bodies computed from the pairs' configurations (both arms' forward
        kinematics included). */
    void timePairChecks(benchmark::State &state, const UrdfArm &a, const UrdfArm &b)
    {
        const auto &set = pairs();
        CollisionBody ba, bb;
        std::size_t k = 0, hits = 0;
        for (auto _ : state)
        {
            a.computeBody(set.qa[k].data(), ba);
            b.computeBody(set.qb[k].data(), bb);
            hits += bodiesCollide(ba, bb) ? 1 : 0;
            k = (k + 1) % SAMPLES;
        }
        state.counters["capsules"] = static_cast<double>(ba.size());
        state.counters["colliding_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
        state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
    }

    void BM_PandaPairCapsules(benchmark::State &state)
    {
        timePairChecks(state, *pairs().a, *pairs().b);
    }
    BENCHMARK(BM_PandaPairCapsules)->Name("PandaPair/Capsules/Configs");

    void BM_PandaPairCapsulesPlaced(benchmark::State &state)
    {
        const auto &set = pairs();
        std::vector<CollisionBody> ba(SAMPLES), bb(SAMPLES);
        for (std::size_t k = 0; k < SAMPLES; ++k)
        {
            set.a->computeBody(set.qa[k].data(), ba[k]);
            set.b->computeBody(set.qb[k].data(), bb[k]);
        }
        const auto cycle = static_cast<std::size_t>(state.range(0));
        std::size_t k = 0, hits = 0;
        for (auto _ : state)
        {
            hits += bodiesCollide(ba[k], bb[k]) ? 1 : 0;
            k = (k + 1) % cycle;
        }
        benchmark::DoNotOptimize(hits);
        state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
    }
    BENCHMARK(BM_PandaPairCapsulesPlaced)->Name("PandaPair/Capsules/Placed")->Arg(SAMPLES)->Arg(256);

    void BM_PandaPairFcl(benchmark::State &state)
    {
        const auto &set = pairs();
        UrdfFclModel ma(set.a), mb(set.b);
        std::size_t k = 0, hits = 0;
        for (auto _ : state)
        {
            ma.setConfig(set.qa[k].data());
            mb.setConfig(set.qb[k].data());
            hits += ma.collides(mb) ? 1 : 0;
            k = (k + 1) % SAMPLES;
        }
        benchmark::DoNotOptimize(hits);
        state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
    }
    BENCHMARK(BM_PandaPairFcl)->Name("PandaPair/FCL/Configs");

    void BM_PandaPairFclPlaced(benchmark::State &state)
    {
        const auto &set = pairs();
        std::vector<UrdfFclModel> ma, mb;
        for (std::size_t k = 0; k < SAMPLES; ++k)
        {
            ma.emplace_back(set.a).setConfig(set.qa[k].data());
            mb.emplace_back(set.b).setConfig(set.qb[k].data());
        }
        const auto cycle = static_cast<std::size_t>(state.range(0));
        std::size_t k = 0, hits = 0;
        for (auto _ : state)
        {
            hits += ma[k].collides(mb[k]) ? 1 : 0;
            k = (k + 1) % cycle;
        }
        benchmark::DoNotOptimize(hits);
        state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
    }
    BENCHMARK(BM_PandaPairFclPlaced)->Name("PandaPair/FCL/Placed")->Arg(SAMPLES)->Arg(256);

    /** The Panda of \e urdf (our built-in one if empty) at \e base, beside a table. */
    std::shared_ptr<UrdfArm> pandaModel(const std::string &urdf, const Eigen::Isometry3d &base)
    {
        auto table = std::make_shared<Environment>();
        Obstacle top;
        top.name = "table";
        top.size = Eigen::Vector3d(1.2, 1.2, 0.1);
        top.pose = Eigen::Translation3d(0.6, 0., -0.15);
        table->addObstacle(top);
        return std::make_shared<UrdfArm>("panda", table, urdf.empty() ? models::pandaUrdf() : UrdfArm::readFile(urdf),
                                         "panda_link0", "panda_hand", base);
    }

    void BM_PandaModelPair(benchmark::State &state, const std::string &urdf)
    {
        timePairChecks(state, *pandaModel(urdf, Eigen::Isometry3d::Identity()),
                       *pandaModel(urdf, UrdfArm::pose(0.6, 0., 1.2, M_PI, 0., M_PI)));
    }

    void BM_PandaModelAlone(benchmark::State &state, const std::string &urdf)
    {
        const auto &set = pairs();
        const auto arm = pandaModel(urdf, Eigen::Isometry3d::Identity());
        // A motion's rake: 8 configurations a small step apart around each sample.
        constexpr std::size_t RAKE = 8;
        std::vector<double> rakes(SAMPLES * RAKE * 7);
        for (std::size_t k = 0; k < SAMPLES; ++k)
            for (std::size_t s = 0; s < RAKE; ++s)
                for (std::size_t d = 0; d < 7; ++d)
                    rakes[(k * RAKE + s) * 7 + d] = set.qa[k][d] + 0.01 * static_cast<double>(s);
        std::size_t k = 0, valid = 0;
        for (auto _ : state)
        {
            valid += arm->allValid(rakes.data() + k * RAKE * 7, RAKE) ? 1 : 0;
            k = (k + 1) % SAMPLES;
        }
        state.counters["valid_fraction"] = static_cast<double>(valid) / static_cast<double>(state.iterations());
        state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * RAKE));
    }

    /** The Capsules cases, and the Spheres ones where OMPL_PARC_SPHERE_PANDA names a URDF. */
    const bool registeredModels = []
    {
        std::vector<std::pair<std::string, std::string>> models{{"Capsules", ""}};
        if (const char *spheres = std::getenv("OMPL_PARC_SPHERE_PANDA"); spheres != nullptr && *spheres != '\0')
            models.emplace_back("Spheres", spheres);
        for (const auto &[name, urdf] : models)
        {
            benchmark::RegisterBenchmark(("PandaModel/" + name + "/Pair").c_str(), BM_PandaModelPair, urdf);
            benchmark::RegisterBenchmark(("PandaModel/" + name + "/Alone").c_str(), BM_PandaModelAlone, urdf);
        }
        return true;
    }();

    void BM_PandaRRTConnect(benchmark::State &state, bool simplify)
    {
        static const MultiRobotProblem problem = scenarios::createPandaCage(8, 0);
        const InitialPlanner planner(problem, simplify);
        TimedPath path;
        std::vector<double> milliseconds;
        std::size_t i = 0, solved = 0;
        for (auto _ : state)
        {
            const auto start = std::chrono::steady_clock::now();
            solved += planner.plan(i % 8, ompl::base::timedPlannerTerminationCondition(10.), i + 1, path) ? 1 : 0;
            milliseconds.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            ++i;
        }
        std::nth_element(milliseconds.begin(), milliseconds.begin() + milliseconds.size() / 2, milliseconds.end());
        state.counters["median_ms"] = milliseconds[milliseconds.size() / 2];
        state.counters["solved_fraction"] = double(solved) / double(i);
    }
    BENCHMARK_CAPTURE(BM_PandaRRTConnect, Simplified, true)
        ->Name("PandaRRTConnect/Simplified")
        ->Iterations(40)
        ->Unit(benchmark::kMillisecond);
    BENCHMARK_CAPTURE(BM_PandaRRTConnect, Raw, false)
        ->Name("PandaRRTConnect/Raw")
        ->Iterations(40)
        ->Unit(benchmark::kMillisecond);
}  // namespace
