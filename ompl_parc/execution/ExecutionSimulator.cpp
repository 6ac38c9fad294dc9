#include "ompl_parc/execution/ExecutionSimulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

ompl_parc::ExecutionSimulator::Disturbance ompl_parc::ExecutionSimulator::Disturbance::random(std::size_t robots,
                                                                                              std::uint64_t seed,
                                                                                              double maxDelay,
                                                                                              double minScale)
{
    if (!(maxDelay >= 0.) || !std::isfinite(maxDelay) || !(minScale > 0.) || !(minScale <= 1.))
        throw std::invalid_argument("ExecutionSimulator: delays must be finite and >= 0, speed scales in (0, 1]");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> delay(0., maxDelay), scale(minScale, 1.);
    Disturbance d;
    for (std::size_t i = 0; i < robots; ++i)
    {
        d.startDelay.push_back(delay(rng));
        d.speedScale.push_back(scale(rng));
    }
    return d;
}

ompl_parc::ExecutionSimulator::ExecutionSimulator(const MultiRobotProblem &problem, const MultiRobotPlan &plan,
                                                  const TeamTrajectory &trajectory, const TemporalPlanGraph &graph,
                                                  double maxSpeed)
    : plan_(plan), trajectory_(trajectory), graph_(graph), check_(problem), maxSpeed_(maxSpeed)
{
    if (graph.getRobotCount() != plan.getRobotCount() || trajectory.getRobotCount() != plan.getRobotCount())
        throw std::invalid_argument("ExecutionSimulator: trajectory, graph and plan are of different teams");
    for (std::size_t p = 0; p <= graph.getPhaseCount(); ++p)
        times_.push_back(trajectory.timeAtPlanStep(static_cast<double>(graph.getBoundary(p))));
}

void ompl_parc::ExecutionSimulator::configAt(std::size_t i, double step, double *out) const
{
    const unsigned int dim = plan_.getDimension(i);
    const double floor = std::floor(step), s = step - floor;
    const auto t = static_cast<std::size_t>(floor);
    plan_.getConfig(i, t, out);
    if (s == 0.)
        return;
    std::vector<double> next(dim);
    plan_.getConfig(i, t + 1, next.data());
    for (unsigned int d = 0; d < dim; ++d)
        out[d] += s * (next[d] - out[d]);
}

ompl_parc::ExecutionSimulator::Outcome ompl_parc::ExecutionSimulator::finish(double makespan,
                                                                             const ExecutionCheck::Motion &motion) const
{
    Outcome outcome;
    outcome.makespan = makespan;
    const ValidationReport report = check_.check(0., makespan, maxSpeed_, motion);
    outcome.collisionFree = report.valid;
    outcome.message = report.message;
    return outcome;
}

ompl_parc::ExecutionSimulator::Outcome ompl_parc::ExecutionSimulator::run(Mode mode,
                                                                          const Disturbance &disturbance) const
{
    const std::size_t n = plan_.getRobotCount(), phases = graph_.getPhaseCount();
    if (disturbance.startDelay.size() != n || disturbance.speedScale.size() != n)
        throw std::invalid_argument("ExecutionSimulator: the disturbance is for another team size");
    const double origin = times_.front();
    if (mode == Mode::TIME_INDEXED)
    {
        double makespan = 0.;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double arrival = trajectory_.timeAtPlanStep(static_cast<double>(plan_.getArrival(i))) - origin;
            makespan = std::max(makespan, disturbance.startDelay[i] + arrival / disturbance.speedScale[i]);
        }
        return finish(makespan,
                      [&](std::size_t i, double t, double *out)
                      {
                          const double own = std::max(0., t - disturbance.startDelay[i]) * disturbance.speedScale[i];
                          configAt(i, trajectory_.planTimeAt(origin + own), out);
                      });
    }

    // Coordinated: phase by phase (every edge points forward in phases), each synchronised group starts when all
    // its members and all their predecessors are done.
    std::vector<double> finished(phases * n, 0.), start(phases * n, 0.);
    std::vector<double> last(disturbance.startDelay);
    std::vector<std::vector<TemporalPlanGraph::Node>> before(phases * n);
    for (const auto &e : graph_.getEdges())
        before[e.to.phase * n + e.to.robot].push_back(e.from);
    std::vector<double> groupReady(n), groupDuration(n);
    for (std::size_t p = 0; p < phases; ++p)
    {
        std::fill(groupReady.begin(), groupReady.end(), 0.);
        std::fill(groupDuration.begin(), groupDuration.end(), 0.);
        const double nominal = times_[p + 1] - times_[p];
        for (std::size_t i = 0; i < n; ++i)
            if (graph_.isMoving(i, p))
            {
                double ready = last[i];
                for (const auto &from : before[p * n + i])
                    ready = std::max(ready, finished[from.phase * n + from.robot]);
                const std::size_t g = graph_.getGroup(i, p);
                groupReady[g] = std::max(groupReady[g], ready);
                groupDuration[g] = std::max(groupDuration[g], nominal / disturbance.speedScale[i]);
            }
        for (std::size_t i = 0; i < n; ++i)
            if (graph_.isMoving(i, p))
            {
                const std::size_t g = graph_.getGroup(i, p);
                start[p * n + i] = groupReady[g];
                last[i] = finished[p * n + i] = groupReady[g] + groupDuration[g];
            }
    }
    // Per robot, its motions in order, for the look-up by time.
    std::vector<std::vector<std::size_t>> motions(n);
    for (std::size_t p = 0; p < phases; ++p)
        for (std::size_t i = 0; i < n; ++i)
            if (graph_.isMoving(i, p))
                motions[i].push_back(p);
    const double makespan = *std::max_element(last.begin(), last.end());
    return finish(makespan,
                  [&](std::size_t i, double t, double *out)
                  {
                      const auto &own = motions[i];
                      // The last motion started at or before t.
                      const auto after =
                          std::upper_bound(own.begin(), own.end(), t,
                                           [&](double value, std::size_t p) { return value < start[p * n + i]; });
                      if (after == own.begin())
                      {
                          configAt(i, static_cast<double>(graph_.getBoundary(0)), out);
                          return;
                      }
                      const std::size_t p = *(after - 1);
                      const double from = start[p * n + i], to = finished[p * n + i];
                      const double s = to > from ? std::min(1., (t - from) / (to - from)) : 1.;
                      const auto b0 = static_cast<double>(graph_.getBoundary(p)),
                                 b1 = static_cast<double>(graph_.getBoundary(p + 1));
                      configAt(i, b0 + s * (b1 - b0), out);
                  });
}
